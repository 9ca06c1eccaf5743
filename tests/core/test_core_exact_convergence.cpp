// Grid convergence of Kalker's exact theory on CONTACT's discretisation:
//  - linear theory: C11, C22, C23, C33 at vanishing creepage (full
//    adhesion), extrapolated to zero element size from N = 40, 80, 160
//    elements across the ellipse, within 2 % of Kalker's Table E.3
//    (tests/data/kalker_cij.csv, nu = 0.25, a/b = 0.5, 1, 2);
//  - the reference cases of contact_exact_dev.csv (a/b = 1 and 2, every
//    creepage set) on N = 20, 40, 80, 160: observed orders and continuum
//    (Richardson) estimates of Fx, Fy, Mz and W_macro, committed in
//    data/exact_convergence.csv (how: data/exact_convergence.md). Run
//    `test_core_exact_convergence --write FILE` to regenerate it (about a
//    minute); by default the test recomputes the N = 20 and 40 columns and
//    checks that the model still gives them.
#include "exact_test_support.hpp"
#include "test_support.h"

#include <algorithm>
#include <cstring>
#include <fstream>

namespace cw = creepwork;

namespace {

const int kGrids[] = {20, 40, 80, 160};

// Observed order from three grids halving h, and the Richardson estimate
// from the two finest: p = observed when in [0.5, 3], else 1 (the scheme's
// one-sided difference is first order); the correction is the uncertainty.
struct Extrapolation {
    double order_coarse, order_fine, estimate, uncertainty;
};

double order(double f1, double f2, double f3)
{
    return std::log2((f1 - f2) / (f2 - f3));
}

Extrapolation extrapolate(const double f[4])
{
    Extrapolation e;
    e.order_coarse = order(f[0], f[1], f[2]);
    e.order_fine = order(f[1], f[2], f[3]);
    const double p = e.order_fine >= 0.5 && e.order_fine <= 3.0 ? e.order_fine : 1.0;
    const double correction = (f[3] - f[2]) / (std::pow(2.0, p) - 1.0);
    e.estimate = f[3] + correction;
    e.uncertainty = std::fabs(correction);
    return e;
}

// Kalker's coefficients at vanishing creepage (signs of tests/data/README.md):
// Fx = -G c^2 C11 xi; Fy = -G c^2 C22 eta - G c^3 C23 phi; Mz = -G c^4 C33 phi.
void coefficients(int N, double a_over_b, double C[4])
{
    cw::ContactInput in;
    in.model = cw::ModelKind::exact;
    const double c = 6.0; // sqrt(ab) [mm]; CONTACT's units
    in.a = c * std::sqrt(a_over_b);
    in.b = c / std::sqrt(a_over_b);
    in.normal_force = 80e3;
    in.mu = 0.3;
    in.G = 82e3;
    in.nu = 0.25;
    cw::Solver s(cwtest::guarded_grid(N));
    const double e = 1e-9; // full adhesion
    in.xi_x = e;
    cw::SolveTotals t = s.solve(in, cw::SolveMode::forces_only);
    assert_int_equal(t.n_slip, 0);
    C[0] = -t.Fx / (in.G * c * c * e);
    in.xi_x = 0.0;
    in.xi_y = e;
    t = s.solve(in, cw::SolveMode::forces_only);
    C[1] = -t.Fy / (in.G * c * c * e);
    in.xi_y = 0.0;
    in.phi = e / c;
    t = s.solve(in, cw::SolveMode::forces_only);
    C[2] = -t.Fy / (in.G * c * c * e);
    C[3] = -t.Mz / (in.G * c * c * c * e);
}

void linear_theory_matches_kalker(void**)
{
    const cwtest::CsvTable k = cwtest::read_csv(cwtest::test_data_path("kalker_cij.csv"));
    const char* names[4] = {"C11", "C22", "C23", "C33"};
    for (double ab : {0.5, 1.0, 2.0}) {
        double C[4][4];
        for (int g = 1; g < 4; ++g) { // 40, 80, 160 (20 is not yet asymptotic)
            double c[4];
            coefficients(kGrids[g], ab, c);
            for (int q = 0; q < 4; ++q) C[q][g] = c[q];
        }
        size_t r = 0;
        while (r < k.rows.size() &&
               !(k.number(r, "a_over_b") == ab && k.number(r, "nu") == 0.25))
            ++r;
        assert_true(r < k.rows.size());
        for (int q = 0; q < 4; ++q) {
            const double p = order(C[q][1], C[q][2], C[q][3]);
            const double pp = p >= 0.5 && p <= 3.0 ? p : 1.0;
            const double ext = C[q][3] + (C[q][3] - C[q][2]) / (std::pow(2.0, pp) - 1.0);
            const double ratio = ext / k.number(r, names[q]);
            printf("  a/b %.1f %s: N=40 %.4f, 80 %.4f, 160 %.4f, order %.2f, extrapolated %.4f, "
                   "Kalker %.4g, ratio %.4f\n",
                   ab, names[q], C[q][1], C[q][2], C[q][3], p, ext, k.number(r, names[q]), ratio);
            assert_true(std::fabs(ratio - 1.0) < 0.02);
        }
    }
}

struct Quantity {
    const char* name;
    double cw::SolveTotals::*member;
};
const Quantity kQuantities[] = {{"FX_N", &cw::SolveTotals::Fx},
                                {"FY_N", &cw::SolveTotals::Fy},
                                {"MZ_Nmm", &cw::SolveTotals::Mz},
                                {"W_macro_N", &cw::SolveTotals::W_macro}};

// The 22 cases (grid 20 rows of contact_exact_dev.csv) on grids[0..count).
std::vector<std::vector<cw::SolveTotals>> reference_solves(int count)
{
    std::vector<std::vector<cw::SolveTotals>> all;
    for (const cwtest::ExactRow& row : cwtest::exact_rows(20)) {
        std::vector<cw::SolveTotals> per_grid;
        for (int g = 0; g < count; ++g) {
            cw::Solver s(cwtest::guarded_grid(kGrids[g]));
            per_grid.push_back(s.solve(row.input, cw::SolveMode::full));
        }
        all.push_back(per_grid);
    }
    return all;
}

int write_table(const char* path)
{
    const std::vector<cwtest::ExactRow> rows = cwtest::exact_rows(20);
    const auto all = reference_solves(4);
    std::ofstream out(path);
    out.precision(12);
    out << "case_id,a_mm,b_mm,cksi,ceta,cphi_rad_per_mm,quantity,N20,N40,N80,N160,"
           "order_20_40_80,order_40_80_160,estimate,uncertainty\n";
    for (size_t r = 0; r < rows.size(); ++r) {
        const cw::ContactInput& in = rows[r].input;
        const double F = std::hypot(all[r][3].Fx, all[r][3].Fy);
        for (const Quantity& q : kQuantities) {
            double f[4];
            for (int g = 0; g < 4; ++g) f[g] = all[r][g].*q.member;
            out << rows[r].case_id << ',' << in.a << ',' << in.b << ',' << in.xi_x << ','
                << in.xi_y << ',' << in.phi << ',' << q.name;
            for (double v : f) out << ',' << v;
            // Zero by symmetry (pure creepage): no order, estimate 0.
            const double scale = std::string(q.name) == "MZ_Nmm" ? F * std::sqrt(in.a * in.b) : F;
            if (std::fabs(f[3]) < 1e-7 * scale && std::string(q.name) != "W_macro_N") {
                out << ",,,0,0\n";
                continue;
            }
            const Extrapolation e = extrapolate(f);
            out << ',' << e.order_coarse << ',' << e.order_fine << ',' << e.estimate << ','
                << e.uncertainty << '\n';
        }
    }
    printf("wrote %s\n", path);
    return 0;
}

// The committed table still describes the model: its N = 20 and 40 columns
// are recomputed (to 1e-7 of |F|, the solver's tolerance), and each
// estimate follows from its row by the rule above.
void committed_table_is_current(void**)
{
    const cwtest::CsvTable t =
        cwtest::read_csv(std::string(CW_CORE_DATA_DIR) + "/exact_convergence.csv");
    const std::vector<cwtest::ExactRow> rows = cwtest::exact_rows(20);
    assert_int_equal(t.rows.size(), rows.size() * 4);
    const auto all = reference_solves(2);
    double worst_order = 1e300, best_order = -1e300;
    for (size_t r = 0; r < rows.size(); ++r) {
        const double F = std::hypot(all[r][1].Fx, all[r][1].Fy);
        for (size_t q = 0; q < 4; ++q) {
            const size_t line = r * 4 + q;
            assert_string_equal(t.text(line, "case_id").c_str(), rows[r].case_id.c_str());
            assert_string_equal(t.text(line, "quantity").c_str(), kQuantities[q].name);
            const double scale =
                q == 2 ? F * std::sqrt(rows[r].input.a * rows[r].input.b) : F;
            for (int g = 0; g < 2; ++g)
                assert_close(all[r][g].*kQuantities[q].member,
                             t.number(line, g == 0 ? "N20" : "N40"), 0.0, 1e-7 * scale);
            const std::string o = t.text(line, "order_40_80_160");
            if (o.empty()) continue;
            const double f[4] = {t.number(line, "N20"), t.number(line, "N40"),
                                 t.number(line, "N80"), t.number(line, "N160")};
            const Extrapolation e = extrapolate(f);
            assert_close(e.estimate, t.number(line, "estimate"), 1e-10, 1e-10 * scale);
            worst_order = std::min(worst_order, e.order_fine);
            best_order = std::max(best_order, e.order_fine);
        }
    }
    printf("  %zu cases x 4 quantities; observed orders (N = 40, 80, 160) %.2f ... %.2f\n",
           rows.size(), worst_order, best_order);
}

} // namespace

int main(int argc, char** argv)
{
    if (argc > 2 && std::strcmp(argv[1], "--write") == 0) return write_table(argv[2]);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(linear_theory_matches_kalker),
        cmocka_unit_test(committed_table_is_current),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
