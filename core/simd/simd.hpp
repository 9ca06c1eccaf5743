// GCC/Clang vector extensions for the march's kernels: one source for every
// ISA (kernel_isa.hpp), W lanes of double. Only IEEE add, subtract,
// multiply, divide and square root act on the lanes, so every ISA rounds
// alike.
#pragma once

#include <cstring>
#include <type_traits>

// Kernel bodies are inlined into each ISA's entry point and compiled there.
#define CREEPWORK_INLINE inline __attribute__((always_inline))
// Loops over the vectors of a group are unrolled, so that each vector's
// state stays in registers.
#if defined(__clang__)
#define CREEPWORK_UNROLL _Pragma("unroll")
#else
#define CREEPWORK_UNROLL _Pragma("GCC unroll 8")
#endif

namespace creepwork::simd {

template <int W>
struct VecOf;
template <>
struct VecOf<2> {
    typedef double type __attribute__((vector_size(16)));
};
template <>
struct VecOf<4> {
    typedef double type __attribute__((vector_size(32)));
};
template <>
struct VecOf<8> {
    typedef double type __attribute__((vector_size(64)));
};
template <int W>
using Vec = typename VecOf<W>::type;

// A V from p: a vector, or one double (the scalar tails of the export).
template <class V>
CREEPWORK_INLINE V load_as(const double* p)
{
    if constexpr (std::is_same_v<V, double>) {
        return *p;
    } else {
        V v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }
}
template <int W>
CREEPWORK_INLINE Vec<W> load(const double* p)
{
    return load_as<Vec<W>>(p);
}
// v to p: a vector, or one double.
template <class V>
CREEPWORK_INLINE void store_as(double* p, const V& v)
{
    std::memcpy(p, &v, sizeof v);
}
template <int W>
CREEPWORK_INLINE void store(double* p, const Vec<W>& v)
{
    std::memcpy(p, &v, sizeof v);
}
template <int W>
CREEPWORK_INLINE Vec<W> broadcast(double x)
{
    return Vec<W>{} + x;
}
// Lane by lane, so compilers emit the packed square root of the target.
template <int W>
CREEPWORK_INLINE Vec<W> sqrt(const Vec<W>& x)
{
    Vec<W> r;
    for (int l = 0; l < W; ++l) r[l] = __builtin_sqrt(x[l]);
    return r;
}
// Largest and smallest lane, halving the vector each time. Used on vectors
// of 0/1 flags made by selects (compilers turn vector comparisons that are
// combined or reduced as integer masks into per-lane scalar code).
CREEPWORK_INLINE double max_lane(const Vec<2>& v) { return v[0] > v[1] ? v[0] : v[1]; }
CREEPWORK_INLINE double min_lane(const Vec<2>& v) { return v[0] < v[1] ? v[0] : v[1]; }
CREEPWORK_INLINE double max_lane(const Vec<4>& v)
{
    const Vec<2> lo = __builtin_shufflevector(v, v, 0, 1), hi = __builtin_shufflevector(v, v, 2, 3);
    return max_lane(lo > hi ? lo : hi);
}
CREEPWORK_INLINE double min_lane(const Vec<4>& v)
{
    const Vec<2> lo = __builtin_shufflevector(v, v, 0, 1), hi = __builtin_shufflevector(v, v, 2, 3);
    return min_lane(lo < hi ? lo : hi);
}
CREEPWORK_INLINE double max_lane(const Vec<8>& v)
{
    const Vec<4> lo = __builtin_shufflevector(v, v, 0, 1, 2, 3),
                 hi = __builtin_shufflevector(v, v, 4, 5, 6, 7);
    return max_lane(lo > hi ? lo : hi);
}
CREEPWORK_INLINE double min_lane(const Vec<8>& v)
{
    const Vec<4> lo = __builtin_shufflevector(v, v, 0, 1, 2, 3),
                 hi = __builtin_shufflevector(v, v, 4, 5, 6, 7);
    return min_lane(lo < hi ? lo : hi);
}

} // namespace creepwork::simd
