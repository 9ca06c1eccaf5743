// The wheel/rail chain up to the forces: every patch solved by the exact
// model on its undeformed distance grid, against CONTACT's module 1 on the
// Manchester benchmark (case, CONTACT's shipped results,
// tests/data/nonhertz/mbench_a22.csv, 4 printed digits), the fast
// model against the exact one on the same positions, and the solver's
// origin shift against a solver on the patch's own grid.
//
//   test_wheelrail_forces [TEST]          the tests (cmocka filter)
//   test_wheelrail_forces --markdown      the exact model's table of doc/validation/manchester.md
//   test_wheelrail_forces --markdown-fast the fast model's table there
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/error.hpp"
#include "mbench_support.hpp"
#include "solver.hpp"
#include "test_support.h"
#include "wheelrail/patch_contact.hpp"

namespace wr = creepwork::wheelrail;
namespace cw = creepwork;

namespace {

wr::PatchContactSettings benchmark_settings(const cwtest::Row& r)
{
    wr::PatchContactSettings s;
    s.mu = r.num("mu");
    s.nu = r.num("nu");
    s.G = r.num("G_N_mm2") * 1e6;
    return s;
}

// A patch with spin, lateral creepage and a grid off the reference point
// (right wheel, y_ws = 8 mm, flange contact at -54 deg): PatchContact's
// shifted creepages on a grid at the origin against a solver on the grid
// at the patch's own position with the creepages as they are. One
// discrete problem, two paths: equal to the solver's tolerance, for the
// exact model and for the fast one (FASTSIM, semi-Hertzian normal problem).
void test_origin_shift(void**)
{
    const cwtest::Benchmark b;
    const auto rows = cwtest::read_rows(cwtest::wheelrail_data("contact_a22_geometry.csv"));
    for (const cwtest::Row& r : rows) {
        if (!(r.text("side") == "right" && r.num("y_ws_mm") == 8.0)) continue;
        wr::WheelRailGeometry g = b.geometry(r);
        const wr::ContactPatch& p = g.evaluate(cwtest::position_of(r), cwtest::velocity_of(r)).patches.at(0);
        assert_true(std::abs(p.cphi) > 1.0 && std::abs(p.x0) > 1e-3);
        for (const bool fast : {false, true}) {
            wr::PatchContactSettings set;
            set.tolerance = 1e-10;
            if (fast) {
                set.model = cw::ModelKind::fastsim;
                set.normal_method = cw::NormalMethod::semi_hertz;
            }
            wr::PatchContact pc(set);
            const wr::PatchSolution s = pc.solve(p);

            cw::GridSpec grid;
            grid.kind = cw::GridKind::gap;
            grid.nx = p.nx;
            grid.ny = p.ny;
            grid.dx = p.dx;
            grid.dy = p.ds;
            grid.x0 = p.x0;
            grid.y0 = -(p.s0 + (p.ny - 1) * p.ds);
            std::vector<double> h(p.h.size());
            for (int j = 0; j < p.ny; ++j)
                for (int i = 0; i < p.nx; ++i) h[i + p.nx * j] = p.h[i + p.nx * (p.ny - 1 - j)];
            cw::ContactInput in;
            in.model = set.model;
            in.normal_method = set.normal_method;
            in.gap = h.data();
            in.gap_len = h.size();
            in.normal_load = cw::NormalLoad::approach;
            in.mu = set.mu;
            in.G = set.G;
            in.nu = set.nu;
            in.tolerance = 1e-10;
            in.xi_x = -p.cksi;
            in.xi_y = p.ceta;
            in.phi = p.cphi;
            cw::Solver direct(grid);
            const cw::SolveTotals& t = direct.solve(in, cw::SolveMode::forces_only);
            assert_close(s.fn, t.normal_force, 1e-9, 0);
            assert_close(s.fx, -t.Fx, 0, 1e-6 * s.fn);
            assert_close(s.fs, t.Fy, 0, 1e-6 * s.fn);
            assert_close(s.mn, t.Mz, 0, 1e-6 * s.fn * 1e-3);
            assert_int_equal(s.n_slip, t.n_slip);
        }
        return;
    }
    fail_msg("no row at y_ws = 8 mm");
}

// One wheel position of case solved for CONTACT's vertical load, and
// CONTACT's printed row.
struct Position {
    cwtest::Row ref;
    wr::WheelRailSolution sol;
    double z = 0;
    bool two_lobes() const { return ref.text("wheel") == "right" && ref.num("y_ws_mm") == 5.0; }
    const wr::PatchSolution& patch() const { return sol.patches.at(static_cast<std::size_t>(ref.num("patch")) - 1); }
    // differences to CONTACT: forces relative to the vertical load, p_max relative
    double dfn() const { return (patch().fn - ref.num("fn_N")) / ref.num("Fz_N"); }
    double dfx() const { return (patch().fx - ref.num("fx_N")) / ref.num("Fz_N"); }
    double dfs() const { return (patch().fs - ref.num("fs_N")) / ref.num("Fz_N"); }
    double dp() const { return patch().p_max / (ref.num("pmax_N_mm2") * 1e6) - 1.0; }
    double dz() const { return z - ref.num("z_ws_mm") * 1e-3; }
};

// Every position of case A-2.2 (21 lateral shifts, both wheels), the
// wheelset height found for CONTACT's 10 kN per wheel, the positions of
// each wheel one after the other.
std::vector<Position> solve_benchmark(bool fast = false)
{
    const cwtest::Benchmark b;
    const auto rows = cwtest::read_rows(cwtest::contact_benchmark_results("mbench_a22.csv"));
    if (rows.size() != 42) throw std::runtime_error("mbench_a22.csv: 42 rows expected");
    wr::PatchContactSettings set = benchmark_settings(rows.at(0));
    set.mode = cw::SolveMode::forces_only;
    if (fast) {
        set.model = cw::ModelKind::fastsim;
        set.normal_method = cw::NormalMethod::semi_hertz;
    }
    wr::WheelRailContact right(b.geometry(wr::Side::right), set);
    wr::WheelRailContact left(b.geometry(wr::Side::left), set);
    std::vector<Position> out;
    for (const cwtest::Row& r : rows) {
        wr::WheelRailContact& c = r.text("wheel") == "right" ? right : left;
        wr::WheelsetPosition pos;
        pos.y = r.num("y_ws_mm") * 1e-3;
        pos.yaw = r.num("yaw_rad");
        pos.roll = r.num("roll_rad");
        wr::WheelsetVelocity vel;
        vel.vs = r.num("vs_mm_s") * 1e-3;
        vel.vpitch = r.num("vpitch_rad_s");
        Position p;
        p.ref = r;
        p.sol = c.solve_force(r.num("Fz_N"), pos, vel);
        p.z = p.sol.z;
        out.push_back(p);
    }
    return out;
}

// Per patch Fn, Fx, Fs within 1 % of the wheel's vertical load of
// CONTACT's, p_max within 3 %, the same number of patches.
void test_benchmark_forces(void**)
{
    double wfn = 0, wfx = 0, wfs = 0, wp = 0, wz = 0;
    for (const Position& p : solve_benchmark()) {
        assert_int_equal(p.sol.patches.size(), static_cast<std::size_t>(p.ref.num("n_patches")));
        assert_true(std::abs(p.dfn()) < 0.01 && std::abs(p.dfx()) < 0.01 && std::abs(p.dfs()) < 0.01);
        assert_true(std::abs(p.dp()) < 0.03);
        // CONTACT prints 4 digits (5 N of 10 kN); the two lobes at 5 mm on
        // the right wheel are sub-patches of one patch in CONTACT, whose
        // mutual influence it reduces (D_SEP rule), here one grid at full
        // influence
        if (!p.two_lobes())
            assert_true(std::abs(p.dfn()) < 1e-3 && std::abs(p.dfx()) < 1e-3 && std::abs(p.dfs()) < 1e-3);
        wfn = std::max(wfn, std::abs(p.dfn()));
        wfx = std::max(wfx, std::abs(p.dfx()));
        wfs = std::max(wfs, std::abs(p.dfs()));
        wp = std::max(wp, std::abs(p.dp()));
        wz = std::max(wz, std::abs(p.dz()));
    }
    std::printf("worst of 42 positions: Fn %.3f %%, Fx %.3f %%, Fs %.3f %% of Fz; p_max %.2f %%; z_ws %.3f um\n",
                100 * wfn, 100 * wfx, 100 * wfs, 100 * wp, 1e6 * wz);
}

// The table of doc/validation/manchester.md (scripts/doc-tables.sh).
int print_markdown()
{
    const std::vector<Position> all = solve_benchmark();
    std::printf("| y_ws [mm] | wheel | z_ws [mm] | dz_ws [um] | Fn [N] | dFn | Fx [N] | dFx | Fs [N] | dFs | "
                "p_max [MPa] | dp_max | contact / slip | CONTACT |\n");
    std::printf("|---:|:---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    double w[5] = {0, 0, 0, 0, 0}, w2[5] = {0, 0, 0, 0, 0};
    for (const Position& p : all) {
        const wr::PatchSolution& s = p.patch();
        std::printf("| %.1f | %s | %.4f | %.2f | %.0f | %.3f %% | %.1f | %.3f %% | %.0f | %.3f %% | %.1f | %.2f %% | "
                    "%d / %d | %d / %d |\n",
                    p.ref.num("y_ws_mm"), p.ref.text("wheel").c_str(), 1e3 * p.z, 1e6 * p.dz(), s.fn, 100 * p.dfn(),
                    s.fx, 100 * p.dfx(), s.fs, 100 * p.dfs(), 1e-6 * s.p_max, 100 * p.dp(), s.n_contact, s.n_slip,
                    static_cast<int>(p.ref.num("ncon")), static_cast<int>(p.ref.num("nslip")));
        const double d[5] = {std::abs(p.dz()), std::abs(p.dfn()), std::abs(p.dfx()), std::abs(p.dfs()),
                             std::abs(p.dp())};
        for (int k = 0; k < 5; ++k) {
            w[k] = std::max(w[k], d[k]);
            if (!p.two_lobes()) w2[k] = std::max(w2[k], d[k]);
        }
    }
    std::printf("\nWorst differences: all 42 positions: z_ws %.2f um, Fn %.3f %%, Fx %.3f %%, Fs %.3f %% of the "
                "vertical load, p_max %.2f %%; without the two-lobe contact (right wheel, 5 mm): z_ws %.2f um, "
                "Fn %.3f %%, Fx %.3f %%, Fs %.3f %%, p_max %.2f %%.\n",
                1e6 * w[0], 100 * w[1], 100 * w[2], 100 * w[3], 100 * w[4], 1e6 * w2[0], 100 * w2[1],
                100 * w2[2], 100 * w2[3], 100 * w2[4]);
    return 0;
}

// The fast model against the exact one, position by position: the
// differences of the fast model's patch from the exact model's (forces in
// per cent of mu Fz, the fast method's yardstick; p_max and the number of
// contact elements relatively). Worst over the 42 positions and over the
// 41 without the two-lobe contact.
struct FastComparison {
    std::vector<Position> exact, fast;
    double worst[5] = {0, 0, 0, 0, 0}, worst_single[5] = {0, 0, 0, 0, 0}; // fn fx fs p_max area
    FastComparison() : exact(solve_benchmark(false)), fast(solve_benchmark(true))
    {
        for (std::size_t k = 0; k < exact.size(); ++k) {
            const double d[5] = {std::abs(dfn(k)), std::abs(dfx(k)), std::abs(dfs(k)), std::abs(dp(k)),
                                 std::abs(darea(k))};
            for (int m = 0; m < 5; ++m) {
                worst[m] = std::max(worst[m], d[m]);
                if (!exact[k].two_lobes()) worst_single[m] = std::max(worst_single[m], d[m]);
            }
        }
    }
    const wr::PatchSolution& e(std::size_t k) const { return exact[k].patch(); }
    const wr::PatchSolution& f(std::size_t k) const { return fast[k].patch(); }
    double mu_fz(std::size_t k) const { return exact[k].ref.num("mu") * exact[k].ref.num("Fz_N"); }
    double dfn(std::size_t k) const { return (f(k).fn - e(k).fn) / mu_fz(k); }
    double dfx(std::size_t k) const { return (f(k).fx - e(k).fx) / mu_fz(k); }
    double dfs(std::size_t k) const { return (f(k).fs - e(k).fs) / mu_fz(k); }
    double dp(std::size_t k) const { return f(k).p_max / e(k).p_max - 1.0; }
    double darea(std::size_t k) const { return static_cast<double>(f(k).n_contact) / e(k).n_contact - 1.0; }
};

// The fast model against the exact one (doc/validation/manchester.md,
// "The fast model"). The yardstick of a fast method is forces within 3 % of
// mu Fz and the contact area within 10 %: met on the tread contacts of
// moderate spin -- right wheel 1.0-4.5 mm, left wheel 1.5-10 mm -- and
// asserted there. Elsewhere the page states the misses (spin at 0-0.5 mm,
// the flange contacts of the right wheel from 6.5 mm, the two-lobe contact
// at 5 mm): there the bounds asserted are the page's worst values, rounded
// up (forces 13 %, p_max 13 %, contact elements 31 %), so that a change
// for the worse fails.
void test_fast_model(void**)
{
    const FastComparison c;
    int tread = 0;
    for (std::size_t k = 0; k < c.exact.size(); ++k) {
        assert_int_equal(c.fast[k].sol.patches.size(), c.exact[k].sol.patches.size());
        assert_close(c.fast[k].sol.total.fz, c.exact[k].ref.num("Fz_N"), 1e-6, 0);
        const double y = c.exact[k].ref.num("y_ws_mm");
        const bool right = c.exact[k].ref.text("wheel") == "right";
        if ((right && y >= 1.0 && y <= 4.5) || (!right && y >= 1.5)) {
            ++tread;
            assert_true(std::abs(c.dfx(k)) < 0.03 && std::abs(c.dfs(k)) < 0.03 && std::abs(c.dfn(k)) < 0.03);
            assert_true(std::abs(c.darea(k)) < 0.10);
        }
    }
    assert_int_equal(tread, 8 + 18);
    assert_true(c.worst[0] < 0.05 && c.worst[1] < 0.13 && c.worst[2] < 0.13);
    assert_true(c.worst[3] < 0.13 && c.worst[4] < 0.31);
}

// The fast model's table of doc/validation/manchester.md.
int print_markdown_fast()
{
    const FastComparison c;
    std::printf("| y_ws [mm] | wheel | Fn [N] | dFn | Fx [N] | dFx | Fs [N] | dFs | p_max [MPa] | dp_max | contact "
                "elements | exact |\n");
    std::printf("|---:|:---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (std::size_t k = 0; k < c.exact.size(); ++k) {
        const wr::PatchSolution& f = c.f(k);
        std::printf("| %.1f | %s | %.0f | %.2f %% | %.1f | %.2f %% | %.0f | %.2f %% | %.1f | %.1f %% | %d | %d |\n",
                    c.exact[k].ref.num("y_ws_mm"), c.exact[k].ref.text("wheel").c_str(), f.fn, 100 * c.dfn(k), f.fx,
                    100 * c.dfx(k), f.fs, 100 * c.dfs(k), 1e-6 * f.p_max, 100 * c.dp(k), f.n_contact,
                    c.e(k).n_contact);
    }
    std::printf("\nWorst differences from the exact model: all 42 positions: Fn %.2f %%, Fx %.2f %%, Fs %.2f %% of "
                "mu Fz, p_max %.1f %%, contact elements %.1f %%; without the two-lobe contact (right wheel, 5 mm): "
                "Fn %.2f %%, Fx %.2f %%, Fs %.2f %%, p_max %.1f %%, contact elements %.1f %%.\n",
                100 * c.worst[0], 100 * c.worst[1], 100 * c.worst[2], 100 * c.worst[3], 100 * c.worst[4],
                100 * c.worst_single[0], 100 * c.worst_single[1], 100 * c.worst_single[2], 100 * c.worst_single[3],
                100 * c.worst_single[4]);
    return 0;
}

// The exact model's force balance solves the tangential problem to a
// looser tolerance at the heights it tries and to the settings' at the
// height it accepts: on a tread, a two-lobe and a flange position of case
// A-2.2 (the benchmark's load, every field, the balance's tolerance 1e-7 so
// that the trials' looser tolerance shows), Fz meets 1e-7; each patch
// solved again at the height found, on the handle (from its own solution)
// and on a fresh handle from a cold start, gives the forces returned to
// the solver's tolerance (1e-8 of the load; a final solve to the trials'
// tolerance, 1e-5, misses that).
void test_exact_final_solve(void**)
{
    const cwtest::Benchmark b;
    const auto rows = cwtest::read_rows(cwtest::contact_benchmark_results("mbench_a22.csv"));
    const wr::PatchContactSettings set = benchmark_settings(rows.at(0)); // every field
    wr::VerticalForceOptions opt;
    opt.tolerance = 1e-7;
    double worst_again = 0.0, worst_cold = 0.0;
    for (const cwtest::Row& r : rows) {
        const double y = r.num("y_ws_mm");
        if (r.text("wheel") != "right" || r.num("patch") != 1.0 || !(y == 0.0 || y == 5.0 || y == 8.0)) continue;
        wr::WheelRailContact c(b.geometry(wr::Side::right), set);
        wr::WheelsetPosition pos;
        pos.y = y * 1e-3;
        pos.yaw = r.num("yaw_rad");
        pos.roll = r.num("roll_rad");
        wr::WheelsetVelocity vel;
        vel.vs = r.num("vs_mm_s") * 1e-3;
        vel.vpitch = r.num("vpitch_rad_s");
        const double load = r.num("Fz_N");
        const wr::WheelRailSolution s = c.solve_force(load, pos, vel, opt);
        assert_close(s.total.fz, load, opt.tolerance, 0);
        const wr::WheelRailState& st = c.geometry().state();
        assert_int_equal(s.patches.size(), st.patches.size());
        wr::PatchContact cold(set);
        for (std::size_t n = 0; n < st.patches.size(); ++n) {
            const wr::PatchSolution& q = s.patches[n];
            const wr::PatchSolution again = c.patch_contact().solve(st.patches[n], n);
            const wr::PatchSolution& fresh = cold.solve(st.patches[n], n);
            worst_again = std::max({worst_again, std::abs(again.fn - q.fn) / load, std::abs(again.fx - q.fx) / load,
                                    std::abs(again.fs - q.fs) / load});
            worst_cold = std::max({worst_cold, std::abs(fresh.fn - q.fn) / load, std::abs(fresh.fx - q.fx) / load,
                                   std::abs(fresh.fs - q.fs) / load});
        }
    }
    std::printf("exact balance: the answer against a solve again %.1e, a cold solve %.1e of the load\n", worst_again,
                worst_cold);
    assert_true(worst_again <= 1e-8);
    assert_true(worst_cold <= 1e-8);
}

// A bad setting is an error naming it.
// A host whose wheelset drifts (right wheel, 10 kN, y from 2 mm in steps
// of 20 um, the fast model), each call from the height of the last: Fz to
// its 1e-6 tolerance every call, and from the third call on, the start
// extrapolated from the last two heights (z changes smoothly with y: the
// start's force is then within a fraction of a percent) and Newton's
// steps with the patches' derivative: at most three evaluations. The
// forces returned are those of the last evaluation's patches, which are
// the solves at the height found: each patch solved again there gives
// the same bits. A host's own guess of the height is its start: the same
// bits as a fresh handle's.
void test_drifting_host(void**)
{
    const cwtest::Benchmark b;
    wr::PatchContactSettings set;
    set.mode = cw::SolveMode::forces_only;
    set.model = cw::ModelKind::fastsim;
    set.normal_method = cw::NormalMethod::semi_hertz;
    wr::WheelRailContact c(b.geometry(wr::Side::right), set);
    const double load = 1e4;
    wr::WheelsetPosition pos;
    wr::WheelsetVelocity vel;
    vel.vs = 20.0;
    vel.vpitch = -vel.vs / b.wheelset.nominal_radius;
    int worst = 0;
    double worst_fresh = 0.0;
    for (int k = 0; k < 8; ++k) {
        pos.y = 2e-3 + 20e-6 * k;
        const wr::WheelRailSolution& s = c.solve_force(load, pos, vel);
        assert_close(s.total.fz, load, 1e-6, 0);
        if (k >= 2) worst = std::max(worst, s.evaluations);
        pos.z = s.z;
        wr::WheelRailContact at_height(b.geometry(wr::Side::right), set);
        const wr::WheelRailSolution& h = at_height.solve_position(pos, vel);
        worst_fresh = std::max({worst_fresh, std::abs(h.total.fx - s.total.fx), std::abs(h.total.fy - s.total.fy),
                                std::abs(h.total.fz - s.total.fz)});
        const wr::WheelRailState& st = c.geometry().state();
        assert_int_equal(s.patches.size(), st.patches.size());
        for (std::size_t n = 0; n < st.patches.size(); ++n) {
            const wr::PatchSolution& again = c.patch_contact().solve(st.patches[n], n, true);
            assert_true(again.fn == s.patches[n].fn && again.fx == s.patches[n].fx && again.fs == s.patches[n].fs);
        }
    }
    std::printf("drifting host: at most %d evaluations per call from the third on; a fresh handle at the "
                "height found: forces within %.1e of the load\n",
                worst, worst_fresh / load);
    assert_true(worst_fresh <= 1e-10 * load);
    assert_true(worst <= 3);
    pos.z -= 1e-6; // the host's own guess
    const wr::WheelRailSolution kept = c.solve_force(load, pos, vel);
    wr::WheelRailContact fresh(b.geometry(wr::Side::right), set);
    const wr::WheelRailSolution& f = fresh.solve_force(load, pos, vel);
    assert_true(kept.z == f.z && kept.total.fz == f.total.fz && kept.evaluations == f.evaluations);
}

// The exact balance starts from the height at which the fast model carries
// the load (doc/wheelrail.md, "Vertical force"): from z = 0 at two of the
// benchmark's positions (a22_right_07 and _15 of contact_a22_geometry.csv,
// the right wheel at 3 and 7 mm) it takes two evaluations -- one Newton step
// from that height meets Fz to 1e-6 -- where the Hertz estimate's height
// took three and four (doc/dev/decisions.md, "Wheel/rail force balance").
void test_exact_balance_start(void**)
{
    const cwtest::Benchmark b;
    const auto rows = cwtest::read_rows(cwtest::wheelrail_data("contact_a22_geometry.csv"));
    const wr::PatchContactSettings set; // the exact model, every field
    for (const std::size_t k : {std::size_t{27}, std::size_t{35}}) {
        const cwtest::Row& r = rows.at(k);
        wr::WheelRailContact c(b.geometry(cwtest::side_of(r)), set);
        wr::WheelsetPosition pos = cwtest::position_of(r);
        pos.z = 0.0;
        const wr::WheelRailSolution& s = c.solve_force(1e4, pos, cwtest::velocity_of(r));
        std::printf("row %zu: %d evaluations, Fz %.9g N\n", k, s.evaluations, s.total.fz);
        assert_close(s.total.fz, 1e4, 1e-6, 0);
        assert_int_equal(s.evaluations, 2);
    }
}

void test_errors(void**)
{
    const char* names[] = {"mu", "G", "nu"};
    for (const char* name : names) {
        wr::PatchContactSettings s;
        if (std::strcmp(name, "mu") == 0) s.mu = -0.1;
        if (std::strcmp(name, "G") == 0) s.G = std::nan("");
        if (std::strcmp(name, "nu") == 0) s.nu = 0.6;
        bool named = false;
        try {
            wr::PatchContact pc(s);
        } catch (const cw::Error& e) {
            named = std::string(e.what()).find(std::string(name) + " must") != std::string::npos;
        }
        assert_true(named);
    }
}

} // namespace

int main(int argc, char** argv)
{
    if (argc > 1 && std::string(argv[1]) == "--markdown") return print_markdown();
    if (argc > 1 && std::string(argv[1]) == "--markdown-fast") return print_markdown_fast();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_origin_shift),
        cmocka_unit_test(test_benchmark_forces),
        cmocka_unit_test(test_fast_model),
        cmocka_unit_test(test_drifting_host),
        cmocka_unit_test(test_exact_final_solve),
        cmocka_unit_test(test_exact_balance_start),
        cmocka_unit_test(test_errors),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
