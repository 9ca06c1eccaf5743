#include "solver.hpp"

#include <cmath>
#include <string>

#include "contact/error.hpp"

namespace creepwork {
namespace {

// The models a solver can make, by ModelKind: a new model is one class
// implementing ContactModel (contact_model.hpp), one ModelKind value
// (contact/params.hpp) and one case here.
std::unique_ptr<ContactModel> make_model(ModelKind kind, const GridSpec& grid)
{
    switch (kind) {
    case ModelKind::fastsim: return std::make_unique<FastsimModel>(grid);
    case ModelKind::exact: return std::make_unique<ExactModel>(grid);
    case ModelKind::calibrated: return std::make_unique<CalibratedModel>(grid);
    }
    throw Error(ErrorKind::invalid_input,
                "model = " + std::to_string(static_cast<int>(kind)) + " is unknown");
}

} // namespace

Solver::Solver(const GridSpec& grid) : grid_(grid)
{
    last_ = &model(ModelKind::fastsim);
    fastsim_ = static_cast<FastsimModel*>(last_);
}

ContactModel* Solver::find(ModelKind kind) const
{
    for (const auto& m : models_)
        if (m.first == kind) return m.second.get();
    return nullptr;
}

ContactModel& Solver::model(ModelKind kind)
{
    if (ContactModel* m = find(kind)) return *m;
    std::unique_ptr<ContactModel> made = make_model(kind, grid_);
    if (fastsim_) made->set_kernel_isa(fastsim_->kernel_isa());
    models_.emplace_back(kind, std::move(made));
    return *models_.back().second;
}

void Solver::prepare(ModelKind kind) { model(kind); }

const ExactModel* Solver::exact_model() const
{
    return static_cast<const ExactModel*>(find(ModelKind::exact));
}

CalibratedModel& Solver::calibrated_model()
{
    return static_cast<CalibratedModel&>(model(ModelKind::calibrated));
}

void Solver::set_kernel_isa(KernelIsa isa)
{
    fastsim_->set_kernel_isa(isa); // throws when this CPU cannot run it
    for (const auto& m : models_) m.second->set_kernel_isa(isa);
}

const SolveTotals& Solver::solve(const ContactInput& input, SolveMode mode)
{
    return solve_impl(input, mode, nullptr);
}

const SolveTotals& Solver::solve_jacobian(const ContactInput& input, SolveMode mode,
                                          Jacobian& jacobian)
{
    Jacobian J;
    solve_impl(input, mode, &J);
    jacobian_work_row(J, totals_.Fx, totals_.Fy, totals_.Mz, input.xi_x, input.xi_y, input.phi);
    for (const auto& row : J.d)
        for (double v : row)
            if (!std::isfinite(v)) {
                solved_ = false;
                throw Error(ErrorKind::numeric_failure,
                            "a Jacobian entry overflowed: the inputs are too extreme for double "
                            "precision");
            }
    jacobian = J;
    return totals_;
}

const SolveTotals& Solver::solve_impl(const ContactInput& input, SolveMode mode,
                                      Jacobian* jacobian)
{
    solved_ = false;
    mode_ = mode;
    ContactModel& m = model(input.model);
    const SolveTotals t = jacobian ? m.solve_jacobian(input, mode, *jacobian) : m.solve(input, mode);
    last_ = &m;

    const double checks[] = {t.Fx, t.Fy, t.Mz, t.W_macro, t.W_micro_paper, t.K, t.W_consistent,
                             t.balance_factor, t.profile_max_diff, t.profile_rms_diff};
    for (double v : checks)
        if (!std::isfinite(v))
            throw Error(ErrorKind::numeric_failure,
                        "a result overflowed: the inputs are too extreme for double precision");
    totals_ = t;
    solved_ = true;
    return totals_;
}

} // namespace creepwork
