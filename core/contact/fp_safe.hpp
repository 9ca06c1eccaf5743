// Arithmetic that raises no floating-point exception, whatever the compiler
// speculates. The core is built with -fno-trapping-math (so the kernels
// vectorise), which lets the compiler evaluate both sides of `c ? x / y : 0`
// -- in vector lanes it then discards, or in a branch-free scalar select --
// and so divide by zero, or 0 by 0, in a host that traps FP exceptions
// (doc/reference/guarantees.md). It even folds a guarded operand back:
// `d > 0 ? p / (d > 0 ? d : 1) : 0` was compiled as a packed p / d. Here the
// divisor passes through an empty asm, which hides its value from the
// optimiser, so the division can only ever see the safe operand.
#pragma once

namespace creepwork {

// v unchanged, but opaque to the optimiser: a double, or a vector of them
// (DoublePair below) in one register.
template <class T>
inline T fp_opaque(T v)
{
#if defined(__clang__) && defined(__x86_64__)
    // clang checks a register constraint against the translation unit's
    // ISA, not that of the AVX kernel the call is inlined into: a vector
    // wider than SSE's passes through memory instead.
    if constexpr (sizeof(T) > 16)
        __asm__("" : "+m"(v));
    else
        __asm__("" : "+x"(v));
#elif defined(__GNUC__) && defined(__x86_64__)
    __asm__("" : "+x"(v));
#elif defined(__GNUC__) && defined(__aarch64__)
    __asm__("" : "+w"(v));
#else
    volatile T copy = v;
    v = copy;
#endif
    return v;
}

// num / den when den != 0, else 0. The caller guarantees that the quotient
// does not overflow.
inline double quotient_or_zero(double num, double den)
{
    const bool ok = den != 0.0;
    return (ok ? num : 0.0) / fp_opaque(ok ? den : 1.0);
}

// num / den when den > 0, else 0.
inline double quotient_if_positive(double num, double den)
{
    const bool ok = den > 0.0;
    return (ok ? num : 0.0) / fp_opaque(ok ? den : 1.0);
}

// Two lanes at once (GCC's vector extension), for loops that take two
// elements per step: the same operations lane by lane, so the same bits.
typedef double DoublePair __attribute__((vector_size(16)));

inline DoublePair quotient_if_positive(DoublePair num, DoublePair den)
{
    const DoublePair zero = {0.0, 0.0}, one = {1.0, 1.0};
    const auto ok = den > zero;
    return (ok ? num : zero) / fp_opaque(ok ? den : one);
}

} // namespace creepwork
