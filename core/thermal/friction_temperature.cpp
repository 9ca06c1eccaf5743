#include "thermal/friction_temperature.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/error.hpp"
#include "contact/number_text.hpp"

namespace creepwork::thermal {

namespace {

[[noreturn]] void reject(const std::string& what)
{
    throw Error(ErrorKind::invalid_input, "mu_T: " + what);
}

std::string entry(const char* name, std::size_t k, double v)
{
    return std::string(name) + "[" + std::to_string(k) + "] = " + number_text(v);
}

} // namespace

void validate(const FrictionTemperature& t)
{
    if (t.count < 2)
        reject("count = " + std::to_string(t.count) +
               ": the table needs at least 2 points");
    if (!t.temperature || !t.mu) reject(std::string(!t.temperature ? "temperature" : "mu") + " is NULL");
    for (std::size_t k = 0; k < t.count; ++k) {
        const double T = t.temperature[k], mu = t.mu[k];
        if (!std::isfinite(T)) reject(entry("temperature", k, T) + " is not finite");
        if (!(T >= -273.15)) reject(entry("temperature", k, T) + " is below absolute zero [deg C]");
        if (!std::isfinite(mu) || !(mu > 0.0))
            reject(entry("mu", k, mu) + " must be finite and > 0");
        if (k > 0 && !(T > t.temperature[k - 1]))
            reject(entry("temperature", k, T) + " is not above " +
                   entry("temperature", k - 1, t.temperature[k - 1]) +
                   ": the temperatures must increase");
    }
}

double mu_of_temperature(const FrictionTemperature& t, double T)
{
    const double* x = t.temperature;
    const std::size_t n = t.count;
    if (!(T > x[0])) return t.mu[0];
    if (T >= x[n - 1]) return t.mu[n - 1];
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(x, x + n, T) - x); // x[k-1] <= T < x[k]
    const double w = (T - x[k - 1]) / (x[k] - x[k - 1]);
    return t.mu[k - 1] + w * (t.mu[k] - t.mu[k - 1]);
}

double mu_max(const FrictionTemperature& t) { return *std::max_element(t.mu, t.mu + t.count); }

void friction_factors(const FrictionTemperature& t, double mu_ref, long n, const double* T,
                      double* factor)
{
    for (long e = 0; e < n; ++e) factor[e] = mu_of_temperature(t, T[e]) / mu_ref;
}

} // namespace creepwork::thermal
