// One slipping element of FASTSIM's march under a law of the slip speed:
// the step the march calls in place of Coulomb's projection. The element's
// elastic predictor has traction magnitude P (the traction it would carry
// if it adhered); slipping, it keeps the predictor's direction and a
// magnitude t < P, and slides at the slip speed s = c (P - t) [m/s], where
// c = V L / h (rolling speed, flexibility, step) turns lost traction into
// slip speed (CONTACT m_solvpt.f90: h s = u - u' + h w). The law closes it:
//   t = p_n mu(c (P - t)).
// Coulomb's law gives t = p_n mu at once. The root is sought in
// [0, min(P, p_n mu(0))], where g(t) = t - p_n mu(c (P - t)) changes sign
// (g(0) <= 0, g(top) >= 0) once the element slips (P > p_n mu(0)); a law that
// falls faster than 1/(c p_n) may have several roots there (the multiple
// solutions of instantaneous laws that friction memory removes): the one
// found is the bracket's safeguarded Newton root, the same for the same
// inputs.
#pragma once

#include "friction/slip_speed_law.hpp"

namespace creepwork {

struct LocalSlip {
    double t = 0.0;     // traction magnitude [Pa]
    double s = 0.0;     // slip speed c (P - t) [m/s]
    double mu = 0.0;    // mu(s)
    double dt_dP = 0.0; // derivative of t with respect to P at fixed p_n
    double dt_dpn = 0.0; // derivative of t with respect to p_n at fixed P
    double dt_dc = 0.0;  // derivative of t with respect to c at fixed P, p_n
    int iterations = 0; // Newton steps taken
};

// P > p_n mu(0) >= 0 (the element slips), c > 0. Newton starts from
// t = p_n mu_guess (clamped into the bracket): a march passes the previous
// element's mu, so that one or two steps suffice; a negative mu_guess starts
// from the bracket's top.
LocalSlip local_slip(const SlipSpeedLaw& law, double P, double pn, double c,
                     double mu_guess = -1.0);

} // namespace creepwork
