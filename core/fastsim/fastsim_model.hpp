// Kalker's simplified theory as one model of the contact: the FASTSIM march
// (march/) with FASTSIM's setup (Kalker's normalisation, march_setup.hpp),
// the pressure law's shape as the traction bound and CONTACT's steps, and
// its Jacobian by forward differentiation of the march (march_tangent.hpp).
// Made once per grid (march_model.hpp: it owns the grid in the kernels'
// layout and every workspace, and picks the kernel for this CPU), then
// solve() many times without allocating.
#pragma once

#include "contact/params.hpp"
#include "fastsim/march_tangent.hpp"
#include "march/march_model.hpp"

namespace creepwork {

class FastsimModel : public MarchModel {
public:
    explicit FastsimModel(const GridSpec& grid);
    explicit FastsimModel(std::shared_ptr<const ContactGrid> grid); // a solver's grid

    // Throws Error(invalid_input) naming a bad input.
    SolveTotals solve(const ContactInput& input, SolveMode mode) override;
    // The march also carries its tangents (march_tangent.hpp); the totals
    // are bitwise those of solve().
    SolveTotals solve_jacobian(const ContactInput& input, SolveMode mode,
                               Jacobian& jacobian) override;
    // Element-wise factors on mu (contact/friction_law.hpp): each element's
    // bound is its factor times mu p; the caller keeps them.
    void set_friction_factors(const double* factor) override { take_friction_factors(factor); }

private:
    SolveTotals solve(const ContactInput& input, SolveMode mode, Jacobian* jacobian);

    TangentState tangent_;
};

} // namespace creepwork
