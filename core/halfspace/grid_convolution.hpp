// Products of the half-space influence coefficients with tractions on a
// uniform grid by FFT: the coefficients depend only on the offset
// between two elements (block Toeplitz), so zero-padding the nx x ny grid to
// Mx x My >= (2 nx + 1) x (2 ny - 1) turns each product into a circular
// convolution. The 2D transforms run as batches of 1D transforms
// (batched_fft.hpp): along y for all columns at once, a transpose, along x
// for all rows at once. Buffers are made by the constructor for its grid;
// set_size() runs the products on any smaller field, with FFT lengths for
// that field. Nothing allocates after the constructor; the spectra are
// computed by the first product after set_coefficients() or a new FFT length.
//
// Tangential products pack the two real traction components into one
// complex field z = px + i py, so one forward and one inverse complex FFT
// give both components of the result: with the 2x2 block kernel K,
//   s = sx + i sy = alpha * z + beta * conj(z),
//   alpha = (K11 + K22)/2,  beta = (K11 - K22)/2 + i K12,
// and in Fourier space s^(k) = alpha^(k) z^(k) + beta^(k) conj(z^(-k)).
// The kernels of the half-space are even (K11, K22, K33) or odd in both
// directions (K12), so their spectra are real and are computed two at a time.
#pragma once

#include <complex>
#include <vector>

#include "halfspace/batched_fft.hpp"

namespace creepwork {

// Largest grid per direction of the problems solved on the half-space (the
// exact model's, any gap grid's): memory grows with the square, about 2 kB
// per element for the exact model with all levels and the Krylov basis, most
// of it in the FFT arrays of the 4x larger padded grid.
constexpr int kMaxExactCells = 256;

// The products a convolution serves; only their spectra are computed.
enum class ConvolutionUse { both, normal, tangential };

class GridConvolution {
public:
    using Complex = std::complex<double>;

    // Throws std::bad_alloc only. nx, ny >= 1: the largest field.
    GridConvolution(int nx, int ny, ConvolutionUse use = ConvolutionUse::both);

    // The products act on fields of nx x ny elements (1 <= nx, ny <= the
    // constructor's): the FFT lengths follow, and when they change the plans
    // and spectra are remade in place (returns true). Allocates nothing.
    bool set_size(int nx, int ny);

    int nx() const { return nx_; }
    int ny() const { return ny_; }
    int fft_nx() const { return mx_; }
    int fft_ny() const { return my_; }

    // The coefficients for elements of length dx = 1 and width rho, Poisson
    // ratio nu (influence.hpp); results scale with dx. Recomputed only when
    // rho or nu change; returns true if they were.
    bool set_coefficients(double rho, double nu);
    // The coefficients of another convolution of the same largest field
    // (its tables copied, not recomputed); returns true if they changed.
    bool copy_coefficients(const GridConvolution& from);
    // The spectra alpha and K33 of another convolution of the same largest
    // field, FFT size and coefficients that has made them (a normal
    // problem's products on the box this one solves on), copied instead of
    // computed: the same bits. Returns false, copying nothing, otherwise.
    bool copy_pair_spectra(const GridConvolution& from);
    double rho() const { return rho_; }
    double nu() const { return nu_; }
    // The copy of the products' kernels to run (the FFTs', the spectral
    // multiply's, the copies'; supported by this CPU; every copy gives the
    // same bits).
    void set_kernel_isa(KernelIsa isa)
    {
        isa_ = isa;
        fft_x_.set_kernel_isa(isa);
        fft_y_.set_kernel_isa(isa);
    }

    // Normal (use both or normal): u[i + nx j] = sum_J cf33(I - J) p[J] (dx = 1). Real fields:
    // two columns go into one complex transform and only half the spectrum
    // is computed (it is Hermitian), about half the work of a tangential
    // product.
    void apply_normal(const double* p, double* u);
    // The inverse of the circulant (periodic) extension of cf33: an
    // approximate inverse of the normal influence matrix on any set of
    // elements, the preconditioner of the normal solver (the spectrum of the
    // half-space kernel is positive).
    void apply_normal_inverse(const double* u, double* p);

    // Tangential, in and out are complex fields z = px + i py on the grid
    // (same layout). steady = false: u = A z, the displacement difference.
    // steady = true: the steady-rolling shift per element length,
    //   (A z)(I) - (A z)(I + e_x), i.e. the kernel B(k, l) = A(k, l) - A(k + 1, l)
    // (doc/theory/exact-discretisation.md rule 5: the particle now at x_I was at x_I + dq).
    // Use both or tangential.
    void apply_tangential(const Complex* z, Complex* s, bool steady);

    // The coefficients at one offset, tabulated (|k| <= max(nx, fft_nx/2),
    // |l| <= max(ny - 1, fft_ny/2)).
    double cf11(int k, int l) const;
    double cf22(int k, int l) const;
    double cf12(int k, int l) const;
    double cf33(int k, int l) const;

private:
    // rows_re_/rows_im_ ([j][i]: cols values per row, rows rows) -> out_re_/
    // out_im_ ([kx][ky]), the 2D forward FFT of the zero-padded field
    // (spec_ and rows_ are overwritten).
    void forward(int cols, int rows);
    // back_ -> out_ ([j][i], the first ny rows of nx values): inverse FFT
    // (back_ is overwritten).
    void inverse();
    void set_shift();
    void compute_spectra(); // the kernels' spectra for the FFT size
    // The preconditioner's spectrum (apply_normal_inverse), made on its first
    // use: a gap grid's whole-grid normal products never take it.
    void compute_inverse_spectrum();
    bool spectra_ready_ = false, inverse_ready_ = false;
    bool pair_copied_ = false; // alpha_ and k33_ hold copy_pair_spectra's
    bool pair_ready() const { return spectra_ready_ || pair_copied_; }
    static void clear_padding(double* re, double* im, int count, size_t stride, int lines);
    void kernel_spectrum_pair(const std::vector<double>& k1, const std::vector<double>& k2,
                              std::vector<double>& s1, std::vector<double>& s2);
    // u = IFFT(spectrum * FFT(p)) for a real field p and a real spectrum
    // ([ky + my kx], scaled as k33_).
    void real_product(const double* p, double* u, const std::vector<double>& spectrum);
    int part_index(int k, int l) const { return k + (kmax_ + 1) * l; }

    int nx_, ny_, nx_max_, ny_max_;
    ConvolutionUse use_;
    int mx_, my_, kmax_ = 0, lmax_ = 0;
    size_t sy_ = 0; // elements of the spectrum's batches along x: my_ lines and padding
    double rho_ = -1.0, nu_ = -1.0;
    KernelIsa isa_ = best_kernel_isa(); // the kernels' copy (set_kernel_isa)
    BatchedFft fft_x_, fft_y_;
    // Tabulated nu-free parts for 0 <= k <= kmax_, 0 <= l <= lmax_.
    std::vector<double> X_, Y_, R_, corner_work_;
    // Kernels on the padded grid [kx + mx * ky] (real space), and their real
    // spectra (scaled by 1/(mx my)) in the transposed layout [ky + my * kx].
    std::vector<double> kern1_, kern2_;
    std::vector<double> alpha_, beta_re_, beta_im_, k33_, k33_inv_;
    std::vector<Complex> shift_; // 1 - exp(2 pi i kx / mx): the steady-rolling shift
    // Work: the field by rows [j][i], the spectrum [kx][ky], and the
    // transforms' scratch; real and imaginary parts apart. A batch's lines
    // are padded (line_stride in the .cpp): rows [j * rc + i], spectrum
    // [kx * sy_ + ky].
    // out_ receives the out-of-place transforms (no copy back after an odd
    // number of stages, batched_fft.hpp).
    std::vector<double> rows_re_, rows_im_, spec_re_, spec_im_, out_re_, out_im_, work_;
    // back_: the product's spectrum and the inverse transform's work, so
    // that rows_ and spec_ keep the zeros around the field between products
    // of one size (padded_cols_ x padded_rows_; -1 when unknown).
    std::vector<double> back_re_, back_im_;
    int padded_cols_ = -1, padded_rows_ = -1;
};

} // namespace creepwork
