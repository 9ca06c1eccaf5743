// Coulomb's law for one element of the steady-rolling problem, solved
// exactly (doc/theory/exact-discretisation.md rule 7). In normalised units (tractions
// per mu p0) the element's slip is s = c + diag(b1, b2) q, where c holds the
// rigid slip and everything the other elements contribute and b1, b2 > 0
// are the element's own (diagonal) coefficients. Find q with
//   adhesion: s = 0 and |q| <= g, or
//   slip:     |q| = g and q = -g s / |s|.
// With q = -g e (|e| = 1) slip reads (sigma + g b1) e1 = c1,
// (sigma + g b2) e2 = c2 with sigma = |s| >= 0: one monotone equation for
// sigma, solved by Newton's method from below (it is convex).
#pragma once

#include <complex>

namespace creepwork {

// dq = J dc: the derivative of q with respect to c, for Newton's method.
struct LocalJacobian {
    double j11 = 0, j12 = 0, j21 = 0, j22 = 0;
};

// Returns true for slip. g >= 0; b1, b2 > 0. q and J are always written.
bool solve_local_friction(std::complex<double> c, double b1, double b2, double g,
                          std::complex<double>& q, LocalJacobian& J);

} // namespace creepwork
