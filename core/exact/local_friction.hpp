// The friction law for one element of the steady-rolling problem, solved
// exactly (doc/theory/exact-discretisation.md rule 7). In normalised units (tractions
// per mu_s p0) the element's slip is s = c + diag(b1, b2) q, where c holds the
// rigid slip and everything the other elements contribute and b1, b2 > 0
// are the element's own (diagonal) coefficients. With the bound
// h = traction_bound(law, g, sigma) (contact/friction_law.hpp: g the
// element's pressure over p0, sigma = |s|) find q with
//   adhesion: s = 0 and |q| <= h(0), or
//   slip:     |q| = h(sigma) and q = -h s / |s|.
// With q = -h e (|e| = 1) slip reads (sigma + h b1) e1 = c1,
// (sigma + h b2) e2 = c2: one equation for sigma. Coulomb's h is constant
// and the equation monotone and convex, solved by Newton's method from
// below; under a law of the slip speed h falls with sigma, and a
// safeguarded Newton method keeps the root bracketed.
#pragma once

#include <complex>

#include "contact/friction_law.hpp"
#include "friction/friction_memory.hpp"
#include "friction/slip_speed_law.hpp"

namespace creepwork {

// dq = J dc: the derivative of q with respect to c, for Newton's method.
struct LocalJacobian {
    double j11 = 0, j12 = 0, j21 = 0, j22 = 0;
};

// A law of the slip speed in the local problem's units: the factor of the
// bound m(sigma) = mu(kappa sigma) / mu_ref at the normalised slip sigma,
// kappa = V times the unit of the normalised slip [m/s], mu_ref = mu(0)
// (the traction unit's coefficient, so m(0) = 1). A law of the friction
// hook (coefficient, slope by sigma, uses_slip_speed).
// Under friction memory (memory.distance > 0) the law is the element's
// mu_m(s) of friction_memory.hpp, with dt = dx / V [s] and mu_prev the
// coefficient of the element ahead, which the caller sets per element.
struct LocalLaw {
    SlipSpeedLaw law;
    double mu_ref = 1.0, kappa = 0.0;
    FrictionMemory memory;
    double dt = 0.0, mu_prev = 0.0;
    static constexpr bool uses_slip_speed = true;
    FrictionValue value(double sigma) const // m and dm/dsigma
    {
        const FrictionValue v = memory.distance > 0.0
                                    ? friction_value(MemoryElement{&law, memory, dt, mu_prev},
                                                     kappa * sigma)
                                    : friction_value(law, kappa * sigma);
        return {v.mu / mu_ref, v.dmu_ds * kappa / mu_ref};
    }
    double coefficient(double sigma) const { return value(sigma).mu; }
    double slope(double sigma) const { return value(sigma).dmu_ds; }
};

// What a slipping element under a law leaves for the derivatives: its
// factor m(sigma) and, per unit change of the bound's scale h, the change
// of q, u = -(I + J B0) e (so dq/dg = m u, and dq/dln kappa = sigma h' u
// with h' = dh/dsigma: the speed source).
struct ElementSlip {
    double m = 1.0;            // the bound's factor m(sigma) (1 in adhesion)
    double speed_source = 0.0; // sigma dh/dsigma
    std::complex<double> u{0.0, 0.0};
    int iterations = 0;        // the scalar equation's Newton steps
};

// The interface layer's yield with hardening or softening (k != 0) in the
// local problem's units, for one element: its friction bound g, the yield
// stress tau_ahead of the element ahead of it in the rolling direction,
// k = k_tau dx / G (the yield stress's change per unit of normalised
// plastic flow) and the floor of the yield stress (CONTACT's 0.1 tau_c0).
// The element flows -- plastically, sliding, or both -- by phi = |s|
// (s = c + B0 q, its total relative displacement per element length) under
// the bound
//   h(phi) = g                          if tau_ahead >= g (it slides, no yield),
//          = min(g, tau_ahead + k phi)  k > 0 (plastic flow until the yield
//                                       stress reaches g, then sliding),
//          = max(floor, tau_ahead + k phi)  k < 0 (plastic flow);
// its own yield stress, the next element's tau_ahead, is h(phi) when
// tau_ahead < g, else tau_ahead (and tau_ahead in adhesion).
struct YieldValue {
    double h = 0, h_phi = 0; // the bound and dh/dphi
    double h_t = 0, h_f = 0; // dh/dtau_ahead, dh/dfloor
};
struct YieldBound {
    double g = 0, tau_ahead = 0, k = 0, floor = 0;
    YieldValue at(double phi) const
    {
        if (!(tau_ahead < g)) return {g, 0.0, 0.0, 0.0};
        const double v = tau_ahead + k * phi;
        if (k > 0.0) return v < g ? YieldValue{v, k, 1.0, 0.0} : YieldValue{g, 0.0, 0.0, 0.0};
        return v > floor ? YieldValue{v, k, 1.0, 0.0} : YieldValue{floor, 0.0, 0.0, 1.0};
    }
};

// What a flowing element under the yield leaves for the derivatives: dq =
// J dc + u dh with dh = h_t dtau_ahead + h_f dfloor, the flow's direction e
// (dphi = e . (dc + B0 dq)), and its yield stress tau with dtau = h_phi dphi
// + dh when it follows h (else dtau = dtau_ahead).
struct YieldElement {
    std::complex<double> u{0.0, 0.0}, e{0.0, 0.0};
    double h_phi = 0.0, h_t = 0.0, h_f = 0.0, tau = 0.0;
    bool follows = false;
    int iterations = 0;
};

// Coulomb's law (the bound traction_bound(law, g): pass CoulombLaw{1} for
// the bound g itself). Returns true for slip. g >= 0; b1, b2 > 0. q and J
// are always written.
bool solve_local_friction(const CoulombLaw& law, std::complex<double> c, double b1, double b2,
                          double g, std::complex<double>& q, LocalJacobian& J);
inline bool solve_local_friction(std::complex<double> c, double b1, double b2, double g,
                                 std::complex<double>& q, LocalJacobian& J)
{
    return solve_local_friction(CoulombLaw{1.0}, c, b1, b2, g, q, J);
}

// A law of the slip speed: the same, with J holding the law's slope (dq =
// -M ds, M = (h/sigma)(I - e e^T) + h' e e^T) and slip's details in out
// (written in slip; m = 1 otherwise).
bool solve_local_friction(const LocalLaw& law, std::complex<double> c, double b1, double b2,
                          double g, std::complex<double>& q, LocalJacobian& J, ElementSlip& out);

// The yield with hardening or softening: adhesion when |B0^-1 c| <= h(0),
// else the flow under h(phi) (YieldBound). Returns true for flow (reported
// as slip); q, J and out are always written.
bool solve_local_yield(const YieldBound& bound, std::complex<double> c, double b1, double b2,
                       std::complex<double>& q, LocalJacobian& J, YieldElement& out);

} // namespace creepwork
