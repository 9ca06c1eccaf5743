// Damage indices (damage/): CONTACT's RCF index in full sliding against
// mu - k/p_n, the T_gamma density against W_macro, FI_surf and Burstow's
// WLRM damage function against hand-computed values at their breakpoints.
#include <cmath>
#include <string>
#include <vector>

#include "contact/error.hpp"
#include "core_test_support.hpp"
#include "damage/damage_indices.hpp"
#include "test_support.h"

namespace cw = creepwork;
namespace dm = creepwork::damage;

namespace {

constexpr double kPi = 3.141592653589793238462643383279502884;

// A solved contact with everything the indices read.
struct Solved {
    cw::SolveTotals t;
    std::vector<double> area, pz, px, py, work;
    std::vector<int> state;
    dm::DamageInput input() const
    {
        dm::DamageInput in;
        in.nx = nx;
        in.ny = ny;
        in.area = area.data();
        in.pz = pz.data();
        in.px = px.data();
        in.py = py.data();
        in.state = state.data();
        in.work = work.data();
        in.Fx = t.Fx;
        in.Fy = t.Fy;
        in.normal_force = t.normal_force;
        in.W_macro = t.W_macro;
        in.contact_area = kPi * t.a * t.b;
        return in;
    }
    int nx = 0, ny = 0;
};

Solved solve(const cw::GridSpec& g, const cw::ContactInput& in)
{
    cw::Solver s(g);
    Solved r;
    r.t = s.solve(in, cw::SolveMode::full);
    r.nx = s.grid().nx();
    r.ny = s.grid().ny();
    using F = cw::Field;
    r.area = cwtest::field(s, F::area);
    r.pz = cwtest::field(s, F::pz);
    r.px = cwtest::field(s, F::px);
    r.py = cwtest::field(s, F::py);
    r.work = cwtest::field(s, F::work_consistent);
    r.state = cwtest::states(s);
    return r;
}

// In full sliding every contact element carries |p_t| = mu p_n, so the
// index is max(-0.5, mu - k/p_n) there and -0.5 outside the contact: to
// 1e-12 for FASTSIM on both grids (the uniform one with exterior
// elements); for the exact model to its solve's tolerance (1e-8: its slip
// tractions meet the bound to that), with spin and lateral creepage.
void rcf_index_full_sliding(void** state)
{
    (void)state;
    struct Case {
        cw::ModelKind model;
        cw::GridSpec grid;
        double tolerance;
    } cases[] = {{cw::ModelKind::fastsim, cwtest::uniform_grid(24, 20, 1.1), 1e-12},
                 {cw::ModelKind::fastsim, cwtest::kalker_grid(30, 30), 1e-12},
                 {cw::ModelKind::exact, cwtest::uniform_grid(24, 20, 1.1), 1e-8}};
    for (const Case& c : cases) {
        cw::ContactInput in = cwtest::steel_contact(1.5);
        in.model = c.model;
        in.xi_x = 0.02;
        in.xi_y = -0.03;
        in.phi = 2.0;
        const Solved s = solve(c.grid, in);
        assert_int_equal(s.t.n_adhesion, 0);
        for (double k : {150e6, 300e6}) {
            dm::DamageParams p;
            p.k_yield = k;
            std::vector<double> rcf(s.area.size(), 9.0);
            const dm::DamageTotals t = dm::damage_indices(s.input(), p, {rcf.data(), nullptr});
            int above_floor = 0;
            double largest = -0.5;
            for (size_t e = 0; e < rcf.size(); ++e) {
                double expect = dm::kRcfNoRisk;
                if (s.state[e] >= 1 && s.pz[e] > 0.0) {
                    expect = std::max(dm::kRcfNoRisk, in.mu - k / s.pz[e]);
                    above_floor += expect > dm::kRcfNoRisk;
                }
                assert_close(rcf[e], expect, 0.0, c.tolerance);
                largest = std::max(largest, expect);
            }
            assert_true(above_floor > 20); // the formula, not only the floor, is tested
            assert_close(t.rcf_index_max, largest, 0.0, c.tolerance);
            assert_close(rcf[t.rcf_element], t.rcf_index_max, 0.0, 0.0);
        }
    }
}

// The RCF index of one element at its breakpoints.
void rcf_index_breakpoints(void** state)
{
    (void)state;
    assert_true(dm::rcf_index(3e8, 4e8, 1e9, false, 2e8) == -0.5); // exterior
    assert_true(dm::rcf_index(3e8, 4e8, 0.0, true, 2e8) == -0.5);  // no pressure
    assert_close(dm::rcf_index(3e8, 4e8, 1e9, true, 5e8), 0.0, 0.0, 1e-16); // |p_t| = k
    assert_close(dm::rcf_index(3e8, 4e8, 1e9, true, 2e8), 0.3, 1e-15, 0.0);
    assert_close(dm::rcf_index(3e8, 4e8, 1e9, true, 1e9), -0.5, 1e-15, 0.0); // on the floor
    assert_true(dm::rcf_index(3e8, 4e8, 1e9, true, 2e9) == -0.5);  // below it: clamped
}

// Sum over the elements of T_gamma density x area = W_macro, to 1e-12: the
// energy-consistent map carries the macroscopic work, every model.
void t_gamma_density_sums_to_macro_work(void** state)
{
    (void)state;
    struct Case {
        cw::GridSpec grid;
        cw::ModelKind model;
    } cases[] = {{cwtest::kalker_grid(40, 40), cw::ModelKind::fastsim},
                 {cwtest::kalker_grid(30, 25), cw::ModelKind::calibrated},
                 {cwtest::uniform_grid(30, 30, 1.1), cw::ModelKind::exact}};
    for (const Case& c : cases) {
        cw::ContactInput in = cwtest::steel_contact(0.7);
        in.model = c.model;
        in.xi_x = -1e-3;
        in.xi_y = 5e-4;
        in.phi = 0.5;
        const Solved s = solve(c.grid, in);
        assert_int_equal(s.t.work_flags, 0);
        assert_true(s.t.n_adhesion > 0 && s.t.n_slip > 0);
        dm::DamageParams p;
        p.k_yield = 300e6;
        std::vector<double> density(s.area.size(), -1.0);
        const dm::DamageTotals t = dm::damage_indices(s.input(), p, {nullptr, density.data()});
        double sum = 0.0;
        for (size_t e = 0; e < density.size(); ++e) {
            assert_true(density[e] >= 0.0);
            if (s.state[e] == 1) assert_true(density[e] == 0.0); // no work in adhesion
            sum += density[e] * s.area[e];
        }
        assert_close(sum, s.t.W_macro, 1e-12, 0.0);
        assert_close(t.T_gamma, s.t.W_macro, 0.0, 0.0);
    }
}

dm::DamageInput contact_totals(double Fx, double Fy, double N, double area, double W)
{
    dm::DamageInput in;
    static const double zero = 0.0;
    static const int exterior = 0;
    in.nx = in.ny = 1;
    in.area = in.pz = in.px = in.py = in.work = &zero;
    in.state = &exterior;
    in.Fx = Fx;
    in.Fy = Fy;
    in.normal_force = N;
    in.contact_area = area;
    in.W_macro = W;
    return in;
}

// FI_surf = mu_eff - 2 pi a b k/(3 F_z) (Ekberg, Kabo & Andersson 2002), by
// hand: a = b = 6 mm, F_z = 100 kN, F_t = (30, 40) kN so mu_eff = 0.5; k =
// 300 MPa: 2 pi 36e-6 3e8/3e5 = 0.2261946711, FI = 0.2738053289. At the
// shakedown line k = mu_eff p0 (p0 = 3 F_z/(2 pi a b)) FI = 0.
void fi_surf_by_hand(void** state)
{
    (void)state;
    const double A = kPi * 6e-3 * 6e-3;
    dm::DamageParams p;
    p.k_yield = 300e6;
    dm::DamageTotals t = dm::damage_indices(contact_totals(3e4, 4e4, 1e5, A, 0.0), p, {});
    assert_close(t.mu_eff, 0.5, 1e-15, 0.0);
    assert_close(t.FI_surf, 0.2738053289, 0.0, 1e-10);
    p.k_yield = 0.5 * 3 * 1e5 / (2 * A);
    t = dm::damage_indices(contact_totals(3e4, 4e4, 1e5, A, 0.0), p, {});
    assert_close(t.FI_surf, 0.0, 0.0, 1e-15);
    // no load: no index (0), no NaN
    t = dm::damage_indices(contact_totals(0, 0, 0, 0, 0), p, {});
    assert_true(t.FI_surf == 0.0 && t.mu_eff == 0.0 && t.rcf_element == -1);
    assert_true(t.rcf_index_max == -0.5);
}

// Burstow's function with the defaults (onset 20 N, peak 1e-5 at 65 N,
// zero at 175 N) at and between its breakpoints, by hand; the published
// rounded lines 2.22e-7 T - 4.44e-6 and -9.09e-8 T + 1.59e-5 within their
// rounding (1e-3 relative).
void wlrm_breakpoints(void** state)
{
    (void)state;
    const dm::WlrmFunction f;
    const double T[] = {-5, 0, 20, 42.5, 50, 65, 120, 175, 300};
    const double D[] = {0, 0, 0, 0.5e-5, 1e-5 * 30 / 45, 1e-5, 0.5e-5, 0, 0};
    for (int k = 0; k < 9; ++k) assert_close(dm::wlrm_damage(T[k], f), D[k], 1e-14, 1e-20);
    for (double x = 21; x < 65; x += 4)
        assert_close(dm::wlrm_damage(x, f), 2.22e-7 * x - 4.44e-6, 1e-3, 1e-9);
    for (double x = 66; x < 170; x += 8)
        assert_close(dm::wlrm_damage(x, f), -9.09e-8 * x + 1.59e-5, 3e-3, 2e-8);
    // per contact: T_gamma = W_macro
    dm::DamageParams p;
    p.k_yield = 3e8;
    const dm::DamageTotals t =
        dm::damage_indices(contact_totals(1e3, 0, 1e5, 1e-4, 42.5), p, {});
    assert_close(t.wlrm_damage, 0.5e-5, 1e-14, 0.0);
}

void expect_invalid(const dm::DamageParams& p, const std::string& name)
{
    try {
        dm::damage_indices(contact_totals(0, 0, 1, 1, 0), p, {});
        fail_msg("no error for %s", name.c_str());
    } catch (const cw::Error& e) {
        if (std::string(e.what()).rfind(name + " = ", 0) != 0)
            fail_msg("message '%s' does not start with '%s = '", e.what(), name.c_str());
    }
}

void invalid_inputs_named(void** state)
{
    (void)state;
    dm::DamageParams ok;
    ok.k_yield = 3e8;
    dm::DamageParams p = ok;
    p.k_yield = 0;
    expect_invalid(p, "k_yield");
    p.k_yield = NAN;
    expect_invalid(p, "k_yield");
    p = ok;
    p.wlrm.onset = -1;
    expect_invalid(p, "wlrm_onset");
    p = ok;
    p.wlrm.peak = 10;
    expect_invalid(p, "wlrm_peak");
    p = ok;
    p.wlrm.zero = 60;
    expect_invalid(p, "wlrm_zero");
    p = ok;
    p.wlrm.peak_damage = 2;
    expect_invalid(p, "wlrm_peak_damage");
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rcf_index_full_sliding),
        cmocka_unit_test(rcf_index_breakpoints),
        cmocka_unit_test(t_gamma_density_sums_to_macro_work),
        cmocka_unit_test(fi_surf_by_hand),
        cmocka_unit_test(wlrm_breakpoints),
        cmocka_unit_test(invalid_inputs_named),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
