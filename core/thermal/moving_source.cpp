#include "thermal/moving_source.hpp"

#include <algorithm>
#include <cmath>

#include "contact/error.hpp"

namespace creepwork::thermal {

namespace {

constexpr double kPi = 3.141592653589793238462643383279502884;

int first_nonzero(const double* q, int n)
{
    for (int t = 0; t < n; ++t)
        if (q[t] != 0.0) return t;
    return n;
}

typedef double Pair __attribute__((vector_size(16)));

inline Pair both(double v)
{
    const Pair p = {v, v};
    return p;
}

// The exponential sum's nodes s_m and weights c_m for the far weights w_k,
// k in [near, n): the trapezoidal rule with step h in x, s = exp(x - beta
// exp(-x)), of w_k = 1/sqrt(pi) integral s^(-3/2) sinh(s/2) exp(-s k) ds.
// From the top, where exp(-s near) is below 1e-12, down to where a term
// weighs less than 3e-12 of w_n.
void trapezoid_nodes(int n, int near, double h, std::vector<double>& s_out,
                     std::vector<double>& c_out)
{
    s_out.clear();
    c_out.clear();
    const double beta = 3.0 / n;
    const double floor = 3e-12 / std::sqrt(static_cast<double>(n));
    for (double x = std::log(28.0 / (near - 0.5));; x -= h) {
        const double e = beta * std::exp(-x);
        const double s = std::exp(x - e);
        const double c = h * std::sinh(0.5 * s) / std::sqrt(kPi * s) * (1.0 + e);
        if (c < floor || s_out.size() > 200) break;
        s_out.push_back(s);
        c_out.push_back(c);
    }
}

} // namespace

double MovingSourceKernel::weight(int k)
{
    return 1.0 / (std::sqrt(k + 0.5) + std::sqrt(k - 0.5));
}

MovingSourceKernel::MovingSourceKernel(int length, Method method) : n_(length)
{
    if (length < 1)
        throw Error(ErrorKind::invalid_input,
                    "row length " + std::to_string(length) + " must be >= 1");
    if (method == Method::automatic)
        method = n_ <= kDirectMaxLength ? Method::direct : Method::recursive;
    method_ = method;
    w_.assign(n_, 0.0);
    for (int k = 1; k < n_; ++k) w_[k] = weight(k);
    if (method_ == Method::direct) {
        pair_.resize(2 * static_cast<size_t>(n_));
    } else if (method_ == Method::recursive) {
        design_recursion();
        pair_.resize(2 * static_cast<size_t>(n_));
    } else {
        int L = 2;
        while (L < 2 * n_) L *= 2; // linear, not circular, convolution of two length-n rows
        fft_ = std::make_unique<RowFft>(L);
        spectrum_.assign(L, {0.0, 0.0});
        for (int k = 1; k < n_; ++k) spectrum_[k] = {w_[k] / L, 0.0};
        fft_->forward(spectrum_.data());
        buffer_.assign(L, {0.0, 0.0});
    }
}

// The exponentials for this row length, and their check against every far
// weight; a finer step until the tolerance holds (the first, h = 0.375,
// does from 4 to 10^5 elements).
void MovingSourceKernel::design_recursion()
{
    const int K = kNearTerms;
    decay_.clear();
    gain_.clear();
    recursion_error_ = 0.0;
    if (n_ <= K) return; // every weight is near
    std::vector<double> s, c;
    for (double h = 0.375;; h *= 0.85) {
        trapezoid_nodes(n_, K, h, s, c);
        std::vector<double> r(s.size()), term(s.size());
        for (size_t m = 0; m < s.size(); ++m) {
            r[m] = std::exp(-s[m]);
            term[m] = c[m] * std::exp(-s[m] * K);
        }
        double worst = 0.0;
        for (int k = K; k < n_; ++k) {
            double sum = 0.0;
            for (size_t m = 0; m < s.size(); ++m) {
                sum += term[m];
                term[m] *= r[m];
            }
            worst = std::max(worst, std::abs(sum / w_[k] - 1.0));
        }
        recursion_error_ = worst;
        if (worst <= kRecursionTolerance || h < 0.05) break;
    }
    if (!(recursion_error_ <= kRecursionTolerance))
        throw Error(ErrorKind::numeric_failure, "moving-source recursion for rows of " +
                                             std::to_string(n_) + " elements misses its tolerance");
    for (size_t m = 0; m < s.size(); ++m) {
        decay_.push_back(std::exp(-s[m]));
        gain_.push_back(c[m] * std::exp(-s[m] * K));
    }
}

void MovingSourceKernel::load(const double* q_a, const double* q_b, Pair* q) const
{
    for (int t = 0; t < n_; ++t) {
        const Pair v = {q_a[t], q_b ? q_b[t] : 0.0};
        q[t] = v;
    }
}

void MovingSourceKernel::direct(const double* q_a, const double* q_b, double* out_a,
                                double* out_b, double self_weight)
{
    Pair* __restrict__ q = pair_.data();
    Pair* __restrict__ out = pair_.data() + n_;
    load(q_a, q_b, q);
    for (int t = 0; t < n_; ++t) out[t] = both(self_weight) * q[t];
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

namespace {

// B exponentials held in registers along the whole row: out[t] += sum of
// U_m[t], U_m[t] = decay_m U_m[t-1] + gain_m q[t-K], from t = start on.
template <int B>
void add_exponentials(const double* decay, const double* gain, const Pair* q, Pair* out,
                      int start, int n, int K)
{
    Pair d[B], g[B], u[B];
    for (int m = 0; m < B; ++m) {
        d[m] = both(decay[m]);
        g[m] = both(gain[m]);
        u[m] = both(0.0);
    }
    for (int t = start; t < n; ++t) {
        const Pair src = q[t - K];
        Pair sum = both(0.0);
        for (int m = 0; m < B; ++m) {
            u[m] = d[m] * u[m] + g[m] * src;
            sum += u[m];
        }
        out[t] += sum;
    }
}

} // namespace

void MovingSourceKernel::recursive(const double* q_a, const double* q_b, double* out_a,
                                   double* out_b, double self_weight)
{
    const int K = kNearTerms, M = exponentials();
    Pair* __restrict__ q = pair_.data();
    Pair* __restrict__ out = pair_.data() + n_;
    load(q_a, q_b, q);
    const double* w = w_.data();
    // Ahead of the heat every term is 0: start at the first heated element.
    const int first = std::min(first_nonzero(q_a, n_), q_b ? first_nonzero(q_b, n_) : n_);
    for (int t = 0; t < first; ++t) out[t] = both(0.0);
    for (int t = first; t < n_; ++t) {
        Pair near = both(self_weight) * q[t];
        for (int k = 1; k < K && k <= t - first; ++k) near += both(w[k]) * q[t - k];
        out[t] = near;
    }
    // The far sources, four exponentials at a time.
    const int start = first + K;
    int m = 0;
    for (; m + 4 <= M; m += 4)
        add_exponentials<4>(&decay_[m], &gain_[m], q, out, start, n_, K);
    for (; m < M; ++m) add_exponentials<1>(&decay_[m], &gain_[m], q, out, start, n_, K);
    for (int t = 0; t < n_; ++t) out_a[t] = out[t][0];
    if (out_b)
        for (int t = 0; t < n_; ++t) out_b[t] = out[t][1];
}

void MovingSourceKernel::fft(const double* q_a, const double* q_b, double* out_a,
                             double* out_b, double self_weight)
{
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

void MovingSourceKernel::apply(const double* q_a, const double* q_b, double* out_a,
                               double* out_b, double self_weight)
{
    switch (method_) {
    case Method::direct: direct(q_a, q_b, out_a, out_b, self_weight); break;
    case Method::recursive: recursive(q_a, q_b, out_a, out_b, self_weight); break;
    default: fft(q_a, q_b, out_a, out_b, self_weight); break;
    }
}

} // namespace creepwork::thermal
