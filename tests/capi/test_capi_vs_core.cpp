// The C ABI adds nothing and loses nothing: every total, field, state and
// profile value through libcreepwork.so equals, bit for bit, what the C++
// core (creepwork::Solver, linked here from the core's objects) computes for
// the same contact. The translation of cw_params into ContactInput is done
// here by hand, independently of capi/capi_translate.cpp.
// The core and the standard library first: cmocka's macros (fail, ...)
// would otherwise clash with names in the C++ headers.
#include <cstring>
#include <vector>

#include "solver.hpp"

#include "capi_fixtures.h"

namespace cw = creepwork;

namespace {

cw::GridSpec core_grid(const cw_grid& g)
{
    cw::GridSpec spec;
    spec.kind = g.kind == CW_GRID_UNIFORM ? cw::GridKind::uniform : cw::GridKind::kalker_strips;
    spec.nx = g.nx;
    spec.ny = g.ny;
    spec.box_scale = g.box_scale;
    return spec;
}

cw::ContactInput core_input(const cw_params& p)
{
    cw::ContactInput in;
    in.a = p.a;
    in.b = p.b;
    in.normal_force = p.normal_force;
    in.mu = p.mu;
    in.flexibility = p.flexibility == CW_FLEX_GIVEN ? cw::FlexibilitySource::given
                                                    : cw::FlexibilitySource::kalker_from_material;
    in.G = p.G;
    in.nu = p.nu;
    in.L1 = p.L1;
    in.L2 = p.L2;
    in.L3 = p.L3;
    in.xi_x = p.xi_x;
    in.xi_y = p.xi_y;
    in.phi = p.phi;
    in.pressure = p.pressure == CW_PRESSURE_ELLIPTIC ? cw::PressureKind::elliptic
                                                     : cw::PressureKind::parabolic;
    in.rolling_direction = p.rolling_direction;
    return in;
}

bool same(double a, double b) { return cw_same_bits(a, b) != 0; }

// Every member of cw_result against its SolveTotals counterpart.
void assert_totals_equal(const cw_result& r, const cw::SolveTotals& t)
{
    assert_true(same(r.Fx, t.Fx) && same(r.Fy, t.Fy) && same(r.Mz, t.Mz));
    assert_true(same(r.W_macro, t.W_macro) && same(r.W_micro_paper, t.W_micro_paper));
    assert_true(same(r.K, t.K) && same(r.W_consistent, t.W_consistent));
    assert_true(same(r.balance_factor, t.balance_factor));
    assert_true(same(r.adhesion_fraction, t.adhesion_fraction));
    assert_int_equal(r.n_contact, t.n_contact);
    assert_int_equal(r.n_adhesion, t.n_adhesion);
    assert_int_equal(r.n_slip, t.n_slip);
    assert_int_equal(r.work_flags, t.work_flags);
    assert_true(same(r.a, t.a) && same(r.b, t.b));
    assert_true(same(r.L1, t.L1) && same(r.L2, t.L2) && same(r.L3, t.L3));
    assert_true(same(r.C11, t.C11) && same(r.C22, t.C22) && same(r.C23, t.C23) &&
                same(r.C33, t.C33));
    assert_true(same(r.profile_max_diff, t.profile_max_diff) &&
                same(r.profile_rms_diff, t.profile_rms_diff));
}

const cw_grid grids[] = {
    {sizeof(cw_grid), CW_GRID_KALKER_STRIPS, 20, 20, 1.0, 0, 0, 0, 0},
    {sizeof(cw_grid), CW_GRID_KALKER_STRIPS, 7, 33, 1.0, 0, 0, 0, 0},
    {sizeof(cw_grid), CW_GRID_UNIFORM, 24, 24, 1.2, 0, 0, 0, 0},
    {sizeof(cw_grid), CW_GRID_UNIFORM, 31, 10, 1.04, 0, 0, 0, 0},
};

// Both grid kinds x every case (both pressures, both flexibility sources,
// spin, both rolling directions, adhesion to full slip) x both modes.
void abi_equals_core(void**)
{
    for (const cw_grid& g : grids) {
        cw_solver* s = nullptr;
        assert_int_equal(cw_solver_create(&g, &s, nullptr, 0), CW_OK);
        cw::Solver core(core_grid(g));
        const size_t n = static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny);
        std::vector<double> abi(n), ref(n);
        std::vector<int> abi_state(n), ref_state(n);
        std::vector<double> abi_y(g.ny), abi_w(g.ny), abi_par(g.ny);
        std::vector<double> ref_y(g.ny), ref_w(g.ny), ref_par(g.ny);
        for (int k = 0; k < CW_TEST_CASES; ++k) {
            for (int mode = CW_SOLVE_FORCES; mode <= CW_SOLVE_FULL; ++mode) {
                cw_params p;
                cw_test_case(k, &p);
                cw_result r;
                cw_result_init(&r);
                assert_int_equal(cw_solver_solve(s, &p, mode, &r), CW_OK);
                const cw::SolveTotals& t = core.solve(
                    core_input(p),
                    mode == CW_SOLVE_FULL ? cw::SolveMode::full : cw::SolveMode::forces_only);
                assert_totals_equal(r, t);

                for (int f = CW_FIELD_X; f <= CW_FIELD_WORK_CONSISTENT; ++f) {
                    const cw::Field field = static_cast<cw::Field>(f);
                    if (mode == CW_SOLVE_FORCES && cw::Solver::needs_work(field)) continue;
                    assert_int_equal(cw_solver_get_field(s, f, abi.data(), n), CW_OK);
                    core.copy_field(field, ref.data());
                    assert_memory_equal(abi.data(), ref.data(), n * sizeof(double));
                }
                assert_int_equal(cw_solver_get_state(s, abi_state.data(), n), CW_OK);
                core.copy_state(ref_state.data());
                assert_memory_equal(abi_state.data(), ref_state.data(), n * sizeof(int));
                if (mode == CW_SOLVE_FULL) {
                    assert_int_equal(cw_solver_get_profile(s, abi_y.data(), abi_w.data(),
                                                           abi_par.data(), abi_y.size()),
                                     CW_OK);
                    core.copy_profile(ref_y.data(), ref_w.data(), ref_par.data());
                    assert_memory_equal(abi_y.data(), ref_y.data(), ref_y.size() * sizeof(double));
                    assert_memory_equal(abi_w.data(), ref_w.data(), ref_w.size() * sizeof(double));
                    assert_memory_equal(abi_par.data(), ref_par.data(),
                                        ref_par.size() * sizeof(double));
                }
            }
        }
        cw_solver_destroy(s);
    }
}

// The ABI casts field ids, states and flags straight into the core's
// enumerations, so the two lists must agree value for value; so must the
// limits the header states.
void field_ids_match_core_order(void**)
{
    assert_int_equal(static_cast<int>(cw::Field::x), CW_FIELD_X);
    assert_int_equal(static_cast<int>(cw::Field::y), CW_FIELD_Y);
    assert_int_equal(static_cast<int>(cw::Field::area), CW_FIELD_AREA);
    assert_int_equal(static_cast<int>(cw::Field::pz), CW_FIELD_PZ);
    assert_int_equal(static_cast<int>(cw::Field::px), CW_FIELD_PX);
    assert_int_equal(static_cast<int>(cw::Field::py), CW_FIELD_PY);
    assert_int_equal(static_cast<int>(cw::Field::sx), CW_FIELD_SX);
    assert_int_equal(static_cast<int>(cw::Field::sy), CW_FIELD_SY);
    assert_int_equal(static_cast<int>(cw::Field::mz), CW_FIELD_MZ);
    assert_int_equal(static_cast<int>(cw::Field::work_paper), CW_FIELD_WORK_PAPER);
    assert_int_equal(static_cast<int>(cw::Field::work_consistent), CW_FIELD_WORK_CONSISTENT);
    assert_int_equal(static_cast<int>(cw::ElementState::exterior), CW_STATE_EXTERIOR);
    assert_int_equal(static_cast<int>(cw::ElementState::adhesion), CW_STATE_ADHESION);
    assert_int_equal(static_cast<int>(cw::ElementState::slip), CW_STATE_SLIP);
    assert_int_equal(cw::kWorkUnresolved, CW_WORK_UNRESOLVED);
    assert_int_equal(cw::kWorkNonPositive, CW_WORK_NON_POSITIVE);
    assert_int_equal(cw::kMaxGridCells, CW_MAX_GRID_CELLS);
    assert_true(cw::kMaxBoxScale == CW_MAX_BOX_SCALE);
    assert_true(cw::kMinAspect == CW_MIN_ASPECT && cw::kMaxAspect == CW_MAX_ASPECT);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(abi_equals_core),
        cmocka_unit_test(field_ids_match_core_order),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
