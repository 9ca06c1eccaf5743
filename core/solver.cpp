#include "solver.hpp"

#include <cmath>
#include <string>

#include "contact/error.hpp"

namespace creepwork {

Solver::Solver(const GridSpec& grid) : fastsim_(grid) {}

const SolveTotals& Solver::solve(const ContactInput& input, SolveMode mode)
{
    solved_ = false;
    mode_ = mode;
    if (input.model != ModelKind::fastsim)
        throw Error(ErrorKind::invalid_input,
                    std::string("model = ") +
                        (input.model == ModelKind::exact ? "exact" : "calibrated") +
                        " is not available in this build");
    const SolveTotals t = fastsim_.solve(input, mode);

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

void Solver::copy_field(Field f, double* out) const { fastsim_.copy_field(f, out); }

void Solver::add_field(Field f, double scale, double* out) const
{
    fastsim_.add_field(f, scale, out);
}

void Solver::copy_state(int* out) const { fastsim_.copy_state(out); }

void Solver::copy_profile(double* y, double* work, double* parabola) const
{
    fastsim_.copy_profile(totals_.W_consistent, y, work, parabola);
}

} // namespace creepwork
