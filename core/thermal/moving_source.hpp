// The steady moving-source integral along one row of the grid, discretised.
//
// A surface point that has travelled a distance u through a heat flux q
// [W/m^2] (high Peclet number: conduction along the surface neglected, as
// Ertz & Knothe, Wear 253 (2002) 498-508) has the flash temperature
//     T(x) = 1/(beta sqrt(pi V)) * integral over upstream xi of q(xi)/sqrt(x - xi) dxi
// (beta the effusivity that takes the heat, V the rolling speed). With q
// constant on each element of length dx, the integral at an element centre
// is exact: element k places upstream contributes
//     2 q sqrt(dx) (sqrt(k + 1/2) - sqrt(k - 1/2)),
// the element itself (the half upstream of its centre) 2 q sqrt(dx) sqrt(1/2).
// This file holds the sum over k, in units of 2 sqrt(dx):
//     out[t] = self * q[t] + sum_{k=1..t} w_k q[t-k],  w_k = sqrt(k+1/2) - sqrt(k-1/2),
// rows in time order (t = 0 the element a material point meets first).
// The weights do not depend on dx, so one table serves every row of every
// grid. Three ways to take the sum, chosen by the row length (measured,
// bench/bench_temperature.cpp):
//  - direct: O(n^2), only heated elements as sources; the fastest for rows
//    up to kDirectMaxLength elements;
//  - recursive: O(n M). The self term and the near weights w_1 .. w_{K-1}
//    (K = kNearTerms) exactly; the far weights w_k, k >= K, from the
//    Laplace integral
//        w_k = 1/sqrt(pi) integral_0^inf s^(-3/2) sinh(s/2) exp(-s k) ds,
//    by the trapezoidal rule after s = exp(x - beta exp(-x)) (beta = 3/n:
//    both ends of the integrand decay double-exponentially), so
//    w_k ~ sum_m c_m exp(-s_m k) with M ~ 25..35 terms, each a one-line
//    recursion along the row. Relative error of every far weight at most
//    kRecursionTolerance, checked at construction against the exact w_k
//    (all weights and heats are >= 0, so every output's relative error is
//    at most that too); the longer rows;
//  - fft: O(n log n), two rows per transform; exact to rounding, slower
//    than the recursion at every length measured, kept for comparison.
// Allocates only at construction.
#pragma once

#include <complex>
#include <memory>
#include <vector>

#include "thermal/row_fft.hpp"

namespace creepwork::thermal {

class MovingSourceKernel {
public:
    enum class Method { automatic, direct, recursive, fft };

    // Longest row summed directly: the measured break-even with the recursion.
    static constexpr int kDirectMaxLength = 100;
    // Self term and w_1 .. w_{kNearTerms-1} exact in the recursion.
    static constexpr int kNearTerms = 3;
    // Bound on the far weights' relative error in the recursion.
    static constexpr double kRecursionTolerance = 3e-10;

    // length: the row length n >= 1; automatic: direct up to
    // kDirectMaxLength, recursive beyond.
    explicit MovingSourceKernel(int length, Method method = Method::automatic);
    int length() const { return n_; }
    Method method() const { return method_; }
    // The recursion's number of exponentials (0 on the other paths) and the
    // largest relative error of its far weights, as checked at construction.
    int exponentials() const { return static_cast<int>(decay_.size()); }
    double recursion_error() const { return recursion_error_; }

    // w_k for k >= 1, written without cancellation: 1/(sqrt(k+1/2) + sqrt(k-1/2)).
    static double weight(int k);

    // out_a from q_a and, when q_b is given, out_b from q_b (two rows per
    // call: one vector operation or one transform serves both). Every array
    // has length() values, in time order. Elements before the first nonzero
    // q of a row get exactly 0.
    void apply(const double* q_a, const double* q_b, double* out_a, double* out_b,
               double self_weight);

private:
    typedef double Pair __attribute__((vector_size(16)));
    void load(const double* q_a, const double* q_b, Pair* q) const;
    void direct(const double* q_a, const double* q_b, double* out_a, double* out_b,
                double self_weight);
    void recursive(const double* q_a, const double* q_b, double* out_a, double* out_b,
                   double self_weight);
    void fft(const double* q_a, const double* q_b, double* out_a, double* out_b,
             double self_weight);
    void design_recursion();

    int n_ = 0;
    Method method_ = Method::direct;
    std::vector<double> w_;                        // w_[k], k < n (w_[0] = 0: the self term is apart)
    // recursion: U_m[t] = decay_m U_m[t-1] + gain_m q[t-K], out[t] += sum_m U_m[t]
    std::vector<double> decay_, gain_;
    double recursion_error_ = 0.0;
    std::unique_ptr<RowFft> fft_;
    std::vector<std::complex<double>> spectrum_;   // FFT of w, scaled by 1/L
    std::vector<std::complex<double>> buffer_;
    // Two rows side by side, one vector operation for both (GCC's vector
    // extension, as march/simd.hpp: plain IEEE multiply and add, so the
    // result does not depend on the instruction set).
    std::vector<Pair> pair_;                       // in and out
};

} // namespace creepwork::thermal
