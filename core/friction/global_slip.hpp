// CONTACT's FASTSIM with a friction law of the slip speed (its M=2/3 with
// L=2..4; m_solvpt.f90, fastsim_params): one coefficient for the whole
// contact, mu(w) at the rigid slip speed w = V |(xi_x, xi_y)| as Polach's
// model takes it, and Spiryagin's slope reduction of the flexibilities
// (Spiryagin, Polach, Cole, Vehicle System Dynamics 51 (2013) 1765-1783):
//   L_i / k,  k = k0 (alpha_inf + (1 - alpha_inf) / (1 + beta eps)),
//   eps = G pi a b k0 C11 nu / (4 mu N),  nu = |(xi_x, nu_phi)|,
//   nu_phi = xi_y + phi a, or xi_y where that is smaller in size.
// k0 = alpha_inf = 1 is no reduction. The result is an input for the
// FASTSIM model: its mu and its (given) flexibilities.
#pragma once

#include "contact/contact_grid.hpp"
#include "contact/jacobian.hpp"
#include "contact/params.hpp"
#include "friction/slip_speed_law.hpp"

namespace creepwork {

struct SlopeReduction {
    double k0 = 1.0;        // initial reduction [-] > 0
    double alpha_inf = 1.0; // its share left at large creepage [-], 0..1
    double beta = 0.0;      // how fast the reduction goes [-] >= 0
};

struct GlobalSlip {
    double slip_speed = 0.0; // w = V |(xi_x, xi_y)| [m/s]
    double mu = 0.0;         // mu(w)
    double epsilon = 0.0;    // Spiryagin's eps
    double k = 1.0;          // the reduction factor
};

// CONTACT's equivalent ellipse of a discrete contact (m_hertz.f90,
// equiv_ellipse): with A the contact elements' area and l, w the lengths of
// the box spanned by them along x and y, a_e = sqrt(A/pi) sqrt(l/w),
// b_e = sqrt(A/pi) sqrt(w/l). On a uniform grid its eps is CONTACT's; on the
// strip grid (no box) the semi-axes a, b are returned.
struct SemiAxes {
    double a = 0.0, b = 0.0; // [m]
};
SemiAxes equivalent_ellipse(const ContactGrid& grid, double a, double b);

// w, mu(w), eps and k for this contact: V [m/s], GC11 = G C11 [Pa] (the
// shear modulus times Kalker's coefficient; 8a / (3 L1) from a given L1).
GlobalSlip global_slip(const ContactInput& in, const SlipSpeedLaw& law, const SlopeReduction& sr,
                       double V, double GC11);

// The input FASTSIM solves on this grid: mu = mu(w) and the flexibilities
// (Kalker's from G and nu, or the given ones) divided by k, given; eps on
// the grid's equivalent ellipse with C11 at its a_e / b_e (from given
// flexibilities G C11 = 8 a / (3 L1) of the nominal ellipse). Throws
// Error(invalid_input) naming a bad law parameter, k0, alpha_inf, beta, or
// V (finite, and > 0 for a law other than Coulomb's).
ContactInput global_slip_input(const ContactInput& in, const ContactGrid& grid,
                               const SlipSpeedLaw& law, const SlopeReduction& sr, double V,
                               GlobalSlip* out = nullptr);

// The Jacobian of the global-slip FASTSIM, d(Fx, Fy, Mz)/d(xi_x, xi_y, phi,
// N), from FASTSIM's Jacobian J and forces F at the input global_slip_input()
// made (its mu(w) and flexibilities L/k held fixed there), by the chain rule
// through mu(w) and k. It uses two identities of FASTSIM: its forces are
// homogeneous of degree 1 in (creepages, mu), so dF/dmu = (F - sum_c xi_c
// dF/dxi_c)/mu; and dividing every flexibility by k is multiplying every
// creepage by k. Needs flexibility_blending off (blending breaks the second
// identity): an error names it.
Jacobian global_slip_jacobian(const ContactInput& in, const ContactGrid& grid,
                              const SlipSpeedLaw& law, const SlopeReduction& sr, double V,
                              const Jacobian& J, const double F[3]);

// Throws Error(invalid_input) naming k0, alpha_inf or beta when out of range.
void check_slope_reduction(const SlopeReduction& sr);

} // namespace creepwork
