// Many complex FFTs of one length at once: a self-sorting (Stockham)
// mixed-radix transform for lengths 2^a 3^b 5^c, applied to L lines stored
// "element-major" (element e of line l at [e * L + l], real and imaginary
// parts in separate arrays). Every butterfly then runs over L contiguous
// values, W lines to a vector (simd/simd.hpp; the compiler's own
// vectoriser left these loops scalar), instead of over one line at a time
// as a one-dimensional FFT library does (Eigen's kissfft took two thirds of
// the exact model's time; this is ~3x faster on its grids). Results are the
// same bits whatever the vector width (no fused multiply-add: the core is
// built with -ffp-contract=off).
//
// Forward: X_k = sum_n x_n exp(-2 pi i k n / N); inverse: exp(+...),
// unscaled. Plans (factors, twiddles) are made by the constructor.
#pragma once

#include <cstddef>
#include <vector>

#include "simd/kernel_isa.hpp"

namespace creepwork {

class BatchedFft {
public:
    explicit BatchedFft(int n); // n = 2^a 3^b 5^c >= 1
    int size() const { return n_; }
    // Plans length n (2^a 3^b 5^c, 1 <= n <= the constructor's n) in place,
    // allocating nothing.
    void plan(int n);
    // In place on (re, im) of n * lines values; work holds 2 n lines.
    // extent < n prunes what the caller never sees, with the same bits in
    // what it does: forward, the elements from extent on are zero (and not
    // read); inverse, only the elements before extent are read afterwards
    // (the others are left undefined). The transform of a zero-padded
    // field and the inverse cut back to the field: about a third of the
    // first or last stage's work each.
    void transform(double* re, double* im, int lines, bool inverse, double* work,
                   int extent = 1 << 30) const;
    // From (in_re, in_im), which are only read, into (out_re, out_im), apart
    // from them; work holds 2 n lines. The stages alternate between out and
    // work so that the last one lands in out whatever their number: no copy
    // (the in-place transform copies its result back after an odd number of
    // stages, as lengths 40 = 4 2 5 and 45 = 3 3 5 have). extent as above.
    void transform(const double* in_re, const double* in_im, double* out_re, double* out_im,
                   int lines, bool inverse, double* work, int extent = 1 << 30) const;
    // Whether a forward transform with this extent reads its inputs from
    // extent on (false: they need not be zeroed).
    bool reads_beyond(int extent) const { return !pruned(0, false, extent); }
    // A cheap 2^a 3^b 5^c length >= n (at most 1.1 n; see the .cpp).
    static int good_size(int n);
    // The copy of the stages to run: best_kernel_isa() unless set (isa must
    // be supported; every copy gives the same bits).
    void set_kernel_isa(KernelIsa isa) { isa_ = isa; }

private:
    // Whether stage k of a transform runs pruned to extent.
    bool pruned(std::size_t stage, bool inverse, int extent) const;
    struct Stage {
        int radix, m, stride; // length n = radix * m of this stage, stride of the sub-transforms
        std::size_t twiddle;      // offset of (radix - 1) * m twiddles in re_/im_
    };
    int n_ = 0;
    KernelIsa isa_; // the stages' copy (simd/kernel_isa.hpp)
    std::vector<Stage> stages_;
    std::vector<double> tw_re_, tw_im_;
};

} // namespace creepwork
