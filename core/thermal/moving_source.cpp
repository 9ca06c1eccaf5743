#include "thermal/moving_source.hpp"

#include <algorithm>
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
    if (n_ <= direct_max) {
        pair_.resize(2 * static_cast<size_t>(n_));
        return;
    }
    int L = 2;
    while (L < 2 * n_) L *= 2; // linear, not circular, convolution of two length-n rows
    fft_ = std::make_unique<RowFft>(L);
    spectrum_.assign(L, {0.0, 0.0});
    for (int k = 1; k < n_; ++k) spectrum_[k] = {w_[k] / L, 0.0};
    fft_->forward(spectrum_.data());
    buffer_.assign(L, {0.0, 0.0});
}

namespace {

inline auto both(double v)
{
    typedef double Pair __attribute__((vector_size(16)));
    const Pair p = {v, v};
    return p;
}

} // namespace

void MovingSourceKernel::direct(const double* q_a, const double* q_b, double* out_a,
                                double* out_b, double self_weight)
{
    Pair* __restrict__ q = pair_.data();
    Pair* __restrict__ out = pair_.data() + n_;
    for (int t = 0; t < n_; ++t) {
        const Pair v = {q_a[t], q_b ? q_b[t] : 0.0};
        q[t] = v;
        out[t] = both(self_weight) * v;
    }
    const double* w = w_.data(); // w[k] = w_k, w[0] unused
    // Four sources at a time (each output loaded and stored once per four
    // products); a block of unheated elements (adhesion, exterior) is skipped.
    const int first = std::min(first_nonzero(q_a, n_), q_b ? first_nonzero(q_b, n_) : n_);
    int s = first;
    for (; s + 3 < n_; s += 4) {
        const Pair p0 = q[s], p1 = q[s + 1], p2 = q[s + 2], p3 = q[s + 3];
        const Pair any = (p0 != 0.0) | (p1 != 0.0) | (p2 != 0.0) | (p3 != 0.0);
        if (!(any[0] || any[1])) continue;
        out[s + 1] += p0 * both(w[1]);
        out[s + 2] += p0 * both(w[2]) + p1 * both(w[1]);
        out[s + 3] += p0 * both(w[3]) + p1 * both(w[2]) + p2 * both(w[1]);
        Pair* __restrict__ o = out + s + 4;
        const int m = n_ - s - 4;
        for (int k = 0; k < m; ++k)
            o[k] += (p0 * both(w[k + 4]) + p1 * both(w[k + 3])) +
                    (p2 * both(w[k + 2]) + p3 * both(w[k + 1]));
    }
    for (; s < n_; ++s) {
        const Pair p0 = q[s];
        Pair* __restrict__ o = out + s + 1;
        const int m = n_ - s - 1;
        for (int k = 0; k < m; ++k) o[k] += p0 * both(w[k + 1]);
    }
    for (int t = 0; t < n_; ++t) out_a[t] = out[t][0];
    if (out_b)
        for (int t = 0; t < n_; ++t) out_b[t] = out[t][1];
}

void MovingSourceKernel::apply(const double* q_a, const double* q_b, double* out_a,
                               double* out_b, double self_weight)
{
    if (!fft_) {
        direct(q_a, q_b, out_a, out_b, self_weight);
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
