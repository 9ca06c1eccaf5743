// Friction that depends on the surface temperature: mu(T) piecewise linear
// through points (T_k, mu_k), constant beyond the first and the last point.
// CONTACT's L=6 (its m_friclaw.f90, fric_tempdep_mu_temp) is the table of
// two points (TREF, FREF), (TREF + DTHEAT, FREF + DFHEAT). In a solve the
// table scales the friction law element by element (the friction hook's
// factors, contact/friction_law.hpp): element e's coefficient is
// mu_law(s) mu(T_e) / mu_law(0), Coulomb's mu(T_e) itself, T_e the rail's
// (body 1's) surface temperature at the element, as CONTACT's TEMP1.
#pragma once

#include <cstddef>

namespace creepwork::thermal {

struct FrictionTemperature {
    std::size_t count = 0;                 // points, >= 2
    const double* temperature = nullptr;   // [deg C], finite, strictly increasing
    const double* mu = nullptr;            // [-], finite, > 0
};

// Throws Error(invalid_input) naming the first offending entry
// (mu_T.temperature[k], mu_T.mu[k]) or the count (mu_T.count).
void validate(const FrictionTemperature& table);

// mu at temperature T [deg C] (a NaN T gives the first point's mu).
double mu_of_temperature(const FrictionTemperature& table, double T);

// The largest mu of the table: the friction law's unit under Coulomb's law.
double mu_max(const FrictionTemperature& table);

// factor[e] = mu(T[e]) / mu_ref for e < n (mu_ref > 0: the law's static
// coefficient).
void friction_factors(const FrictionTemperature& table, double mu_ref, long n, const double* T,
                      double* factor);

} // namespace creepwork::thermal
