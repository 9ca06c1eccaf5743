// Forward-mode differentiation of the march (march/march.hpp) along
// directions of the calibrated model's whole setup, whose kinematics and
// traction bound all move with the caller's inputs (its table's factors,
// flexibility equalisation, edge gain and bound blend depend on the
// saturation level). fastsim/march_tangent.hpp is the special case of
// FASTSIM's three kinematic parameters, kept for its speed.
//
// A direction k gives the derivatives of what the march reads:
//   wx[k * stride + j], wy[k * stride + j]  each strip's rigid slip over
//       flexibility along x and its part along y that is constant along the
//       strip (as calibrated_rigid_slip() makes them),
//   cy[k]     the coefficient of X_slip in the y part (uy + cy X_slip),
//   blend[k]  the bound blend (blended_bound.hpp; parabolic pressure only).
// Per element, with q' the elastic predictor and g the bound:
//   dq = inside (dp_prev - h (dwx, dwy + dcy X_slip))
//   adhesion (|q| <= g):  dp = dq
//   slip     (|q| >  g):  dp = f (dq - q (q.dq)/|q|^2) + dg q/|q|
//                        = f dq - (f/g^2) (p.dq) p + (dg/g) p
// with dg = dblend d(shape)/d(blend) = dblend (0.75 sqrt(P) - P)
// (blended_bound.hpp). The element's state is the one the primal march found
// (on the bound: adhesion, the one-sided derivative from inside). The primal
// part is the march's own step (march/march_step.hpp): the state and its sums
// are bitwise those of march().
#pragma once

#include <Eigen/Core>

#include "contact/contact_grid.hpp"
#include "contact/jacobian.hpp"
#include "march/march_setup.hpp"
#include "march/march.hpp"
#include "march/march_step.hpp"

namespace creepwork {

// One per creepage: xi_x, xi_y, phi. The traction scale T = mu p0 does not
// move along them (it depends on N only); models homogeneous in (creepages,
// N) get the N column from Euler's identity (calibrated_model.cpp).
constexpr int kMarchDirections = 3;

struct MarchDirections {
    int stride = 0;
    // Inputs (see above), [k * stride + j] and per direction.
    Eigen::ArrayXd wx, wy;
    double cy[kMarchDirections] = {}, blend[kMarchDirections] = {};
    // Outputs: per direction and strip, the derivatives of the strip's sums
    // of p'_x, p'_y and X p'_y (MarchState's sums), [k * stride + j].
    Eigen::ArrayXd sum_px, sum_py, sum_x_py;

    void resize(int ny); // stride = padded_strips(ny)
};

// The march of view (as march(), bitwise the same state and sums) and its
// derivatives along every direction. Throws nothing; allocates nothing.
// A direction with blend != 0 needs the parabolic pressure (the blend is
// relative to it); callers check.
void march_directional(const MarchView& view, const MarchGeometry& geometry,
                       MarchDirections& directions, KernelIsa isa);

// Fx, Fy, Mz (caller's frame) differentiated along the directions, from the
// state and sums march_directional() left: column k of rows jac_Fx..jac_Mz
// (jacobian.hpp) is direction k; column jac_N and row jac_W are left 0 (the
// caller's).
Jacobian directional_jacobian(const ModelSetup& setup, const ContactGrid& grid,
                              const MarchState& march, const MarchDirections& directions);

} // namespace creepwork
