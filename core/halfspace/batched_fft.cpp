#include "halfspace/batched_fft.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "simd/kernel_isa.hpp"
#include "simd/simd.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One butterfly of a Stockham stage on the values t ... t + lanes - 1 of each
// run (lanes: 1 for V = double, W for V = simd::Vec<W>): the same
// operations on every lane, so a vector gives each lane the bits of the
// scalar butterfly. Sign = -1 forward, +1 inverse. K < R: the inputs k >= K
// are the constant 0.0 (zero inputs not read); J < R: only the outputs
// j < J are stored (stage()).
template <class V, int R, int Sign, int K, int J>
CREEPWORK_INLINE void butterfly(const double* const* ar, const double* const* ai,
                                double* const* br, double* const* bi, const double* wr,
                                const double* wi, bool twiddled, size_t t)
{
    constexpr double sg = Sign;
    V vr[R], vi[R]; // the inputs, the zero ones as constants
    for (int k = 0; k < R; ++k) {
        vr[k] = k < K ? simd::load_as<V>(ar[k] + t) : V{} + 0.0;
        vi[k] = k < K ? simd::load_as<V>(ai[k] + t) : V{} + 0.0;
    }
    V ur[R], ui[R];
    if constexpr (R == 2) {
        ur[0] = vr[0] + vr[1];
        ui[0] = vi[0] + vi[1];
        ur[1] = vr[0] - vr[1];
        ui[1] = vi[0] - vi[1];
    } else if constexpr (R == 3) {
        constexpr double h = 0.86602540378443864676; // sin(2 pi/3)
        const V t1r = vr[1] + vr[2], t1i = vi[1] + vi[2];
        const V t2r = vr[0] - 0.5 * t1r, t2i = vi[0] - 0.5 * t1i;
        // Sign * i * h (a1 - a2)
        const V t3r = -sg * h * (vi[1] - vi[2]);
        const V t3i = sg * h * (vr[1] - vr[2]);
        ur[0] = vr[0] + t1r;
        ui[0] = vi[0] + t1i;
        ur[1] = t2r + t3r;
        ui[1] = t2i + t3i;
        ur[2] = t2r - t3r;
        ui[2] = t2i - t3i;
    } else if constexpr (R == 4) {
        const V t0r = vr[0] + vr[2], t0i = vi[0] + vi[2];
        const V t1r = vr[0] - vr[2], t1i = vi[0] - vi[2];
        const V t2r = vr[1] + vr[3], t2i = vi[1] + vi[3];
        // Sign * i * (a1 - a3)
        const V t3r = -sg * (vi[1] - vi[3]);
        const V t3i = sg * (vr[1] - vr[3]);
        ur[0] = t0r + t2r;
        ui[0] = t0i + t2i;
        ur[2] = t0r - t2r;
        ui[2] = t0i - t2i;
        ur[1] = t1r + t3r;
        ui[1] = t1i + t3i;
        ur[3] = t1r - t3r;
        ui[3] = t1i - t3i;
    } else {
        constexpr double c1 = 0.30901699437494742410;  // cos(2 pi/5)
        constexpr double c2 = -0.80901699437494742410; // cos(4 pi/5)
        constexpr double s1 = 0.95105651629515357212;  // sin(2 pi/5)
        constexpr double s2 = 0.58778525229247312917;  // sin(4 pi/5)
        const V t1r = vr[1] + vr[4], t1i = vi[1] + vi[4];
        const V t2r = vr[2] + vr[3], t2i = vi[2] + vi[3];
        const V t3r = vr[1] - vr[4], t3i = vi[1] - vi[4];
        const V t4r = vr[2] - vr[3], t4i = vi[2] - vi[3];
        const V b1r = vr[0] + c1 * t1r + c2 * t2r;
        const V b1i = vi[0] + c1 * t1i + c2 * t2i;
        const V b2r = vr[0] + c2 * t1r + c1 * t2r;
        const V b2i = vi[0] + c2 * t1i + c1 * t2i;
        const V d1r = s1 * t3r + s2 * t4r, d1i = s1 * t3i + s2 * t4i;
        const V d2r = s2 * t3r - s1 * t4r, d2i = s2 * t3i - s1 * t4i;
        ur[0] = vr[0] + t1r + t2r;
        ui[0] = vi[0] + t1i + t2i;
        // y1 = b1 + Sign i d1, y4 = b1 - Sign i d1; y2, y3 likewise with d2.
        ur[1] = b1r - sg * d1i;
        ui[1] = b1i + sg * d1r;
        ur[4] = b1r + sg * d1i;
        ui[4] = b1i - sg * d1r;
        ur[2] = b2r - sg * d2i;
        ui[2] = b2i + sg * d2r;
        ur[3] = b2r + sg * d2i;
        ui[3] = b2i - sg * d2r;
    }
    simd::store_as(br[0] + t, ur[0]);
    simd::store_as(bi[0] + t, ui[0]);
    for (int j = 1; j < J; ++j) {
        if (twiddled) {
            simd::store_as(br[j] + t, ur[j] * wr[j] - ui[j] * wi[j]);
            simd::store_as(bi[j] + t, ur[j] * wi[j] + ui[j] * wr[j]);
        } else {
            simd::store_as(br[j] + t, ur[j]);
            simd::store_as(bi[j] + t, ui[j]);
        }
    }
}

// One Stockham stage: sub-transforms of length n = r m with stride s, every
// value a run of L contiguous lines. Decimation in frequency:
//   y[s (r p + j) + q] = w_n^(p j) sum_k x[s (p + k m) + q] w_r^(j k).
// Sign = -1 forward, +1 inverse (the sign of the exponent). For the
// sub-transforms p0 <= p < p1 and the values t0 <= t < t1 of each run, W
// values at a time (the vector of the kernel's ISA) and the rest one by one.
// K < R: the inputs k >= K are zero (a first stage, whose inputs beyond the
// transform's nonzero ones are zero), taken as the constant 0.0, so the
// compiler drops only what IEEE arithmetic leaves unchanged: the same bits
// as reading zeros. J < R: only the outputs j < J are stored (a last stage,
// whose other outputs the caller does not read).
template <int W, int R, int Sign, int K = R, int J = R>
CREEPWORK_INLINE void stage(int m, int s, int L, const double* xr, const double* xi, double* yr,
                            double* yi, const double* twr, const double* twi, int p0, int p1,
                            size_t t0, size_t t1)
{
    const size_t run = static_cast<size_t>(s) * L; // contiguous values per (p, k)
    const size_t vector_end = t0 + (t1 - t0) / W * W;
    for (int p = p0; p < p1; ++p) {
        double wr[R], wi[R];
        wr[0] = 1.0;
        wi[0] = 0.0;
        for (int j = 1; j < R; ++j) {
            wr[j] = twr[p * (R - 1) + j - 1];
            wi[j] = -Sign * twi[p * (R - 1) + j - 1]; // the table holds the forward sign
        }
        const double* ar[R];
        const double* ai[R];
        double* br[R];
        double* bi[R];
        for (int k = 0; k < R; ++k) {
            ar[k] = k < K ? xr + (static_cast<size_t>(p) + static_cast<size_t>(k) * m) * run
                          : nullptr;
            ai[k] = k < K ? xi + (static_cast<size_t>(p) + static_cast<size_t>(k) * m) * run
                          : nullptr;
            br[k] = yr + (static_cast<size_t>(R) * p + k) * run;
            bi[k] = yi + (static_cast<size_t>(R) * p + k) * run;
        }
        const bool twiddled = p != 0;
        size_t t = t0;
        for (; t < vector_end; t += W)
            butterfly<simd::Vec<W>, R, Sign, K, J>(ar, ai, br, bi, wr, wi, twiddled, t);
        for (; t < t1; ++t) butterfly<double, R, Sign, K, J>(ar, ai, br, bi, wr, wi, twiddled, t);
    }
}

template <int W, int Sign>
CREEPWORK_INLINE void run_stage(int radix, int m, int s, int L, const double* xr,
                                const double* xi, double* yr, double* yi, const double* twr,
                                const double* twi)
{
    const size_t run = static_cast<size_t>(s) * L;
    switch (radix) {
    case 2: stage<W, 2, Sign>(m, s, L, xr, xi, yr, yi, twr, twi, 0, m, 0, run); break;
    case 3: stage<W, 3, Sign>(m, s, L, xr, xi, yr, yi, twr, twi, 0, m, 0, run); break;
    case 4: stage<W, 4, Sign>(m, s, L, xr, xi, yr, yi, twr, twi, 0, m, 0, run); break;
    default: stage<W, 5, Sign>(m, s, L, xr, xi, yr, yi, twr, twi, 0, m, 0, run); break;
    }
}

// A first stage (stride 1) whose inputs from nonzero on are zero: the
// sub-transform p reads x[p + k m], nonzero for k < K(p) = ceil((nonzero -
// p) / m) (at most R), which falls with p; each run of p with one K by the
// stage with those inputs zero.
template <int W, int R, int Sign>
CREEPWORK_INLINE void first_stage_radix(int m, int L, const double* xr, const double* xi,
                                        double* yr, double* yi, const double* twr,
                                        const double* twi, int nonzero)
{
    const size_t run = static_cast<size_t>(L);
    int p0 = 0;
    while (p0 < m) {
        const int K = std::min(R, std::max(0, (nonzero - p0 + m - 1) / m));
        // The last p with this K: p < nonzero - (K - 1) m (K >= 1), all the rest for K = 0.
        const int p1 = K == 0 ? m : std::min(m, nonzero - (K - 1) * m);
        switch (K) {
        case 0: stage<W, R, Sign, 0>(m, 1, L, xr, xi, yr, yi, twr, twi, p0, p1, 0, run); break;
        case 1: stage<W, R, Sign, 1>(m, 1, L, xr, xi, yr, yi, twr, twi, p0, p1, 0, run); break;
        case 2:
            if constexpr (R >= 2)
                stage<W, R, Sign, (R >= 2 ? 2 : R)>(m, 1, L, xr, xi, yr, yi, twr, twi, p0, p1, 0,
                                                 run);
            break;
        case 3:
            if constexpr (R >= 3)
                stage<W, R, Sign, (R >= 3 ? 3 : R)>(m, 1, L, xr, xi, yr, yi, twr, twi, p0, p1, 0,
                                                 run);
            break;
        case 4:
            if constexpr (R >= 4)
                stage<W, R, Sign, (R >= 4 ? 4 : R)>(m, 1, L, xr, xi, yr, yi, twr, twi, p0, p1, 0,
                                                 run);
            break;
        default:
            stage<W, R, Sign>(m, 1, L, xr, xi, yr, yi, twr, twi, p0, p1, 0, run);
            break;
        }
        p0 = p1;
    }
}

// A last stage (m = 1, stride s = n / R) of which only the outputs
// e = j s + q < needed are read: for each q, J(q) = ceil((needed - q) / s)
// outputs (at most R), which falls with q; each run of q with one J by the
// stage storing those only, and none where J(q) = 0.
template <int W, int R, int Sign>
CREEPWORK_INLINE void last_stage_radix(int s, int L, const double* xr, const double* xi,
                                       double* yr, double* yi, const double* twr,
                                       const double* twi, int needed)
{
    int q0 = 0;
    while (q0 < s) {
        const int J = std::min(R, std::max(0, (needed - q0 + s - 1) / s));
        if (J == 0) break;
        const int q1 = std::min(s, needed - (J - 1) * s);
        const size_t t0 = static_cast<size_t>(q0) * L, t1 = static_cast<size_t>(q1) * L;
        switch (J) {
        case 1: stage<W, R, Sign, R, 1>(1, s, L, xr, xi, yr, yi, twr, twi, 0, 1, t0, t1); break;
        case 2:
            stage<W, R, Sign, R, (R >= 2 ? 2 : R)>(1, s, L, xr, xi, yr, yi, twr, twi, 0, 1, t0, t1);
            break;
        case 3:
            if constexpr (R >= 3)
                stage<W, R, Sign, R, (R >= 3 ? 3 : R)>(1, s, L, xr, xi, yr, yi, twr, twi, 0, 1, t0,
                                                    t1);
            break;
        case 4:
            if constexpr (R >= 4)
                stage<W, R, Sign, R, (R >= 4 ? 4 : R)>(1, s, L, xr, xi, yr, yi, twr, twi, 0, 1, t0,
                                                    t1);
            break;
        default: stage<W, R, Sign>(1, s, L, xr, xi, yr, yi, twr, twi, 0, 1, t0, t1); break;
        }
        q0 = q1;
    }
}

// One stage, a kernel of simd/kernel_isa.hpp: compiled for every ISA and
// run by run_kernel in the copy the FFT's owner chose, W lines to a vector
// (GCC 12 left the plain loops over the lines scalar in every copy: the
// stages' input and output runs may alias). The same operations on every lane and no fused multiply-add (-ffp-contract=off), so
// every copy gives the same bits.
// pruned: a forward transform's first stage with its inputs from extent on
// zero, or an inverse transform's last stage with only its first extent
// outputs stored (transform()).
struct StageKernel : KernelWidths {
    template <int W>
    CREEPWORK_INLINE static void run(const bool& inverse, const int& radix, const int& m,
                                     const int& s, const int& L, const double* const& xr,
                                     const double* const& xi, double* const& yr,
                                     double* const& yi, const double* const& twr,
                                     const double* const& twi, const bool& pruned,
                                     const int& extent)
    {
        if (inverse) {
            if (!pruned)
                run_stage<W, 1>(radix, m, s, L, xr, xi, yr, yi, twr, twi);
            else if (radix == 2)
                last_stage_radix<W, 2, 1>(s, L, xr, xi, yr, yi, twr, twi, extent);
            else if (radix == 3)
                last_stage_radix<W, 3, 1>(s, L, xr, xi, yr, yi, twr, twi, extent);
            else if (radix == 4)
                last_stage_radix<W, 4, 1>(s, L, xr, xi, yr, yi, twr, twi, extent);
            else
                last_stage_radix<W, 5, 1>(s, L, xr, xi, yr, yi, twr, twi, extent);
        } else {
            if (!pruned)
                run_stage<W, -1>(radix, m, s, L, xr, xi, yr, yi, twr, twi);
            else if (radix == 2)
                first_stage_radix<W, 2, -1>(m, L, xr, xi, yr, yi, twr, twi, extent);
            else if (radix == 3)
                first_stage_radix<W, 3, -1>(m, L, xr, xi, yr, yi, twr, twi, extent);
            else if (radix == 4)
                first_stage_radix<W, 4, -1>(m, L, xr, xi, yr, yi, twr, twi, extent);
            else
                first_stage_radix<W, 5, -1>(m, L, xr, xi, yr, yi, twr, twi, extent);
        }
    }
};

} // namespace

int BatchedFft::good_size(int n)
{
    // Among the 2^a 3^b 5^c lengths from n to 1.1 n, the one with the least
    // estimated cost per transform: n (sum of the stage costs + 1), stage
    // costs per point measured on this machine's 2D batches (radix 4: 0.75,
    // 2: 0.6, 3: 0.85, 5: 1.1 ns; the + 1 stands for the work per point
    // outside the transforms). So 96 beats 90 (9 % faster measured) and 48
    // beats 50 (24 %). Not further than 1.1 n: every other pass over the
    // spectrum grows with it (256 instead of 216 made a 104 x 104 product
    // 1.5x slower). A fixed rule, not a timing: the same grid always gets
    // the same transforms, so the same bits.
    if (n <= 1) return 1;
    int best = 0;
    double best_cost = 0.0;
    for (int m = n; m <= n + (n + 9) / 10; ++m) {
        int r = m;
        double per_point = 1.0;
        while (r % 4 == 0) r /= 4, per_point += 0.75;
        while (r % 2 == 0) r /= 2, per_point += 0.6;
        while (r % 3 == 0) r /= 3, per_point += 0.85;
        while (r % 5 == 0) r /= 5, per_point += 1.1;
        if (r != 1) continue;
        const double cost = m * per_point;
        if (best == 0 || cost < best_cost) {
            best = m;
            best_cost = cost;
        }
    }
    return best;
}

BatchedFft::BatchedFft(int n) : isa_(best_kernel_isa())
{
    // A length n has at most log2(n) stages and n - 1 twiddles (stage by
    // stage (r - 1) m = rest - rest / r, a telescoping sum).
    stages_.reserve(32);
    tw_re_.reserve(static_cast<size_t>(n));
    tw_im_.reserve(static_cast<size_t>(n));
    plan(n);
}

void BatchedFft::plan(int n)
{
    if (n == n_) return;
    n_ = n;
    stages_.clear();
    tw_re_.clear();
    tw_im_.clear();
    int rest = n, stride = 1;
    while (rest > 1) {
        int r = rest % 4 == 0 ? 4 : rest % 2 == 0 ? 2 : rest % 3 == 0 ? 3 : 5;
        Stage st;
        st.radix = r;
        st.m = rest / r;
        st.stride = stride;
        st.twiddle = tw_re_.size();
        // w_(rest)^(p j), p < m, 1 <= j < r (forward sign)
        for (int p = 0; p < st.m; ++p)
            for (int j = 1; j < r; ++j) {
                const double a = -2.0 * kPi * static_cast<double>(p) * j / rest;
                tw_re_.push_back(std::cos(a));
                tw_im_.push_back(std::sin(a));
            }
        stages_.push_back(st);
        rest = st.m;
        stride *= r;
    }
}

bool BatchedFft::pruned(size_t stage, bool inverse, int extent) const
{
    // The first stage of a forward transform, the last of an inverse one,
    // never the only one (which would need both).
    const size_t count = stages_.size();
    return extent < n_ && count >= 2 && stage == (inverse ? count - 1 : 0);
}

void BatchedFft::transform(double* re, double* im, int lines, bool inverse, double* work,
                           int extent) const
{
    const size_t total = static_cast<size_t>(n_) * lines;
    double* xr = re;
    double* xi = im;
    double* yr = work;
    double* yi = work + total;
    for (size_t k = 0; k < stages_.size(); ++k) {
        const Stage& st = stages_[k];
        const double* twr = tw_re_.data() + st.twiddle;
        const double* twi = tw_im_.data() + st.twiddle;
        run_kernel<StageKernel>(isa_, inverse, st.radix, st.m, st.stride, lines, xr, xi, yr, yi,
                                twr, twi, pruned(k, inverse, extent), extent);
        std::swap(xr, yr);
        std::swap(xi, yi);
    }
    if (xr != re) { // an odd number of stages: the result is in work
        std::memcpy(re, xr, total * sizeof(double));
        std::memcpy(im, xi, total * sizeof(double));
    }
}

void BatchedFft::transform(const double* in_re, const double* in_im, double* out_re,
                           double* out_im, int lines, bool inverse, double* work,
                           int extent) const
{
    const size_t total = static_cast<size_t>(n_) * lines;
    if (stages_.empty()) { // length 1
        std::memcpy(out_re, in_re, total * sizeof(double));
        std::memcpy(out_im, in_im, total * sizeof(double));
        return;
    }
    // Stage s writes out when (stages - s) is odd, work otherwise: the last
    // one writes out.
    const double* xr = in_re;
    const double* xi = in_im;
    const size_t count = stages_.size();
    for (size_t k = 0; k < count; ++k) {
        const bool to_out = (count - k) % 2 == 1;
        double* yr = to_out ? out_re : work;
        double* yi = to_out ? out_im : work + total;
        const Stage& st = stages_[k];
        const double* twr = tw_re_.data() + st.twiddle;
        const double* twi = tw_im_.data() + st.twiddle;
        run_kernel<StageKernel>(isa_, inverse, st.radix, st.m, st.stride, lines, xr, xi, yr, yi,
                                twr, twi, pruned(k, inverse, extent), extent);
        xr = yr;
        xi = yi;
    }
}

} // namespace creepwork
