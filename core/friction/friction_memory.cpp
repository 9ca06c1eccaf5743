#include "friction/friction_memory.hpp"

#include "contact/error.hpp"

#include <algorithm>
#include <cmath>

namespace creepwork {

FrictionValue friction_value(const MemoryElement& e, double s)
{
    const FrictionValue steady = friction_value(*e.law, s);
    // CONTACT treats d_c <= 1e-9 mm as no memory: theta = 0.
    if (!(e.memory.distance > 0.0)) return steady;
    const double d_c = e.memory.distance;
    const bool above = s > e.memory.s0;
    const double denominator = d_c + e.dt * (above ? s : e.memory.s0);
    const double theta = d_c / denominator;
    const double dtheta = above ? -d_c * e.dt / (denominator * denominator) : 0.0;
    return {theta * e.mu_prev + (1.0 - theta) * steady.mu,
            dtheta * (e.mu_prev - steady.mu) + (1.0 - theta) * steady.dmu_ds};
}

void memory_row(const SlipSpeedLaw& law, const FrictionMemory& memory, double dt, const double* s,
                int n, double* mu)
{
    MemoryElement e{&law, memory, dt, static_friction(law)};
    for (int i = 0; i < n; ++i) {
        mu[i] = friction_value(e, s[i]).mu;
        e.mu_prev = mu[i];
    }
}

void check_friction_memory(const FrictionMemory& memory)
{
    if (!(std::isfinite(memory.distance) && memory.distance >= 0.0))
        throw Error(ErrorKind::invalid_input, "memory_distance must be finite and >= 0 [m]");
    if (!(std::isfinite(memory.s0) && memory.s0 >= 0.0))
        throw Error(ErrorKind::invalid_input, "memory_s0 must be finite and >= 0 [m/s]");
}

} // namespace creepwork
