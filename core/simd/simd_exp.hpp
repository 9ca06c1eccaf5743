// exp(x) for x <= 0 on W lanes, for the kernels that evaluate a friction law
// of the slip speed. Written with IEEE add, subtract and multiply and exact
// exponent arithmetic only, so every ISA's copy gives the same bits (as the
// march's kernels, march/march.hpp), and without a call into libm.
//
// Method: x = n ln2 + r with n = round(x / ln2) and |r| <= ln2/2 (Cody and
// Waite's two-part ln2, whose high part has 21 trailing zero bits, so n ln2_hi
// is exact), exp(r) by its Taylor polynomial of degree 13 (truncation below
// r^14/14! < 5e-18 relative) in Estrin's scheme, times 2^n built in the
// exponent bits. Relative
// error against the correctly rounded exp below 1e-15 over [-700, 0]
// (test_core_slip_speed_laws samples it); x below -700 gives exp(-700)
// (~1e-304, a normal number: no lane ever meets a subnormal), and so does a
// NaN lane; above -1e-20, exactly 1.
#pragma once

#include <cstring>

#include "simd/simd.hpp"

namespace creepwork::simd {

template <int W>
struct IntVecOf {
    typedef long long type __attribute__((vector_size(8 * W)));
};

template <int W>
CREEPWORK_INLINE Vec<W> exp_nonpositive(const Vec<W>& x_in)
{
    using V = Vec<W>;
    using I = typename IntVecOf<W>::type;
    const V lowest = broadcast<W>(-700.0), zero = broadcast<W>(0.0);
    const V x0 = x_in > lowest ? x_in : lowest; // NaN compares false: lowest
    // Above -1e-20 exp rounds to 1: x = 0 gives it exactly and keeps r^8
    // from underflowing.
    const V x = x0 < broadcast<W>(-1e-20) ? x0 : zero;
    // n = round(x log2 e): adding 1.5 2^52 rounds to an integer, held in
    // the low bits of the sum.
    const V shifter = broadcast<W>(0x1.8p52);
    const V kd = x * broadcast<W>(1.4426950408889634074) + shifter;
    const V n = kd - shifter;
    const V r = (x - n * broadcast<W>(6.93147180369123816490e-01)) -
                n * broadcast<W>(1.90821492927058770002e-10);
    // The Taylor polynomial sum r^k/k!, k <= 13, by Estrin's scheme (pairs,
    // then pairs of pairs: a short chain of dependent operations).
    const V one = broadcast<W>(1.0);
    const V r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
    const V p01 = one + r, p23 = broadcast<W>(0.5) + broadcast<W>(1.0 / 6.0) * r,
            p45 = broadcast<W>(1.0 / 24.0) + broadcast<W>(1.0 / 120.0) * r,
            p67 = broadcast<W>(1.0 / 720.0) + broadcast<W>(1.0 / 5040.0) * r,
            p89 = broadcast<W>(1.0 / 40320.0) + broadcast<W>(1.0 / 362880.0) * r,
            p1011 = broadcast<W>(1.0 / 3628800.0) + broadcast<W>(1.0 / 39916800.0) * r,
            p1213 = broadcast<W>(1.0 / 479001600.0) + broadcast<W>(1.0 / 6227020800.0) * r;
    const V p03 = p01 + p23 * r2, p47 = p45 + p67 * r2, p811 = p89 + p1011 * r2;
    const V p = (p03 + p47 * r4) + (p811 + p1213 * r4) * r8;
    // 2^n, n in [-1010, 0]: the biased exponent n + 1023 in bits 52-62.
    I kbits, sbits;
    std::memcpy(&kbits, &kd, sizeof kbits);
    const V sh = shifter;
    std::memcpy(&sbits, &sh, sizeof sbits);
    const I ebits = (kbits - sbits + 1023) << 52;
    V scale;
    std::memcpy(&scale, &ebits, sizeof scale);
    return p * scale;
}

} // namespace creepwork::simd
