// The exact model on a gap grid against CONTACT (module 3, commit d431cdb,
// the same undeformed distance per element, exact normal and tangential
// problems): the 15 DEV cases of tests/data/nonhertz/dev (solved
// at EPS 1e-10; element fields too) and the 11 shapes of gap_shapes.hpp,
// which no choice in the model was made on (data/contact_cases.csv, CONTACT
// at EPS 1e-12, and data/contact_patches.csv per patch).
//
// Bounds (issue 24): forces within 1e-5 of max(|F|, 0.01 mu N), Mz within
// 1e-5 of max(|Mz|, 0.01 mu N c) (c: radius of a circle of the contact's
// area), p_max, the approach (the normal force when the approach is
// prescribed) within 1e-5 relative, adhesion and slip counts within 2
// elements, the same number of patches. `test_nonhertz_contact --markdown
// dev|new` prints the tables of doc/validation/non-hertzian.md (the same
// comparisons; scripts/doc-tables.sh pastes and checks them).
#include "gap_shapes.hpp"
#include "gap_test_support.hpp"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace cw = creepwork;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Errors {
    double F = 0, M = 0, p = 0, normal = 0;
    int counts = 0;
};

std::string e1(double v)
{
    char b[16];
    std::snprintf(b, sizeof b, "%.0e", v);
    return b;
}

// A comparison of a set of cases: the page's table, the worst errors, and
// every bound missed (a message each).
struct Run {
    std::string table;
    Errors worst;
    double patch_worst = 0.0;
    std::vector<std::string> failures;
};

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* fmt, ...)
{
    char b[512];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(b, sizeof b, fmt, args);
    va_end(args);
    return b;
}

// One case solved (full mode) and compared; its row of the page's table.
Errors compare(const cwtest::GapCase& c, const cw::ContactInput& in, cw::Solver& s,
               bool approach_given, Run& run)
{
    const cw::SolveTotals t = s.solve(in, cw::SolveMode::full);
    const double muN = in.mu * c.Fn;
    const double radius = std::sqrt(c.n_contact * c.gap.grid.dx * c.gap.grid.dy / kPi);
    Errors e;
    e.F = std::max(std::fabs(t.Fx - c.Fx), std::fabs(t.Fy - c.Fy)) /
          std::max(std::hypot(c.Fx, c.Fy), 0.01 * muN);
    e.M = std::fabs(t.Mz - c.Mz) / std::max(std::fabs(c.Mz), 0.01 * muN * radius);
    e.p = std::fabs(t.p_max / c.p_max - 1.0);
    e.normal = approach_given ? std::fabs(t.normal_force / c.Fn - 1.0)
                              : std::fabs(t.approach / c.approach - 1.0);
    e.counts = std::max(std::abs(t.n_adhesion - c.n_adhesion), std::abs(t.n_slip - c.n_slip));
    run.table += "| " + c.id + " | " + std::to_string(t.n_contact) + " | " +
             std::to_string(t.n_patches) + " | " + e1(e.F) + " | " + e1(e.M) + " | " + e1(e.p) +
             " | " + e1(e.normal) + " | " + std::to_string(t.n_adhesion) + "/" +
             std::to_string(t.n_slip) + " | " + std::to_string(c.n_adhesion) + "/" +
             std::to_string(c.n_slip) + " |\n";
    if (e.F > 1e-5 || e.M > 1e-5 || e.p > 1e-5 || e.normal > 1e-5 || e.counts > 2 ||
        t.n_patches != c.n_patches)
        run.failures.push_back(format(
            "%s: dF %.3g dMz %.3g dp_max %.3g d%s %.3g counts %d/%d vs %d/%d, patches %d vs %d",
            c.id.c_str(), e.F, e.M, e.p, approach_given ? "Fn" : "approach", e.normal,
            t.n_adhesion, t.n_slip, c.n_adhesion, c.n_slip, t.n_patches, c.n_patches));
    run.worst.F = std::max(run.worst.F, e.F);
    run.worst.M = std::max(run.worst.M, e.M);
    run.worst.p = std::max(run.worst.p, e.p);
    run.worst.normal = std::max(run.worst.normal, e.normal);
    run.worst.counts = std::max(run.worst.counts, e.counts);
    return e;
}

std::string table_header(const char* normal)
{
    return std::string("| case | elements | patches | forces | Mz | p_max | ") + normal +
           " | adhesion/slip | CONTACT's |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
}

Run run_dev()
{
    Run run;
    run.table = table_header("approach");
    for (const cwtest::GapCase& c : cwtest::dev_cases()) {
        cw::Solver s(c.gap.grid);
        compare(c, c.bind(), s, false, run);
        // Element by element: CONTACT's element division, pressure and
        // traction (1e-5 of p_max and of mu p_max).
        const cwtest::ContactFields f = cwtest::read_contact_fields(
            cwtest::test_data_path("nonhertz/dev/fields/" + c.id + ".csv"), c.gap.grid);
        const auto pz = cwtest::field(s, cw::Field::pz), px = cwtest::field(s, cw::Field::px),
                   py = cwtest::field(s, cw::Field::py);
        const std::vector<int> st = cwtest::states(s);
        int differ = 0;
        double dp = 0.0, dt = 0.0;
        for (size_t k = 0; k < pz.size(); ++k) {
            differ += st[k] != std::min(f.eldiv[k], 2);
            dp = std::max(dp, std::fabs(pz[k] - f.pn[k]));
            dt = std::max(dt, std::hypot(px[k] - f.px[k], py[k] - f.py[k]));
        }
        if (differ > 2 || dp > 1e-5 * c.p_max || dt > 1e-5 * c.input.mu * c.p_max)
            run.failures.push_back(format(
                "%s fields: %d element states differ, pressure %.3g, traction %.3g of p_max",
                c.id.c_str(), differ, dp / c.p_max, dt / (c.input.mu * c.p_max)));
    }
    return run;
}

// The shapes no choice was made on, against CONTACT at EPS 1e-12.
Run run_new()
{
    const std::string data = CW_NONHERTZ_DATA_DIR;
    const cwtest::CsvTable t = cwtest::read_quoted_csv(data + "/contact_cases.csv");
    const cwtest::CsvTable per_patch = cwtest::read_csv(data + "/contact_patches.csv");
    Run run;
    run.table = table_header("approach (N08: Fn)");
    const std::vector<gapshapes::Shape> shapes = gapshapes::shapes();
    if (t.rows.size() != shapes.size()) {
        run.failures.push_back("data/contact_cases.csv has another number of shapes");
        return run;
    }
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const gapshapes::Shape& sh = shapes[r];
        if (t.text(r, "case_id") != sh.id) run.failures.push_back("row " + sh.id + " out of order");
        cwtest::GapCase c;
        c.id = sh.id;
        c.gap.grid.kind = cw::GridKind::gap;
        c.gap.grid.nx = sh.nx;
        c.gap.grid.ny = sh.ny;
        c.gap.grid.x0 = sh.x0;
        c.gap.grid.y0 = sh.y0;
        c.gap.grid.dx = sh.dx;
        c.gap.grid.dy = sh.dy;
        c.gap.h = sh.h;
        cw::ContactInput& in = c.input;
        in.model = cw::ModelKind::exact;
        const bool approach_given = t.number(r, "approach_given") != 0.0;
        in.normal_load = approach_given ? cw::NormalLoad::approach : cw::NormalLoad::force;
        in.normal_force = t.number(r, "N_N");
        in.approach = t.number(r, "approach_in_m");
        in.G = t.number(r, "G_Pa");
        in.nu = t.number(r, "nu");
        in.mu = t.number(r, "mu");
        in.xi_x = t.number(r, "xi_x");
        in.xi_y = t.number(r, "xi_y");
        in.phi = t.number(r, "phi_per_m");
        in.rolling_direction = static_cast<int>(t.number(r, "rolling_direction"));
        in.warm_start = false;
        c.Fn = t.number(r, "Fn_N");
        c.Fx = t.number(r, "Fx_N");
        c.Fy = t.number(r, "Fy_N");
        c.Mz = t.number(r, "Mz_Nm");
        c.p_max = t.number(r, "p_max_Pa");
        c.approach = t.number(r, "approach_m");
        c.n_contact = static_cast<int>(t.number(r, "n_contact"));
        c.n_adhesion = static_cast<int>(t.number(r, "n_adhesion"));
        c.n_slip = static_cast<int>(t.number(r, "n_slip"));
        c.n_patches = static_cast<int>(t.number(r, "n_patches"));
        cw::Solver s(c.gap.grid);
        compare(c, c.bind(), s, approach_given, run);

        // Per patch, against CONTACT's tractions summed over its patches
        // (the same numbering): forces within 1e-5 of the case's scale.
        const double muN = in.mu * c.Fn;
        const double radius = std::sqrt(c.n_contact * sh.dx * sh.dy / kPi);
        const std::vector<cw::PatchTotals>& P = s.patches();
        for (size_t q = 0; q < per_patch.rows.size(); ++q) {
            if (per_patch.text(q, "case_id") != c.id) continue;
            const size_t k = static_cast<size_t>(per_patch.number(q, "patch"));
            if (k >= P.size()) {
                run.failures.push_back(c.id + ": fewer patches than CONTACT's");
                continue;
            }
            const double eF = std::max({std::fabs(P[k].Fx - per_patch.number(q, "Fx_N")),
                                        std::fabs(P[k].Fy - per_patch.number(q, "Fy_N")),
                                        std::fabs(P[k].Fn - per_patch.number(q, "Fn_N"))}) /
                              std::max(std::hypot(c.Fx, c.Fy), 0.01 * muN);
            const double eM = std::fabs(P[k].Mz - per_patch.number(q, "Mz_Nm")) /
                              std::max(std::fabs(c.Mz), 0.01 * muN * radius);
            run.patch_worst = std::max({run.patch_worst, eF, eM});
            const int dn = std::abs(P[k].n_contact - static_cast<int>(per_patch.number(q, "n_contact")));
            if (eF > 1e-5 || eM > 1e-5 || dn > 2)
                run.failures.push_back(format("%s patch %zu: forces %.3g, Mz %.3g, elements %d",
                                              c.id.c_str(), k, eF, eM, dn));
        }
    }
    return run;
}

void report(const Run& run, const char* set)
{
    print_message("%s worst: forces %.2g, Mz %.2g, p_max %.2g, approach/Fn %.2g, counts %d, per "
                  "patch %.2g\n",
                  set, run.worst.F, run.worst.M, run.worst.p, run.worst.normal, run.worst.counts,
                  run.patch_worst);
    for (const std::string& f : run.failures) print_error("%s\n", f.c_str());
    assert_true(run.failures.empty());
}

void dev_cases_match_contact(void**) { report(run_dev(), "DEV"); }

void new_shapes_match_contact(void**) { report(run_new(), "new shapes"); }

} // namespace

int main(int argc, char** argv)
{
    if (argc == 3 && std::strcmp(argv[1], "--markdown") == 0) {
        const Run run = std::strcmp(argv[2], "new") == 0 ? run_new() : run_dev();
        std::fputs(run.table.c_str(), stdout);
        return run.failures.empty() ? 0 : 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(dev_cases_match_contact),
        cmocka_unit_test(new_shapes_match_contact),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
