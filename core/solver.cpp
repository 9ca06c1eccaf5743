#include "solver.hpp"

#include <cmath>
#include <string>

#include "contact/error.hpp"

namespace creepwork {

Solver::Solver(const GridSpec& grid) : fastsim_(grid) {}

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
    SolveTotals t;
    if (input.model == ModelKind::exact) {
        prepare(ModelKind::exact);
        t = jacobian ? exact_->solve_jacobian(input, mode, *jacobian) : exact_->solve(input, mode);
    } else if (input.model == ModelKind::calibrated) {
        t = jacobian ? calibrated_model().solve_jacobian(input, mode, *jacobian)
                     : calibrated_model().solve(input, mode);
    } else {
        t = fastsim_.solve(input, mode, jacobian);
    }
    last_model_ = input.model;

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

void Solver::prepare(ModelKind model)
{
    if (model == ModelKind::exact) {
        if (!exact_) exact_ = std::make_unique<ExactModel>(fastsim_.grid().spec());
    } else if (model == ModelKind::calibrated) {
        if (!calibrated_) calibrated_ = std::make_unique<CalibratedModel>(fastsim_.grid().spec());
    } else if (model != ModelKind::fastsim) {
        throw Error(ErrorKind::invalid_input,
                    "model = " + std::to_string(static_cast<int>(model)) + " is unknown");
    }
}

CalibratedModel& Solver::calibrated_model()
{
    prepare(ModelKind::calibrated);
    return *calibrated_;
}

bool Solver::exact_last() const { return last_model_ == ModelKind::exact && exact_; }
bool Solver::calibrated_last() const
{
    return last_model_ == ModelKind::calibrated && calibrated_;
}

void Solver::copy_field(Field f, double* out) const
{
    if (exact_last())
        exact_->copy_field(f, out);
    else if (calibrated_last())
        calibrated_->copy_field(f, out);
    else
        fastsim_.copy_field(f, out);
}

void Solver::add_field(Field f, double scale, double* out) const
{
    if (exact_last())
        exact_->add_field(f, scale, out);
    else if (calibrated_last())
        calibrated_->add_field(f, scale, out);
    else
        fastsim_.add_field(f, scale, out);
}

void Solver::copy_state(int* out) const
{
    if (exact_last())
        exact_->copy_state(out);
    else if (calibrated_last())
        calibrated_->copy_state(out);
    else
        fastsim_.copy_state(out);
}

void Solver::copy_profile(double* y, double* work, double* parabola) const
{
    if (exact_last())
        exact_->copy_profile(totals_.W_consistent, y, work, parabola);
    else if (calibrated_last())
        calibrated_->copy_profile(totals_.W_consistent, y, work, parabola);
    else
        fastsim_.copy_profile(totals_.W_consistent, y, work, parabola);
}

} // namespace creepwork
