#include "thermal/moving_source.hpp"

#include <cmath>

#include "contact/error.hpp"

namespace creepwork::thermal {

namespace {

int first_nonzero(const double* q, int n)
{
    for (int t = 0; t < n; ++t)
        if (q[t] != 0.0) return t;
    return n;
}

} // namespace

double MovingSourceKernel::weight(int k)
{
    return 1.0 / (std::sqrt(k + 0.5) + std::sqrt(k - 0.5));
}

MovingSourceKernel::MovingSourceKernel(int length, int direct_max) : n_(length)
{
    if (length < 1)
        throw Error(ErrorKind::invalid_input,
                    "row length " + std::to_string(length) + " must be >= 1");
    w_.assign(n_, 0.0);
    for (int k = 1; k < n_; ++k) w_[k] = weight(k);
    if (n_ <= direct_max) return;
    int L = 2;
    while (L < 2 * n_) L *= 2; // linear, not circular, convolution of two length-n rows
    fft_ = std::make_unique<RowFft>(L);
    spectrum_.assign(L, {0.0, 0.0});
    for (int k = 1; k < n_; ++k) spectrum_[k] = {w_[k] / L, 0.0};
    fft_->forward(spectrum_.data());
    buffer_.assign(L, {0.0, 0.0});
}

void MovingSourceKernel::direct(const double* q, double* out, double self_weight) const
{
    for (int t = 0; t < n_; ++t) out[t] = self_weight * q[t];
    // Source by source: only heated elements cost anything (adhesion and the
    // exterior release no heat), and the inner loop vectorises.
    for (int s = first_nonzero(q, n_); s < n_; ++s) {
        const double qs = q[s];
        if (qs == 0.0) continue;
        const double* w = w_.data() - s; // w[t] = w_k for k = t - s
        for (int t = s + 1; t < n_; ++t) out[t] += qs * w[t];
    }
}

void MovingSourceKernel::apply(const double* q_a, const double* q_b, double* out_a,
                               double* out_b, double self_weight)
{
    if (!fft_) {
        direct(q_a, out_a, self_weight);
        if (q_b) direct(q_b, out_b, self_weight);
        return;
    }
    // Both rows in one complex transform: the kernel is real, so the real
    // and the imaginary part of the product stay the two rows' convolutions.
    const int L = fft_->length();
    for (int t = 0; t < n_; ++t) buffer_[t] = {q_a[t], q_b ? q_b[t] : 0.0};
    for (int t = n_; t < L; ++t) buffer_[t] = {0.0, 0.0};
    fft_->forward(buffer_.data());
    for (int m = 0; m < L; ++m) {
        const std::complex<double> z = buffer_[m], k = spectrum_[m];
        buffer_[m] = {z.real() * k.real() - z.imag() * k.imag(),
                      z.real() * k.imag() + z.imag() * k.real()};
    }
    fft_->inverse(buffer_.data());
    const int first_a = first_nonzero(q_a, n_);
    for (int t = 0; t < n_; ++t)
        out_a[t] = t < first_a ? 0.0 : buffer_[t].real() + self_weight * q_a[t];
    if (!q_b) return;
    const int first_b = first_nonzero(q_b, n_);
    for (int t = 0; t < n_; ++t)
        out_b[t] = t < first_b ? 0.0 : buffer_[t].imag() + self_weight * q_b[t];
}

} // namespace creepwork::thermal
