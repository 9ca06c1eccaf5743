#include "thermal/row_fft.hpp"

#include <cmath>
#include <utility>

#include "contact/error.hpp"

namespace creepwork::thermal {

RowFft::RowFft(int length) : n_(length)
{
    if (length < 2 || (length & (length - 1)) != 0)
        throw Error(ErrorKind::invalid_input, "FFT length " + std::to_string(length) +
                                                  " is not a power of two >= 2");
    int bits = 0;
    while ((1 << bits) < n_) ++bits;
    reversed_.resize(n_);
    for (int i = 0; i < n_; ++i) {
        int r = 0;
        for (int b = 0; b < bits; ++b)
            if (i & (1 << b)) r |= 1 << (bits - 1 - b);
        reversed_[i] = r;
    }
    // Each twiddle from its own angle (no recurrence: no drift along the table).
    const double pi = 3.141592653589793238462643383279502884;
    twiddle_.resize(n_ / 2);
    for (int k = 0; k < n_ / 2; ++k) {
        const double angle = -2.0 * pi * k / n_;
        twiddle_[k] = {std::cos(angle), std::sin(angle)};
    }
}

void RowFft::run(std::complex<double>* data, bool inverse) const
{
    for (int i = 0; i < n_; ++i)
        if (reversed_[i] > i) std::swap(data[i], data[reversed_[i]]);
    for (int half = 1; half < n_; half *= 2) {
        const int stride = n_ / (2 * half); // twiddle step of this stage
        for (int start = 0; start < n_; start += 2 * half) {
            for (int k = 0; k < half; ++k) {
                std::complex<double> w = twiddle_[k * stride];
                if (inverse) w = std::conj(w);
                std::complex<double>& lo = data[start + k];
                std::complex<double>& hi = data[start + k + half];
                // (a + ib)(c + id) written out: std::complex's operator* checks
                // for NaN and calls a library routine.
                const double re = w.real() * hi.real() - w.imag() * hi.imag();
                const double im = w.real() * hi.imag() + w.imag() * hi.real();
                const std::complex<double> t(re, im);
                hi = lo - t;
                lo = lo + t;
            }
        }
    }
}

} // namespace creepwork::thermal
