// The Jacobians on a gap grid (core/gap/gap_exact_jacobian.cpp,
// core/gap/gap_fastsim_jacobian.cpp) against independent numbers:
//  - on the Hertzian gap of a uniform grid the exact model on the gap solves
//    the elliptic exact model's discrete problem (test_nonhertz_model), so
//    its creepage columns must be the elliptic model's (exact_jacobian.cpp,
//    another implementation of the same derivative). Not its N column: the
//    elliptic model holds a and b (so its gap scales with N), a gap grid
//    holds the gap (so the contact grows with N): two different derivatives
//    (the elliptic one, by Euler's relation, is d/dl F(l N, l h) / N);
//  - central differences of each model's own solves on three non-Hertzian
//    shapes of gap_shapes.hpp (three lobes, a crescent, a flange root: one
//    to three patches), partial slip, with a step study as
//    tests/core/jacobian_step_study.hpp's: steps 1e-4 ... 1e-7 of each
//    input's scale (xi_sat for the creepages, xi_sat / c for the spin, N),
//    the error of each entry relative to its row's scale; steps at which an
//    element changes state or enters or leaves contact cross a kink and do
//    not count. The N column with the force prescribed (central differences
//    in N) and with the approach prescribed (dF / dN from the differences of
//    F and N in the approach), for the exact normal problem and for the
//    semi-Hertzian method, and rolling towards -x;
//  - normal_force = 0 is an error naming it; mu = 0 gives zeros.
// `test_nonhertz_jacobian --markdown` prints the accuracy table of
// doc/validation/jacobians.md (scripts/doc-tables.sh).
#include "gap_shape_grid.hpp"
#include "gap_shapes.hpp"
#include "gap_test_support.hpp"
#include "test_support.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "contact/error.hpp"
#include "contact/hertz.hpp"
#include "contact/jacobian.hpp"
#include "solver.hpp"

namespace cw = creepwork;

namespace {

const gapshapes::Shape& shape(const std::string& id)
{
    static const std::vector<gapshapes::Shape> all = gapshapes::shapes();
    for (const gapshapes::Shape& s : all)
        if (s.id == id) return s;
    throw std::runtime_error("no shape " + id);
}

// The exact model on a 24 x 24 uniform grid (S = 1.2) and on that grid's
// Hertzian gap, both at tolerance 1e-12 (the Jacobians' linear solves too):
// the worst difference of the creepage columns over the row's scale, per
// rolling direction (+1, -1).
std::array<double, 2> hertzian_gap_against_the_elliptic_jacobian()
{
    std::array<double, 2> worst_of{};
    const int n = cwtest::kHertzianGapCells;
    const double S = cwtest::kHertzianGapScale;
    cw::ContactInput e = cwtest::hertzian_gap_reference();
    for (int direction : {1, -1}) {
        e.rolling_direction = direction;
        cw::Solver elliptic(cwtest::uniform_grid(n, n, S));
        cw::Jacobian Je, Jg;
        const cw::SolveTotals te = elliptic.solve_jacobian(e, cw::SolveMode::forces_only, Je);

        std::vector<double> h;
        const cw::GridSpec g = gapshapes::hertzian_gap(e, n, S, h);
        cw::ContactInput in = e;
        in.gap = h.data();
        in.gap_len = h.size();
        cw::Solver gap(g);
        const cw::SolveTotals tg = gap.solve_jacobian(in, cw::SolveMode::forces_only, Jg);
        if (!(tg.n_slip > 0 && tg.n_adhesion > 0 && tg.n_slip == te.n_slip))
            throw std::runtime_error("the Hertzian gap is not in the elliptic model's partial slip");
        const double c = std::sqrt(e.a * e.b), xs = 1e-3;
        const double scale[4] = {xs, xs, xs / c, e.normal_force};
        double worst = 0.0;
        for (int r = 0; r < 4; ++r) {
            double row = 0.0;
            for (int k = 0; k < 4; ++k) row += std::fabs(Je.d[r][k]) * scale[k];
            for (int k = 0; k < 3; ++k)
                worst = std::max(worst, std::fabs(Jg.d[r][k] - Je.d[r][k]) * scale[k] / row);
        }
        worst_of[direction > 0 ? 0 : 1] = worst;
    }
    return worst_of;
}

void hertzian_gap_matches_the_elliptic_jacobian(void**)
{
    const std::array<double, 2> worst = hertzian_gap_against_the_elliptic_jacobian();
    for (int d = 0; d < 2; ++d) {
        print_message("Hertzian gap vs elliptic Jacobian, direction %+d: worst %.2g of the row\n",
                      d == 0 ? 1 : -1, worst[d]);
        // Both solve one discrete problem to 1e-12 and differentiate it by
        // linear solves to 1e-12.
        assert_true(worst[d] < 1e-8);
    }
}

struct Case {
    const char* id;
    cw::ModelKind model;
    cw::NormalMethod normal;
    bool approach;
};

// Fx, Fy, Mz, W_macro, N of a forces-only solve; slips and contact counts.
std::array<double, 5> totals(cw::Solver& s, const cw::ContactInput& in, int& slips, int& contact)
{
    const cw::SolveTotals& t = s.solve(in, cw::SolveMode::forces_only);
    slips = t.n_slip;
    contact = t.n_contact;
    return {t.Fx, t.Fy, t.Mz, t.W_macro, t.normal_force};
}

// Prints the step study's lines (the test's log), or not (the table).
bool g_verbose = true;

// The step study: the best error (over steps that change no state or
// contact element) of J against central differences.
double step_study(const Case& c, cw::Solver& s, const cw::ContactInput& in, const cw::Jacobian& J,
                  const std::array<double, 4>& scale, int slips, int contact)
{
    if (g_verbose)
        printf("  %-16s %-8s %-10s %-8s", c.id, c.model == cw::ModelKind::exact ? "exact" : "fastsim",
           c.normal == cw::NormalMethod::exact ? "exact" : "semi-Hertz",
           c.approach ? "approach" : "force");
    double best = 1e300;
    for (double rel = 1e-4; rel >= 0.5e-7; rel /= 10) {
        double worst = 0.0;
        bool changed = false;
        for (int col = 0; col < 4; ++col) {
            cw::ContactInput up = in, down = in;
            double h = rel * scale[col];
            double* up_v = col == 0 ? &up.xi_x : col == 1 ? &up.xi_y : col == 2 ? &up.phi
                           : c.approach ? &up.approach : &up.normal_force;
            double* down_v = col == 0 ? &down.xi_x : col == 1 ? &down.xi_y : col == 2 ? &down.phi
                             : c.approach ? &down.approach : &down.normal_force;
            if (col == 3 && c.approach) h = rel * 10e-6; // of an approach of tens of um
            *up_v += h;
            *down_v -= h;
            int su, sd, cu, cd;
            const auto fu = totals(s, up, su, cu), fd = totals(s, down, sd, cd);
            changed |= su != slips || sd != slips || cu != contact || cd != contact;
            // d/dN: with the approach prescribed, per the force it carries.
            const double denominator = col == 3 ? fu[4] - fd[4] : 2.0 * h;
            for (int r = 0; r < 4; ++r) {
                double row = 0.0;
                for (int k = 0; k < 4; ++k) row += std::fabs(J.d[r][k]) * scale[k];
                const double diff = (fu[r] - fd[r]) / denominator;
                worst = std::max(worst, std::fabs(diff - J.d[r][col]) * scale[col] / row);
            }
        }
        if (g_verbose) printf(" %8.1e%s", worst, changed ? "*" : " ");
        if (!changed) best = std::min(best, worst);
    }
    if (g_verbose) printf("  best %.1e\n", best);
    return best;
}

const Case kCases[] = {
    {"N03_three_lobes", cw::ModelKind::exact, cw::NormalMethod::exact, false},
    {"N04_crescent", cw::ModelKind::exact, cw::NormalMethod::exact, false},
    {"N06_flange_root", cw::ModelKind::exact, cw::NormalMethod::exact, false},
    {"N06_flange_root", cw::ModelKind::exact, cw::NormalMethod::exact, true},
    {"N04_crescent", cw::ModelKind::exact, cw::NormalMethod::semi_hertz, false},
    {"N03_three_lobes", cw::ModelKind::fastsim, cw::NormalMethod::exact, false},
    {"N04_crescent", cw::ModelKind::fastsim, cw::NormalMethod::exact, false},
    {"N06_flange_root", cw::ModelKind::fastsim, cw::NormalMethod::exact, false},
    {"N06_flange_root", cw::ModelKind::fastsim, cw::NormalMethod::exact, true},
    {"N03_three_lobes", cw::ModelKind::fastsim, cw::NormalMethod::semi_hertz, false},
    {"N04_crescent", cw::ModelKind::fastsim, cw::NormalMethod::semi_hertz, false},
    {"N06_flange_root", cw::ModelKind::fastsim, cw::NormalMethod::semi_hertz, true},
    {"N09_rolling_back", cw::ModelKind::exact, cw::NormalMethod::exact, false},
    {"N09_rolling_back", cw::ModelKind::fastsim, cw::NormalMethod::semi_hertz, false},
};

// One case's best agreement with central differences (the step study).
double best_agreement(const Case& c)
{
    const gapshapes::Shape& sh = shape(c.id);
    cw::Solver s(gapshapes::grid_of(sh));
    cw::ContactInput in;
    in.model = c.model;
    in.normal_method = c.normal;
    in.gap = sh.h.data();
    in.gap_len = sh.h.size();
    in.normal_force = sh.normal_force;
    in.G = sh.G;
    in.nu = sh.nu;
    in.mu = sh.mu;
    in.rolling_direction = sh.rolling_direction;
    in.tolerance = c.model == cw::ModelKind::exact ? 1e-12 : 0.0;
    in.warm_start = false;
    // Creepages of about half saturation (partial slip): xi_sat =
    // 3 mu N / (4.2 G c^2), c the radius of the contact's area.
    const cw::SolveTotals t0 = s.solve(in, cw::SolveMode::forces_only);
    const double c_r = std::sqrt(t0.n_contact * sh.dx * sh.dy / gapshapes::kPi);
    const double xs = 3 * sh.mu * sh.normal_force / (4.2 * sh.G * c_r * c_r);
    const double th = sh.theta_deg * gapshapes::kPi / 180;
    // (The flange root's small lobe saturates first: a lower level.)
    const double level = std::string(c.id) == "N06_flange_root" ? 0.1 : 0.5;
    in.xi_x = level * xs * std::cos(th);
    in.xi_y = level * xs * std::sin(th);
    in.phi = 0.6 * level * xs / c_r;
    if (c.approach) {
        in.normal_load = cw::NormalLoad::approach;
        in.approach = t0.approach;
    }
    cw::Jacobian J;
    const cw::SolveTotals t = s.solve_jacobian(in, cw::SolveMode::forces_only, J);
    if (!(t.n_slip > 0 && t.n_adhesion > 0))
        throw std::runtime_error(std::string(c.id) + " is not in partial slip");
    const std::array<double, 4> scale = {xs, xs, xs / c_r, sh.normal_force};
    return step_study(c, s, in, J, scale, t.n_slip, t.n_contact);
}

// The solves' tolerances (1e-12 tangential, 1e-10 normal, 1e-13
// semi-Hertzian force) over the step bound what a difference resolves:
// measured 4e-11 ... 8e-10 at the best step, held to 1e-8.
constexpr double kHeld = 1e-8;

void against_central_differences(void**)
{
    printf("  shape            model    normal     load      error at step/scale 1e-4 ... 1e-7"
           " (* = an element changed state or contact)\n");
    for (const Case& c : kCases) assert_true(best_agreement(c) <= kHeld);
}

const char* model_name(const Case& c)
{
    return c.model == cw::ModelKind::exact ? "exact model" : "FASTSIM";
}

const char* normal_name(const Case& c)
{
    return c.normal == cw::NormalMethod::exact ? "exact" : "semi-Hertzian";
}

// doc/validation/jacobians.md's table: every case's best agreement, and the
// Hertzian gap against the elliptic model.
void print_markdown()
{
    g_verbose = false;
    printf("| shape | model | normal method | load prescribed | best agreement | test holds |\n");
    printf("|---|---|---|---|---:|---:|\n");
    double worst = 0.0;
    for (const Case& c : kCases) {
        const double best = best_agreement(c);
        worst = std::max(worst, best);
        printf("| %s | %s | %s | %s | %.0e | %.0e |\n", c.id, model_name(c), normal_name(c),
               c.approach ? "approach" : "force", best, kHeld);
    }
    printf("| worst | | | | %.0e | |\n", worst);
    const std::array<double, 2> h = hertzian_gap_against_the_elliptic_jacobian();
    printf("\nOn the Hertzian gap of a 24 x 24 uniform grid the exact model's creepage columns equal "
           "the\nelliptic exact model's to %.0e (rolling towards +x) and %.0e (towards -x) of the "
           "row's\nscale (held to 1e-8).\n",
           h[0], h[1]);
}

void invalid_inputs(void**)
{
    const gapshapes::Shape& sh = shape("N06_flange_root");
    for (cw::ModelKind model : {cw::ModelKind::exact, cw::ModelKind::fastsim}) {
        cw::Solver s(gapshapes::grid_of(sh));
        cw::ContactInput in;
        in.model = model;
        in.gap = sh.h.data();
        in.gap_len = sh.h.size();
        in.normal_force = 0.0;
        in.G = sh.G;
        in.nu = sh.nu;
        in.mu = sh.mu;
        in.xi_x = 1e-3;
        cw::Jacobian J;
        try {
            s.solve_jacobian(in, cw::SolveMode::forces_only, J);
            fail_msg("normal_force = 0 was accepted");
        } catch (const cw::Error& e) {
            assert_true(e.kind() == cw::ErrorKind::invalid_input);
            assert_true(std::string(e.what()).find("normal_force") != std::string::npos);
        }
        // Apart: no contact, no derivative by N.
        in.normal_load = cw::NormalLoad::approach;
        in.approach = -1e-3;
        try {
            s.solve_jacobian(in, cw::SolveMode::forces_only, J);
            fail_msg("an approach without contact was accepted");
        } catch (const cw::Error& e) {
            assert_true(std::string(e.what()).find("approach") != std::string::npos);
        }
        // mu = 0: no traction, every derivative zero (W_macro's too: F = 0).
        in.normal_load = cw::NormalLoad::force;
        in.normal_force = sh.normal_force;
        in.mu = 0.0;
        s.solve_jacobian(in, cw::SolveMode::forces_only, J);
        for (const auto& row : J.d)
            for (double v : row) assert_true(v == 0.0);
    }
}

} // namespace

int main(int argc, char** argv)
{
    if (argc == 2 && std::strcmp(argv[1], "--markdown") == 0) {
        print_markdown();
        return 0;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hertzian_gap_matches_the_elliptic_jacobian),
        cmocka_unit_test(against_central_differences),
        cmocka_unit_test(invalid_inputs),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
