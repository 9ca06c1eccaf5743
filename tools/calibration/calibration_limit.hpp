// A model's continuum limit of one total from its three finest grids
// (creepwork_calibration discretisation): Q(h) = Q0 + C h^p with h = 1/n.
#pragma once

namespace cwcal {

struct ContinuumLimit {
    double value = 0;  // Q0, or the finest value when the order is not clean
    double order = 0;  // p when richardson, else 0
    bool richardson = false;
    bool resolved = false; // the differences are at rounding level: nothing to see
};

// h[0] > h[1] > h[2] and the values q on them. The order p solves
// (q2 - q1)/(q1 - q0) = (h2^p - h1^p)/(h1^p - h0^p) (grids need not be in a
// constant ratio). It is clean when the two differences have one sign and
// shrink, and 0.5 <= p <= 4; then value = q2 + (q2 - q1) h2^p/(h1^p - h2^p)
// (Richardson from the two finest). Differences below 1e-10 scale count as
// resolved.
ContinuumLimit continuum_limit(const double h[3], const double q[3], double scale);

} // namespace cwcal
