// The one primal step of the march and what every march kernel reads: the
// view of the march's data (MarchView, made by march_view() alone, field by
// field), the element step (march_step) and the step-and-store of one vector
// of strips (PrimalStrip). The plain march (march.cpp), FASTSIM's tangent
// march (fastsim/march_tangent.cpp) and the calibrated model's directional
// march (calibrated/march_directional.cpp) all advance through PrimalStrip,
// so their primal state and sums are the same operations in the same order:
// a change to the step is made here once.
#pragma once

#include "contact/friction_law.hpp"
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
// L mu p0), then the friction law's projection (contact/friction_law.hpp):
// slip when |q| > g, and then p = f q with f = g/|q| < 1; otherwise f = 1
// (exterior elements have q = g = 0 and so restart the strip from zero
// displacement: each contact segment of a strip is marched from its own
// leading edge).
//
// g is 0 (exterior, padding) or at least ~1e-32 (a grid's pressure shape),
// so for creepages in the practical range q, |q|^2 and f stay normal numbers
// (tests/robustness/test_robustness_fptrap_kernels.cpp); absurd inputs are
// the C ABI's floating-point mode's business (capi/capi_fp_mode.hpp).
template <int W>
struct MarchStep : Projection<W> {
    simd::Vec<W> qx, qy;
};

template <int W>
CREEPWORK_INLINE MarchStep<W> march_step(const simd::Vec<W>& px_prev, const simd::Vec<W>& py_prev,
                                         const simd::Vec<W>& h, const simd::Vec<W>& inside,
                                         const simd::Vec<W>& bound, const simd::Vec<W>& wx,
                                         const simd::Vec<W>& wy)
{
    MarchStep<W> s;
    s.qx = inside * (px_prev - h * wx);
    s.qy = inside * (py_prev - h * wy);
    static_cast<Projection<W>&>(s) = project_traction<W>(s.qx, s.qy, bound);
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
