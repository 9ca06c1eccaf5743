#include "friction/friction_memory.hpp"

#include "contact/error.hpp"

#include <algorithm>
#include <cmath>

namespace creepwork {

void memory_row(const SlipSpeedLaw& law, const FrictionMemory& memory, double dt, const double* s,
                int n, double* mu)
{
    double previous = static_friction(law);
    for (int i = 0; i < n; ++i) {
        const double steady = friction_value(law, s[i]).mu;
        // CONTACT treats d_c <= 1e-9 mm as no memory: theta = 0.
        const double theta = memory.distance > 0.0
                                 ? memory.distance /
                                       (memory.distance + dt * std::max(s[i], memory.s0))
                                 : 0.0;
        mu[i] = theta * previous + (1.0 - theta) * steady;
        previous = mu[i];
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
