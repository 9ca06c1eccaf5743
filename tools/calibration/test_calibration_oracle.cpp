// The search of `creepwork_calibration oracle` (calibration_oracle.hpp), on
// objectives whose minimum is known by hand: it must reach it, so that the
// per-case floors it reports are the knobs' best and not the search's
// shortfall (on these separable quadratics; on the real errors it is a
// local search, as doc/dev/calibration.md says).
#include <cmath>

#include "calibration_oracle.hpp"
#include "test_support.h"

namespace {

namespace cw = creepwork;

double squared_distance(const cw::CalibrationParams& p, const double target[8])
{
    const double v[8] = {p.k_long,   p.k_lat,          p.k_spin_x,  p.k_spin_y,
                         p.equalise, p.lateral_moment, p.edge_gain, p.bound_blend};
    double d = 0;
    for (int k = 0; k < 8; ++k) d += (v[k] - target[k]) * (v[k] - target[k]);
    return d;
}

// Targets on the search's lattice (start + multiples of the last step
// 0.0125; k_long and k_spin_x need that last step): reached to rounding,
// every knob but k_spin_y moved, some down.
void search_reaches_a_known_minimum(void**)
{
    const double target[8] = {1.3125, 0.7, 2.0375, 1.0, 0.4, 0.6, 1.1, 0.3};
    cw::CalibrationParams found;
    const double best = cwcal::search_knobs(
        [&](const cw::CalibrationParams& p) { return squared_distance(p, target); },
        cw::CalibrationParams{}, &found);
    assert_close(best, 0.0, 0.0, 1e-24);
    assert_close(found.k_long, 1.3125, 0.0, 1e-12);
    assert_close(found.k_lat, 0.7, 0.0, 1e-12);
    assert_close(found.k_spin_x, 2.0375, 0.0, 1e-12);
    assert_close(found.equalise, 0.4, 0.0, 1e-12);
    assert_close(found.lateral_moment, 0.6, 0.0, 1e-12);
    assert_close(found.edge_gain, 1.1, 0.0, 1e-12);
    assert_close(found.bound_blend, 0.3, 0.0, 1e-12);
}

// Minima outside the ranges: each knob stops at its range's end (k 5 and
// 0.2, equalise 1, lateral 0, edge -0.9, blend 1; then k_spin_x 0.2,
// k_spin_y 5, edge 5 and blend 0), never beyond.
void search_keeps_each_knob_in_range(void**)
{
    const double target[8] = {9.0, 0.01, 1.0, 1.0, 3.0, -2.0, -5.0, 4.0};
    cw::CalibrationParams found;
    cwcal::search_knobs([&](const cw::CalibrationParams& p) { return squared_distance(p, target); },
                        cw::CalibrationParams{}, &found);
    // At the range's end (to the rounding of the steps that led there),
    // never beyond it.
    const struct {
        double value, end, lo, hi;
    } checks[] = {{found.k_long, 5.0, 0.2, 5.0},          {found.k_lat, 0.2, 0.2, 5.0},
                  {found.equalise, 1.0, 0.0, 1.0},        {found.lateral_moment, 0.0, 0.0, 1.5},
                  {found.edge_gain, -0.9, -0.9, 5.0},     {found.bound_blend, 1.0, 0.0, 1.0}};
    for (const auto& c : checks) {
        assert_true(c.value >= c.lo && c.value <= c.hi);
        assert_close(c.value, c.end, 0.0, 1e-12);
    }

    // The other ends: a negative blend (the quartic side of the bound) is
    // not searched.
    const double other[8] = {1.0, 1.0, 0.01, 9.0, 0.5, 0.5, 9.0, -4.0};
    cwcal::search_knobs([&](const cw::CalibrationParams& p) { return squared_distance(p, other); },
                        cw::CalibrationParams{}, &found);
    const struct {
        double value, end, lo, hi;
    } ends[] = {{found.k_spin_x, 0.2, 0.2, 5.0},
                {found.k_spin_y, 5.0, 0.2, 5.0},
                {found.edge_gain, 5.0, -0.9, 5.0},
                {found.bound_blend, 0.0, 0.0, 1.0}};
    for (const auto& c : ends) {
        assert_true(c.value >= c.lo && c.value <= c.hi);
        assert_close(c.value, c.end, 0.0, 1e-12);
    }
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(search_reaches_a_known_minimum),
        cmocka_unit_test(search_keeps_each_knob_in_range),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
