// FASTSIM with a friction law at the contact's global slip speed, as
// CONTACT's FASTSIM takes a law (its M=2/3 with L=2..4): one coefficient
// mu(w) at w = V |(xi_x, xi_y)| for the whole contact, and Spiryagin's slope
// reduction of the flexibilities L/k (friction/global_slip.hpp: the input's
// k0, alpha_inf, beta; k0 = alpha_inf = 1 is none). FASTSIM solves the
// input global_slip_input() makes; its Jacobian adds the chain rule through
// mu(w) and k (global_slip_jacobian). Every mode and field is FASTSIM's.
#pragma once

#include "fastsim/fastsim_model.hpp"
#include "friction/slip_speed_law.hpp"

namespace creepwork {

class FastsimGlobalSlipModel : public FastsimModel {
public:
    explicit FastsimGlobalSlipModel(std::shared_ptr<const ContactGrid> grid);

    // The law and V [m/s] (> 0 for a law other than Coulomb's) of the next
    // solves.
    void set_law(const SlipSpeedLaw& law, double V) override;
    // Throws Error(invalid_input) naming a bad input (the law's, V, k0,
    // alpha_inf, beta).
    SolveTotals solve(const ContactInput& input, SolveMode mode) override;
    // Needs flexibility_blending off (an error names it).
    SolveTotals solve_jacobian(const ContactInput& input, SolveMode mode,
                               Jacobian& jacobian) override;
    // mu(w) of the last solve, for both.
    bool friction_range(double& mu_min, double& mu_max) const override;
    // One mu for the whole contact: element-wise factors are refused by name.
    void set_friction_factors(const double* factor) override
    {
        ContactModel::set_friction_factors(factor);
    }

private:
    ContactInput effective(const ContactInput& input);

    SlipSpeedLaw law_;
    double V_ = 0.0;
    double mu_ = 0.0;
};

} // namespace creepwork
