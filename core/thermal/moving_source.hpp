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
// grid. Rows up to kDirectMaxLength elements are summed directly (O(n^2),
// only heated elements as sources: the fastest up to about 250 elements,
// bench/bench_temperature.cpp); longer rows by FFT, O(n log n), two rows
// per transform. Allocates only at construction.
#pragma once

#include <complex>
#include <memory>
#include <vector>

#include "thermal/row_fft.hpp"

namespace creepwork::thermal {

class MovingSourceKernel {
public:
    // Longest row summed directly: the measured break-even with the FFT.
    static constexpr int kDirectMaxLength = 256;

    // length: the row length n >= 1; rows longer than direct_max go by FFT
    // (a parameter for the tests and the benchmark).
    explicit MovingSourceKernel(int length, int direct_max = kDirectMaxLength);
    int length() const { return n_; }
    bool uses_fft() const { return fft_ != nullptr; }

    // w_k for k >= 1, written without cancellation: 1/(sqrt(k+1/2) + sqrt(k-1/2)).
    static double weight(int k);

    // out_a from q_a and, when q_b is given, out_b from q_b (the FFT path
    // transforms both rows at once). Every array has length() values, in
    // time order. Elements before the first nonzero q of a row get exactly 0.
    void apply(const double* q_a, const double* q_b, double* out_a, double* out_b,
               double self_weight);

private:
    void direct(const double* q_a, const double* q_b, double* out_a, double* out_b,
                double self_weight);

    int n_ = 0;
    std::vector<double> w_;                        // w_[k], k < n (w_[0] = 0: the self term is apart)
    std::unique_ptr<RowFft> fft_;                  // rows longer than kDirectMaxLength
    std::vector<std::complex<double>> spectrum_;   // FFT of w, scaled by 1/L
    std::vector<std::complex<double>> buffer_;
    // Two rows side by side, one vector operation for both (GCC's vector
    // extension, as march/simd.hpp: plain IEEE multiply and add, so the
    // result does not depend on the instruction set).
    typedef double Pair __attribute__((vector_size(16)));
    std::vector<Pair> pair_;                       // direct path: in and out
};

} // namespace creepwork::thermal
