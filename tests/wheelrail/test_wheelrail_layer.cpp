// Friction memory and the interface layer in the wheel/rail patches
// (cw_wheelrail_params' memory_distance, memory_s0, layer_h, layer_G,
// tau_c0, k_tau), on the Manchester benchmark's case wheel (y = 3 mm):
//  * a patch with the layer, and one with a law and memory, equal bit for bit
//    cw_solver_solve on the same gap grid with the same inputs (another door: the
//    gap is the core geometry's at the handle's height, turned into
//    creepwork's patch frame here by hand, as doc/wheelrail.md states it);
//  * the layer lowers the initial slope by springs in series,
//    L1 / (L1 + h / G3) (doc/theory/interface-layer.md) with L1 from the
//    patch's own semi-axes;
//  * a caller's struct cut before the fields gets neither;
//  * every invalid field is refused naming it; the layer's units are warned of
//    by the single contact's rules (cw_wheelrail_check).
// The core and the standard library first: cmocka's macros would clash.
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "mbench_support.hpp"

#include "capi_fixtures.h"

namespace {

const char* const kRail = CW_WHEELRAIL_DATA "/MBench_UIC60_v3.prr";
const char* const kWheel = CW_WHEELRAIL_DATA "/MBench_S1002_v3.prw";
const double kLayerH = 1.25e-3, kLayerG = 8.2e9; // CONTACT's tractcurv layer (LAYTHK, GG3)
const double kVs = 10.0;                            // [m/s]
const double kVpitch = -5 * 4.34515030; // [rad/s] case A-2.2's, scaled to kVs: partial slip

// Case A-2.2's wheel at y = 3 mm with a little yaw: partial slip.
cw_wheelrail_motion motion(double z, double vpitch, double yaw = 0.0003)
{
    cw_wheelrail_motion m;
    cw_wheelrail_motion_init(&m);
    m.y = 3.0e-3;
    m.roll = -0.00018030;
    m.yaw = yaw;
    m.z = z;
    m.vs = kVs;
    m.vpitch = vpitch;
    return m;
}

// CONTACT's tractcurv law (FKIN 0.14, FEXP1 0.19, SABSH1 1.25 m/s).
void tractcurv_law(cw_wheelrail_params& p)
{
    p.friction_law = CW_FRICTION_EXPONENTIAL;
    p.mu = 0.14;
    p.mu_e1 = 0.19;
    p.s_h1 = 1.25;
}

struct Solved {
    cw_wheelrail_totals totals;
    cw_wheelrail_patch patch;
    double a = 0, b = 0; // [m] half the contact's extent along x and s
};

// The wheel at height z (or at Fz = 10 kN when force is set): totals, patch
// 0 and its semi-axes from the contact elements. Returns the status; the
// handle's error in error.
int solve(const cw_wheelrail_params& p, const cw_wheelrail_motion& m, bool force, Solved& out,
          std::string& error)
{
    cw_wheelrail* w = nullptr;
    char message[512] = "";
    int rc = cw_wheelrail_create(&p, kRail, kWheel, &w, message, sizeof message);
    if (rc != CW_OK) {
        error = message;
        return rc;
    }
    cw_wheelrail_totals_init(&out.totals);
    rc = cw_wheelrail_solve(w, &m, force ? CW_WHEELRAIL_FORCE : CW_WHEELRAIL_HEIGHT, 1e4, &out.totals);
    error = cw_wheelrail_last_error(w);
    if (rc == CW_OK) {
        cw_wheelrail_patch_init(&out.patch);
        assert_int_equal(cw_wheelrail_get_patch(w, 0, &out.patch), CW_OK);
        const cw_wheelrail_patch& q = out.patch;
        const size_t n = static_cast<size_t>(q.field_nx) * static_cast<size_t>(q.field_ny);
        std::vector<double> x(n), s(n), area(n);
        assert_int_equal(cw_wheelrail_get_patch_field(w, 0, CW_FIELD_X, x.data(), n), CW_OK);
        assert_int_equal(cw_wheelrail_get_patch_field(w, 0, CW_FIELD_Y, s.data(), n), CW_OK);
        assert_int_equal(cw_wheelrail_get_patch_field(w, 0, CW_FIELD_AREA, area.data(), n), CW_OK);
        double x_lo = 1, x_hi = -1, s_lo = 1, s_hi = -1;
        for (size_t k = 0; k < n; ++k)
            if (area[k] > 0.0) {
                x_lo = std::fmin(x_lo, x[k]), x_hi = std::fmax(x_hi, x[k]);
                s_lo = std::fmin(s_lo, s[k]), s_hi = std::fmax(s_hi, s[k]);
            }
        out.a = 0.5 * (x_hi - x_lo + q.field_dx);
        out.b = 0.5 * (s_hi - s_lo + q.field_ds);
    }
    cw_wheelrail_destroy(w);
    return rc;
}

// The height at which the plain wheel carries 10 kN.
double height()
{
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    Solved s;
    std::string error;
    assert_int_equal(solve(p, motion(0.0, kVpitch), true, s, error), CW_OK);
    return s.totals.z;
}

// Patch 0 at motion m solved by cw_solve on the geometry's gap grid with
// params' inputs: the patch frame x_cw = x, y_cw = -s, z_cw = -n (gap rows
// reversed in s), creepages xi = -cksi, eta = ceta about the grid's origin,
// forces back on the rail (Fx = -Fx_cw, Fs = Fy_cw).
struct DoorForces {
    double Fn = 0, Fx = 0, Fs = 0;
};

DoorForces solve_same_gap(const cw_wheelrail_params& wp, const cw_wheelrail_motion& m)
{
    cwtest::Benchmark bench;
    cwtest::wr::WheelRailGeometry g = bench.geometry(cwtest::wr::Side::right);
    const cwtest::wr::ContactPatch c =
        g.evaluate({m.y, m.z, m.roll, m.yaw, m.pitch}, {m.vs, m.vy, m.vz, m.vroll, m.vyaw, m.vpitch})
            .patches.at(0);
    assert_true(c.nx <= CW_MAX_EXACT_CELLS && c.ny <= CW_MAX_EXACT_CELLS); // no coarsening
    std::vector<double> gap(c.h.size());
    for (int j = 0; j < c.ny; ++j)
        for (int i = 0; i < c.nx; ++i) gap[i + c.nx * j] = c.h[i + c.nx * (c.ny - 1 - j)];
    const double x0 = c.x0, y0 = -(c.s0 + (c.ny - 1) * c.ds);
    cw_grid grid;
    cw_grid_init(&grid);
    grid.kind = CW_GRID_GAP;
    grid.nx = c.nx;
    grid.ny = c.ny;
    grid.dx = c.dx;
    grid.dy = c.ds;
    cw_params p;
    cw_params_init(&p);
    p.model = CW_MODEL_EXACT;
    p.gap = gap.data();
    p.gap_len = gap.size();
    p.normal_load = CW_NORMAL_APPROACH;
    p.approach = 0.0;
    p.mu = wp.mu;
    p.G = wp.G;
    p.nu = wp.nu;
    p.rolling_direction = c.forward ? 1 : -1;
    p.xi_x = -c.cksi - c.cphi * y0;
    p.xi_y = c.ceta + c.cphi * x0;
    p.phi = c.cphi;
    if (wp.friction_law != CW_FRICTION_COULOMB) {
        p.friction_law = wp.friction_law;
        p.mu_e1 = wp.mu_e1;
        p.s_h1 = wp.s_h1;
        p.mu_e2 = wp.mu_e2;
        p.s_h2 = wp.s_h2;
        p.V = c.veloc;
        p.memory_distance = wp.memory_distance;
        p.memory_s0 = wp.memory_s0;
    }
    p.layer_h = wp.layer_h;
    p.layer_G = wp.layer_G;
    cw_solver* solver = nullptr;
    char message[512] = "";
    assert_int_equal(cw_solver_create(&grid, &solver, message, sizeof message), CW_OK);
    cw_result t;
    cw_result_init(&t);
    const int rc = cw_solver_solve(solver, &p, CW_SOLVE_FULL, &t);
    if (rc != CW_OK) fail_msg("cw_solve: %s", cw_solver_last_error(solver));
    cw_solver_destroy(solver);
    return {t.normal_force, -t.Fx, t.Fy};
}

// The patch at pitch rate vpitch and cw_solve on its gap agree bit for bit,
// and the inputs under test moved the forces (against the plain patch) by
// more than 1 % of mu Fn.
void same_as_cw_solve(const cw_wheelrail_params& p, const char* what, double vpitch)
{
    const cw_wheelrail_motion m = motion(height(), vpitch);
    Solved with, plain;
    std::string error;
    assert_int_equal(solve(p, m, false, with, error), CW_OK);
    cw_wheelrail_params bare = p;
    bare.memory_distance = bare.memory_s0 = bare.layer_h = bare.layer_G = 0.0;
    assert_int_equal(solve(bare, m, false, plain, error), CW_OK);
    const DoorForces d = solve_same_gap(p, m);
    const cw_wheelrail_patch& q = with.patch;
    std::printf("%s: patch Fn %.9g Fx %.9g Fs %.9g; cw_solve Fn %.9g Fx %.9g Fs %.9g; "
                "without it Fx %.9g Fs %.9g (%d adhesion, %d slip)\n",
                what, q.Fn, q.Fx, q.Fs, d.Fn, d.Fx, d.Fs, plain.patch.Fx, plain.patch.Fs, q.n_adhesion,
                q.n_slip);
    assert_true(q.n_slip > 0);
    assert_true(q.Fn == d.Fn && q.Fx == d.Fx && q.Fs == d.Fs);
    const double moved = std::hypot(q.Fx - plain.patch.Fx, q.Fs - plain.patch.Fs);
    assert_true(moved > 0.01 * p.mu * q.Fn);
}

void layer_patch_is_cw_solve_on_its_gap(void**)
{
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    p.layer_h = kLayerH;
    p.layer_G = kLayerG;
    same_as_cw_solve(p, "layer", kVpitch);
}

// Memory lags the coefficient behind the slip speed over d_c: at 5 %
// creepage (slip speeds about 0.5 m/s, where the law has fallen by a third)
// a slip distance of 1 mm, a quarter of the patch, holds it up.
void memory_patch_is_cw_solve_on_its_gap(void**)
{
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    tractcurv_law(p);
    p.memory_distance = 3e-3;
    p.memory_s0 = 1e-3;
    same_as_cw_solve(p, "memory", 0.95 * kVpitch);
}

// The slope dFx/dcksi by central differences at cksi = +-1e-5 about pure
// rolling (the pitch rate from the rolling radius; the difference removes the
// force that the spin gives a patch that is no ellipse), with the layer over
// without it. Kalker's simplified theory puts the layer's compliance h / G3 in
// series with L1 = 8a / (3 G c11): L1 / (L1 + h / G3). The patch's semi-axes
// are its contact's extent on the 0.2 mm grid, each end within half an
// element: the ratio must lie in the band of L1 / (L1 + h / G3) over a +-
// dx / 2, b +- ds / 2, widened by 1 % for the exact half-space, which is no
// uniform flexibility (0.6 % above on an ellipse, held to 1 % by
// test_core_exact_layer).
void layer_lowers_the_initial_slope(void**)
{
    const double z = height();
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    Solved rolling;
    std::string error;
    assert_int_equal(solve(p, motion(z, kVpitch, 0.0), false, rolling, error), CW_OK);
    const double R = rolling.patch.rolling_radius;
    p.mu = 5.0; // the spin's slip at mu = 0.3 would soften the patch without the layer more
    double slope[2], a = 0, b = 0;
    for (int layer = 0; layer < 2; ++layer) {
        p.layer_h = layer ? kLayerH : 0.0;
        p.layer_G = layer ? kLayerG : 0.0;
        Solved lo, hi;
        assert_int_equal(solve(p, motion(z, -kVs / R * (1.0 - 1e-5), 0.0), false, lo, error), CW_OK);
        assert_int_equal(solve(p, motion(z, -kVs / R * (1.0 + 1e-5), 0.0), false, hi, error), CW_OK);
        slope[layer] = (hi.patch.Fx - lo.patch.Fx) / (hi.patch.cksi - lo.patch.cksi);
        if (!layer) a = lo.a, b = lo.b;
        std::printf("layer %d: %d of %d elements slip\n", layer, lo.patch.n_slip, lo.patch.n_contact);
    }
    const double ratio = slope[1] / slope[0];
    double lo_band = 1.0, hi_band = 0.0;
    for (double da : {-0.5, 0.5})
        for (double db : {-0.5, 0.5}) {
            double L[3];
            char message[256];
            assert_int_equal(cw_kalker_flexibilities(a + da * p.dx, b + db * p.ds, p.G, p.nu, L, message,
                                                     sizeof message),
                             CW_OK);
            const double series = L[0] / (L[0] + kLayerH / kLayerG);
            lo_band = std::fmin(lo_band, series);
            hi_band = std::fmax(hi_band, series);
        }
    std::printf("a %.2f mm, b %.2f mm: dFx/dcksi with the layer / without %.4f; springs in series "
                "%.4f .. %.4f\n",
                1e3 * a, 1e3 * b, ratio, lo_band, hi_band);
    assert_true(ratio >= 0.99 * lo_band && ratio <= 1.01 * hi_band);
}

// A caller built before the fields (struct_size ending at mu_e2, s_h2) gets
// their defaults whatever lies beyond: no memory, no layer, the plain
// patch to the bit.
void older_callers_have_neither(void**)
{
    const cw_wheelrail_motion m = motion(height(), kVpitch);
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    Solved plain, cut;
    std::string error;
    assert_int_equal(solve(p, m, false, plain, error), CW_OK);
    p.layer_h = kLayerH;
    p.layer_G = kLayerG;
    p.struct_size = offsetof(cw_wheelrail_params, memory_distance);
    assert_int_equal(solve(p, m, false, cut, error), CW_OK);
    assert_true(cut.patch.Fx == plain.patch.Fx && cut.patch.Fs == plain.patch.Fs &&
                cut.patch.Fn == plain.patch.Fn);
}

void refused(const cw_wheelrail_params& p, int status, const char* needle)
{
    Solved s;
    std::string error;
    assert_int_equal(solve(p, motion(0.0, kVpitch), true, s, error), status);
    if (error.find(needle) == std::string::npos) fail_msg("'%s' does not name %s", error.c_str(), needle);
}

void errors_name_their_field(void**)
{
    const struct {
        const char* field;
        double cw_wheelrail_params::*member;
        double value;
        const char* needle;
    } cases[] = {
        {"memory_distance", &cw_wheelrail_params::memory_distance, NAN, "params->memory_distance"},
        {"memory_distance", &cw_wheelrail_params::memory_distance, -1e-4, "memory_distance"},
        {"memory_s0", &cw_wheelrail_params::memory_s0, -1.0, "memory_s0"},
        {"layer_h", &cw_wheelrail_params::layer_h, INFINITY, "params->layer_h"},
        {"layer_h", &cw_wheelrail_params::layer_h, -1e-3, "layer_h"},
        {"layer_G", &cw_wheelrail_params::layer_G, -1.0, "layer_G"},
        {"tau_c0", &cw_wheelrail_params::tau_c0, -1.0, "tau_c0"},
        {"tau_c0", &cw_wheelrail_params::tau_c0, 150e6, "tau_c0"}, // no yield on a gap grid
        {"k_tau", &cw_wheelrail_params::k_tau, 1e9, "k_tau"},
    };
    for (const auto& c : cases) {
        cw_wheelrail_params p;
        cw_wheelrail_params_init(&p);
        tractcurv_law(p);
        p.*c.member = c.value; // k_tau without tau_c0: nothing to harden
        refused(p, CW_ERR_INVALID_INPUT, c.needle);
    }
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    p.layer_h = kLayerH; // layer_G left 0
    refused(p, CW_ERR_INVALID_INPUT, "layer_G");
    p.layer_G = kLayerG;
    p.model = CW_MODEL_FASTSIM;
    p.normal_method = CW_NORMAL_SEMI_HERTZ;
    refused(p, CW_ERR_INVALID_INPUT, "layer_h");
}

// A layer in millimetres typed as metres and its modulus in MPa typed as Pa:
// the single contact's rules (CW_CHECK_LAYER_THICKNESS, CW_CHECK_MODULUS).
void layer_units_are_warned_of(void**)
{
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    p.layer_h = 1.25;
    p.layer_G = 8200.0;
    p.tau_c0 = 150.0;
    cw_wheelrail* w = nullptr;
    char message[512] = "";
    assert_int_equal(cw_wheelrail_create(&p, kRail, kWheel, &w, message, sizeof message), CW_OK);
    cw_check checks[8];
    for (cw_check& c : checks) cw_check_init(&c);
    size_t n = 0;
    assert_int_equal(cw_wheelrail_check(w, checks, 8, &n), CW_OK);
    cw_wheelrail_destroy(w);
    const struct {
        int rule;
        const char* input;
        double value;
    } expected[] = {{CW_CHECK_LAYER_THICKNESS, "layer_h", 1.25},
                    {CW_CHECK_MODULUS, "layer_G", 8200.0},
                    {CW_CHECK_YIELD_STRESS, "tau_c0", 150.0}};
    assert_int_equal(n, 3);
    for (size_t k = 0; k < 3; ++k) {
        assert_int_equal(checks[k].rule, expected[k].rule);
        assert_string_equal(checks[k].input, expected[k].input);
        assert_true(checks[k].value == expected[k].value);
    }
    // and CONTACT's layer is plausible
    p.layer_h = kLayerH;
    p.layer_G = kLayerG;
    p.tau_c0 = 150e6;
    assert_int_equal(cw_wheelrail_create(&p, kRail, kWheel, &w, message, sizeof message), CW_OK);
    assert_int_equal(cw_wheelrail_check(w, checks, 8, &n), CW_OK);
    cw_wheelrail_destroy(w);
    assert_int_equal(n, 0);
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(layer_patch_is_cw_solve_on_its_gap),
        cmocka_unit_test(memory_patch_is_cw_solve_on_its_gap),
        cmocka_unit_test(layer_lowers_the_initial_slope),
        cmocka_unit_test(older_callers_have_neither),
        cmocka_unit_test(errors_name_their_field),
        cmocka_unit_test(layer_units_are_warned_of),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
