// The FASTSIM march (Kalker 1982) in normalised units: tractions p' in units
// of mu*p0, bound = pressure shape (1 at the centre). Strips are independent:
// the kernels advance a group of strips (several SIMD vectors of them) from
// the leading edge to the trailing edge together, with each strip's running
// traction and sums held in registers.
//
// Kernels. The hot loops are compiled for the baseline x86-64 ISA (SSE2, two
// strips per vector) and, on x86-64 with GCC or Clang, for AVX2 (four) and
// AVX-512 (eight); a solver picks the widest one the CPU runs once, when it
// is created. Results are bitwise identical whichever kernel runs: every
// operation is an IEEE add, subtract, multiply, divide or square root
// (correctly rounded on every ISA), no multiply-add is contracted
// (-ffp-contract=off, no -ffast-math), and every sum runs in a fixed order
// that does not depend on the vector width (each strip along the march, then
// the strips in order).
#pragma once

#include <cstring>

#include <Eigen/Core>

#include "contact/contact_grid.hpp"
#include "march/march_setup.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define CREEPWORK_X86_KERNELS 1
#define CREEPWORK_TARGET_AVX2 __attribute__((target("avx2")))
#define CREEPWORK_TARGET_AVX512 __attribute__((target("avx512f,avx512vl,avx512dq,avx512bw")))
#else
#define CREEPWORK_X86_KERNELS 0
#endif
// Kernel bodies are inlined into each ISA's entry point and compiled there.
#define CREEPWORK_INLINE inline __attribute__((always_inline))
// Loops over the vectors of a group are unrolled, so that each vector's
// state stays in registers.
#if defined(__clang__)
#define CREEPWORK_UNROLL _Pragma("unroll")
#else
#define CREEPWORK_UNROLL _Pragma("GCC unroll 8")
#endif

namespace creepwork {

enum class KernelIsa {
    baseline, // the build's own target (SSE2 on x86-64)
    avx2,
    avx512,   // AVX-512 F, VL, DQ, BW
};

// The widest kernel this CPU (and OS) runs.
KernelIsa best_kernel_isa();
bool kernel_isa_supported(KernelIsa isa);
const char* kernel_isa_name(KernelIsa isa); // "baseline", "avx2", "avx512"

// Strips are padded to a multiple of this (the widest vector), so that every
// kernel runs whole vectors. Padding strips are exterior: they stay zero.
constexpr int kStripPad = 8;
constexpr int padded_strips(int ny) { return (ny + kStripPad - 1) / kStripPad * kStripPad; }

// The grid's per-element arrays in the kernels' layout: [m * stride + j],
// stride = padded_strips(ny). Made once per solver.
struct MarchGeometry {
    int nx = 0, ny = 0, stride = 0;
    Eigen::ArrayXd x_centre, x_slip, step, inside, shape_parabolic, shape_elliptic;
    // The calibrated model's blended bound (bound_shape.hpp) for the blend
    // set_blend() last made, in units of the parabolic p0; empty until then.
    Eigen::ArrayXd shape_blended;
    double blend = 0.0, blend_max = 0.0; // blend_max: largest shape_blended
    double max_parabolic = 0.0;          // largest shape_parabolic

    MarchGeometry() = default;
    explicit MarchGeometry(const ContactGrid& grid);
    // The bound of the march: the pressure law's shape, or with a blend != 0
    // (NormalisedKinematics::bound_blend; parabolic units) shape_blended,
    // which set_blend(blend) must have made.
    const Eigen::ArrayXd& bound(PressureKind kind, double bound_blend = 0.0) const
    {
        if (bound_blend != 0.0) return shape_blended;
        return kind == PressureKind::parabolic ? shape_parabolic : shape_elliptic;
    }
    // Allocates shape_blended (models that blend call it when they are made,
    // so that their solves allocate nothing).
    void reserve_blend();
    // Makes shape_blended for this blend (nothing to do when it is the last
    // one); allocates only if reserve_blend() was not called.
    void set_blend(double bound_blend);
    // On the uniform grid, each strip's first step from where the strip
    // enters the ellipse (X = sqrt(1 - Y^2)), not a full element, and the
    // rigid slip at each step's midpoint, as Kalker's strip grid does: both
    // of CONTACT's choices (a full first step, the slip at the element
    // centre) are first-order errors. Used by the calibrated model; plain
    // FASTSIM keeps CONTACT's. Nothing to do on the strip grid.
    void march_from_leading_edge(const ContactGrid& grid);
};

// Per-element state of one solve, [m * stride + j] (see MarchGeometry): the
// trial traction q' (elastic predictor) and the factor f that scales it onto
// the traction bound: p' = f q', f = 1 in adhesion, f < 1 in slip. Slip,
// dissipation and every other field follow from (q', f).
struct MarchState {
    int nx = 0, ny = 0, stride = 0;
    Eigen::ArrayXd qx, qy, factor;
    // Per strip: sums over the strip of p'_x, p'_y and X p'_y, and the
    // number of slip elements (a double so the kernels stay all-double).
    Eigen::ArrayXd sum_px, sum_py, sum_x_py, slip_count;
    // Per strip: the traction leaving the trailing edge.
    Eigen::ArrayXd px, py;
    // Per strip: rigid slip over flexibility along x, ux - cx Y, and the
    // part of the one along y that does not vary along the strip, uy (plus
    // cy times the spin offset); scratch, set by set_rigid_slip().
    Eigen::ArrayXd wx, wy;

    void resize(int n_elements, int ny);
};

// The per-strip rigid slip of kin (state.wx, state.wy) for strips [first, last).
void set_rigid_slip(const ContactGrid& grid, const NormalisedKinematics& kin, MarchState& state,
                    int first, int last);
// The same into wx[j], wy[j] (callers that differentiate it).
void rigid_slip_of_strips(const ContactGrid& grid, const NormalisedKinematics& kin, double* wx,
                          double* wy, int first, int last);

// Advance every strip from the leading edge (m = 0) to the trailing edge.
// Writes state (sized by resize(nx * ny, ny)); allocates nothing.
void march(const MarchGeometry& geometry, const ContactGrid& grid,
           const NormalisedKinematics& kin, PressureKind pressure, MarchState& state,
           KernelIsa isa);
// Only strips [first, last) (first a multiple of kStripBlock), the rigid slip
// state.wx, state.wy of which is set: callers that follow each block with
// more work while its data are in cache.
constexpr int kStripBlock = 32;
void march_strips(const MarchGeometry& geometry, const NormalisedKinematics& kin,
                  PressureKind pressure, MarchState& state, KernelIsa isa, int first, int last);
// The same for a one-off grid (allocates its MarchGeometry).
void march(const ContactGrid& grid, const NormalisedKinematics& kin, PressureKind pressure,
           MarchState& state, KernelIsa isa = best_kernel_isa());

// ------------------------------------------------------------- kernel support
//
// GCC/Clang vector extensions: one source for every ISA; W lanes of double.
namespace simd {

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

template <int W>
CREEPWORK_INLINE Vec<W> load(const double* p)
{
    Vec<W> v;
    std::memcpy(&v, p, sizeof v);
    return v;
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

} // namespace simd

// One step of W strips: the elastic predictor u = u_prev - h w (divided by
// L mu p0), then Coulomb: slip when |q| > g, and then p = f q with
// f = g/|q| < 1; otherwise f = 1 (exterior elements have q = g = 0 and so
// restart the strip from zero displacement). The division never sees a zero
// (hosts may trap FP exceptions).
//
// Shortcut, exact: when every lane has |q|^2 <= g^2 (1 - 2^-50) with g^2 a
// normal number, or |q|^2 = 0 = g^2, then RN(sqrt(|q|^2)) <= g in every lane
// (the margin covers the rounding of g^2 and of the product), so no lane
// slips and the square root and the division are skipped: f = 1, p = q,
// exactly as the full test gives. It applies to adhesion zones, exterior
// elements and the padding strips.
//
// Floating-point exceptions (hosts may trap them, doc/reference/guarantees.md): no
// lane, live or masked, divides by zero (safe_norm), takes the root of a
// negative number, or meets a subnormal constant (the test for g = 0 is
// |q|^2 <= 0, not a comparison with the smallest subnormal). g is 0
// (exterior, padding) or at least ~1e-32 (a grid's pressure shape), so for
// creepages in the practical range q, |q|^2 and f stay normal numbers
// (tests/robustness/test_robustness_fptrap_kernels.cpp); absurd inputs are
// the C ABI's floating-point mode's business (capi/capi_fp_mode.hpp).
template <int W>
struct MarchStep {
    using V = simd::Vec<W>;
    V qx, qy, f, px, py, slip; // slip: 1 or 0
    bool any_slip;
};

template <int W>
CREEPWORK_INLINE MarchStep<W> march_step(const simd::Vec<W>& px_prev, const simd::Vec<W>& py_prev,
                                         const simd::Vec<W>& h, const simd::Vec<W>& inside,
                                         const simd::Vec<W>& bound, const simd::Vec<W>& wx,
                                         const simd::Vec<W>& wy)
{
    using V = simd::Vec<W>;
    const V one = simd::broadcast<W>(1.0), zero = simd::broadcast<W>(0.0);
    const V tiny = simd::broadcast<W>(2.2250738585072014e-308); // DBL_MIN
    const V margin = simd::broadcast<W>(1.0 - 0x1p-50);
    MarchStep<W> s;
    s.qx = inside * (px_prev - h * wx);
    s.qy = inside * (py_prev - h * wy);
    const V n2 = s.qx * s.qx + s.qy * s.qy;
    const V g2 = bound * bound;
    const V threshold = g2 >= tiny ? g2 * margin : zero; // g = 0: only q = 0
    if (simd::min_lane((n2 <= threshold) ? one : zero) > 0.0) {
        s.f = one;
        s.px = s.qx;
        s.py = s.qy;
        s.slip = zero;
        s.any_slip = false;
        return s;
    }
    const V norm = simd::sqrt<W>(n2);
    const V safe_norm = norm > tiny ? norm : tiny;
    const auto slip = norm > bound;
    s.f = slip ? bound / safe_norm : one;
    s.px = s.f * s.qx;
    s.py = s.f * s.qy;
    s.slip = slip ? one : zero;
    s.any_slip = simd::max_lane(s.slip) > 0.0;
    return s;
}

} // namespace creepwork
