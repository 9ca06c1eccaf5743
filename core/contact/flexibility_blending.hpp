// CONTACT's blending of the three flexibilities of the simplified theory
// (Vollebregt & Kalker, CONTACT, src/m_hertz.f90, subroutine simpflex, with
// use_blending on: what CONTACT's FASTSIM does by default for prescribed
// creepages). FASTSIM with Kalker's three L's is right at small creepage;
// at large creepage one flexibility fits the exact theory better. CONTACT
// moves from L1, L2, L3 towards one combined L_crss as the creepage grows:
//
//   t      = phi (pi a^2/4) / (8 a/3)                      spin, as a creepage
//   L_crss = (xi^2 + eta^2 + t^2) / (xi^2/L1 + eta^2/L2 + t^2/L3)
//   f      = max(1e-10, sqrt((xi^2 + eta^2) / (ch_xi^2 + ch_eta^2)))
//   w      = min(1, f/3)
//   Li    <- (1 - w) Li + w L_crss,   i = 1, 2, 3
//
// with the characteristic creepages ch_xi = mu N/(c^2 G C11) and
// ch_eta = mu N/(c^2 G C22), c^2 = a b, written here through Kalker's
// L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G) as ch_xi = 3 mu N L1/(8 a^2 b),
// ch_eta = 3 mu N L2/(8 a^2 b), so that given flexibilities blend too.
// Note w >= 3.3e-11 always: even at zero creepage CONTACT's L's differ from
// Kalker's in the 11th digit.
//
// Departures, all below rounding of CONTACT's printed output: CONTACT floors
// the denominator of L_crss at 1e-14 in its units (mm, N), which matters
// only for creepages below ~1e-9; here the sums are scaled by the largest
// term so that no square can overflow, and mu N = 0 (no traction at all)
// gives w = 1 for nonzero creepage (CONTACT would divide by zero).
#pragma once

#include "contact/kalker_coefficients.hpp"

namespace creepwork {

Flexibilities blend_flexibilities(const Flexibilities& L, double a, double b, double mu,
                                  double normal_force, double xi, double eta, double phi);

// Derivatives of blend_flexibilities' L1, L2, L3 (index i) with respect to
// xi, eta, phi and normal_force (index k), d[i][k], on the branch the
// function takes at these inputs (the kinks of w = min(1, max(1e-10, f)/3)
// give the derivative of the side the value is taken from). At zero
// creepage the blend is constant (w = 1e-10/3, L_crss read as 0) and so are
// its derivatives, zero; they only ever multiply creepages in the chain rule.
void blend_flexibilities_derivatives(const Flexibilities& L, double a, double b, double mu,
                                     double normal_force, double xi, double eta, double phi,
                                     double d[3][4]);

} // namespace creepwork
