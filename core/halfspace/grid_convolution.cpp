#include "halfspace/grid_convolution.hpp"

#include <algorithm>
#include <cmath>

#include "halfspace/influence.hpp"
#include "simd/kernel_isa.hpp"
#include "simd/simd.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The distance between one element of a batch and the next (the lines are
// contiguous, BatchedFft): a multiple of 16 lines puts every element of a
// stage's butterflies on the same few cache sets (a 128 x 128 batch took
// 2.5 times as long per point as a 132 x 128 one on this machine's cores;
// 128, 144 and 160 lines were slow, 120 ... 168 otherwise not), so such a
// count gets 4 lines more, zero and transformed with the rest.
int line_stride(int lines) { return lines % 16 == 0 ? lines + 4 : lines; }

// Vector v with its lanes in reverse order.
template <int W>
CREEPWORK_INLINE simd::Vec<W> reversed(const simd::Vec<W>& v)
{
    if constexpr (W == 2)
        return __builtin_shufflevector(v, v, 1, 0);
    else if constexpr (W == 4)
        return __builtin_shufflevector(v, v, 3, 2, 1, 0);
    else
        return __builtin_shufflevector(v, v, 7, 6, 5, 4, 3, 2, 1, 0);
}

// dst[c * ds + r] = src[r * ss + c] for r < rows, c < cols (the transposes
// between a 2D FFT's two batches), a kernel of simd/kernel_isa.hpp: W x W
// blocks transposed in registers, the edges one value at a time. Only copies,
// so every copy gives the same bits.
struct TransposeKernel : KernelWidths {
    static constexpr int avx512 = 4; // 4 x 4 blocks: AVX-512 gains nothing
    template <int W>
    CREEPWORK_INLINE static void block(const double* src, size_t ss, double* dst, size_t ds)
    {
        using V = simd::Vec<W>;
        if constexpr (W == 2) {
            const V a0 = simd::load<2>(src), a1 = simd::load<2>(src + ss);
            simd::store<2>(dst, __builtin_shufflevector(a0, a1, 0, 2));
            simd::store<2>(dst + ds, __builtin_shufflevector(a0, a1, 1, 3));
        } else {
            const V a0 = simd::load<4>(src), a1 = simd::load<4>(src + ss),
                    a2 = simd::load<4>(src + 2 * ss), a3 = simd::load<4>(src + 3 * ss);
            const V t0 = __builtin_shufflevector(a0, a1, 0, 4, 2, 6),
                    t1 = __builtin_shufflevector(a0, a1, 1, 5, 3, 7),
                    t2 = __builtin_shufflevector(a2, a3, 0, 4, 2, 6),
                    t3 = __builtin_shufflevector(a2, a3, 1, 5, 3, 7);
            simd::store<4>(dst, __builtin_shufflevector(t0, t2, 0, 1, 4, 5));
            simd::store<4>(dst + ds, __builtin_shufflevector(t1, t3, 0, 1, 4, 5));
            simd::store<4>(dst + 2 * ds, __builtin_shufflevector(t0, t2, 2, 3, 6, 7));
            simd::store<4>(dst + 3 * ds, __builtin_shufflevector(t1, t3, 2, 3, 6, 7));
        }
    }
    template <int W>
    CREEPWORK_INLINE static void run(const double* const& src, const size_t& ss,
                                     double* const& dst, const size_t& ds, const int& rows,
                                     const int& cols)
    {
        const int rb = rows / W * W, cb = cols / W * W;
        for (int r = 0; r < rb; r += W) {
            for (int c = 0; c < cb; c += W) block<W>(src + r * ss + c, ss, dst + c * ds + r, ds);
            for (int c = cb; c < cols; ++c)
                for (int q = r; q < r + W; ++q) dst[c * ds + q] = src[q * ss + c];
        }
        for (int r = rb; r < rows; ++r)
            for (int c = 0; c < cols; ++c) dst[c * ds + r] = src[r * ss + c];
    }
};

// The normal product's real rows and its complex lines of column pairs
// (real_product), a kernel of simd/kernel_isa.hpp: split (to null), re[c] =
// from[2 c], im[c] = from[2 c + 1] (0 past the row's end); join (from null),
// the reverse into to; count rows of nx values, the lines at [j * rc + c]. Only copies, W
// pairs at a time where they lie inside the row, so every copy gives the
// same bits.
struct ColumnPairKernel : KernelWidths {
    static constexpr int avx512 = 4; // 4 pairs a vector: AVX-512 gains nothing
    template <int W>
    CREEPWORK_INLINE static void run(const int& nx, const int& count, const size_t& rc,
                                     const double* const& from, double* const& to,
                                     double* const& re, double* const& im)
    {
        using V = simd::Vec<W>;
        const int nc = (nx + 1) / 2, vc = nx / (2 * W) * W; // pairs, those in vectors
        const bool join = to != nullptr;                   // else split from
        for (int j = 0; j < count; ++j) {
            const size_t o = static_cast<size_t>(nx) * j;
            double* r = join ? to + o : nullptr;
            const double* f = join ? nullptr : from + o;
            double* a = re + j * rc;
            double* b = im + j * rc;
            for (int c = 0; c < vc; c += W) {
                if (join) {
                    const V x = simd::load<W>(a + c), y = simd::load<W>(b + c);
                    if constexpr (W == 2) {
                        simd::store<2>(r + 2 * c, __builtin_shufflevector(x, y, 0, 2));
                        simd::store<2>(r + 2 * c + 2, __builtin_shufflevector(x, y, 1, 3));
                    } else {
                        simd::store<4>(r + 2 * c, __builtin_shufflevector(x, y, 0, 4, 1, 5));
                        simd::store<4>(r + 2 * c + 4, __builtin_shufflevector(x, y, 2, 6, 3, 7));
                    }
                } else {
                    const V x = simd::load<W>(f + 2 * c), y = simd::load<W>(f + 2 * c + W);
                    if constexpr (W == 2) {
                        simd::store<2>(a + c, __builtin_shufflevector(x, y, 0, 2));
                        simd::store<2>(b + c, __builtin_shufflevector(x, y, 1, 3));
                    } else {
                        simd::store<4>(a + c, __builtin_shufflevector(x, y, 0, 2, 4, 6));
                        simd::store<4>(b + c, __builtin_shufflevector(x, y, 1, 3, 5, 7));
                    }
                }
            }
            for (int c = vc; c < nc; ++c) {
                const bool second = 2 * c + 1 < nx;
                if (join) {
                    r[2 * c] = a[c];
                    if (second) r[2 * c + 1] = b[c];
                } else {
                    a[c] = f[2 * c];
                    b[c] = second ? f[2 * c + 1] : 0.0;
                }
            }
        }
    }
};

// out[kx * stride + ky] *= spectrum[ky + my kx] for kx < mx, ky < lines (the
// normal product's real spectrum), a kernel of simd/kernel_isa.hpp: one
// product per value, so every copy gives the same bits.
struct RealSpectrumKernel : KernelWidths {
    template <int W>
    CREEPWORK_INLINE static void run(const int& mx, const int& my, const int& lines,
                                     const size_t& stride, const double* const& spectrum,
                                     double* const& re, double* const& im)
    {
        for (int kx = 0; kx < mx; ++kx) {
            const double* k = spectrum + static_cast<size_t>(my) * kx;
            double* a = re + kx * stride;
            double* b = im + kx * stride;
            int ky = 0;
            for (; ky + W <= lines; ky += W) {
                const simd::Vec<W> f = simd::load<W>(k + ky);
                simd::store<W>(a + ky, simd::load<W>(a + ky) * f);
                simd::store<W>(b + ky, simd::load<W>(b + ky) * f);
            }
            for (; ky < lines; ++ky) {
                a[ky] *= k[ky];
                b[ky] *= k[ky];
            }
        }
    }
};

// The tangential product in Fourier space (apply_tangential), a kernel of
// simd/kernel_isa.hpp: for every column kx, s^(k) = f(kx) (alpha^(k) z^(k) +
// beta^(k) conj(z^(-k))), z read from (zr, zi) and s written to (sr, si)
// ([kx * sy + ky]), alpha and beta ([ky + my kx]), f = (fr, fi) per column or
// 1 (shift null). z^(-k) of the column mx - kx is read backwards, W values
// at a time reversed in the register (the first vector's lanes one by one:
// ky = 0 mirrors to itself), so ky runs forward in vectors: the same
// operations on every lane, the same bits on every ISA.
struct SpectralProductKernel : KernelWidths {
    template <class V>
    CREEPWORK_INLINE static void point(const double* al, const double* br, const double* bi,
                                       const V& zr, const V& zi, const V& mr, const V& mi,
                                       double fr, double fi, double* sr, double* si)
    {
        const V a = simd::load_as<V>(al), b = simd::load_as<V>(br), c = simd::load_as<V>(bi);
        const V tr = a * zr + b * mr + c * mi;
        const V ti = a * zi + c * mr - b * mi;
        simd::store_as(sr, fr * tr - fi * ti);
        simd::store_as(si, fr * ti + fi * tr);
    }
    template <int W>
    CREEPWORK_INLINE static void run(const int& mx, const int& my, const size_t& sy,
                                     const std::complex<double>* const& shift,
                                     const double* const& alpha, const double* const& beta_re,
                                     const double* const& beta_im, const double* const& zr,
                                     const double* const& zi, double* const& sr,
                                     double* const& si)
    {
        using V = simd::Vec<W>;
        for (int kx = 0; kx < mx; ++kx) {
            const int kxm = kx == 0 ? 0 : mx - kx;
            const double fr = shift ? shift[kx].real() : 1.0, fi = shift ? shift[kx].imag() : 0.0;
            const size_t c = static_cast<size_t>(my) * kx, o = sy * kx;
            const double* al = alpha + c;
            const double* br = beta_re + c;
            const double* bi = beta_im + c;
            const double* zcr = zr + o;
            const double* zci = zi + o;
            const double* mr = zr + sy * kxm; // z^(-k): ky = 0 at 0, ky > 0 at my - ky
            const double* mi = zi + sy * kxm;
            int ky = 0;
            if (my >= W) { // the first vector's mirror: ky = 0 at 0, the others at my - ky
                V m0r, m0i;
                m0r[0] = mr[0];
                m0i[0] = mi[0];
                for (int l = 1; l < W; ++l) {
                    m0r[l] = mr[my - l];
                    m0i[l] = mi[my - l];
                }
                point<V>(al, br, bi, simd::load<W>(zcr), simd::load<W>(zci), m0r, m0i, fr, fi,
                         sr + o, si + o);
                ky = W;
            } else {
                point<double>(al, br, bi, zcr[0], zci[0], mr[0], mi[0], fr, fi, sr + o, si + o);
                ky = 1;
            }
            for (; ky + W <= my; ky += W) {
                const size_t back = static_cast<size_t>(my - ky - (W - 1));
                point<V>(al + ky, br + ky, bi + ky, simd::load<W>(zcr + ky),
                         simd::load<W>(zci + ky), reversed<W>(simd::load<W>(mr + back)),
                         reversed<W>(simd::load<W>(mi + back)), fr, fi, sr + o + ky, si + o + ky);
            }
            for (; ky < my; ++ky)
                point<double>(al + ky, br + ky, bi + ky, zcr[ky], zci[ky], mr[my - ky],
                              mi[my - ky], fr, fi, sr + o + ky, si + o + ky);
        }
    }
};

} // namespace

GridConvolution::GridConvolution(int nx, int ny, ConvolutionUse use)
    : nx_(nx), ny_(ny), nx_max_(nx), ny_max_(ny), use_(use),
      // The steady shift needs A(k + 1) for k up to nx - 1, and the kernels
      // are stored symmetrically (real spectra): offsets -nx..nx along x
      // without wrap-around, -(ny - 1)..(ny - 1) along y.
      mx_(BatchedFft::good_size(2 * nx + 1)), my_(BatchedFft::good_size(2 * ny - 1)),
      fft_x_(mx_), fft_y_(my_)
{
    // Offsets to tabulate: |k| <= nx, |l| <= ny - 1 for the products, and the
    // whole periodic cell |k| <= mx/2, |l| <= my/2 for the preconditioner.
    kmax_ = std::max(nx_, mx_ / 2);
    lmax_ = std::max(ny_ - 1, my_ / 2);
    const size_t parts = static_cast<size_t>(kmax_ + 1) * (lmax_ + 1);
    X_.resize(parts);
    Y_.resize(parts);
    R_.resize(parts);
    corner_work_.resize(3 * static_cast<size_t>(kmax_ + 2) * (lmax_ + 2));
    const size_t m = static_cast<size_t>(mx_) * my_;
    sy_ = line_stride(my_);
    // The largest batch of any size up to this one: the padded field by rows
    // (my lines of mx columns and padding) or by columns (mx lines of my and
    // padding); line_stride adds at most 4.
    const size_t cap = static_cast<size_t>(mx_ + 4) * (my_ + 4);
    kern1_.resize(m);
    kern2_.resize(m);
    alpha_.resize(m);
    beta_re_.resize(m);
    beta_im_.resize(m);
    k33_.resize(m);
    k33_inv_.resize(m);
    shift_.resize(mx_);
    set_shift();
    rows_re_.assign(cap, 0.0);
    rows_im_.assign(cap, 0.0);
    spec_re_.assign(cap, 0.0);
    spec_im_.assign(cap, 0.0);
    out_re_.assign(cap, 0.0);
    out_im_.assign(cap, 0.0);
    back_re_.assign(cap, 0.0);
    back_im_.assign(cap, 0.0);
    work_.assign(2 * cap, 0.0);
}

void GridConvolution::set_shift()
{
    for (int kx = 0; kx < mx_; ++kx) {
        const double t = 2.0 * kPi * kx / mx_;
        shift_[kx] = Complex(1.0 - std::cos(t), -std::sin(t));
    }
}

bool GridConvolution::set_size(int nx, int ny)
{
    nx_ = nx;
    ny_ = ny;
    padded_cols_ = padded_rows_ = -1;
    const int mx = BatchedFft::good_size(2 * nx + 1), my = BatchedFft::good_size(2 * ny - 1);
    if (mx == mx_ && my == my_) return false;
    mx_ = mx;
    my_ = my;
    sy_ = line_stride(my_);
    fft_x_.plan(mx_);
    fft_y_.plan(my_);
    set_shift();
    spectra_ready_ = inverse_ready_ = pair_copied_ = false;
    return true;
}

double GridConvolution::cf11(int k, int l) const
{
    const int i = part_index(std::abs(k), std::abs(l));
    return ((1.0 - nu_) * X_[i] + Y_[i]) / kPi;
}

double GridConvolution::cf22(int k, int l) const
{
    const int i = part_index(std::abs(k), std::abs(l));
    return (X_[i] + (1.0 - nu_) * Y_[i]) / kPi;
}

double GridConvolution::cf12(int k, int l) const
{
    const int i = part_index(std::abs(k), std::abs(l));
    return ((k < 0) != (l < 0) ? -nu_ : nu_) * R_[i] / kPi;
}

double GridConvolution::cf33(int k, int l) const
{
    const int i = part_index(std::abs(k), std::abs(l));
    return (1.0 - nu_) * (X_[i] + Y_[i]) / kPi;
}

bool GridConvolution::set_coefficients(double rho, double nu)
{
    if (rho == rho_ && nu == nu_) return false;
    if (rho != rho_)
        influence_quadrant(kmax_, lmax_, rho, X_.data(), Y_.data(), R_.data(),
                           corner_work_.data());
    rho_ = rho;
    nu_ = nu;
    spectra_ready_ = inverse_ready_ = pair_copied_ = false;
    return true;
}

bool GridConvolution::copy_coefficients(const GridConvolution& from)
{
    if (from.rho_ == rho_ && from.nu_ == nu_) return false;
    if (from.rho_ != rho_) {
        std::copy(from.X_.begin(), from.X_.end(), X_.begin());
        std::copy(from.Y_.begin(), from.Y_.end(), Y_.begin());
        std::copy(from.R_.begin(), from.R_.end(), R_.begin());
    }
    rho_ = from.rho_;
    nu_ = from.nu_;
    spectra_ready_ = inverse_ready_ = pair_copied_ = false;
    return true;
}

void GridConvolution::compute_spectra()
{
    spectra_ready_ = true;
    // Real-space kernels on the padded grid, offsets -ex..ex along x and
    // -(ey-1)..(ey-1) along y, zero elsewhere: the largest field this FFT
    // size holds without wrap-around, within the tabulated offsets (the
    // constructor's nx x ny field: ex = nx, ey = ny). So the spectra depend
    // on the FFT size only, not on the field's size below it.
    const int ex = std::min(nx_max_, (mx_ - 1) / 2), ey = std::min(ny_max_, (my_ + 1) / 2);
    const size_t m = static_cast<size_t>(mx_) * my_;
    auto fill = [&](auto value, std::vector<double>& out) {
        std::fill(out.begin(), out.begin() + m, 0.0);
        for (int l = -(ey - 1); l <= ey - 1; ++l)
            for (int k = -ex; k <= ex; ++k)
                out[(k < 0 ? k + mx_ : k) + static_cast<size_t>(mx_) * (l < 0 ? l + my_ : l)] =
                    value(k, l);
    };
    // The same for a kernel even in both directions (a function of |k| and
    // |l|, so the same bits): each value computed once, stored four times
    // (2 ex < mx and 2 (ey - 1) < my: no two offsets share a cell).
    auto fill_even = [&](auto value, std::vector<double>& out) {
        std::fill(out.begin(), out.begin() + m, 0.0);
        for (int l = 0; l <= ey - 1; ++l) {
            const size_t r0 = static_cast<size_t>(mx_) * l,
                         r1 = static_cast<size_t>(mx_) * (l == 0 ? 0 : my_ - l);
            for (int k = 0; k <= ex; ++k) {
                const double v = value(k, l);
                const size_t c1 = k == 0 ? 0 : mx_ - k;
                out[k + r0] = v;
                out[c1 + r0] = v;
                out[k + r1] = v;
                out[c1 + r1] = v;
            }
        }
    };
    if (!pair_copied_) {
        fill_even([&](int k, int l) { return 0.5 * (cf11(k, l) + cf22(k, l)); }, kern1_);
        fill_even([&](int k, int l) { return cf33(k, l); }, kern2_);
        kernel_spectrum_pair(kern1_, kern2_, alpha_, k33_);
    }

    if (use_ != ConvolutionUse::normal) {
        fill_even([&](int k, int l) { return 0.5 * (cf11(k, l) - cf22(k, l)); }, kern1_);
        fill([&](int k, int l) { return cf12(k, l); }, kern2_);
        kernel_spectrum_pair(kern1_, kern2_, beta_re_, beta_im_);
    }
}

bool GridConvolution::copy_pair_spectra(const GridConvolution& from)
{
    // The spectra depend on the FFT size, the largest field (the kernels'
    // extent, compute_spectra) and the coefficients only.
    if (pair_ready() || !from.pair_ready() || from.mx_ != mx_ || from.my_ != my_ ||
        from.nx_max_ != nx_max_ || from.ny_max_ != ny_max_ || from.rho_ != rho_ ||
        from.nu_ != nu_)
        return false;
    const size_t m = static_cast<size_t>(mx_) * my_;
    std::copy(from.alpha_.begin(), from.alpha_.begin() + m, alpha_.begin());
    std::copy(from.k33_.begin(), from.k33_.begin() + m, k33_.begin());
    pair_copied_ = true;
    return true;
}

void GridConvolution::compute_inverse_spectrum()
{
    inverse_ready_ = true;
    // The preconditioner: the kernel over the whole periodic cell, not cut
    // off at the grid's offsets. Cut off, its spectrum has negative values
    // when dy != dx (measured: a/b = 2 on 24 x 24 and 44 x 44 grids); over
    // the whole cell it stayed positive for dy/dx = 0.05 ... 20 (min/max
    // 1e-3 ... 1e-2). The clamp only keeps the inverse finite regardless.
    const size_t m = static_cast<size_t>(mx_) * my_;
    for (int l = 0; l < my_; ++l)
        for (int k = 0; k < mx_; ++k) {
            const int kk = k <= mx_ / 2 ? k : k - mx_, ll = l <= my_ / 2 ? l : l - my_;
            kern1_[k + static_cast<size_t>(mx_) * l] = cf33(kk, ll);
        }
    std::fill(kern2_.begin(), kern2_.begin() + m, 0.0);
    // kern2_'s zero spectrum is not wanted: it overwrites kern2_ itself (read
    // before the spectra are written).
    kernel_spectrum_pair(kern1_, kern2_, k33_inv_, kern2_);
    // k33_inv_ holds spectrum / (mx my); the inverse needs 1 / (spectrum mx my).
    const double m2 = static_cast<double>(mx_) * my_ * static_cast<double>(mx_) * my_;
    double largest = 0.0;
    for (size_t i = 0; i < m; ++i) largest = std::max(largest, k33_inv_[i]);
    for (size_t i = 0; i < m; ++i)
        k33_inv_[i] = 1.0 / (std::max(k33_inv_[i], 1e-6 * largest) * m2);
}

// Two real kernels with real spectra (even, or odd in both directions) in one
// complex FFT: the spectrum of k1 + i k2 is s1 + i s2.
void GridConvolution::kernel_spectrum_pair(const std::vector<double>& k1,
                                           const std::vector<double>& k2, std::vector<double>& s1,
                                           std::vector<double>& s2)
{
    const double scale = 1.0 / (static_cast<double>(mx_) * my_);
    // The kernel fills the padded grid; k1 and k2 are [kx + mx ky].
    const size_t rc = line_stride(mx_);
    for (int ky = 0; ky < my_; ++ky)
        for (int kx = 0; kx < mx_; ++kx) {
            rows_re_[ky * rc + kx] = k1[kx + static_cast<size_t>(mx_) * ky];
            rows_im_[ky * rc + kx] = k2[kx + static_cast<size_t>(mx_) * ky];
        }
    forward(mx_, my_);
    for (int kx = 0; kx < mx_; ++kx)
        for (int ky = 0; ky < my_; ++ky) {
            s1[ky + static_cast<size_t>(my_) * kx] = out_re_[ky + sy_ * kx] * scale;
            s2[ky + static_cast<size_t>(my_) * kx] = out_im_[ky + sy_ * kx] * scale;
        }
}

void GridConvolution::forward(int cols, int rows)
{
    // Along y: lines are the columns, element j at [j * rc + i] (rc >= cols:
    // the columns cols ... rc - 1 are zero).
    const size_t rc = line_stride(cols);
    // The zeros around the field (rows_) and its columns (spec_) stay from the
    // last call of the same size: nothing else writes there meanwhile.
    const bool padded = cols == padded_cols_ && rows == padded_rows_;
    padded_cols_ = cols;
    padded_rows_ = rows;
    if (!padded) {
        clear_padding(rows_re_.data(), rows_im_.data(), rows, rc, cols);
        const size_t used = static_cast<size_t>(rows) * rc;
        std::fill(rows_re_.begin() + used, rows_re_.begin() + static_cast<size_t>(my_) * rc, 0.0);
        std::fill(rows_im_.begin() + used, rows_im_.begin() + static_cast<size_t>(my_) * rc, 0.0);
    }
    fft_y_.transform(rows_re_.data(), rows_im_.data(), out_re_.data(), out_im_.data(),
                     static_cast<int>(rc), false, work_.data(), rows);
    // Transpose [ky][i] -> [i][ky], zero columns i >= cols, then along x:
    // lines are the my rows ky (and sy_ - my zero ones), element i at
    // [i * sy_ + ky].
    run_kernel<TransposeKernel>(isa_, out_re_.data(), rc, spec_re_.data(), sy_, my_, cols);
    run_kernel<TransposeKernel>(isa_, out_im_.data(), rc, spec_im_.data(), sy_, my_, cols);
    if (!padded) {
        clear_padding(spec_re_.data(), spec_im_.data(), cols, sy_, my_);
        std::fill(spec_re_.begin() + static_cast<size_t>(cols) * sy_,
                  spec_re_.begin() + static_cast<size_t>(mx_) * sy_, 0.0);
        std::fill(spec_im_.begin() + static_cast<size_t>(cols) * sy_,
                  spec_im_.begin() + static_cast<size_t>(mx_) * sy_, 0.0);
    }
    fft_x_.transform(spec_re_.data(), spec_im_.data(), out_re_.data(), out_im_.data(),
                     static_cast<int>(sy_), false, work_.data(), cols);
}

// Zero the values lines ... stride - 1 of the first count elements (the
// padding lines of a batch: transformed, never read).
void GridConvolution::clear_padding(double* re, double* im, int count, size_t stride, int lines)
{
    if (stride == static_cast<size_t>(lines)) return;
    for (int e = 0; e < count; ++e) {
        std::fill(re + e * stride + lines, re + (e + 1) * stride, 0.0);
        std::fill(im + e * stride + lines, im + (e + 1) * stride, 0.0);
    }
}

void GridConvolution::inverse()
{
    fft_x_.transform(back_re_.data(), back_im_.data(), out_re_.data(), out_im_.data(),
                     static_cast<int>(sy_), true, work_.data(), nx_);
    const size_t rc = line_stride(nx_);
    run_kernel<TransposeKernel>(isa_, out_re_.data(), sy_, back_re_.data(), rc, nx_, my_);
    run_kernel<TransposeKernel>(isa_, out_im_.data(), sy_, back_im_.data(), rc, nx_, my_);
    clear_padding(back_re_.data(), back_im_.data(), my_, rc, nx_);
    fft_y_.transform(back_re_.data(), back_im_.data(), out_re_.data(), out_im_.data(),
                     static_cast<int>(rc), true, work_.data(), ny_);
}

void GridConvolution::real_product(const double* p, double* u,
                                   const std::vector<double>& spectrum)
{
    padded_cols_ = padded_rows_ = -1; // rows_ and spec_ in other layouts
    const int nc = (nx_ + 1) / 2;  // complex columns: x-columns 2c and 2c + 1
    const int h = my_ / 2;         // spectrum rows ky = 0 .. h (the rest by symmetry)
    const size_t hl = static_cast<size_t>(h) + 1;
    const size_t rc = line_stride(nc), sh = line_stride(static_cast<int>(hl));
    // Along y: column pairs as one complex line, element j at [j * rc + c].
    run_kernel<ColumnPairKernel>(isa_, nx_, ny_, rc, p, static_cast<double*>(nullptr),
                                 rows_re_.data(), rows_im_.data());
    clear_padding(rows_re_.data(), rows_im_.data(), ny_, rc, nc);
    const size_t used = static_cast<size_t>(ny_) * rc, total = static_cast<size_t>(my_) * rc;
    if (fft_y_.reads_beyond(ny_)) { // else the zero padding is never read
        std::fill(rows_re_.begin() + used, rows_re_.begin() + total, 0.0);
        std::fill(rows_im_.begin() + used, rows_im_.begin() + total, 0.0);
    }
    // The transforms run out of place (rows_ -> out_ -> spec_ ... ): no copy
    // back after an odd number of stages (batched_fft.hpp).
    fft_y_.transform(rows_re_.data(), rows_im_.data(), out_re_.data(), out_im_.data(),
                     static_cast<int>(rc), false, work_.data(), ny_);
    // Separate the pair, Z = A + i B: A(k) = (Z(k) + conj Z(-k)) / 2,
    // B(k) = (Z(k) - conj Z(-k)) / 2i, for ky <= h, into [i][ky] (stride sh).
    for (int c = 0; c < nc; ++c)
        for (int ky = 0; ky <= h; ++ky) {
            const int km = ky == 0 ? 0 : my_ - ky;
            const double zr = out_re_[ky * rc + c];
            const double zi = out_im_[ky * rc + c];
            const double wr = out_re_[km * rc + c];
            const double wi = out_im_[km * rc + c];
            const size_t a = static_cast<size_t>(2 * c) * sh + ky;
            spec_re_[a] = 0.5 * (zr + wr);
            spec_im_[a] = 0.5 * (zi - wi);
            if (2 * c + 1 < nx_) {
                spec_re_[a + sh] = 0.5 * (zi + wi);
                spec_im_[a + sh] = -0.5 * (zr - wr);
            }
        }
    clear_padding(spec_re_.data(), spec_im_.data(), nx_, sh, static_cast<int>(hl));
    if (fft_x_.reads_beyond(nx_)) {
        std::fill(spec_re_.begin() + static_cast<size_t>(nx_) * sh,
                  spec_re_.begin() + static_cast<size_t>(mx_) * sh, 0.0);
        std::fill(spec_im_.begin() + static_cast<size_t>(nx_) * sh,
                  spec_im_.begin() + static_cast<size_t>(mx_) * sh, 0.0);
    }
    // Along x on the h + 1 lines, times the (real) kernel, and back.
    fft_x_.transform(spec_re_.data(), spec_im_.data(), out_re_.data(), out_im_.data(),
                     static_cast<int>(sh), false, work_.data(), nx_);
    run_kernel<RealSpectrumKernel>(isa_, mx_, my_, h + 1, sh, spectrum.data(), out_re_.data(),
                                   out_im_.data());
    fft_x_.transform(out_re_.data(), out_im_.data(), spec_re_.data(), spec_im_.data(),
                     static_cast<int>(sh), true, work_.data(), nx_);
    // Each column's y-spectrum is Hermitian (the column is real): complete it
    // and pair the columns again, W = T_2c + i T_2c+1, into [ky][c].
    for (int c = 0; c < nc; ++c) {
        const size_t a = static_cast<size_t>(2 * c) * sh;
        const bool second = 2 * c + 1 < nx_;
        for (int ky = 0; ky < my_; ++ky) {
            const bool mirrored = ky > h;
            const int kk = mirrored ? my_ - ky : ky;
            const double s = mirrored ? -1.0 : 1.0; // conjugate
            const double ar = spec_re_[a + kk], ai = s * spec_im_[a + kk];
            const double br = second ? spec_re_[a + sh + kk] : 0.0;
            const double bi = second ? s * spec_im_[a + sh + kk] : 0.0;
            rows_re_[ky * rc + c] = ar - bi;
            rows_im_[ky * rc + c] = ai + br;
        }
    }
    clear_padding(rows_re_.data(), rows_im_.data(), my_, rc, nc);
    fft_y_.transform(rows_re_.data(), rows_im_.data(), out_re_.data(), out_im_.data(),
                     static_cast<int>(rc), true, work_.data(), ny_);
    run_kernel<ColumnPairKernel>(isa_, nx_, ny_, rc, static_cast<const double*>(nullptr), u,
                                 out_re_.data(), out_im_.data());
}

void GridConvolution::apply_normal(const double* p, double* u)
{
    if (!spectra_ready_) compute_spectra();
    real_product(p, u, k33_);
}

void GridConvolution::apply_normal_inverse(const double* u, double* p)
{
    if (!inverse_ready_) compute_inverse_spectrum();
    real_product(u, p, k33_inv_);
}

void GridConvolution::apply_tangential(const Complex* z, Complex* s, bool steady)
{
    if (!spectra_ready_) compute_spectra();
    const size_t rc = line_stride(nx_);
    // A row of complex values is a row of 2 nx doubles in real-imaginary
    // pairs (std::complex's layout), split and joined as the normal product's
    // column pairs.
    run_kernel<ColumnPairKernel>(isa_, 2 * nx_, ny_, rc, reinterpret_cast<const double*>(z),
                                 static_cast<double*>(nullptr), rows_re_.data(), rows_im_.data());
    forward(nx_, ny_);
    // The spectrum z is read from out_ and s written to back_.
    run_kernel<SpectralProductKernel>(isa_, mx_, my_, sy_, steady ? shift_.data() : nullptr,
                                      alpha_.data(), beta_re_.data(), beta_im_.data(),
                                      out_re_.data(), out_im_.data(), back_re_.data(),
                                      back_im_.data());
    inverse();
    run_kernel<ColumnPairKernel>(isa_, 2 * nx_, ny_, rc, static_cast<const double*>(nullptr),
                                 reinterpret_cast<double*>(s), out_re_.data(), out_im_.data());
}

} // namespace creepwork
