// A radix-2 complex FFT of one power-of-two length, planned once (twiddles
// and bit reversal at construction) and run in place without allocating:
// what the moving-source convolution of a long row needs, nothing more.
#pragma once

#include <complex>
#include <vector>

namespace creepwork::thermal {

class RowFft {
public:
    // length: a power of two >= 2.
    explicit RowFft(int length);
    int length() const { return n_; }
    // In place, data[0 .. length-1]: forward exp(-2 pi i jk/n), or inverse
    // exp(+2 pi i jk/n) without the 1/n.
    void forward(std::complex<double>* data) const { run(data, false); }
    void inverse(std::complex<double>* data) const { run(data, true); }

private:
    void run(std::complex<double>* data, bool inverse) const;

    int n_ = 0;
    std::vector<int> reversed_;                  // bit-reversed index of each position
    std::vector<std::complex<double>> twiddle_;  // exp(-2 pi i k/n), k < n/2
};

} // namespace creepwork::thermal
