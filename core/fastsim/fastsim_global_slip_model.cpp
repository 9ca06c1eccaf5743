#include "fastsim/fastsim_global_slip_model.hpp"

#include <utility>

#include "friction/friction_input.hpp"
#include "friction/global_slip.hpp"

namespace creepwork {

FastsimGlobalSlipModel::FastsimGlobalSlipModel(std::shared_ptr<const ContactGrid> grid)
    : FastsimModel(std::move(grid))
{
}

void FastsimGlobalSlipModel::set_law(const SlipSpeedLaw& law, double V)
{
    check_slip_speed_law(law);
    law_ = law;
    V_ = V;
}

ContactInput FastsimGlobalSlipModel::effective(const ContactInput& input)
{
    GlobalSlip g;
    const ContactInput eff =
        global_slip_input(input, grid(), law_, slope_reduction(input), V_, &g);
    mu_ = g.mu;
    return eff;
}

SolveTotals FastsimGlobalSlipModel::solve(const ContactInput& input, SolveMode mode)
{
    return FastsimModel::solve(effective(input), mode);
}

SolveTotals FastsimGlobalSlipModel::solve_jacobian(const ContactInput& input, SolveMode mode,
                                                   Jacobian& jacobian)
{
    Jacobian J;
    const SolveTotals t = FastsimModel::solve_jacobian(effective(input), mode, J);
    const double F[3] = {t.Fx, t.Fy, t.Mz};
    jacobian = global_slip_jacobian(input, grid(), law_, slope_reduction(input), V_, J, F);
    return t;
}

bool FastsimGlobalSlipModel::friction_range(double& mu_min, double& mu_max) const
{
    mu_min = mu_max = mu_;
    return true;
}

} // namespace creepwork
