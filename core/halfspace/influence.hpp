// Influence coefficients of Kalker's exact half-space theory on a uniform
// grid: the displacement difference at the centre of one element caused by a
// unit traction spread uniformly over another element (the Boussinesq and
// Cerruti solutions integrated over a rectangle; Kalker 1990, section 1.5;
// CONTACT's m_visc.f90:elascf_pcwcns, see
// doc/theory/exact-discretisation.md rule 3).
//
// For an observation element at offset (k, l) elements from the loaded one
// (k along x, l along y; "observation minus load"), quasi-identical bodies
// with combined shear modulus G and Poisson ratio nu, u = cf * p / G with
//   cf11 = ((1 - nu) X + Y) / pi     cf22 = (X + (1 - nu) Y) / pi
//   cf12 = cf21 = nu R / pi          cf33 = (1 - nu) (X + Y) / pi
// (the factor 2 for the two bodies included). X, Y and R do not depend on nu
// and are homogeneous of degree 1 in length, so they are tabulated once for
// an element of length 1 and width rho = dy/dx and scaled by dx: X, Y, R are
// even in k and l except R, which is odd in both.
#pragma once

namespace creepwork {

struct InfluenceParts {
    double X = 0, Y = 0, R = 0;
};

// The parts of cf for offset (k, l) on elements of length 1 and width rho.
// Evaluated with inverse hyperbolic sines instead of CONTACT's logarithms of
// (y + r): the same function without the cancellation of y + r for y < 0.
InfluenceParts influence_parts(int k, int l, double rho);

// The quadrant 0 <= k <= kmax, 0 <= l <= lmax at once, sharing the corner
// terms (three transcendental evaluations per offset instead of twelve).
// X, Y, R each hold (kmax + 1) * (lmax + 1) values at [k + (kmax + 1) * l];
// work holds at least 3 * (kmax + 2) * (lmax + 2) doubles.
void influence_quadrant(int kmax, int lmax, double rho, double* X, double* Y, double* R,
                        double* work);

} // namespace creepwork
