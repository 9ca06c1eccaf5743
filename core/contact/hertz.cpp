#include "contact/hertz.hpp"

#include <cmath>

#include "contact/fp_safe.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;

// sum_{n>=1} 2^(n-1) c_n^2 of the AGM started at (1, k') with c_0 = k:
// E = K (1 - k^2/2 - tail), so K - E = K (k^2/2 + tail) has no cancellation.
struct AgmResult {
    double K;
    double tail;
};

AgmResult agm(double k)
{
    double an = 1.0;
    double bn = std::sqrt((1.0 - k) * (1.0 + k));
    double tail = 0.0;
    double weight = 1.0;  // 2^(n-1) for c_n, n = 1, 2, ...
    for (int n = 1; n < 60; ++n) {
        const double c = 0.5 * (an - bn);
        // Converged to rounding: a and b may stall one ulp apart, and the
        // doubling weight must not keep adding that ulp.
        if (c <= 4.0 * 2.220446049250313e-16 * an) break;
        tail += weight * c * c;
        weight *= 2.0;
        const double a_next = 0.5 * (an + bn);
        bn = std::sqrt(an * bn);
        an = a_next;
    }
    return {kPi / (2.0 * an), tail};
}

// Ratio of the larger to the smaller relative curvature for an ellipse of
// eccentricity e = k (Johnson eq. 4.39): ((a/b)^2 E - K) / (K - E).
double curvature_ratio(double k)
{
    if (k == 0.0) return 1.0;
    const AgmResult r = agm(k);
    const double m = k * k;
    return (0.5 * m - r.tail) / ((1.0 - m) * (0.5 * m + r.tail));
}

} // namespace

EllipticIntegrals complete_elliptic_integrals(double k)
{
    const AgmResult r = agm(k);
    const double k_minus_e = r.K * (0.5 * k * k + r.tail);
    return {r.K, r.K - k_minus_e, k_minus_e};
}

HertzContact hertz_from_curvatures(double A, double B, double N, double E_star)
{
    const double small = A < B ? A : B;
    const double ratio = (A < B ? B : A) / small;

    // The ratio grows monotonically with the eccentricity: bisection in k.
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 200 && ratio > 1.0; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        (curvature_ratio(mid) < ratio ? lo : hi) = mid;
    }
    const double k = ratio > 1.0 ? 0.5 * (lo + hi) : 0.0;
    const EllipticIntegrals ell = complete_elliptic_integrals(k);

    // Johnson eq. 4.38: small = (p0/E*) (b/(e^2 a^2)) (K - E), p0 = 3N/(2 pi a b);
    // for e -> 0, (K - E)/e^2 -> pi/4.
    const double k_minus_e_over_m = k > 0.0 ? quotient_or_zero(ell.K_minus_E, k * k) : 0.25 * kPi;
    const double major = std::cbrt(3.0 * N * k_minus_e_over_m / (2.0 * kPi * E_star * small));
    const double minor = major * std::sqrt((1.0 - k) * (1.0 + k));

    HertzContact h{};
    h.a = A <= B ? major : minor;
    h.b = A <= B ? minor : major;
    h.p0 = quotient_if_positive(3.0 * N, 2.0 * kPi * major * minor);
    h.approach = h.p0 * minor * ell.K / E_star;
    return h;
}

HertzCurvatures hertz_from_semi_axes(double a, double b, double N, double E_star)
{
    // Johnson eqs. 4.38-4.39 with e^2 = 1 - (small/big)^2: with
    // c = p0 small/(E* e^2 big^2), the curvature along the major axis is
    // c (K - E) and along the minor axis c ((big/small)^2 E - K); for e -> 0
    // both tend to p0 pi/(4 E* a).
    const double big = a > b ? a : b, small = a > b ? b : a;
    const double k = std::sqrt((1.0 - small / big) * (1.0 + small / big));
    const EllipticIntegrals ell = complete_elliptic_integrals(k);
    HertzCurvatures h{};
    h.p0 = 3.0 * N / (2.0 * kPi * a * b);
    double along_major, along_minor;
    if (k > 0.0) {
        const double c = quotient_or_zero(h.p0 * small, E_star * k * k * big * big);
        along_major = c * ell.K_minus_E;
        along_minor = c * ((big / small) * (big / small) * ell.E - ell.K);
    } else {
        along_major = along_minor = h.p0 * kPi / (4.0 * E_star * a);
    }
    h.A = a >= b ? along_major : along_minor;
    h.B = a >= b ? along_minor : along_major;
    h.approach = h.p0 * small * ell.K / E_star;
    return h;
}

} // namespace creepwork
