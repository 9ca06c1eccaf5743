#include "wear/wear_law.hpp"

#include <algorithm>
#include <cmath>

#include "contact/contact_input.hpp"

namespace creepwork::wear {

namespace {

// Coefficients are bounded far beyond any steel pair so that no product in
// the map can overflow (rates stay below ~1e12 kg/m^3 for work densities up
// to 1e18 Pa), and no input is a subnormal number a trapping host would
// trip on.
constexpr double kMaxCoefficient = 1e6;

void require_coefficient(const char* name, double v)
{
    require_non_negative(name, v);
    if (v > kMaxCoefficient) reject_input(name, v, "must be <= 1e6 (SI units, doc/theory/wear.md)");
}

} // namespace

void validate(const WearLaw& w)
{
    if (w.law != Law::usfd && w.law != Law::archard_kth)
        reject_input("law", static_cast<double>(w.law), "unknown wear law");
    if (w.source != Source::consistent && w.source != Source::paper && w.source != Source::slip)
        reject_input("source", static_cast<double>(w.source), "unknown work source");
    require_positive("density", w.density);
    if (w.density < 1.0 || w.density > 1e5)
        reject_input("density", w.density, "must lie in [1, 1e5] kg/m^3");
    require_positive("pass_length", w.pass_length);
    if (w.pass_length > 1e6) reject_input("pass_length", w.pass_length, "must be <= 1e6 m");
    if (w.law == Law::usfd) {
        require_coefficient("usfd_k1", w.usfd.k1);
        require_coefficient("usfd_k2", w.usfd.k2);
        require_coefficient("usfd_k3", w.usfd.k3);
        require_coefficient("usfd_c3", w.usfd.c3);
        require_positive("usfd_t1", w.usfd.t1);
        require_positive("usfd_t2", w.usfd.t2);
        if (w.usfd.t1 > 1e12) reject_input("usfd_t1", w.usfd.t1, "must be <= 1e12 Pa");
        if (w.usfd.t2 > 1e12) reject_input("usfd_t2", w.usfd.t2, "must be <= 1e12 Pa");
        if (!(w.usfd.t2 >= w.usfd.t1))
            reject_input("usfd_t2", w.usfd.t2, "must be >= usfd_t1");
        require_non_negative("rolling_speed", w.rolling_speed);
    } else {
        require_positive("rolling_speed", w.rolling_speed);
        if (w.rolling_speed > 1e3)
            reject_input("rolling_speed", w.rolling_speed, "must be <= 1e3 m/s");
        require_positive("hardness", w.kth.hardness);
        if (w.kth.hardness < 1e6 || w.kth.hardness > 1e12)
            reject_input("hardness", w.kth.hardness, "must lie in [1e6, 1e12] Pa");
        require_non_negative("kth_v1", w.kth.v1);
        require_non_negative("kth_v2", w.kth.v2);
        if (w.kth.v2 > 1e3) reject_input("kth_v2", w.kth.v2, "must be <= 1e3 m/s");
        if (!(w.kth.v2 >= w.kth.v1)) reject_input("kth_v2", w.kth.v2, "must be >= kth_v1");
        require_positive("kth_seizure_ratio", w.kth.seizure_ratio);
        if (w.kth.seizure_ratio > 1e3)
            reject_input("kth_seizure_ratio", w.kth.seizure_ratio, "must be <= 1e3");
        require_coefficient("kth_k_seizure", w.kth.k_seizure);
        require_coefficient("kth_k_slow", w.kth.k_slow);
        require_coefficient("kth_k_severe", w.kth.k_severe);
        require_coefficient("kth_k_fast", w.kth.k_fast);
    }
}

} // namespace creepwork::wear
