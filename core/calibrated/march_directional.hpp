// Forward-mode differentiation of the FASTSIM march (march/march.hpp) along
// directions of its whole setup, for models built on the march whose
// kinematics and traction bound all move with the caller's inputs
// (calibrated/: its table's factors, flexibility equalisation, edge gain and
// bound blend depend on the saturation level). march_tangent.hpp is the
// special case of FASTSIM's three kinematic parameters, kept for its speed.
//
// A direction k gives the derivatives of what the march reads:
//   wx[k * stride + j], wy[k * stride + j]  each strip's rigid slip over
//       flexibility along x and its part along y that is constant along the
//       strip (as rigid_slip_of_strips() makes them),
//   cy[k]     the coefficient of X_slip in the y part (uy + cy X_slip),
//   blend[k]  the bound blend (bound_shape.hpp; parabolic pressure only).
// Per element, with q' the elastic predictor and g the bound:
//   dq = inside (dp_prev - h (dwx, dwy + dcy X_slip))
//   adhesion (|q| <= g):  dp = dq
//   slip     (|q| >  g):  dp = f (dq - q (q.dq)/|q|^2) + dg q/|q|
//                        = f dq - (f/g^2) (p.dq) p + (dg/g) p
// with dg = dblend d(shape)/d(blend) (bound_shape.hpp): 0.75 sqrt(P) - P for
// blends >= 0, 1.5 P^2 - P below. The element's state is the one the primal
// march found (on the bound: adhesion, the one-sided derivative from inside).
// The primal part is march_step() in march()'s order: the state and its sums
// are bitwise those of march().
#pragma once

#include <Eigen/Core>

#include "contact/contact_grid.hpp"
#include "contact/jacobian.hpp"
#include "march/march_setup.hpp"
#include "march/march.hpp"

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

// The march (as march(), bitwise the same state and sums) and its
// derivatives along every direction. Throws nothing; allocates nothing.
// A direction with blend != 0 needs the parabolic pressure (the blend is
// relative to it); callers check.
void march_directional(const MarchGeometry& geometry, const ContactGrid& grid,
                       const ModelSetup& setup, MarchState& state, MarchDirections& directions,
                       KernelIsa isa);

// Fx, Fy, Mz (caller's frame) differentiated along the directions, from the
// state and sums march_directional() left: column k of rows jac_Fx..jac_Mz
// (jacobian.hpp) is direction k; column jac_N and row jac_W are left 0 (the
// caller's).
Jacobian directional_jacobian(const ModelSetup& setup, const ContactGrid& grid,
                              const MarchState& march, const MarchDirections& directions);

// Rolling-frame forces over the traction scale T, Phi = (fx, fy, mz) / T, from
// the march sums, and their derivatives along n tangents whose per-strip sums
// are at [k * stride + j] (MarchDirections, TangentState). n <= 4.
void scaled_forces_and_derivatives(const ContactGrid& grid, double a, double b,
                                   const MarchState& march, const double* t_sum_px,
                                   const double* t_sum_py, const double* t_sum_x_py, int stride,
                                   int n, double Phi[3], double dPhi[3][4]);

} // namespace creepwork
