// The exact model on a gap grid against CONTACT (module 3, commit d431cdb,
// the same undeformed distance per element, exact normal and tangential
// problems): the 15 DEV cases of ../shared/reference/nonhertz/dev (solved
// at EPS 1e-10; element fields too) and the 11 shapes of gap_shapes.hpp,
// which no choice in the model was made on (data/contact_cases.csv, CONTACT
// at EPS 1e-12, and data/contact_patches.csv per patch).
//
// Bounds (issue 24): forces within 1e-5 of max(|F|, 0.01 mu N), Mz within
// 1e-5 of max(|Mz|, 0.01 mu N c) (c: radius of a circle of the contact's
// area), p_max, the approach (the normal force when the approach is
// prescribed) within 1e-5 relative, adhesion and slip counts within 2
// elements, the same number of patches. The tables of
// doc/validation/non-hertzian.md are these comparisons (doc_table.hpp).
#include "doc_table.hpp"
#include "gap_shapes.hpp"
#include "gap_test_support.hpp"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

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

// One case solved (full mode) and compared; its row of the page's table.
Errors compare(const cwtest::GapCase& c, const cw::ContactInput& in, cw::Solver& s,
               bool approach_given, std::string& table)
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
    table += "| " + c.id + " | " + std::to_string(t.n_contact) + " | " +
             std::to_string(t.n_patches) + " | " + e1(e.F) + " | " + e1(e.M) + " | " + e1(e.p) +
             " | " + e1(e.normal) + " | " + std::to_string(t.n_adhesion) + "/" +
             std::to_string(t.n_slip) + " | " + std::to_string(c.n_adhesion) + "/" +
             std::to_string(c.n_slip) + " |\n";
    if (e.F > 1e-5 || e.M > 1e-5 || e.p > 1e-5 || e.normal > 1e-5 || e.counts > 2 ||
        t.n_patches != c.n_patches)
        fail_msg("%s: dF %.3g dMz %.3g dp_max %.3g d%s %.3g counts %d/%d vs %d/%d, patches %d "
                 "vs %d",
                 c.id.c_str(), e.F, e.M, e.p, approach_given ? "Fn" : "approach", e.normal,
                 t.n_adhesion, t.n_slip, c.n_adhesion, c.n_slip, t.n_patches, c.n_patches);
    return e;
}

std::string table_header(const char* normal)
{
    return std::string("| case | elements | patches | forces | Mz | p_max | ") + normal +
           " | adhesion/slip | CONTACT's |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
}

void check_page(const char* name, const std::string& table)
{
    const std::string why =
        cwtest::check_doc_table(CW_DOC_DIR "/validation/non-hertzian.md", name, table);
    if (!why.empty()) fail_msg("%s", why.c_str());
}

void dev_cases_match_contact(void**)
{
    std::string table = table_header("approach");
    Errors worst;
    for (const cwtest::GapCase& c : cwtest::dev_cases()) {
        cw::Solver s(c.gap.grid);
        const Errors e = compare(c, c.bind(), s, false, table);
        worst.F = std::max(worst.F, e.F);
        worst.M = std::max(worst.M, e.M);
        worst.p = std::max(worst.p, e.p);
        worst.normal = std::max(worst.normal, e.normal);
        worst.counts = std::max(worst.counts, e.counts);

        // Element by element: CONTACT's element division, pressure and
        // traction (1e-5 of p_max and of mu p_max).
        const cwtest::ContactFields f = cwtest::read_contact_fields(
            cwtest::shared_path("reference/nonhertz/dev/fields/" + c.id + ".csv"), c.gap.grid);
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
            fail_msg("%s fields: %d element states differ, pressure %.3g, traction %.3g of "
                     "p_max",
                     c.id.c_str(), differ, dp / c.p_max, dt / (c.input.mu * c.p_max));
    }
    print_message("DEV worst: forces %.2g, Mz %.2g, p_max %.2g, approach %.2g, counts %d\n",
                  worst.F, worst.M, worst.p, worst.normal, worst.counts);
    check_page("exact-dev", table);
}

// The shapes no choice was made on, against CONTACT at EPS 1e-12.
void new_shapes_match_contact(void**)
{
    const std::string data = CW_NONHERTZ_DATA_DIR;
    const cwtest::CsvTable t = cwtest::read_quoted_csv(data + "/contact_cases.csv");
    const cwtest::CsvTable per_patch = cwtest::read_csv(data + "/contact_patches.csv");
    std::string table = table_header("approach (N08: Fn)");
    const std::vector<gapshapes::Shape> shapes = gapshapes::shapes();
    assert_int_equal(t.rows.size(), shapes.size());
    Errors worst;
    double patch_worst = 0.0;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const gapshapes::Shape& sh = shapes[r];
        assert_string_equal(t.text(r, "case_id").c_str(), sh.id.c_str());
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
        const Errors e = compare(c, c.bind(), s, approach_given, table);
        worst.F = std::max(worst.F, e.F);
        worst.M = std::max(worst.M, e.M);
        worst.p = std::max(worst.p, e.p);
        worst.normal = std::max(worst.normal, e.normal);
        worst.counts = std::max(worst.counts, e.counts);

        // Per patch, against CONTACT's tractions summed over its patches
        // (the same numbering): forces within 1e-5 of the case's scale.
        const double muN = in.mu * c.Fn;
        const double radius = std::sqrt(c.n_contact * sh.dx * sh.dy / kPi);
        const std::vector<cw::PatchTotals>& P = s.patches();
        for (size_t q = 0; q < per_patch.rows.size(); ++q) {
            if (per_patch.text(q, "case_id") != c.id) continue;
            const size_t k = static_cast<size_t>(per_patch.number(q, "patch"));
            assert_true(k < P.size());
            const double eF = std::max({std::fabs(P[k].Fx - per_patch.number(q, "Fx_N")),
                                        std::fabs(P[k].Fy - per_patch.number(q, "Fy_N")),
                                        std::fabs(P[k].Fn - per_patch.number(q, "Fn_N"))}) /
                              std::max(std::hypot(c.Fx, c.Fy), 0.01 * muN);
            const double eM = std::fabs(P[k].Mz - per_patch.number(q, "Mz_Nm")) /
                              std::max(std::fabs(c.Mz), 0.01 * muN * radius);
            patch_worst = std::max({patch_worst, eF, eM});
            assert_true(std::abs(P[k].n_contact - static_cast<int>(per_patch.number(q, "n_contact"))) <= 2);
            if (eF > 1e-5 || eM > 1e-5)
                fail_msg("%s patch %zu: forces %.3g, Mz %.3g", c.id.c_str(), k, eF, eM);
        }
    }
    print_message("new shapes worst: forces %.2g, Mz %.2g, p_max %.2g, approach/Fn %.2g, "
                  "counts %d, per patch %.2g\n",
                  worst.F, worst.M, worst.p, worst.normal, worst.counts, patch_worst);
    check_page("exact-new", table);
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(dev_cases_match_contact),
        cmocka_unit_test(new_shapes_match_contact),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
