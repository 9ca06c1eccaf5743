// CONTACT's friction memory in steady rolling: the coefficient lags behind
// its steady value mu_s(s) over a characteristic slip distance d_c,
//   dmu/dt = -max(s, s0) / d_c (mu - mu_s(s)),
// integrated by implicit Euler along each row from the leading edge, with
// the time step dt = dx / V of one element rolled (CONTACT m_stang.f90;
// user guide, "friction memory"; Vollebregt & Schuttelaars, JSV 331 (2012)).
#pragma once

#include "friction/slip_speed_law.hpp"

namespace creepwork {

struct FrictionMemory {
    double distance = 0.0; // d_c [m] >= 0; 0: no memory, mu = mu_s(s)
    double s0 = 0.0;       // background slip speed [m/s] >= 0
};

// One element under memory, as a law of its own slip speed s:
//   mu_m(s) = theta(s) mu_prev + (1 - theta(s)) mu_s(s),
//   theta(s) = d_c / (d_c + dt max(s, s0)),
// mu_prev the coefficient of the element before it in the row. The model
// that solves an element's slip with it (local_slip.hpp) and memory_row()
// take the coefficient from here.
struct MemoryElement {
    const SlipSpeedLaw* law = nullptr;
    FrictionMemory memory;
    double dt = 0.0;      // [s] > 0
    double mu_prev = 0.0; // [-]
};

// mu_m(s) and dmu_m/ds (the right-hand slope at s = s0).
FrictionValue friction_value(const MemoryElement& element, double s);
// An upper bound of mu_m over every s: the law's static coefficient.
inline double static_friction(const MemoryElement& element) { return static_friction(*element.law); }

// One row of n elements from the leading edge (index 0) to the trailing
// edge: slip speed s[i] [m/s] in, mu[i] out. Before the leading edge mu is
// the static coefficient; then mu_i = theta_i mu_{i-1} + (1 - theta_i)
// mu_s(s_i), theta_i = d_c / (d_c + dt max(s_i, s0)), dt [s] > 0.
void memory_row(const SlipSpeedLaw& law, const FrictionMemory& memory, double dt, const double* s,
                int n, double* mu);

// Throws Error(invalid_input) naming memory_distance or memory_s0 when one
// is negative or not finite.
void check_friction_memory(const FrictionMemory& memory);

} // namespace creepwork
