// CONTACT's own FASTSIM example, reproduced. A CONTACT
// user who runs its shipped examples/fastsim.inp and then creepwork with the
// two compatibility options -- spin_offset = 1/6 (CONTACT's facphi) and
// flexibility_blending = 1 -- must see the same output: every number CONTACT
// prints rounds from ours (forces, moment, frictional power, flexibilities,
// p_max, approach, element counts), and the adhesion/slip map is identical
// element by element. Source: data/contact_fastsim_example.txt, copied from
// CONTACT's examples/fastsim.ref_out (commit d431cdb) by
// extract_contact_example.py. The FASTRIP cases (M = 5) of that example are
// another algorithm and are not in the data.
#include "compat_support.hpp"
#include "test_support.h"

#include <vector>

namespace {

struct Solved {
    cw_result r{};
    std::vector<int> state;
    double fric_power_W = 0; // CONTACT's FRIC.POWER: V sum over slip of p.s area, < 0
    int n = 0;
};

// The contact of one case in SI (CONTACT prints mm, N, N/mm^2, rad/mm).
Solved solve_case(const compat::ContactCase& c, bool compatible)
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_UNIFORM;
    g.nx = int(c.number_of("mx_my_dx_dy", 0));
    g.ny = int(c.number_of("mx_my_dx_dy", 1));
    g.box_scale = c.number_of("box", 2);
    cw_solver* s = nullptr;
    assert_int_equal(cw_solver_create(&g, &s, nullptr, 0), CW_OK);

    cw_params p;
    cw_params_init(&p);
    p.a = 1e-3 * c.number_of("aa_bb", 0);
    p.b = 1e-3 * c.number_of("aa_bb", 1);
    p.normal_force = c.number_of("FN");
    p.mu = c.number_of("FSTAT");
    p.G = 1e6 * c.number_of("G");
    p.nu = c.number_of("NU");
    p.xi_x = c.number_of("CKSI");
    p.xi_y = c.number_of("CETA");
    p.phi = 1e3 * c.number_of("CPHI");
    // CHI = 0: rolling towards +x; CHI = 180 deg (printed in rad, 3.142): -x.
    p.rolling_direction = std::cos(c.number_of("CHI")) > 0.0 ? 1 : -1;
    // BOUND 3: parabolic traction bound, 2: elliptic (CONTACT's user guide).
    p.pressure = c.token("bound") == "2" ? CW_PRESSURE_ELLIPTIC : CW_PRESSURE_PARABOLIC;
    if (compatible) {
        // facphi = 1/6 of DQ, and DQ = DX in every case of the example.
        assert_true(c.token("DQ") == c.token("mx_my_dx_dy", 2));
        p.spin_offset = 1.0 / 6.0;
        p.flexibility_blending = 1;
    }

    Solved out;
    cw_result_init(&out.r);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &out.r), CW_OK);
    out.n = g.nx * g.ny;
    const size_t n = static_cast<size_t>(out.n);
    std::vector<double> px(n), py(n), sx(n), sy(n), area(n);
    out.state.resize(n);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PX, px.data(), n), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PY, py.data(), n), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_SX, sx.data(), n), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_SY, sy.data(), n), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_AREA, area.data(), n), CW_OK);
    assert_int_equal(cw_solver_get_state(s, out.state.data(), n), CW_OK);
    double sum = 0.0;
    for (size_t k = 0; k < n; ++k)
        if (out.state[k] == CW_STATE_SLIP) sum += (px[k] * sx[k] + py[k] * sy[k]) * area[k];
    out.fric_power_W = 1e-3 * c.number_of("VELOC") * sum; // VELOC in mm/s
    cw_solver_destroy(s);
    return out;
}

// Cells of CONTACT's map that differ from ours.
int map_differences(const compat::ContactCase& c, const Solved& s, int* compared)
{
    const int nx = int(c.number_of("mx_my_dx_dy", 0));
    int differ = 0;
    *compared = 0;
    for (const auto& [iy, cells] : c.map)
        for (size_t k = 0; k < cells.size(); ++k) {
            const int i = c.first_ix - 1 + int(k), j = iy - 1;
            const int state = s.state[static_cast<size_t>(i + j * nx)];
            const char ours = state == CW_STATE_SLIP ? 'S' : state == CW_STATE_ADHESION ? '*' : '.';
            differ += ours != cells[k];
            ++*compared;
        }
    return differ;
}

#define assert_rounds_to(value, c, key)                                                     \
    do {                                                                                    \
        const double v_ = (value);                                                          \
        if (!compat::rounds_to(v_, (c).token(key))) {                                       \
            print_error("case %d: %s = %.9g does not round to CONTACT's %s\n", (c).number, \
                        key, v_, (c).token(key).c_str());                                   \
            fail();                                                                         \
        }                                                                                   \
    } while (0)

std::vector<compat::ContactCase> example_cases()
{
    auto cases = compat::read_contact_cases(CW_COMPAT_DATA_DIR "/contact_fastsim_example.txt");
    assert_int_equal(cases.size(), 5); // cases 2, 3, 5, 6, 8 of fastsim.inp
    return cases;
}

void test_contact_default_fastsim_output_reproduced(void**)
{
    int cells = 0;
    for (const compat::ContactCase& c : example_cases()) {
        assert_string_equal(c.token("mater").c_str(), "3"); // FASTSIM, three flexibilities
        const Solved s = solve_case(c, true);
        // Units of CONTACT's printout: N, N mm, W, mm^3/N, N/mm^2, mm.
        assert_rounds_to(s.r.Fx, c, "FX");
        assert_rounds_to(s.r.Fy, c, "FY");
        assert_rounds_to(1e3 * s.r.Mz, c, "MZ");
        assert_rounds_to(s.fric_power_W, c, "FRIC.POWER");
        assert_rounds_to(s.r.Fy / (c.number_of("FSTAT") * c.number_of("FN")), c, "FY/FSTAT/FN");
        assert_rounds_to(1e9 * s.r.L1, c, "FLX1");
        assert_rounds_to(1e9 * s.r.L2, c, "FLX2");
        assert_rounds_to(1e9 * s.r.L3, c, "FLX3");
        assert_rounds_to(1e-6 * s.r.p_max, c, "PMAX");
        assert_rounds_to(1e3 * s.r.approach, c, "APPROACH");
        assert_int_equal(s.r.n_contact, std::atoi(c.token("NCON").c_str()));
        assert_int_equal(s.r.n_adhesion, std::atoi(c.token("NADH").c_str()));
        assert_int_equal(s.r.n_slip, std::atoi(c.token("NSLIP").c_str()));
        int compared = 0;
        const int differ = map_differences(c, s, &compared);
        if (differ != 0) print_error("case %d: %d map cells differ\n", c.number, differ);
        assert_int_equal(differ, 0);
        assert_int_equal(compared, c.map_rows * c.map_cols);
        cells += compared;
    }
    print_message("CONTACT example: 5 cases, %d map cells identical\n", cells);
}

// Without the options the same cases differ: other
// slip counts in every case, FY by up to 2.3 %. The options are what the
// match rests on.
void test_plain_fastsim_differs_from_contact_default(void**)
{
    double worst = 0.0;
    for (const compat::ContactCase& c : example_cases()) {
        const Solved s = solve_case(c, false);
        int compared = 0;
        assert_true(map_differences(c, s, &compared) > 0);
        assert_true(s.r.n_slip != std::atoi(c.token("NSLIP").c_str()));
        worst = std::fmax(worst, std::fabs(s.r.Fy / c.number_of("FY") - 1.0));
    }
    assert_true(worst > 0.02);
}

// CONTACT's blended L1, L2, L3 of every FASTSIM row of the shared reference
// (contact_fastsim_dev.csv: methods b, c and b0 blend, bk does not), from a,
// b, G, nu, mu, N and the creepages alone. 2e-7: CONTACT holds Kalker's
// table in single precision (doc/validation/index.md, flexibilities 4e-8).
void test_blended_flexibilities_match_contact_rows(void**)
{
    const compat::CsvTable t =
        compat::read_csv(CW_TEST_DATA_DIR "/contact_fastsim_dev.csv");
    int checked = 0;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const std::string m = t.text(r, "method");
        if (m != "b" && m != "c" && m != "b0" && m != "bk") continue;
        cw_params p;
        cw_params_init(&p);
        p.a = t.number(r, "a_mm"); // CONTACT's units: mm, N, N/mm^2 (unit-consistent)
        p.b = t.number(r, "b_mm");
        p.normal_force = t.number(r, "FN_N");
        p.mu = t.number(r, "mu");
        p.G = t.number(r, "G_N_per_mm2");
        p.nu = t.number(r, "nu");
        p.xi_x = t.number(r, "cksi");
        p.xi_y = t.number(r, "ceta");
        p.phi = t.number(r, "cphi_rad_per_mm");
        p.flexibility_blending = m != "bk";
        p.pressure = m == "c" ? CW_PRESSURE_ELLIPTIC : CW_PRESSURE_PARABOLIC;
        cw_grid g;
        cw_grid_init(&g);
        g.kind = CW_GRID_UNIFORM;
        g.nx = int(t.number(r, "MX"));
        g.ny = int(t.number(r, "MY"));
        g.box_scale = t.number(r, "SCALE");
        cw_solver* s = nullptr;
        assert_int_equal(cw_solver_create(&g, &s, nullptr, 0), CW_OK);
        cw_result res;
        cw_result_init(&res);
        assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &res), CW_OK);
        cw_solver_destroy(s);
        assert_close(res.L1, t.number(r, "L1_mm3_per_N"), 2e-7, 0.0);
        assert_close(res.L2, t.number(r, "L2_mm3_per_N"), 2e-7, 0.0);
        assert_close(res.L3, t.number(r, "L3_mm3_per_N"), 2e-7, 0.0);
        // The rows' forces from our own flexibilities (the exact-match test
        // with CONTACT's L's is tests/core/test_core_contact_reference.cpp).
        const double F = std::hypot(t.number(r, "FX_N"), t.number(r, "FY_N"));
        assert_close(res.Fx, t.number(r, "FX_N"), 0.0, 1e-6 * F);
        assert_close(res.Fy, t.number(r, "FY_N"), 0.0, 1e-6 * F);
        ++checked;
    }
    assert_int_equal(checked, 96); // every b, c, b0 and bk row, 3 grids each
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_contact_default_fastsim_output_reproduced),
        cmocka_unit_test(test_plain_fastsim_differs_from_contact_default),
        cmocka_unit_test(test_blended_flexibilities_match_contact_rows),
    };
    return cmocka_run_group_tests_name("compat_contact_example", tests, nullptr, nullptr);
}
