// Grid convergence: totals converge as nx, ny grow (observed order
// printed per case), the paper's K tends to 1, and the energy-consistent
// work map meets its four properties on every grid of a sweep and converges
// to one density.
#include "core_test_support.hpp"
#include "test_support.h"

namespace cw = creepwork;

namespace {

struct Case {
    const char* name;
    double a_over_b, xi, eta, phi; // creepages; spin in 1/m (a ~ 6 mm)
    bool full_slip;
    double order[2]; // observed order of |F| (Kalker strips, uniform), measured
};

const Case kCases[] = {
    {"partial", 1.0, 0.0005, 0.0, 0.0, false, {1.85, 1.18}},
    {"partial + spin", 1.0, 0.0005, 0.0003, 0.1, false, {1.57, 1.12}},
    {"full", 2.0, 0.01, 0.005, 0.0, true, {2.05, 2.27}},
    {"full + spin", 0.5, 0.01, 0.0, 2.0, true, {0.99, 1.52}},
};

cw::ContactInput input(const Case& c, double a_over_b)
{
    cw::ContactInput in = cwtest::steel_contact(a_over_b);
    in.xi_x = c.xi;
    in.xi_y = c.eta;
    in.phi = c.phi;
    return in;
}

cw::GridSpec grid(cw::GridKind kind, int n)
{
    return kind == cw::GridKind::uniform ? cwtest::uniform_grid(n, n) : cwtest::kalker_grid(n, n);
}

const char* name(cw::GridKind kind)
{
    return kind == cw::GridKind::uniform ? "uniform" : "Kalker strips";
}

// |F(n) - F(2n)| shrinks with n; the observed order (between 40-80 and
// 160-320) is at least first order and is held to its measured value.
void totals_converge(void**)
{
    for (cw::GridKind kind : {cw::GridKind::kalker_strips, cw::GridKind::uniform}) {
        for (const Case& c : kCases) {
            double F[5];
            const int n[5] = {20, 40, 80, 160, 320};
            for (int k = 0; k < 5; ++k) {
                cw::Solver s(grid(kind, n[k]));
                const cw::SolveTotals& t = s.solve(input(c, c.a_over_b), cw::SolveMode::forces_only);
                F[k] = std::hypot(t.Fx, t.Fy);
            }
            const double d_coarse = std::fabs(F[2] - F[1]), d_fine = std::fabs(F[4] - F[3]);
            const double order = std::log(d_coarse / d_fine) / std::log(4.0);
            printf("  %-13s %-14s |F|: %.6g .. %.6g, observed order %.2f\n", name(kind), c.name,
                   F[0], F[4], order);
            assert_close(order, c.order[kind == cw::GridKind::uniform], 0.0, 0.01);
            assert_true(d_fine < d_coarse);
            assert_true(d_fine < 0.005 * F[4]);
        }
    }
}

// K = W_macro / W_micro_paper (paper eq. 39): >= 1, near 1 in full slip,
// large at small creepage, and -> 1 roughly as 1/n (paper Table 1 trend).
// doc/validation/index.md quotes the Kalker-strip partial-slip sequence.
void paper_K_tends_to_one(void**)
{
    const double readme[6] = {2.13, 1.83, 1.34, 1.16, 1.08, 1.04};
    for (cw::GridKind kind : {cw::GridKind::kalker_strips, cw::GridKind::uniform}) {
        for (const Case& c : kCases) {
            double previous = 1e300;
            printf("  %-13s %-14s K:", name(kind), c.name);
            int step = 0;
            for (int n : {10, 20, 40, 80, 160, 320}) {
                cw::Solver s(grid(kind, n));
                const double K = s.solve(input(c, c.a_over_b)).K;
                printf(" %.4f", K);
                if (kind == cw::GridKind::kalker_strips && &c == &kCases[0])
                    assert_close(K, readme[step], 0.0, 0.005);
                ++step;
                assert_true(K >= 1.0);
                assert_true(K < previous);
                // K - 1 ~ 1/n: halved by each of the last two refinements
                // (measured 1.99 ... 2.10).
                if (n >= 160) assert_close((previous - 1.0) / (K - 1.0), 2.0, 0.0, 0.15);
                if (c.full_slip) assert_true(K < 1.1);
                previous = K;
            }
            printf("\n");
            assert_true(previous - 1.0 < 0.05);
        }
        // Small creepage: few slip elements carry the work, K is large.
        cw::Solver s(grid(kind, 160));
        cw::ContactInput in = cwtest::steel_contact(1.0);
        in.xi_x = 1e-5;
        assert_true(s.solve(in).K > 5.0);
    }
}

// On every grid of the sweep: non-negative, zero in adhesion (and exterior)
// elements, no flag. The sum = W_macro holds by construction (the map is
// scaled by W_macro / total): asserted as a wiring check of the exported
// field, not as validation; test_core_work checks the ingredients (balance
// factor against the energy identity and its limits, a 3 x 3 map by hand).
// Convergence is the next test.
void consistent_map_properties_sweep(void**)
{
    int solves = 0;
    for (cw::GridKind kind : {cw::GridKind::kalker_strips, cw::GridKind::uniform}) {
        for (int n : {5, 10, 20, 50, 100, 200}) {
            cw::Solver s(grid(kind, n));
            for (double ratio : {0.2, 1.0, 5.0}) {
                for (const Case& c : kCases) {
                    const cw::SolveTotals t = s.solve(input(c, ratio));
                    assert_int_equal(t.work_flags, 0);
                    assert_true(t.n_slip > 0);
                    const auto w = cwtest::field(s, cw::Field::work_consistent);
                    const auto st = cwtest::states(s);
                    long double total = 0.0L;
                    for (size_t k = 0; k < w.size(); ++k) {
                        assert_true(w[k] >= 0.0);
                        if (st[k] != 2) assert_true(w[k] == 0.0);
                        total += w[k];
                    }
                    assert_close(static_cast<double>(total), t.W_macro, 1e-12, 0.0);
                    assert_close(t.W_consistent, t.W_macro, 1e-12, 0.0);
                    ++solves;
                }
            }
        }
    }
    assert_int_equal(solves, 2 * 6 * 3 * 4);
}

// Convergence to one density: the map is binned on a fixed 8 x 8 partition
// of the normalised patch; the L1 distance to a 512 x 512 solution, relative
// to W, falls as the grid is refined: below 1 % at 256 x 256 in every case
// (doc/validation/index.md), at most half the 16 x 16 value.
std::vector<double> binned(const cw::Solver& s, const cw::ContactInput& in)
{
    const auto w = cwtest::field(s, cw::Field::work_consistent);
    const auto x = cwtest::field(s, cw::Field::x), y = cwtest::field(s, cw::Field::y);
    std::vector<double> bins(64, 0.0);
    for (size_t k = 0; k < w.size(); ++k) {
        const int bx = std::min(7, std::max(0, int((x[k] / in.a + 1.0) * 4.0)));
        const int by = std::min(7, std::max(0, int((y[k] / in.b + 1.0) * 4.0)));
        bins[bx + 8 * by] += w[k];
    }
    return bins;
}

void consistent_map_converges(void**)
{
    for (cw::GridKind kind : {cw::GridKind::kalker_strips, cw::GridKind::uniform}) {
        for (const Case& c : kCases) {
            const cw::ContactInput in = input(c, c.a_over_b);
            cw::Solver fine(grid(kind, 512));
            const double W = fine.solve(in).W_macro;
            const std::vector<double> reference = binned(fine, in);
            printf("  %-13s %-14s L1 distance / W:", name(kind), c.name);
            double first = 0.0, last = 0.0;
            for (int n : {16, 32, 64, 128, 256}) {
                cw::Solver s(grid(kind, n));
                s.solve(in);
                const std::vector<double> b = binned(s, in);
                double d = 0.0;
                for (size_t k = 0; k < b.size(); ++k) d += std::fabs(b[k] - reference[k]);
                d /= W;
                printf(" %.4f", d);
                if (n == 16) first = d;
                last = d;
            }
            printf("\n");
            assert_true(last < 0.5 * first);
            assert_true(last < 0.01);
        }
    }
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(totals_converge),
        cmocka_unit_test(paper_K_tends_to_one),
        cmocka_unit_test(consistent_map_properties_sweep),
        cmocka_unit_test(consistent_map_converges),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
