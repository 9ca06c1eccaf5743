// The chain rule from the march's tangents (march_tangent.hpp: derivatives of
// each strip's traction sums with respect to ux, uy, kappa) to the caller's
// Jacobian of Fx, Fy, Mz with respect to xi_x, xi_y, phi and N.
//
// What N moves, as the model defines it: the pressure scale p0 (2N/(pi a b)
// parabolic, 3N/(2 pi a b) elliptic) and so the traction bound mu p0 and the
// normalised creepages a xi/(L mu p0); with flexibility blending also the
// characteristic creepage, and so L1..L3. Held fixed: the semi-axes a, b
// (inputs of the model, not derived from N), mu, G, nu and Kalker's
// L1..L3 (functions of a, b, G, nu only) or the given L1..L3.
//
// Creepages beyond kMaxNormalisedCreepage (march/march_setup.hpp): the march
// runs on rescaled kinematics and every element slides, so the tractions do
// not depend on the scale and the rescaling needs no derivative.
#pragma once

#include "contact/contact_grid.hpp"
#include "contact/jacobian.hpp"
#include "contact/params.hpp"
#include "march/march_setup.hpp"
#include "march/march.hpp"
#include "fastsim/march_tangent.hpp"

namespace creepwork {

// Rows Fx, Fy, Mz (the W_macro row is the caller's, jacobian_work_row).
// Throws Error(invalid_input) for normal_force = 0 with mu > 0: the forces
// are then not differentiable in N (only from above).
Jacobian fastsim_jacobian(const ContactInput& input, const ModelSetup& setup,
                          const ContactGrid& grid, const MarchState& march,
                          const TangentState& tangents);

} // namespace creepwork
