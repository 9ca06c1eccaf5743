#include "exact/grid_convolution.hpp"

#include <algorithm>
#include <cmath>

#include "exact/influence.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Smallest 2^a 3^b 5^c >= n (kissfft has dedicated butterflies for 2, 3, 4, 5).
int good_fft_size(int n)
{
    for (int m = n < 2 ? 2 : n;; ++m) {
        int r = m;
        for (int p : {2, 3, 5})
            while (r % p == 0) r /= p;
        if (r == 1) return m;
    }
}

} // namespace

GridConvolution::GridConvolution(int nx, int ny)
    : nx_(nx), ny_(ny),
      // The steady shift needs A(k + 1) for k up to nx - 1, and the kernels
      // are stored symmetrically (real spectra): offsets -nx..nx along x
      // without wrap-around, -(ny - 1)..(ny - 1) along y.
      mx_(good_fft_size(2 * nx + 1)), my_(good_fft_size(2 * ny - 1))
{
    fft_.SetFlag(Eigen::FFT<double>::Unscaled);
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
    kern1_.resize(m);
    kern2_.resize(m);
    alpha_.resize(m);
    beta_re_.resize(m);
    beta_im_.resize(m);
    k33_.resize(m);
    k33_inv_.resize(m);
    shift_.resize(mx_);
    for (int kx = 0; kx < mx_; ++kx) {
        const double t = 2.0 * kPi * kx / mx_;
        shift_[kx] = Complex(1.0 - std::cos(t), -std::sin(t));
    }
    grid_.assign(static_cast<size_t>(nx_) * ny_, Complex(0.0, 0.0));
    spec_.assign(m, Complex(0.0, 0.0));
    const int longest = mx_ > my_ ? mx_ : my_;
    line_in_.assign(longest, Complex(0.0, 0.0));
    line_out_.assign(longest, Complex(0.0, 0.0));
    // Make the four plans now (kissfft makes a plan on first use of a size).
    fft_.fwd(line_out_.data(), line_in_.data(), mx_);
    fft_.inv(line_out_.data(), line_in_.data(), mx_);
    fft_.fwd(line_out_.data(), line_in_.data(), my_);
    fft_.inv(line_out_.data(), line_in_.data(), my_);
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
    const bool geometry = rho != rho_;
    rho_ = rho;
    nu_ = nu;
    if (geometry)
        influence_quadrant(kmax_, lmax_, rho, X_.data(), Y_.data(), R_.data(),
                           corner_work_.data());

    // Real-space kernels on the padded grid, offsets -nx..nx along x and
    // -(ny-1)..(ny-1) along y, zero elsewhere.
    auto fill = [&](auto value, std::vector<double>& out) {
        std::fill(out.begin(), out.end(), 0.0);
        for (int l = -(ny_ - 1); l <= ny_ - 1; ++l)
            for (int k = -nx_; k <= nx_; ++k)
                out[(k < 0 ? k + mx_ : k) + static_cast<size_t>(mx_) * (l < 0 ? l + my_ : l)] =
                    value(k, l);
    };
    fill([&](int k, int l) { return 0.5 * (cf11(k, l) + cf22(k, l)); }, kern1_);
    fill([&](int k, int l) { return cf33(k, l); }, kern2_);
    kernel_spectrum_pair(kern1_, kern2_, alpha_, k33_);

    // The preconditioner: the kernel over the whole periodic cell, not cut
    // off at the grid's offsets. Cut off, its spectrum has negative values
    // when dy != dx (measured: a/b = 2 on 24 x 24 and 44 x 44 grids); over
    // the whole cell it stayed positive for dy/dx = 0.05 ... 20 (min/max
    // 1e-3 ... 1e-2). The clamp only keeps the inverse finite regardless.
    for (int l = 0; l < my_; ++l)
        for (int k = 0; k < mx_; ++k) {
            const int kk = k <= mx_ / 2 ? k : k - mx_, ll = l <= my_ / 2 ? l : l - my_;
            kern1_[k + static_cast<size_t>(mx_) * l] = cf33(kk, ll);
        }
    std::fill(kern2_.begin(), kern2_.end(), 0.0);
    kernel_spectrum_pair(kern1_, kern2_, k33_inv_, beta_re_); // beta_re_: scratch here
    // k33_inv_ holds spectrum / (mx my); the inverse needs 1 / (spectrum mx my).
    const double m2 = static_cast<double>(mx_) * my_ * static_cast<double>(mx_) * my_;
    double largest = 0.0;
    for (double v : k33_inv_) largest = std::max(largest, v);
    for (double& v : k33_inv_) v = 1.0 / (std::max(v, 1e-6 * largest) * m2);
    fill([&](int k, int l) { return 0.5 * (cf11(k, l) - cf22(k, l)); }, kern1_);
    fill([&](int k, int l) { return cf12(k, l); }, kern2_);
    kernel_spectrum_pair(kern1_, kern2_, beta_re_, beta_im_);
    return true;
}

// Two real kernels with real spectra (even, or odd in both directions) in one
// complex FFT: the spectrum of k1 + i k2 is s1 + i s2.
void GridConvolution::kernel_spectrum_pair(const std::vector<double>& k1,
                                           const std::vector<double>& k2, std::vector<double>& s1,
                                           std::vector<double>& s2)
{
    const double scale = 1.0 / (static_cast<double>(mx_) * my_);
    // Full-size transform: the kernel fills the padded grid.
    for (int ky = 0; ky < my_; ++ky) {
        for (int kx = 0; kx < mx_; ++kx) {
            const size_t i = kx + static_cast<size_t>(mx_) * ky;
            line_in_[kx] = Complex(k1[i], k2[i]);
        }
        fft_.fwd(line_out_.data(), line_in_.data(), mx_);
        for (int kx = 0; kx < mx_; ++kx) spec_[ky + static_cast<size_t>(my_) * kx] = line_out_[kx];
    }
    for (int kx = 0; kx < mx_; ++kx) {
        Complex* col = spec_.data() + static_cast<size_t>(my_) * kx;
        fft_.fwd(line_out_.data(), col, my_);
        for (int ky = 0; ky < my_; ++ky) {
            s1[ky + static_cast<size_t>(my_) * kx] = line_out_[ky].real() * scale;
            s2[ky + static_cast<size_t>(my_) * kx] = line_out_[ky].imag() * scale;
        }
    }
}

void GridConvolution::forward()
{
    for (int j = 0; j < ny_; ++j) {
        const Complex* row = grid_.data() + static_cast<size_t>(nx_) * j;
        for (int i = 0; i < nx_; ++i) line_in_[i] = row[i];
        for (int i = nx_; i < mx_; ++i) line_in_[i] = Complex(0.0, 0.0);
        fft_.fwd(line_out_.data(), line_in_.data(), mx_);
        for (int kx = 0; kx < mx_; ++kx) spec_[j + static_cast<size_t>(my_) * kx] = line_out_[kx];
    }
    for (int kx = 0; kx < mx_; ++kx) {
        Complex* col = spec_.data() + static_cast<size_t>(my_) * kx;
        for (int ky = ny_; ky < my_; ++ky) col[ky] = Complex(0.0, 0.0);
        fft_.fwd(line_out_.data(), col, my_);
        for (int ky = 0; ky < my_; ++ky) col[ky] = line_out_[ky];
    }
}

void GridConvolution::inverse()
{
    for (int kx = 0; kx < mx_; ++kx) {
        Complex* col = spec_.data() + static_cast<size_t>(my_) * kx;
        fft_.inv(line_out_.data(), col, my_);
        for (int j = 0; j < ny_; ++j) col[j] = line_out_[j];
    }
    for (int j = 0; j < ny_; ++j) {
        for (int kx = 0; kx < mx_; ++kx) line_in_[kx] = spec_[j + static_cast<size_t>(my_) * kx];
        fft_.inv(line_out_.data(), line_in_.data(), mx_);
        Complex* row = grid_.data() + static_cast<size_t>(nx_) * j;
        for (int i = 0; i < nx_; ++i) row[i] = line_out_[i];
    }
}

void GridConvolution::apply_normal(const double* p1, const double* p2, double* u1, double* u2)
{
    const size_t n = static_cast<size_t>(nx_) * ny_;
    for (size_t i = 0; i < n; ++i) grid_[i] = Complex(p1[i], p2 ? p2[i] : 0.0);
    forward();
    const size_t m = static_cast<size_t>(mx_) * my_;
    for (size_t i = 0; i < m; ++i) spec_[i] *= k33_[i];
    inverse();
    for (size_t i = 0; i < n; ++i) u1[i] = grid_[i].real();
    if (u2)
        for (size_t i = 0; i < n; ++i) u2[i] = grid_[i].imag();
}

void GridConvolution::apply_normal_inverse(const double* u, double* p)
{
    const size_t n = static_cast<size_t>(nx_) * ny_;
    for (size_t i = 0; i < n; ++i) grid_[i] = Complex(u[i], 0.0);
    forward();
    const size_t m = static_cast<size_t>(mx_) * my_;
    for (size_t i = 0; i < m; ++i) spec_[i] *= k33_inv_[i];
    inverse();
    for (size_t i = 0; i < n; ++i) p[i] = grid_[i].real();
}

void GridConvolution::apply_tangential(const Complex* z, Complex* s, bool steady)
{
    const size_t n = static_cast<size_t>(nx_) * ny_;
    for (size_t i = 0; i < n; ++i) grid_[i] = z[i];
    forward();
    // Pairs (k, -k): s^(k) = alpha^(k) z^(k) + beta^(k) conj(z^(-k)), times the
    // shift factor of column kx for the steady operator. Each pair is visited
    // once, from its lower-indexed member (self-paired modes alone).
    for (int kx = 0; kx < mx_; ++kx) {
        const int kxm = kx == 0 ? 0 : mx_ - kx;
        for (int ky = 0; ky < my_; ++ky) {
            const int kym = ky == 0 ? 0 : my_ - ky;
            const size_t a = ky + static_cast<size_t>(my_) * kx;
            const size_t b = kym + static_cast<size_t>(my_) * kxm;
            if (b < a) continue;
            const Complex za = spec_[a], zb = spec_[b];
            Complex sa = alpha_[a] * za + Complex(beta_re_[a], beta_im_[a]) * std::conj(zb);
            Complex sb = alpha_[b] * zb + Complex(beta_re_[b], beta_im_[b]) * std::conj(za);
            if (steady) {
                sa *= shift_[kx];
                sb *= shift_[kxm];
            }
            spec_[a] = sa;
            spec_[b] = sb;
        }
    }
    inverse();
    for (size_t i = 0; i < n; ++i) s[i] = grid_[i];
}

} // namespace creepwork
