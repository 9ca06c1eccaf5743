// Hertz solution for two elastically similar bodies with a point contact:
// the contact ellipse from the principal relative curvatures, the load and
// the contact modulus (Johnson, Contact Mechanics, 1985, section 4.2).
#pragma once

namespace creepwork {

struct EllipticIntegrals {
    double K;            // complete elliptic integral of the first kind
    double E;            // complete elliptic integral of the second kind
    double K_minus_E;    // K - E without cancellation for small modulus
};

// Complete elliptic integrals K(k), E(k) for modulus 0 <= k < 1, by the
// arithmetic-geometric mean (converges quadratically; ~1e-16 relative).
EllipticIntegrals complete_elliptic_integrals(double k);

struct HertzContact {
    double a;         // semi-axis along x [m]
    double b;         // semi-axis along y [m]
    double p0;        // maximum pressure 3N/(2 pi a b) [Pa]
    double approach;  // mutual approach of distant points [m]
};

// Gap h = A x^2 + B y^2 (A, B > 0: principal relative curvatures [1/m]),
// normal force N >= 0 [N], contact modulus E* > 0 [Pa]
// (1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2; for identical bodies E* = G/(1-nu)).
HertzContact hertz_from_curvatures(double A, double B, double N, double E_star);

// The same contact from its semi-axes: the gap coefficients A, B (h = A x^2
// + B y^2) and the approach that Hertz's theory gives for semi-axes a, b
// under N with contact modulus E* (the inverse of hertz_from_curvatures;
// CONTACT's hzcalc3d for IPOTCN = -3).
struct HertzCurvatures {
    double A, B;     // gap coefficients [1/m]
    double p0;       // 3N/(2 pi a b) [Pa]
    double approach; // [m]
};
HertzCurvatures hertz_from_semi_axes(double a, double b, double N, double E_star);

} // namespace creepwork
