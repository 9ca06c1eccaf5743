// The floating-point mode of a library call: exceptions masked, subnormal
// numbers flushed to zero, and the caller's mode and exception flags put
// back on return.
//
// Why. Hosts -- legacy Fortran codes in particular -- trap floating-point
// exceptions (gfortran -ffpe-trap=invalid,zero,overflow,denormal), and a
// trap inside a library kills the host. Two layers keep them safe:
//  1. The core's arithmetic raises no invalid, divide-by-zero, overflow or
//     denormal exception, in any vector lane, for valid inputs of any
//     practical magnitude (contact/fp_safe.hpp, march/march.hpp; tested
//     kernel by kernel with those traps on and without this mode,
//     tests/robustness/test_robustness_fptrap_kernels.cpp).
//  2. This mode, for everything else: hostile input (NaN, 1e300 loads) is
//     compared and rejected with a status instead of trapping, and absurd
//     magnitudes (creepages below ~1e-290, contacts below ~1e-100 m) that
//     would make a subnormal number give 0 instead (flush-to-zero,
//     denormals-are-zero: a subnormal operand reads as 0). Results of
//     practical inputs do not change: layer 1 makes no subnormal there.
// The caller's MXCSR -- masks, rounding, flush bits and sticky flags -- is
// restored on return, so a call leaves no trace in the host's floating-point
// state (no IEEE_DENORMAL or IEEE_UNDERFLOW_FLAG note at a Fortran STOP).
// Rounding is round-to-nearest, as the core assumes, whatever the caller set.
//
// Cost: one STMXCSR and two LDMXCSR per call, about 8 ns (doc/performance.md).
// Other architectures: no change of mode; layer 1 holds.
#pragma once

#if defined(__x86_64__) || defined(_M_X64)
#include <xmmintrin.h>
#define CREEPWORK_HAVE_MXCSR 1
#else
#define CREEPWORK_HAVE_MXCSR 0
#endif

namespace creepwork::capi {

class ScopedFpMode {
public:
#if CREEPWORK_HAVE_MXCSR
    ScopedFpMode() noexcept : saved_(_mm_getcsr()) { _mm_setcsr(kCallMode); }
    ~ScopedFpMode() { _mm_setcsr(saved_); }
#else
    ScopedFpMode() noexcept {}
#endif
    ScopedFpMode(const ScopedFpMode&) = delete;
    ScopedFpMode& operator=(const ScopedFpMode&) = delete;

private:
#if CREEPWORK_HAVE_MXCSR
    // MXCSR: all six exceptions masked (bits 7-12), flags clear (0-5),
    // round to nearest (13-14 = 0), denormals-are-zero (6), flush-to-zero (15).
    static constexpr unsigned kCallMode = 0x1f80u | (1u << 6) | (1u << 15);
    unsigned saved_;
#endif
};

} // namespace creepwork::capi
