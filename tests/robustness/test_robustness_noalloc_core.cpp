// No heap allocation in creepwork::Solver::solve (both modes) nor in
// copying its fields, states and profile out, counted by interposing malloc
// (count_malloc.h sees operator new, which libstdc++ implements with
// malloc, and Eigen's aligned_malloc, which calls std::malloc). This is
// stricter than Eigen's EIGEN_RUNTIME_NO_MALLOC, which would see only
// Eigen's own allocations and only in code compiled with the macro.
#include <vector>

#include "count_malloc.h"
#include "solver.hpp"
#include "test_support.h"

namespace cw = creepwork;

namespace {

cw::ContactInput contact(int k)
{
    cw::ContactInput in;
    in.a = 6e-3;
    in.b = 6e-3;
    in.normal_force = 80e3;
    in.mu = 0.3;
    in.G = 82e9;
    in.nu = 0.28;
    in.xi_x = 1e-3 * (k % 3);
    in.xi_y = -5e-4 * (k % 2);
    in.phi = 10.0 * (k % 5 - 2);
    in.pressure = k % 2 ? cw::PressureKind::elliptic : cw::PressureKind::parabolic;
    in.rolling_direction = k % 4 == 3 ? -1 : 1;
    if (k == 5) {
        in.flexibility = cw::FlexibilitySource::given;
        in.L1 = in.L2 = in.L3 = 1e-11;
    }
    if (k == 6) in.xi_x = 1e150; // scaled to full sliding
    if (k == 7) in.normal_force = 0.0;
    return in;
}

// Buffers for every export of a solver's grid, made before counting.
struct Exports {
    std::vector<double> out, y, w, parabola;
    std::vector<int> states;
    explicit Exports(const cw::GridSpec& g)
        : out(static_cast<size_t>(g.nx) * g.ny), y(g.ny), w(g.ny), parabola(g.ny),
          states(static_cast<size_t>(g.nx) * g.ny)
    {
    }
};

// A full solve and every field (copied and added), the states and the
// profile: what a wear code reads after each contact.
void solve_full_and_export_all(cw::Solver& solver, const cw::ContactInput& in, Exports& e)
{
    solver.solve(in, cw::SolveMode::full);
    for (int f = 0; f <= static_cast<int>(cw::Field::work_consistent); ++f) {
        solver.copy_field(static_cast<cw::Field>(f), e.out.data());
        solver.add_field(static_cast<cw::Field>(f), 0.5, e.out.data());
    }
    solver.copy_state(e.states.data());
    solver.copy_profile(e.y.data(), e.w.data(), e.parabola.data());
}

void test_counter_works(void**)
{
    cw_count_start();
    std::vector<double>* v = new std::vector<double>(10);
    const long n = cw_count_stop();
    delete v;
    assert_true(n >= 2); // the vector object and its storage
}

void test_solver_solve_allocates_nothing(void**)
{
    for (int kind = 0; kind < 2; ++kind) {
        cw::GridSpec g;
        g.kind = kind ? cw::GridKind::uniform : cw::GridKind::kalker_strips;
        g.nx = 41;
        g.ny = 27;
        g.box_scale = 1.2;
        cw_count_start();
        cw::Solver solver(g);
        assert_true(cw_count_stop() > 0);

        Exports e(g);
        cw::Jacobian jacobian;
        long allocations = 0;
        for (int k = 0; k < 8; ++k) {
            const cw::ContactInput in = contact(k);
            cw_count_start();
            solver.solve(in, cw::SolveMode::forces_only);
            for (cw::Field f : {cw::Field::x, cw::Field::y, cw::Field::area, cw::Field::pz,
                                cw::Field::px, cw::Field::py, cw::Field::mz})
                solver.copy_field(f, e.out.data());
            solver.copy_state(e.states.data());
            solve_full_and_export_all(solver, in, e);
            // The Jacobian (forward mode in the march): needs N > 0.
            cw::ContactInput jin = in;
            jin.normal_force = 80e3;
            jin.flexibility_blending = k % 2 == 0;
            solver.solve_jacobian(jin, k % 2 ? cw::SolveMode::full : cw::SolveMode::forces_only,
                                  jacobian);
            // The calibrated model's (made on first use, as the C ABI's
            // prepare does; its Jacobian's workspaces come with it).
            if (k == 0) {
                allocations += cw_count_stop();
                solver.prepare(cw::ModelKind::calibrated);
                cw_count_start();
            }
            jin.model = cw::ModelKind::calibrated;
            jin.flexibility_blending = false;
            jin.flexibility = cw::FlexibilitySource::kalker_from_material;
            solver.solve_jacobian(jin, k % 2 ? cw::SolveMode::full : cw::SolveMode::forces_only,
                                  jacobian);
            allocations += cw_count_stop();
        }
        assert_int_equal(allocations, 0);
    }
}

// The exact model: after prepare(), its successful solves (warm or
// cold, forces or full, a new a/b) and every export allocate nothing.
void test_exact_solve_allocates_nothing_after_prepare(void**)
{
    cw::GridSpec g;
    g.kind = cw::GridKind::uniform;
    g.nx = 26;
    g.ny = 22;
    g.box_scale = 1.15;
    cw_count_start();
    cw::Solver solver(g);
    solver.prepare(cw::ModelKind::exact);
    assert_true(cw_count_stop() > 0);
    Exports e(g);
    cw::Jacobian jacobian;
    long allocations = 0;
    for (int k = 0; k < 10; ++k) {
        cw::ContactInput in = contact(k % 8);
        in.model = cw::ModelKind::exact;
        in.flexibility = cw::FlexibilitySource::kalker_from_material;
        in.warm_start = k % 3 != 0;
        if (k == 8) in.a *= 1.7; // a new a/b: coefficients and normal problem again
        if (k == 9) in.xi_x = 1e-9; // full adhesion, unresolved work
        cw_count_start();
        solver.solve(in, cw::SolveMode::forces_only);
        for (cw::Field f : {cw::Field::x, cw::Field::y, cw::Field::area, cw::Field::pz,
                            cw::Field::px, cw::Field::py, cw::Field::mz})
            solver.copy_field(f, e.out.data());
        solver.copy_state(e.states.data());
        solve_full_and_export_all(solver, in, e);
        // The Jacobian: three more linear solves in the prepared workspaces.
        in.normal_force = 80e3;
        solver.solve_jacobian(in, cw::SolveMode::forces_only, jacobian);
        allocations += cw_count_stop();
    }
    assert_int_equal(allocations, 0);
}

// The calibrated model: once made (prepare), its solves, with a
// blended traction bound that changes from solve to solve, and every export
// allocate nothing.
void test_calibrated_solve_allocates_nothing_after_prepare(void**)
{
    for (int kind = 0; kind < 2; ++kind) {
        cw::GridSpec g;
        g.kind = kind ? cw::GridKind::uniform : cw::GridKind::kalker_strips;
        g.nx = 33;
        g.ny = 29;
        cw::Solver solver(g);
        solver.prepare(cw::ModelKind::calibrated);
        Exports e(g);
        long allocations = 0;
        for (int k = 0; k < 8; ++k) {
            if (k == 5) continue; // given flexibilities: refused by this model
            cw::ContactInput in = contact(k);
            in.model = cw::ModelKind::calibrated;
            cw_count_start();
            solver.solve(in, cw::SolveMode::forces_only);
            solver.copy_field(cw::Field::pz, e.out.data());
            solve_full_and_export_all(solver, in, e);
            allocations += cw_count_stop();
        }
        assert_int_equal(allocations, 0);
    }
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_counter_works),
        cmocka_unit_test(test_solver_solve_allocates_nothing),
        cmocka_unit_test(test_exact_solve_allocates_nothing_after_prepare),
        cmocka_unit_test(test_calibrated_solve_allocates_nothing_after_prepare),
    };
    return cmocka_run_group_tests_name("robustness_noalloc_core", tests, nullptr, nullptr);
}
