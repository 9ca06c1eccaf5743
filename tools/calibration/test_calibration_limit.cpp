// The continuum limit behind doc/validation/calibrated.md
// (calibration_limit.hpp), on sequences whose limit and order are known by
// construction: Q(h) = Q0 + C h^p on the study's grids 80, 112, 160 (not in
// a constant ratio), and the sequences it must refuse to extrapolate.
#include <cmath>

#include "calibration_limit.hpp"
#include "test_support.h"

namespace {

const double kH[3] = {1.0 / 80, 1.0 / 112, 1.0 / 160};

cwcal::ContinuumLimit limit_of(double q0, double c, double p)
{
    double q[3];
    for (int k = 0; k < 3; ++k) q[k] = q0 + c * std::pow(kH[k], p);
    return cwcal::continuum_limit(kH, q, std::fabs(q0));
}

// Known order and limit come back, from either side and for any order the
// study accepts (0.5 .. 4).
void recovers_order_and_limit(void**)
{
    const struct {
        double q0, c, p;
    } seqs[] = {{2.0, 3.0, 1.5}, {5.0, -0.7, 1.0}, {-400.0, 90.0, 0.6}, {1.25, 40.0, 2.0},
                {0.3, -2.0e3, 3.7}};
    for (const auto& s : seqs) {
        const cwcal::ContinuumLimit L = limit_of(s.q0, s.c, s.p);
        assert_true(L.richardson);
        assert_false(L.resolved);
        assert_close(L.order, s.p, 1e-9, 0.0);
        // The finest grid misses by C h2^p; the estimate by rounding only.
        assert_close(L.value, s.q0, 0.0, 1e-10 * std::fabs(s.c));
    }
}

// Sequences that are not in the asymptotic range keep the finest value.
void refuses_unclean_sequences(void**)
{
    // Oscillating (the slip boundary jumping by whole elements).
    const double zigzag[3] = {1.00, 1.02, 1.01};
    cwcal::ContinuumLimit L = cwcal::continuum_limit(kH, zigzag, 1.0);
    assert_false(L.richardson);
    assert_true(L.value == 1.01);
    // Growing differences (diverging on these grids).
    const double growing[3] = {1.00, 1.01, 1.03};
    L = cwcal::continuum_limit(kH, growing, 1.0);
    assert_false(L.richardson);
    assert_true(L.value == 1.03);
    // Orders outside 0.5 .. 4: p = 0.3 and p = 6.
    L = limit_of(1.0, 1.0, 0.3);
    assert_false(L.richardson);
    L = limit_of(1.0, 1.0, 6.0);
    assert_false(L.richardson);
    assert_true(L.value == 1.0 + std::pow(kH[2], 6.0));
}

// A total zero by symmetry, seen through rounding, has no order.
void rounding_level_is_resolved(void**)
{
    const double noise[3] = {2e-13, -3e-14, 1e-13};
    const cwcal::ContinuumLimit L = cwcal::continuum_limit(kH, noise, 3000.0);
    assert_true(L.resolved);
    assert_false(L.richardson);
    assert_true(L.value == 1e-13);
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(recovers_order_and_limit),
        cmocka_unit_test(refuses_unclean_sequences),
        cmocka_unit_test(rounding_level_is_resolved),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
