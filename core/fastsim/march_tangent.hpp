// Forward-mode differentiation of the FASTSIM march (march/march.hpp) in the same
// pass: every strip carries, beside its traction p', the derivatives of p'
// with respect to the march's three kinematic parameters
//   k = 0: ux,  k = 1: uy,  k = 2: kappa = a phi / (L3 mu p0)
// (the spin enters the rigid slip only through cx = b kappa and cy = a kappa,
// march/march_setup.hpp). The chain rule from these to the caller's xi_x, xi_y,
// phi and N is fastsim_jacobian.cpp's.
//
// Per element, with q' the elastic predictor and g the traction bound:
//   dq = inside (dp_prev - h dw_k)
//   adhesion (|q| <= g):  dp = dq
//   slip     (|q| >  g):  dp = f (dq - q (q.dq)/|q|^2),   f = g/|q|
//                        = f dq - (f/g^2) (p.dq) p        (p = f q, |p| = g)
// (the second form needs no division: 1/g^2 is made once per grid), i.e.
// the derivative of the projection onto the disc of radius g, with the
// element's state (adhesion or slip) taken as the primal march found it. At
// an element exactly on the bound (|q| = g) the march takes adhesion and so
// does its derivative: the one-sided derivative from inside the disc. The
// rigid-slip derivatives dw_k: ux (1, 0); uy (0, 1); kappa
// (-b Y, a (X_slip + spin_offset dX)).
//
// The primal part is march_step() itself, summed in the same order, so the
// march state and its sums are bitwise those of march(): the Jacobian is the
// derivative of exactly the totals a forces-only solve reports.
#pragma once

#include <Eigen/Core>

#include "contact/contact_grid.hpp"
#include "march/march_setup.hpp"
#include "march/march.hpp"
#include "march/march_step.hpp"

namespace creepwork {

constexpr int kTangents = 3; // ux, uy, kappa

// Per strip (j < stride, the kernels' layout): for each tangent k the sums
// over the strip of dp'_x, dp'_y and X dp'_y, at [k * stride + j].
struct TangentState {
    int stride = 0;
    // Per element: 1/g^2 of each pressure law (0 where g = 0), made once.
    Eigen::ArrayXd inv_bound2_parabolic, inv_bound2_elliptic;
    Eigen::ArrayXd sum_px, sum_py, sum_x_py;
    // Per strip: dwx/dkappa = -b Y and the strip part of dwy/dkappa, a
    // spin_offset dX (scratch, set by march_tangent()).
    Eigen::ArrayXd kappa_wx, kappa_wy;

    void resize(const MarchGeometry& geometry);
};

// The kappa tangent's rigid slip per strip into t.kappa_wx, t.kappa_wy:
// -b Y and the strip part of a (X_slip + spin_offset dX).
void set_kappa_slip(const ContactGrid& grid, const ModelSetup& setup, TangentState& t);

// The march of view (as march(), bitwise the same state) and its tangents,
// with FASTSIM's bound for setup.pressure. Writes the view's state and
// tangents (sized by resize()); allocates nothing.
void march_tangent(const MarchView& view, const ContactGrid& grid, const ModelSetup& setup,
                   TangentState& tangents, KernelIsa isa);

} // namespace creepwork
