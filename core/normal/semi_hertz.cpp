#include "normal/semi_hertz.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/error.hpp"
#include "contact/hertz.hpp"
#include "simd/kernel_isa.hpp"
#include "simd/simd.hpp"

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
    static constexpr int kBuckets = 2048;      // uniform in log r, for the search
    double log_r[kNodes], f[kNodes], w2[kNodes], K[kNodes];
    // Per start i0 of four nodes: 1 / prod_{b != a} (x_a - x_b).
    double inv_den[kNodes - 3][4];
    // The last node at or below bucket b's lower end (b = 0 .. kBuckets - 1).
    int bucket[kBuckets];
    double bucket_scale = 0;

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
        for (int i0 = 0; i0 + 3 < kNodes; ++i0)
            for (int a = 0; a < 4; ++a) {
                double den = 1.0;
                for (int b = 0; b < 4; ++b)
                    if (b != a) den *= log_r[i0 + a] - log_r[i0 + b];
                inv_den[i0][a] = 1.0 / den;
            }
        bucket_scale = kBuckets / log_r[kNodes - 1];
        for (int b = 0, i = 0; b < kBuckets; ++b) {
            while (i + 1 < kNodes && log_r[i + 1] * bucket_scale <= b) ++i;
            bucket[b] = i;
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
        // The last node at or below lr: from its bucket's, a few steps on.
        int i = bucket[std::min(static_cast<int>(lr * bucket_scale), kBuckets - 1)];
        while (i > 0 && log_r[i] > lr) --i; // (a bucket's end rounded)
        while (log_r[i + 1] <= lr) ++i;
        // Cubic Lagrange through the four nodes around lr (two at the ends).
        const int i0 = std::min(std::max(i - 1, 0), kNodes - 4);
        double w[4];
        for (int a = 0; a < 4; ++a) {
            w[a] = inv_den[i0][a];
            for (int b = 0; b < 4; ++b)
                if (b != a) w[a] *= lr - log_r[i0 + b];
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

constexpr double kFitDepth = 0.3;    // fit over elements penetrating > 30 % of the locus
constexpr double kWidenScale = 1.0 / (1.0 - kFitDepth);
constexpr int kMaxForceIterations = 100;

} // namespace

SemiHertz::SemiHertz(int nx, int ny)
    : nx_(nx), ny_(ny), rows_(ny > 0 ? ny : 0),
      roots_(nx > 0 && ny > 0 ? static_cast<size_t>(nx) * ny : 0), weights_(roots_.size()),
      list_local_(rows_.size()), list_c_(rows_.size()), list_p_factor_(rows_.size()),
      list_both_(rows_.size()), list_M_(rows_.size()), list_offset_(rows_.size())
{
    if (nx < 3 || ny < 3)
        throw Error(ErrorKind::grid_out_of_range, "the semi-Hertzian normal method needs at "
                                                  "least 3 x 3 cells");
    shape_table();
}

SemiHertz::FitMoments::FitMoments()
{
    double M0 = 1.0, M2 = 0.0, M4 = 0.0;
    m0[0] = m2[0] = inv_den[0] = 0.0;
    for (int k = 1; k <= kMaxFitHalfWidth; ++k) {
        const double k2 = double(k) * k;
        M0 += 2.0;
        M2 += 2.0 * k2;
        M4 += 2.0 * k2 * k2;
        m0[k] = M0;
        m2[k] = M2;
        inv_den[k] = 1.0 / (M0 * M4 - M2 * M2);
    }
}

int SemiHertz::shape_change(int j, double d)
{
    Row& R = rows_[j];
    // The fit's half-width: as long as the next pair still penetrates by
    // more than kFitDepth of the locus (CONTACT's rule), walked from the
    // last depth's (the depths of an iteration lie close together).
    const bool in = d > R.g; // the row penetrates
    int k = R.shape_k < 1 ? 1 : R.shape_k;
    while (k < kMaxFitHalfWidth && in && d >= R.widen[k]) ++k;
    while (k > 1 && !(in && d >= R.widen[k - 1])) --k;
    if (k != R.shape_k) {
        if (!(R.known & (1u << k))) {
            const double A = std::max(R.A[k], kMinCurvature), B = R.B;
            const double small = std::min(A, B), big = std::max(A, B);
            double f, w2, K;
            shape_table().at(big / small, f, w2, K);
            // alpha = d/(A a^2), beta = d/(B b^2); the major axis lies along
            // the smaller curvature. (Few divisions, and none waiting on
            // another: a row's shape is a chain of roots and divisions.)
            const double across = f * small / (big * w2);
            const double alpha = A <= B ? f : across;
            R.beta_k[k] = A <= B ? across : f;
            R.p_factor_k[k] = E_star_ * std::sqrt(small * f / (w2 * K * K));
            R.c_k[k] = alpha * A * dx_ * dx_;
            R.inv_c_k[k] = 1.0 / R.c_k[k];
            // The semi-ellipse p_factor sqrt(local - alpha A x^2) over x:
            // pi/2 p_factor local / sqrt(alpha A), times dy (sqrt(alpha A)
            // = sqrt(c) / dx).
            R.slope_k[k] = 1.57079632679489661923 * R.p_factor_k[k] * dy_ * dx_ *
                           std::sqrt(R.inv_c_k[k]);
            R.known |= 1u << k;
        }
        R.beta = R.beta_k[k];
        R.p_factor = R.p_factor_k[k];
        R.c = R.c_k[k];
        R.inv_c = R.inv_c_k[k];
        R.shape_k = k;
    }
    return k;
}

namespace {

// The rows' semi-ellipses packed and summed: for each listed row r, the
// roots' arguments local - c m^2 at m = 0 .. M (M + 1 values from
// offset[r]), each weighted by the row's pressure factor times the number
// of its elements (two for 1 <= m <= both, the |m| on both sides of the
// locus; one otherwise); then the roots sqrt(max(v, 0)) in place and their
// weighted sum, in eight partial sums, in one long loop over all rows (a
// row has a few dozen elements: its own roots would leave the vector unit
// waiting). A kernel of simd/kernel_isa.hpp, so that the solver's ISA
// picks the copy (W itself is unused, the compiler vectorises the loops
// for the copy's ISA), bitwise the same result in every copy (each value,
// root and partial sum the same operations in the same order). Not a
// target_clones function: its load-time resolver runs before a sanitizer's
// runtime is ready (ThreadSanitizer faults in it).
struct PackedRows {
    const double *local, *c, *p_factor;
    const int *both, *M, *offset;
    int rows = 0;
};
struct WeightedRoots : KernelWidths {
    template <int W>
    CREEPWORK_INLINE static void run(const PackedRows& rows, double* const& v, double* const& w,
                                     double* const& sum)
    {
        for (int r = 0; r < rows.rows; ++r) {
            double* vr = v + rows.offset[r];
            double* wr = w + rows.offset[r];
            const double local = rows.local[r], c = rows.c[r], pf = rows.p_factor[r];
            const double two = 2.0 * pf;
            const int both = rows.both[r], M = rows.M[r];
            for (int m = 0; m <= M; ++m) {
                const double mm = m;
                vr[m] = local - c * mm * mm;
                wr[m] = m >= 1 && m <= both ? two : pf;
            }
        }
        const int n = rows.rows > 0 ? rows.offset[rows.rows - 1] + rows.M[rows.rows - 1] + 1 : 0;
        for (int e = 0; e < n; ++e) v[e] = std::sqrt(std::max(v[e], 0.0));
        double s[8] = {};
        int e = 0;
        for (; e + 7 < n; e += 8)
            for (int l = 0; l < 8; ++l) s[l] += w[e + l] * v[e + l];
        for (; e < n; ++e) s[0] += w[e] * v[e];
        *sum = ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7]));
    }
};

// A row's lowest value and the index of its first occurrence: W lanes,
// each its own first lowest element by selects (no branch to mispredict
// where the row turns), then the lowest of the lanes', the first of equals.
// The answer does not depend on W. A kernel of simd/kernel_isa.hpp.
struct RowMinimum : KernelWidths {
    template <int W>
    CREEPWORK_INLINE static void run(const double* const& row, const int& n, double* const& lowest,
                                     int* const& at)
    {
        using V = simd::Vec<W>;
        V m = simd::broadcast<W>(row[0]), index{}, lane{};
        for (int l = 0; l < W; ++l) lane[l] = l;
        int i = 0;
        for (; i + W <= n; i += W) {
            const V v = simd::load<W>(row + i);
            const auto lower = v < m;
            index = lower ? lane + double(i) : index;
            m = lower ? v : m;
        }
        double best = m[0], first = index[0];
        for (int l = 1; l < W; ++l)
            if (m[l] < best || (m[l] == best && index[l] < first)) best = m[l], first = index[l];
        for (; i < n; ++i)
            if (row[i] < best) best = row[i], first = i;
        *lowest = best;
        *at = static_cast<int>(first);
    }
};

} // namespace

double SemiHertz::force_at(double d)
{
    // Per row its elements in contact, lo .. hi, and the semi-ellipse
    // p = p_factor sqrt(local - c m^2) on them (Hertz's p0 sqrt(1 - (x /
    // a)^2) with p0 = p_factor sqrt(local), a^2 = local / c; m = i - locus):
    // the roots' arguments packed, once per |m| (the value at -m is the one
    // at m, bitwise) on the side of the locus with more elements, each
    // weighted by p_factor and the number of its elements (1 or 2).
    // First each row's contact elements (the rows independent, so that
    // their divisions and roots overlap), then the packing.
    for (int j = 0; j < ny_; ++j) {
        Row& R = rows_[j];
        shape_at(j, d);
        const double local = d - R.beta * R.g;
        const double half = std::sqrt(std::max(local, 0.0) * R.inv_c); // in elements
        R.local = local;
        R.lo = local > 0.0 ? std::max(0, static_cast<int>(std::ceil(R.locus - half))) : 0;
        R.hi = local > 0.0 ? std::min(nx_ - 1, static_cast<int>(std::floor(R.locus + half))) : -1;
    }
    // The rows in contact, listed for the kernel.
    int n = 0, listed = 0;
    for (int j = 0; j < ny_; ++j) {
        Row& R = rows_[j];
        R.packed = n;
        if (R.hi < R.lo) continue;
        const int M = std::max(R.locus - R.lo, R.hi - R.locus);
        list_local_[listed] = R.local;
        list_c_[listed] = R.c;
        list_p_factor_[listed] = R.p_factor;
        list_both_[listed] = std::min(R.locus - R.lo, R.hi - R.locus); // |m| on both sides
        list_M_[listed] = M;
        list_offset_[listed] = n;
        ++listed;
        n += M + 1;
    }
    const PackedRows rows{list_local_.data(), list_c_.data(),  list_p_factor_.data(),
                          list_both_.data(),  list_M_.data(), list_offset_.data(), listed};
    double sum = 0.0;
    run_kernel<WeightedRoots>(isa_, rows, roots_.data(), weights_.data(), &sum);
    return sum * dx_ * dy_;
}

int SemiHertz::write_pressure(double scale, double* out)
{
    int n_contact = 0;
    for (int j = 0; j < ny_; ++j) {
        Row& R = rows_[j];
        R.written_lo = R.lo;
        R.written_hi = R.hi;
        if (R.hi < R.lo) continue;
        double* p = out + static_cast<size_t>(nx_) * j;
        const double* r = roots_.data() + R.packed; // r[|i - locus|]
        for (int i = R.lo; i < R.locus; ++i) {
            p[i] = R.p_factor * r[R.locus - i] * scale;
            n_contact += p[i] > 0.0;
        }
        for (int i = std::max(R.lo, R.locus); i <= R.hi; ++i) {
            p[i] = R.p_factor * r[i - R.locus] * scale;
            n_contact += p[i] > 0.0;
        }
    }
    return n_contact;
}

double SemiHertz::continuous_depth(double N)
{
    // Per row with local = d - beta g > 0 the semi-ellipse's force
    // slope_k local: convex and piecewise linear in d. Newton's steps from
    // Hertz's circle on the lowest row's curvature (from below they overshoot
    // once, from above they decrease to the root); the fit's half-widths
    // follow the depth.
    double A0 = kMinCurvature;
    for (const Row& R : rows_)
        if (R.g == 0.0) A0 = std::max(A0, std::max(R.A[1], kMinCurvature));
    double d = std::cbrt(9.0 * N * N * A0 / (16.0 * E_star_ * E_star_)) * std::cbrt(2.0);
    for (int it = 0; it < 20; ++it) {
        double F = 0.0, slope = 0.0;
        for (int j = 0; j < ny_; ++j) {
            const int k = shape_at(j, d);
            const Row& R = rows_[j];
            const double local = d - R.beta * R.g;
            if (!(local > 0.0)) continue;
            F += R.slope_k[k] * local;
            slope += R.slope_k[k];
        }
        continuous_slope_ = slope;
        if (!(slope > 0.0)) { // no row in contact yet: deeper
            d *= 2.0;
            continue;
        }
        const double next = d - (F - N) / slope;
        if (!(next > 0.0)) return d;
        if (std::fabs(next - d) <= 1e-12 * d) return next;
        d = next;
    }
    return d;
}

SemiHertzResult SemiHertz::solve(const double* h, double dx, double dy, double E_star,
                                 bool force, double value, double* pressure,
                                 bool zero_outside_extents)
{
    // Zeros where the pressure may be nonzero: the last solve's extents, or
    // everywhere.
    if (zero_outside_extents)
        for (int j = 0; j < ny_; ++j) {
            const Row& R = rows_[j];
            double* p = pressure + static_cast<size_t>(nx_) * j;
            if (R.written_hi >= R.written_lo) std::fill(p + R.written_lo, p + R.written_hi + 1, 0.0);
        }
    else
        std::fill(pressure, pressure + static_cast<size_t>(nx_) * ny_, 0.0);
    dx_ = dx;
    dy_ = dy;
    E_star_ = E_star;
    fit_rows(h);

    SemiHertzResult res;
    double d = 0.0, F = 0.0;
    if (!force) {
        d = value - h_min_;
        F = force_at(d);
    } else {
        res.iterations = depth_for_force(value, d, F);
    }
    const double scale = force && F > 0.0 ? value / F : 1.0;
    res.n_contact = write_pressure(scale, pressure);
    res.normal_force = F * scale;
    res.approach = d + h_min_;
    if (force && !(F > 0.0))
        throw Error(ErrorKind::not_converged,
                    "the semi-Hertzian normal method found no contact for the normal force");
    return res;
}

// The rows' loci, heights and curvatures, and the depths at which their
// fits widen, for the gap h (dx_, dy_ set).
void SemiHertz::fit_rows(const double* h)
{
    const double dx = dx_, dy = dy_;
    // Each row's lowest element (the first of equals), then the gap's.
    h_min_ = h[0];
    for (int j = 0; j < ny_; ++j) {
        double lowest = 0.0;
        int at = 0;
        run_kernel<RowMinimum>(isa_, h + static_cast<size_t>(nx_) * j, nx_, &lowest, &at);
        rows_[j].locus = at;
        h_min_ = std::min(h_min_, lowest);
    }
    // Per row: the locus, its height, the curvature across and the
    // least-squares curvature along x for each half-width k (the parabola
    // c0 + c1 t + c2 t^2 over t = -k..k: c2 from the even moments).
    const double inv_dx2 = 1.0 / (dx * dx);
    for (int j = 0; j < ny_; ++j) {
        Row& R = rows_[j];
        const double* row = h + static_cast<size_t>(nx_) * j;
        R.locus = std::min(std::max(R.locus, 1), nx_ - 2);
        R.g = row[R.locus] - h_min_;
        const int jm = j == 0 ? 0 : j == ny_ - 1 ? ny_ - 3 : j - 1; // three rows from jm
        const double* r0 = h + static_cast<size_t>(nx_) * jm;
        R.B = std::max(0.5 * (r0[R.locus] - 2.0 * r0[R.locus + nx_] + r0[R.locus + 2 * nx_]) /
                           (dy * dy),
                       kMinCurvature);
        double s0 = row[R.locus], s2 = 0.0;
        for (int k = 1; k <= kMaxFitHalfWidth; ++k) {
            const int l = std::max(R.locus - k, 0), r = std::min(R.locus + k, nx_ - 1);
            const double k2 = double(k) * k;
            s0 += row[l] + row[r];
            s2 += k2 * (row[l] + row[r]);
            R.A[k] = (fit_.m0[k] * s2 - fit_.m2[k] * s0) * fit_.inv_den[k] * inv_dx2;
        }
        // pair[k] - d <= kFitDepth (g - d) where d >= (pair[k] - kFitDepth g)
        // / (1 - kFitDepth).
        double widen = -std::numeric_limits<double>::infinity();
        for (int k = 1; k < kMaxFitHalfWidth; ++k) {
            // The higher of the pair's heights above the gap's lowest element.
            const double pair = R.locus - k - 1 >= 0 && R.locus + k + 1 < nx_
                                    ? std::max(row[R.locus - k - 1], row[R.locus + k + 1]) - h_min_
                                    : std::numeric_limits<double>::infinity();
            widen = std::max(widen, (pair - kFitDepth * R.g) * kWidenScale);
            R.widen[k] = widen;
        }
        R.known = 0;
        R.shape_k = -1;
        R.written_lo = 0;
        R.written_hi = -1;
    }

}

// The depth d that carries the normal force N, and the force F there (the
// last evaluation's, whose pressures write_pressure writes); returns the
// force evaluations.
int SemiHertz::depth_for_force(double N, double& d, double& F)
{
    // Bracket [lo, hi] with F(lo) < N <= F(hi); log d interpolated in
    // log F (F grows like d^(3/2) for a Hertzian gap): a secant step
    // from two evaluations, an inverse quadratic one from three;
    // bisection in log d when a step leaves the bracket.
    double lo = 0.0, hi = 0.0;
    // First guess: the depth of the continuous semi-ellipses' force.
    d = continuous_depth(N);
    double d_prev = 0.0, f_prev = 0.0, d_prev2 = 0.0, f_prev2 = 0.0;
    // The last evaluation is the answer (write_pressure after the loop).
    int iterations = 1;
    for (; iterations <= kMaxForceIterations; ++iterations) {
        F = force_at(d);
        (F < N ? lo : hi) = d;
        if (std::fabs(F - N) <= 1e-13 * N || (hi > 0.0 && hi - lo <= 1e-15 * hi)) break;
        double next;
        if (F > 0.0 && f_prev > 0.0 && f_prev2 > 0.0 && F != f_prev && F != f_prev2 &&
            f_prev != f_prev2) {
            // Inverse quadratic interpolation of log d in log F through
            // the last three evaluations.
            const double y0 = std::log(F), y1 = std::log(f_prev), y2 = std::log(f_prev2);
            const double Y = std::log(N);
            next = std::exp(std::log(d) * (Y - y1) * (Y - y2) / ((y0 - y1) * (y0 - y2)) +
                            std::log(d_prev) * (Y - y0) * (Y - y2) / ((y1 - y0) * (y1 - y2)) +
                            std::log(d_prev2) * (Y - y0) * (Y - y1) / ((y2 - y0) * (y2 - y1)));
        } else if (F > 0.0 && f_prev > 0.0 && d != d_prev)
            next = std::exp(std::log(d) + (std::log(N) - std::log(F)) *
                                              (std::log(d) - std::log(d_prev)) /
                                              (std::log(F) - std::log(f_prev)));
        else if (F > 0.0 && iterations == 1)
            // The discrete force as the continuous one times F / N:
            // Newton's step on that.
            next = d + N * (N / F - 1.0) / continuous_slope_;
        else
            next = F > 0.0 ? d * std::pow(N / F, 2.0 / 3.0) : 2.0 * d;
        if (hi == 0.0) {
            next = std::max(next, (1.0 + 1e-6) * d); // still below N: grow
        } else if (!(next > lo && next < hi)) {
            next = lo > 0.0 ? std::sqrt(lo * hi) : 0.5 * hi;
        }
        d_prev2 = d_prev;
        f_prev2 = f_prev;
        d_prev = d;
        f_prev = F;
        d = next;
    }
    // Where the force jumps past N (the fit widening at a row), the
    // bracket closes on the jump: the answer is its upper end, whatever
    // side the iteration ended on.
    if (iterations > kMaxForceIterations ||
        (F < N && std::fabs(F - N) > 1e-13 * N && hi > 0.0)) {
        d = hi > 0.0 ? hi : d;
        F = force_at(d);
    }
    return iterations;
}

} // namespace creepwork
