// The tractcurv contact (tractcurv_contact.hpp) for the exact model with
// CONTACT's series-2 law alone (the exponential law FKIN 0.14, FEXP1 0.19,
// SABSH1 1250 mm/s): shared by the exact model's law tests and
// bench/bench_friction_exact.cpp.
#pragma once

#include "friction/slip_speed_law.hpp"
#include "tractcurv_contact.hpp"

namespace cwtest {

inline creepwork::SlipSpeedLaw tractcurv_exponential_law()
{
    creepwork::SlipSpeedLaw law;
    law.kind = creepwork::SlipSpeedLawKind::exponential;
    law.mu_kin = 0.14;
    law.mu_e1 = 0.19;
    law.s_h1 = 1.25;
    return law;
}

// The exact model on the tractcurv contact: Hertz's pressure on the given
// semi-axes, Coulomb's mu = 0.33 = mu(0) of the law.
inline creepwork::ContactInput tractcurv_exact(double xi_x, double xi_y = 0.0, double phi = 0.0)
{
    creepwork::ContactInput in = tractcurv_contact(xi_x, xi_y, phi);
    in.model = creepwork::ModelKind::exact;
    in.pressure = creepwork::PressureKind::elliptic;
    in.exact_load = false;
    in.mu = 0.33;
    return in;
}

} // namespace cwtest
