// The one primal step of the march and what every march kernel reads: the
// view of the march's data (MarchView, made by march_view() alone, field by
// field), the element step (march_step) and the step-and-store of one vector
// of strips (PrimalStrip). The plain march (march.cpp), FASTSIM's tangent
// march (fastsim/march_tangent.cpp) and the calibrated model's directional
// march (calibrated/march_directional.cpp) all advance through PrimalStrip,
// so their primal state and sums are the same operations in the same order:
// a change to the step is made here once.
#pragma once

#include "march/march_geometry.hpp"
#include "simd/simd.hpp"

namespace creepwork {

// What the march kernels read and write, for strips [first, last): the
// grid in the kernels' layout, the traction bound, the rigid slip and the
// state of the solve. Per element [m * stride + j], per strip [j].
struct MarchView {
    int nx = 0, stride = 0, first = 0, last = 0;
    double cy = 0; // coefficient of X_slip in the lateral rigid slip
    const double *x_centre = nullptr, *x_slip = nullptr, *step = nullptr, *inside = nullptr;
    const double* bound = nullptr;                      // per element, the traction bound
    const double *wx = nullptr, *wy = nullptr;          // per strip, the rigid slip
    double *qx = nullptr, *qy = nullptr, *factor = nullptr; // per element, out
    double *px = nullptr, *py = nullptr;                // per strip, out: traction at the exit
    double *sum_px = nullptr, *sum_py = nullptr, *sum_x_py = nullptr, *slip_count = nullptr;
};

// The view of geometry and state with this bound (per element, the kernels'
// layout) and cy, for strips [first, last).
MarchView march_view(const MarchGeometry& geometry, const double* bound, double cy,
                     MarchState& state, int first, int last);

// One step of W strips: the elastic predictor u = u_prev - h w (divided by
// L mu p0), then Coulomb: slip when |q| > g, and then p = f q with
// f = g/|q| < 1; otherwise f = 1 (exterior elements have q = g = 0 and so
// restart the strip from zero displacement: each contact segment of a strip
// is marched from its own leading edge). The division never sees a zero
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

// The view's per-element pointers from strip j0 on, as locals: the kernels'
// stores may alias anything, so the view's own fields would be reloaded
// after each store.
struct MarchRows {
    const double *x_centre, *x_slip, *step, *inside, *bound;
    double *qx, *qy, *factor;

    CREEPWORK_INLINE MarchRows(const MarchView& v, int j0)
        : x_centre(v.x_centre + j0), x_slip(v.x_slip + j0), step(v.step + j0),
          inside(v.inside + j0), bound(v.bound + j0), qx(v.qx + j0), qy(v.qy + j0),
          factor(v.factor + j0)
    {
    }
};

// One element of W strips: the step and the inputs it read, for kernels
// that carry more than the primal march (tangents, directions).
template <int W>
struct MarchElement {
    const MarchStep<W>& s;
    const simd::Vec<W>&h, &inside, &x_slip, &x_centre, &bound;
};

// The primal march of one vector of W strips: its running traction and
// sums, held in registers from the leading edge (start) to the trailing
// edge (finish), one element per advance().
template <int W>
struct PrimalStrip {
    using V = simd::Vec<W>;
    V px, py, sum_px, sum_py, sum_x_py, slip_count, wx, wy;

    // Strip vector j: zero traction and sums, its rigid slip.
    CREEPWORK_INLINE void start(const MarchView& v, int j)
    {
        px = py = sum_px = sum_py = sum_x_py = slip_count = simd::broadcast<W>(0.0);
        wx = simd::load<W>(v.wx + j);
        wy = simd::load<W>(v.wy + j);
    }
    // The element at offset e of rows: the step (lateral rigid slip
    // wy + cy X_slip), q' and f stored, the sums accumulated; then
    // then(MarchElement) for kernels that carry more (the plain march
    // passes nothing).
    template <class Then>
    CREEPWORK_INLINE void advance(const MarchRows& rows, long e, const V& cy, const Then& then)
    {
        const V xs = simd::load<W>(rows.x_slip + e), h = simd::load<W>(rows.step + e),
                in = simd::load<W>(rows.inside + e), g = simd::load<W>(rows.bound + e);
        const MarchStep<W> s = march_step<W>(px, py, h, in, g, wx, wy + cy * xs);
        simd::store<W>(rows.qx + e, s.qx);
        simd::store<W>(rows.qy + e, s.qy);
        simd::store<W>(rows.factor + e, s.f);
        px = s.px;
        py = s.py;
        sum_px += s.px;
        sum_py += s.py;
        const V xc = simd::load<W>(rows.x_centre + e);
        sum_x_py += xc * s.py;
        slip_count += s.slip;
        then(MarchElement<W>{s, h, in, xs, xc, g});
    }
    CREEPWORK_INLINE void advance(const MarchRows& rows, long e, const V& cy)
    {
        advance(rows, e, cy, [](const MarchElement<W>&) {});
    }
    // Strip vector j's exit traction and sums into the view's per-strip
    // arrays.
    CREEPWORK_INLINE void finish(const MarchView& v, int j) const
    {
        simd::store<W>(v.px + j, px);
        simd::store<W>(v.py + j, py);
        simd::store<W>(v.sum_px + j, sum_px);
        simd::store<W>(v.sum_py + j, sum_py);
        simd::store<W>(v.sum_x_py + j, sum_x_py);
        simd::store<W>(v.slip_count + j, slip_count);
    }
};

} // namespace creepwork
