#include "nonhertz/semi_hertz.hpp"

#include <algorithm>
#include <cmath>

#include "contact/error.hpp"
#include "contact/hertz.hpp"

namespace creepwork {
namespace {

// Hertz's ellipse as a function of the ratio r >= 1 of the larger to the
// smaller gap curvature kappa (Johnson 1985, eqs. 4.38-4.39), tabulated by
// the log of the semi-axis ratio s = log(major / minor): e^2 = 1 - exp(-2 s)
// and, with K, E the complete elliptic integrals of modulus e,
//   r        = (e^2 K - (K - E)) / ((1 - e^2) (K - E))
//   f        = e^2 K / (K - E) = d / (kappa c^2)   (c: the major semi-axis)
//   1 - e^2  = (minor / major)^2
//   p0       = d E* / (minor K).
// Built once (immutable afterwards); cubic in log r between nodes (the
// pressure's relative error is below 1e-8 with these nodes; linear
// interpolation left 1e-5).
struct ShapeTable {
    static constexpr int kNodes = 1025;
    static constexpr double kMaxLogAxes = 7.0; // major / minor up to 1100
    double log_r[kNodes], f[kNodes], w2[kNodes], K[kNodes];

    ShapeTable()
    {
        for (int i = 0; i < kNodes; ++i) {
            const double s = kMaxLogAxes * i / (kNodes - 1);
            const double m = -std::expm1(-2.0 * s);
            if (i == 0) {
                log_r[i] = 0.0;
                f[i] = 2.0;
                w2[i] = 1.0;
                K[i] = 0.5 * 3.14159265358979323846;
                continue;
            }
            const EllipticIntegrals e = complete_elliptic_integrals(std::sqrt(m));
            log_r[i] = std::log((m * e.K - e.K_minus_E) / ((1.0 - m) * e.K_minus_E));
            f[i] = m * e.K / e.K_minus_E;
            w2[i] = std::exp(-2.0 * s);
            K[i] = e.K;
        }
    }
    // (f, w2, K) at curvature ratio r >= 1 (clamped to the table).
    void at(double r, double& fr, double& w2r, double& Kr) const
    {
        const double lr = std::log(r);
        if (!(lr > 0.0)) {
            fr = f[0], w2r = w2[0], Kr = K[0];
            return;
        }
        if (lr >= log_r[kNodes - 1]) {
            fr = f[kNodes - 1], w2r = w2[kNodes - 1], Kr = K[kNodes - 1];
            return;
        }
        // Cubic Lagrange through the four nodes around lr (two at the ends).
        const int i = static_cast<int>(std::upper_bound(log_r, log_r + kNodes, lr) - log_r) - 1;
        const int i0 = std::min(std::max(i - 1, 0), kNodes - 4);
        double w[4];
        for (int a = 0; a < 4; ++a) {
            w[a] = 1.0;
            for (int b = 0; b < 4; ++b)
                if (b != a) w[a] *= (lr - log_r[i0 + b]) / (log_r[i0 + a] - log_r[i0 + b]);
        }
        fr = w2r = Kr = 0.0;
        for (int a = 0; a < 4; ++a) {
            fr += w[a] * f[i0 + a];
            w2r += w[a] * w2[i0 + a];
            Kr += w[a] * K[i0 + a];
        }
    }
};

const ShapeTable& shape_table()
{
    static const ShapeTable table;
    return table;
}

constexpr int kMaxFitHalfWidth = 10; // elements on each side of the locus
constexpr double kFitDepth = 0.3;    // fit over elements penetrating > 30 % of the locus
constexpr int kMaxForceIterations = 100;

} // namespace

SemiHertz::SemiHertz(int nx, int ny) : nx_(nx), ny_(ny), rows_(ny)
{
    if (nx < 3 || ny < 3)
        throw Error(ErrorKind::grid_out_of_range, "the semi-Hertzian normal method needs at "
                                                  "least 3 x 3 cells");
    shape_table();
}

double SemiHertz::force_at(double d, double* out)
{
    const ShapeTable& T = shape_table();
    double force = 0.0;
    for (int j = 0; j < ny_; ++j) {
        Row& R = rows_[j];
        const double* h = h_ + static_cast<size_t>(nx_) * j;
        double* p = out ? out + static_cast<size_t>(nx_) * j : nullptr;
        if (p) std::fill(p, p + nx_, 0.0);
        const double top = h[R.locus] - h_min_ - d; // < 0 where the row penetrates
        // The fit's half-width: as long as the next pair still penetrates by
        // more than kFitDepth of the locus (CONTACT's rule).
        int k = 1;
        while (k < kMaxFitHalfWidth && R.locus - k - 1 >= 0 && R.locus + k + 1 < nx_ &&
               top < 0.0 &&
               std::max(h[R.locus - k - 1], h[R.locus + k + 1]) - h_min_ - d <= kFitDepth * top)
            ++k;
        if (k != R.shape_k) {
            const double A = std::max(R.A[k], kMinCurvature), B = R.B;
            const double small = std::min(A, B);
            double f, w2, K;
            T.at(std::max(A, B) / small, f, w2, K);
            // alpha = d/(A a^2), beta = d/(B b^2); the major axis lies along
            // the smaller curvature.
            const double across = f / (std::max(A, B) / small * w2);
            R.alpha = A <= B ? f : across;
            R.beta = A <= B ? across : f;
            R.p_factor = E_star_ * std::sqrt(small * f / w2) / K;
            R.shape_k = k;
        }
        const double local = d - R.beta * R.g;
        if (!(local > 0.0)) continue;
        const double A = std::max(R.A[k], kMinCurvature);
        const double half = std::sqrt(local / (R.alpha * A)) / dx_; // in elements
        const double p0 = R.p_factor * std::sqrt(local);
        const int lo = std::max(0, static_cast<int>(std::ceil(R.locus - half)));
        const int hi = std::min(nx_ - 1, static_cast<int>(std::floor(R.locus + half)));
        double row = 0.0;
        for (int i = lo; i <= hi; ++i) {
            const double t = (i - R.locus) / half;
            const double v = 1.0 - t * t;
            if (!(v > 0.0)) continue;
            const double pi = p0 * std::sqrt(v);
            row += pi;
            if (p) p[i] = pi;
        }
        force += row;
    }
    return force * dx_ * dy_;
}

SemiHertzResult SemiHertz::solve(const double* h, double dx, double dy, double E_star,
                                 bool force, double value, double* pressure)
{
    h_ = h;
    dx_ = dx;
    dy_ = dy;
    E_star_ = E_star;
    const int n = nx_ * ny_;
    h_min_ = *std::min_element(h, h + n);

    // Per row: the locus, its height, the curvature across and the
    // least-squares curvature along x for each half-width k (the parabola
    // c0 + c1 t + c2 t^2 over t = -k..k: c2 from the even moments).
    for (int j = 0; j < ny_; ++j) {
        Row& R = rows_[j];
        const double* row = h + static_cast<size_t>(nx_) * j;
        const int lowest = static_cast<int>(std::min_element(row, row + nx_) - row);
        R.locus = std::min(std::max(lowest, 1), nx_ - 2);
        R.g = row[R.locus] - h_min_;
        const int jm = j == 0 ? 0 : j == ny_ - 1 ? ny_ - 3 : j - 1; // three rows from jm
        const double* r0 = h + static_cast<size_t>(nx_) * jm;
        R.B = std::max(0.5 * (r0[R.locus] - 2.0 * r0[R.locus + nx_] + r0[R.locus + 2 * nx_]) /
                           (dy * dy),
                       kMinCurvature);
        double s0 = row[R.locus], s2 = 0.0, m0 = 1.0, m2 = 0.0, m4 = 0.0;
        for (int k = 1; k <= kMaxFitHalfWidth; ++k) {
            const int l = std::max(R.locus - k, 0), r = std::min(R.locus + k, nx_ - 1);
            const double k2 = double(k) * k;
            s0 += row[l] + row[r];
            s2 += k2 * (row[l] + row[r]);
            m0 += 2.0;
            m2 += 2.0 * k2;
            m4 += 2.0 * k2 * k2;
            R.A[k] = (m0 * s2 - m2 * s0) / ((m0 * m4 - m2 * m2) * dx * dx);
        }
        R.shape_k = -1;
    }

    SemiHertzResult res;
    double d = 0.0;
    if (!force) {
        d = value - h_min_;
    } else {
        // Bracket [lo, hi] with F(lo) < N <= F(hi); secant steps on log F
        // against log d (F grows like d^(3/2) for a Hertzian gap), bisection
        // in log d when a step leaves the bracket.
        const double N = value;
        double lo = 0.0, hi = 0.0;
        // First guess: Hertz's circle on the lowest row's curvature.
        double A0 = kMinCurvature;
        for (const Row& R : rows_)
            if (R.g == 0.0) A0 = std::max(A0, std::max(R.A[1], kMinCurvature));
        d = std::cbrt(9.0 * N * N * A0 / (16.0 * E_star * E_star)) * std::cbrt(2.0);
        double d_prev = 0.0, f_prev = 0.0;
        for (res.iterations = 1; res.iterations <= kMaxForceIterations; ++res.iterations) {
            const double F = force_at(d, nullptr);
            (F < N ? lo : hi) = d;
            if (std::fabs(F - N) <= 1e-13 * N || (hi > 0.0 && hi - lo <= 1e-15 * hi)) break;
            double next;
            if (F > 0.0 && f_prev > 0.0 && d != d_prev)
                next = std::exp(std::log(d) + (std::log(N) - std::log(F)) *
                                                  (std::log(d) - std::log(d_prev)) /
                                                  (std::log(F) - std::log(f_prev)));
            else
                next = F > 0.0 ? d * std::pow(N / F, 2.0 / 3.0) : 2.0 * d;
            if (hi == 0.0) {
                next = std::max(next, 1.1 * d); // still below N: grow
            } else if (!(next > lo && next < hi)) {
                next = lo > 0.0 ? std::sqrt(lo * hi) : 0.5 * hi;
            }
            d_prev = d;
            f_prev = F;
            d = next;
        }
    }
    const double F = force_at(d, pressure);
    const double scale = force && F > 0.0 ? value / F : 1.0;
    for (int k = 0; k < n; ++k) {
        pressure[k] *= scale;
        res.n_contact += pressure[k] > 0.0;
    }
    res.normal_force = F * scale;
    res.approach = d + h_min_;
    if (force && !(F > 0.0))
        throw Error(ErrorKind::not_converged,
                    "the semi-Hertzian normal method found no contact for the normal force");
    return res;
}

} // namespace creepwork
