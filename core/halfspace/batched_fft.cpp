#include "halfspace/batched_fft.hpp"

#include <cmath>
#include <cstring>

#include "simd/kernel_isa.hpp"
#include "simd/simd.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One Stockham stage: sub-transforms of length n = r m with stride s, every
// value a run of L contiguous lines. Decimation in frequency:
//   y[s (r p + j) + q] = w_n^(p j) sum_k x[s (p + k m) + q] w_r^(j k).
// Sign = -1 forward, +1 inverse (the sign of the exponent).
template <int R, int Sign>
CREEPWORK_INLINE void stage(int m, int s, int L, const double* xr, const double* xi, double* yr,
                            double* yi, const double* twr, const double* twi)
{
    const size_t run = static_cast<size_t>(s) * L; // contiguous values per (p, k)
    for (int p = 0; p < m; ++p) {
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
            ar[k] = xr + (static_cast<size_t>(p) + static_cast<size_t>(k) * m) * run;
            ai[k] = xi + (static_cast<size_t>(p) + static_cast<size_t>(k) * m) * run;
            br[k] = yr + (static_cast<size_t>(R) * p + k) * run;
            bi[k] = yi + (static_cast<size_t>(R) * p + k) * run;
        }
        const bool twiddled = p != 0;
        for (size_t t = 0; t < run; ++t) {
            double ur[R], ui[R];
            if constexpr (R == 2) {
                ur[0] = ar[0][t] + ar[1][t];
                ui[0] = ai[0][t] + ai[1][t];
                ur[1] = ar[0][t] - ar[1][t];
                ui[1] = ai[0][t] - ai[1][t];
            } else if constexpr (R == 3) {
                constexpr double h = 0.86602540378443864676; // sin(2 pi/3)
                const double t1r = ar[1][t] + ar[2][t], t1i = ai[1][t] + ai[2][t];
                const double t2r = ar[0][t] - 0.5 * t1r, t2i = ai[0][t] - 0.5 * t1i;
                // Sign * i * h (a1 - a2)
                const double t3r = -Sign * h * (ai[1][t] - ai[2][t]);
                const double t3i = Sign * h * (ar[1][t] - ar[2][t]);
                ur[0] = ar[0][t] + t1r;
                ui[0] = ai[0][t] + t1i;
                ur[1] = t2r + t3r;
                ui[1] = t2i + t3i;
                ur[2] = t2r - t3r;
                ui[2] = t2i - t3i;
            } else if constexpr (R == 4) {
                const double t0r = ar[0][t] + ar[2][t], t0i = ai[0][t] + ai[2][t];
                const double t1r = ar[0][t] - ar[2][t], t1i = ai[0][t] - ai[2][t];
                const double t2r = ar[1][t] + ar[3][t], t2i = ai[1][t] + ai[3][t];
                // Sign * i * (a1 - a3)
                const double t3r = -Sign * (ai[1][t] - ai[3][t]);
                const double t3i = Sign * (ar[1][t] - ar[3][t]);
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
                const double t1r = ar[1][t] + ar[4][t], t1i = ai[1][t] + ai[4][t];
                const double t2r = ar[2][t] + ar[3][t], t2i = ai[2][t] + ai[3][t];
                const double t3r = ar[1][t] - ar[4][t], t3i = ai[1][t] - ai[4][t];
                const double t4r = ar[2][t] - ar[3][t], t4i = ai[2][t] - ai[3][t];
                const double b1r = ar[0][t] + c1 * t1r + c2 * t2r;
                const double b1i = ai[0][t] + c1 * t1i + c2 * t2i;
                const double b2r = ar[0][t] + c2 * t1r + c1 * t2r;
                const double b2i = ai[0][t] + c2 * t1i + c1 * t2i;
                const double d1r = s1 * t3r + s2 * t4r, d1i = s1 * t3i + s2 * t4i;
                const double d2r = s2 * t3r - s1 * t4r, d2i = s2 * t3i - s1 * t4i;
                ur[0] = ar[0][t] + t1r + t2r;
                ui[0] = ai[0][t] + t1i + t2i;
                // y1 = b1 + Sign i d1, y4 = b1 - Sign i d1; y2, y3 likewise with d2.
                ur[1] = b1r - Sign * d1i;
                ui[1] = b1i + Sign * d1r;
                ur[4] = b1r + Sign * d1i;
                ui[4] = b1i - Sign * d1r;
                ur[2] = b2r - Sign * d2i;
                ui[2] = b2i + Sign * d2r;
                ur[3] = b2r + Sign * d2i;
                ui[3] = b2i - Sign * d2r;
            }
            br[0][t] = ur[0];
            bi[0][t] = ui[0];
            for (int j = 1; j < R; ++j) {
                if (twiddled) {
                    br[j][t] = ur[j] * wr[j] - ui[j] * wi[j];
                    bi[j][t] = ur[j] * wi[j] + ui[j] * wr[j];
                } else {
                    br[j][t] = ur[j];
                    bi[j][t] = ui[j];
                }
            }
        }
    }
}

template <int Sign>
CREEPWORK_INLINE void run_stage(int radix, int m, int s, int L, const double* xr,
                                const double* xi, double* yr, double* yi, const double* twr,
                                const double* twi)
{
    switch (radix) {
    case 2: stage<2, Sign>(m, s, L, xr, xi, yr, yi, twr, twi); break;
    case 3: stage<3, Sign>(m, s, L, xr, xi, yr, yi, twr, twi); break;
    case 4: stage<4, Sign>(m, s, L, xr, xi, yr, yi, twr, twi); break;
    default: stage<5, Sign>(m, s, L, xr, xi, yr, yi, twr, twi); break;
    }
}

// One stage, a kernel of simd/kernel_isa.hpp: compiled for every ISA and
// run by run_kernel in the copy the FFT's owner chose (W unused: the compiler
// vectorises the butterflies over the lines for the copy's ISA). The same
// operations on every lane and no fused multiply-add (-ffp-contract=off), so
// every copy gives the same bits.
struct StageKernel : KernelWidths {
    template <int W>
    CREEPWORK_INLINE static void run(const bool& inverse, const int& radix, const int& m,
                                     const int& s, const int& L, const double* const& xr,
                                     const double* const& xi, double* const& yr,
                                     double* const& yi, const double* const& twr,
                                     const double* const& twi)
    {
        if (inverse)
            run_stage<1>(radix, m, s, L, xr, xi, yr, yi, twr, twi);
        else
            run_stage<-1>(radix, m, s, L, xr, xi, yr, yi, twr, twi);
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

void BatchedFft::transform(double* re, double* im, int lines, bool inverse, double* work) const
{
    const size_t total = static_cast<size_t>(n_) * lines;
    double* xr = re;
    double* xi = im;
    double* yr = work;
    double* yi = work + total;
    for (const Stage& st : stages_) {
        const double* twr = tw_re_.data() + st.twiddle;
        const double* twi = tw_im_.data() + st.twiddle;
        run_kernel<StageKernel>(isa_, inverse, st.radix, st.m, st.stride, lines, xr, xi, yr, yi,
                                twr, twi);
        std::swap(xr, yr);
        std::swap(xi, yi);
    }
    if (xr != re) { // an odd number of stages: the result is in work
        std::memcpy(re, xr, total * sizeof(double));
        std::memcpy(im, xi, total * sizeof(double));
    }
}

void BatchedFft::transform(const double* in_re, const double* in_im, double* out_re,
                           double* out_im, int lines, bool inverse, double* work) const
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
                                twr, twi);
        xr = yr;
        xi = yi;
    }
}

} // namespace creepwork
