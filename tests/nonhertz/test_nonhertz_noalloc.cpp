// No heap allocation in a gap grid's solves once the solver exists (it makes
// the exact model at creation, FASTSIM's by prepare()): cold and warm, the
// gap or the load changed, the approach given, the semi-Hertzian method, no
// contact, FASTSIM with either normal method, and every export (fields,
// states, profile, strips, patches); and both models' Jacobians. Counted by interposing malloc
// (../robustness/count_malloc.h), so built without sanitizers.
#include <vector>

#include "count_malloc.h"
#include "gap_shape_grid.hpp"
#include "gap_shapes.hpp"
#include "solver.hpp"
#include "test_support.h"

namespace cw = creepwork;

namespace {

void gap_solves_allocate_nothing(void**)
{
    const std::vector<gapshapes::Shape> shapes = gapshapes::shapes();
    const gapshapes::Shape& s = shapes[2]; // three lobes: three patches
    const cw::GridSpec g = gapshapes::grid_of(s);
    cw_count_start();
    cw::Solver solver(g);
    solver.prepare(cw::ModelKind::fastsim); // FASTSIM's memory on a gap grid
    assert_true(cw_count_stop() > 0);
    const size_t n = s.h.size();
    std::vector<double> out(n), moved = s.h, y(s.ny), w(s.ny), p(s.ny);
    std::vector<int> states(n);
    for (double& v : moved) v *= 1.01;
    long allocations = 0;
    // k < 9 the exact model, then FASTSIM (both normal methods).
    for (int k = 0; k < 14; ++k) {
        cw::ContactInput in;
        in.model = k < 9 ? cw::ModelKind::exact : cw::ModelKind::fastsim;
        in.gap = (k % 2 ? moved : s.h).data();
        in.gap_len = n;
        in.normal_force = k == 4 ? 0.8 * s.normal_force : s.normal_force;
        in.G = s.G;
        in.nu = s.nu;
        in.mu = k == 7 ? 0.0 : s.mu;
        in.xi_x = 2e-4 * (1 + 0.01 * k);
        in.xi_y = -1e-4;
        in.phi = 0.3;
        in.warm_start = k % 3 != 0;
        in.rolling_direction = k == 6 ? -1 : 1;
        if (k == 5) {
            in.normal_load = cw::NormalLoad::approach;
            in.approach = k == 5 ? 5e-5 : 0.0;
        }
        if (k == 8) in.normal_load = cw::NormalLoad::approach, in.approach = -1.0; // apart
        if (k == 3 || (k >= 9 && k != 12)) in.normal_method = cw::NormalMethod::semi_hertz;
        if (k == 11) in.rolling_direction = -1;
        cw_count_start();
        solver.solve(in, k % 2 ? cw::SolveMode::forces_only : cw::SolveMode::full);
        solver.copy_field(cw::Field::pz, out.data());
        solver.copy_field(cw::Field::px, out.data());
        solver.copy_state(states.data());
        if (solver.has_work()) {
            solver.copy_field(cw::Field::work_consistent, out.data());
            solver.copy_profile(y.data(), w.data(), p.data());
        }
        solver.copy_strips(y.data(), w.data());
        const size_t patches = solver.patches().size();
        allocations += cw_count_stop();
        assert_true(k == 8 ? patches == 0 : patches >= 1);
    }
    assert_int_equal(allocations, 0);

    // The Jacobians on the gap grid: both models, both normal methods, the
    // force or the approach prescribed, warm and cold.
    cw::Jacobian jacobian;
    for (int k = 0; k < 8; ++k) {
        cw::ContactInput in;
        in.model = k < 4 ? cw::ModelKind::exact : cw::ModelKind::fastsim;
        in.gap = s.h.data();
        in.gap_len = n;
        in.normal_force = s.normal_force * (1 + 0.01 * k);
        in.G = s.G;
        in.nu = s.nu;
        in.mu = s.mu;
        in.xi_x = 2e-4;
        in.xi_y = -1e-4;
        in.phi = 0.3;
        in.warm_start = k % 2 != 0;
        if (k % 4 == 1) in.normal_method = cw::NormalMethod::semi_hertz;
        if (k % 4 == 2) in.normal_load = cw::NormalLoad::approach, in.approach = 5e-5;
        if (k % 4 == 3) in.rolling_direction = -1;
        cw_count_start();
        solver.solve_jacobian(in, k % 2 ? cw::SolveMode::forces_only : cw::SolveMode::full,
                              jacobian);
        allocations += cw_count_stop();
        assert_true(jacobian.d[0][0] < 0.0); // dFx/dxi_x: the force opposes the creepage
    }
    assert_int_equal(allocations, 0);
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(gap_solves_allocate_nothing)};
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
