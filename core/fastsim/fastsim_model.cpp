#include "fastsim/fastsim_model.hpp"

#include <utility>

#include "fastsim/fastsim_jacobian.hpp"

namespace creepwork {

FastsimModel::FastsimModel(const GridSpec& grid)
    : FastsimModel(std::make_shared<const ContactGrid>(grid))
{
}

FastsimModel::FastsimModel(std::shared_ptr<const ContactGrid> grid) : MarchModel(std::move(grid))
{
    tangent_.resize(geometry());
}

SolveTotals FastsimModel::solve(const ContactInput& input, SolveMode mode)
{
    return solve(input, mode, nullptr);
}

SolveTotals FastsimModel::solve_jacobian(const ContactInput& input, SolveMode mode,
                                         Jacobian& jacobian)
{
    return solve(input, mode, &jacobian);
}

SolveTotals FastsimModel::solve(const ContactInput& input, SolveMode mode, Jacobian* jacobian)
{
    const ModelSetup setup =
        make_model_setup(input, discrete_load_of(discrete_load(), input.pressure));
    begin(setup, geometry().shape(setup.pressure).data(), geometry().max_shape(setup.pressure));
    if (mode == SolveMode::full) march_with_work();
    // With work, the tangent march repeats the march: the same state, bitwise.
    if (jacobian) {
        march_tangent(view(), grid(), setup, tangent_, kernel_isa());
        *jacobian = fastsim_jacobian(input, setup, grid(), march_state(), tangent_);
    } else if (mode != SolveMode::full) {
        march();
    }
    return totals(input, mode, ModelKind::fastsim);
}

} // namespace creepwork
