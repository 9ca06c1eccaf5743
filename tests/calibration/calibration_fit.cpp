#include "calibration_fit.hpp"

#include <cstdio>

namespace cwcal {

namespace cw = creepwork;

ModelResult solved_result(cw::Solver& solver, const cw::ContactInput& in)
{
    const cw::SolveTotals& t = solver.solve(in, cw::SolveMode::full);
    ModelResult r;
    r.Fx = t.Fx;
    r.Fy = t.Fy;
    r.Mz = t.Mz;
    r.W = t.W_macro;
    r.adhesion_fraction = t.adhesion_fraction;
    r.work_map.resize(size_t(solver.grid().nx()) * solver.grid().ny());
    solver.copy_field(cw::Field::work_consistent, r.work_map.data());
    return r;
}

int fit_table(const std::vector<CalibrationCase>& cases, const std::vector<CaseReference>& refs)
{
    (void)cases;
    (void)refs;
    std::fprintf(stderr, "fit: not yet\n");
    return 1;
}

} // namespace cwcal
