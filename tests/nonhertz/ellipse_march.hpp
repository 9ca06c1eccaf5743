// The gap march (gap/gap_march.hpp) set up on the elliptic contact a solver
// on the uniform grid has just solved: its element pressures, one patch with
// the ellipse's flexibilities L1, L2, L3 centred on the ellipse (its
// centroid by symmetry), the input's creepages and mu (rolling towards +x:
// the rolling frame is the caller's). For the tests that the march on an
// elliptic patch is FASTSIM's march there, under Coulomb's law or a law of
// the slip speed.
#pragma once

#include <vector>

#include "core_test_support.hpp"
#include "gap/gap_march.hpp"
#include "solver.hpp"

namespace cwtest {

struct EllipseMarch {
    std::vector<double> pz;
    std::vector<int> patch;
    creepwork::GapMarchPatch P;
    creepwork::GapMarchInput in; // points into pz, patch and P: not copied

    EllipseMarch(const creepwork::Solver& s, const creepwork::SolveTotals& t,
                 const creepwork::ContactInput& e)
        : pz(field(s, creepwork::Field::pz)), patch(pz.size(), 0), P{t.L1, t.L2, t.L3, 0.0, 0.0}
    {
        const int nx = s.grid().nx();
        const std::vector<double> x = field(s, creepwork::Field::x), y = field(s, creepwork::Field::y);
        in.nx = nx;
        in.ny = s.grid().ny();
        in.x0 = x[0];
        in.y0 = y[0];
        in.dx = x[1] - x[0];
        in.dy = y[nx] - y[0];
        in.pressure = pz.data();
        in.patch = patch.data();
        in.patches = &P;
        in.law = creepwork::CoulombLaw{e.mu};
        in.xi = e.xi_x;
        in.eta = e.xi_y;
        in.phi = e.phi;
    }
    EllipseMarch(const EllipseMarch&) = delete;
    EllipseMarch& operator=(const EllipseMarch&) = delete;
};

} // namespace cwtest
