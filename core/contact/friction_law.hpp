// The friction law: the one place every model takes its local law from --
// the friction coefficient (mu applied to a pressure here alone), the
// projection of a trial traction onto the bound and the projection's
// derivative. The FASTSIM-class marches (march/march_step.hpp and their
// tangent kernels), the gap march (gap/gap_march.cpp and its tangent) and
// the exact models (their traction scale mu p_ref) all call these.
//
// A law is a small type with
//   coefficient(s)  mu(s) [-] at the slip speed s = |micro-slip| V [m/s],
//   slope(s)        dmu/ds [s/m], for Newton's method and the Jacobians,
//   uses_slip_speed whether mu depends on s (false: s is never formed).
// CoulombLaw is every model's law. ConstantLaw is the same mu written as a
// law of the slip speed: it takes the path a law of s takes and gives
// Coulomb's bits (tests/core/test_core_friction_law.cpp). Adding a law:
// CONTRIBUTING.md, "How to add a friction law".
//
// The projection (Coulomb's, at the bound g = mu(s) p): q -> p = f q with
// f = g/|q| when |q| > g (slip), f = 1 otherwise; its derivative in slip
//   dp = f dq - c p,  c = r (p . dq) - dg/g,  r = f/g^2,
// where dg/g is the bound's own relative change (a change of the pressure,
// the calibrated model's blend, or -- for a law of s -- (dmu/ds) ds / mu).
// The vector form (march kernels) and the scalar form (gap march, written
// with e = q/|q|) are this formula in the roundings each model has always
// had: the outputs keep their bits.
#pragma once

#include <cmath>
#include <cstddef>

#include "contact/params.hpp"
#include "simd/simd.hpp"

namespace creepwork {

// Coulomb's law: mu constant.
struct CoulombLaw {
    double mu = 0.0;
    static constexpr bool uses_slip_speed = false;
    double coefficient(double /*slip_speed*/) const { return mu; }
    double slope(double /*slip_speed*/) const { return 0.0; }
};

// A constant mu written as a law of the slip speed: the hook's example and
// its test (bitwise Coulomb's).
struct ConstantLaw {
    double mu = 0.0;
    static constexpr bool uses_slip_speed = true;
    double coefficient(double /*slip_speed*/) const { return mu; }
    double slope(double /*slip_speed*/) const { return 0.0; }
};

// The law of an input (Coulomb's, the input's mu).
inline CoulombLaw friction_law(const ContactInput& in) { return CoulombLaw{in.mu}; }

// The traction bound mu(s) p [Pa] at pressure p [Pa] and slip speed s
// [m/s]: the one place mu scales a traction (the march's and the exact
// models' traction scale mu p0, the gap march's bound mu pz).
template <class Law>
inline double traction_bound(const Law& law, double pressure, double slip_speed = 0.0)
{
    return law.coefficient(slip_speed) * pressure;
}

// Element-wise factors on the coefficient: friction that depends on a field
// of the surface (the temperature, thermal/friction_temperature.hpp). Element
// k's coefficient is factor[k] mu(s), its bound factor[k] mu(s) p. factor
// holds nx*ny values >= 0 at [i + j*nx] in the caller's layout; a model
// whose x runs mirrored against the caller's reads element i' = nx - 1 - i
// (the exact models for rolling_direction -1, the march for +1: it starts
// at the leading edge).
// Without factors (null) the bound is the law's alone, bitwise.
struct ElementFriction {
    const double* factor = nullptr;
    int nx = 0;
    bool mirrored = false;
    // Where the model's element (0, 0) lies in its whole grid (a model that
    // solves on a box of the grid, the gap grid's exact model).
    int i0 = 0, j0 = 0;
    bool active() const { return factor != nullptr; }
    // Element (i, j) of the model's layout.
    double at(int i, int j) const
    {
        const int g = i0 + i;
        return factor[static_cast<std::size_t>(mirrored ? nx - 1 - g : g) +
                      static_cast<std::size_t>(nx) * (j0 + j)];
    }
};

// Scales the bounds of elements (i, j), i < nx, j < ny of the model's
// layout, stored at g[i step_i + j step_j], by the element-wise factors;
// nothing without them.
inline void scale_bounds(const ElementFriction& f, double* g, int nx, int ny, std::size_t step_i,
                         std::size_t step_j)
{
    if (!f.active()) return;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            g[static_cast<std::size_t>(i) * step_i + step_j * static_cast<std::size_t>(j)] *=
                f.at(i, j);
}
// The same for g[i + nx j] (the exact models).
inline void scale_bounds(const ElementFriction& f, double* g, int nx, int ny)
{
    scale_bounds(f, g, nx, ny, 1, static_cast<std::size_t>(nx));
}

// ---- the vector form (the march kernels, W strips at once)

template <int W>
struct Projection {
    using V = simd::Vec<W>;
    V f, px, py, slip; // slip: 1 or 0
    bool any_slip;
};

// q -> p at the bound g per lane (g >= 0). The division never sees a zero
// (hosts may trap FP exceptions).
//
// Shortcut, exact: when every lane has |q|^2 <= g^2 (1 - 2^-50) with g^2 a
// normal number, or |q|^2 = 0 = g^2, then RN(sqrt(|q|^2)) <= g in every lane
// (the margin covers the rounding of g^2 and of the product), so no lane
// slips and the square root and the division are skipped: f = 1, p = q,
// exactly as the full test gives. It applies to adhesion zones, exterior
// elements and the padding strips.
//
// Floating-point exceptions (doc/reference/guarantees.md): no lane, live or
// masked, divides by zero (safe_norm), takes the root of a negative number,
// or meets a subnormal constant (the test for g = 0 is |q|^2 <= 0, not a
// comparison with the smallest subnormal).
template <int W>
CREEPWORK_INLINE Projection<W> project_traction(const simd::Vec<W>& qx, const simd::Vec<W>& qy,
                                                const simd::Vec<W>& bound)
{
    using V = simd::Vec<W>;
    const V one = simd::broadcast<W>(1.0), zero = simd::broadcast<W>(0.0);
    const V tiny = simd::broadcast<W>(2.2250738585072014e-308); // DBL_MIN
    const V margin = simd::broadcast<W>(1.0 - 0x1p-50);
    Projection<W> s;
    const V n2 = qx * qx + qy * qy;
    const V g2 = bound * bound;
    const V threshold = g2 >= tiny ? g2 * margin : zero; // g = 0: only q = 0
    if (simd::min_lane((n2 <= threshold) ? one : zero) > 0.0) {
        s.f = one;
        s.px = qx;
        s.py = qy;
        s.slip = zero;
        s.any_slip = false;
        return s;
    }
    const V norm = simd::sqrt<W>(n2);
    const V safe_norm = norm > tiny ? norm : tiny;
    const auto slip = norm > bound;
    s.f = slip ? bound / safe_norm : one;
    s.px = s.f * qx;
    s.py = s.f * qy;
    s.slip = slip ? one : zero;
    s.any_slip = simd::max_lane(s.slip) > 0.0;
    return s;
}

// dp of dq in the lanes where r != 0 (r = f/g^2 in slip, 0 in adhesion,
// where dp = dq follows with f = 1): dp = f dq - r (p . dq) p.
template <int W>
CREEPWORK_INLINE void projection_derivative(const Projection<W>& s, const simd::Vec<W>& r,
                                            const simd::Vec<W>& dqx, const simd::Vec<W>& dqy,
                                            simd::Vec<W>& dpx, simd::Vec<W>& dpy)
{
    const simd::Vec<W> c = r * (s.px * dqx + s.py * dqy);
    dpx = s.f * dqx - c * s.px;
    dpy = s.f * dqy - c * s.py;
}

// The same with the bound's own relative change dg/g (0 outside slip).
template <int W>
CREEPWORK_INLINE void projection_derivative(const Projection<W>& s, const simd::Vec<W>& r,
                                            const simd::Vec<W>& dqx, const simd::Vec<W>& dqy,
                                            const simd::Vec<W>& dbound_over_bound,
                                            simd::Vec<W>& dpx, simd::Vec<W>& dpy)
{
    const simd::Vec<W> cb = r * (s.px * dqx + s.py * dqy) - dbound_over_bound;
    dpx = s.f * dqx - cb * s.px;
    dpy = s.f * dqy - cb * s.py;
}

// ---- the scalar form (the gap march, one element)

struct ScalarProjection {
    bool slips = false;
    double f = 1.0, norm = 0.0; // norm: |q|, set in slip
};

// q -> p at the bound g >= 0, in place. |q| > g compared squared: the root
// only in slip (the gap march keeps dx |omega| far below overflow).
inline ScalarProjection project_traction(double& qx, double& qy, double bound)
{
    ScalarProjection s;
    const double n2 = qx * qx + qy * qy;
    s.slips = n2 > bound * bound;
    if (s.slips) {
        s.norm = std::sqrt(n2);
        s.f = bound / s.norm; // |q| > bound >= 0
        qx *= s.f;
        qy *= s.f;
    }
    return s;
}

// dp of dq in slip, with e = q/|q| of the trial q: dp = f (dq - e (e . dq))
// (the bound's own change e dg is the caller's: it adds to the columns
// that move the bound).
inline void projection_derivative(const ScalarProjection& s, double ex, double ey, double& dqx,
                                  double& dqy)
{
    const double along = ex * dqx + ey * dqy;
    dqx = s.f * (dqx - ex * along);
    dqy = s.f * (dqy - ey * along);
}

} // namespace creepwork
