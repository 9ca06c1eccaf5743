// CONTACT's tractcurv example contact (examples/tractcurv.inp, the
// Eurosprinter wheel of Polach 2005): A1 = 0.0008/mm, a/b = 0.5, N = 106.7 kN,
// G = 82 GPa, nu = 0.28, V = 10 m/s, on CONTACT's 48 x 44 grid over 1.1
// times the semi-axes; the semi-axes are those CONTACT prints, 6.304 and
// 12.61 mm. Shared by the friction tests and bench/bench_friction.cpp.
#pragma once

#include "contact/params.hpp"

namespace cwtest {

constexpr double kTractcurvN = 106.7e3;  // [N]
constexpr double kTractcurvV = 10.0;     // [m/s]

inline creepwork::GridSpec tractcurv_grid()
{
    creepwork::GridSpec g;
    g.kind = creepwork::GridKind::uniform;
    g.nx = 48;
    g.ny = 44;
    g.box_scale = 1.1;
    return g;
}

// FASTSIM with the parabolic bound scaled to carry N (CONTACT's B=3); mu
// left to the caller.
inline creepwork::ContactInput tractcurv_contact(double xi_x, double xi_y = 0.0, double phi = 0.0)
{
    creepwork::ContactInput in;
    in.a = 6.304e-3;
    in.b = 12.61e-3;
    in.normal_force = kTractcurvN;
    in.G = 82e9;
    in.nu = 0.28;
    in.model = creepwork::ModelKind::fastsim;
    in.pressure = creepwork::PressureKind::parabolic;
    in.exact_load = true;
    in.xi_x = xi_x;
    in.xi_y = xi_y;
    in.phi = phi;
    return in;
}

} // namespace cwtest
