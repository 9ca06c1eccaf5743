#include "calibrated/calibration_table.hpp"

#include <cmath>

#include "contact/kalker_coefficients.hpp"

namespace creepwork {

NormalisedCreepage normalised_creepage(const ContactInput& in)
{
    NormalisedCreepage s;
    const double muN = in.mu * in.normal_force;
    if (!(muN > 0.0)) return s;
    const CreepCoefficients C = kalker_coefficients(in.a / in.b, in.nu);
    const double c2 = in.a * in.b, c = std::sqrt(c2);
    s.s_long = in.xi_x * in.G * c2 * C.C11 / muN;
    s.s_lat = in.xi_y * in.G * c2 * C.C22 / muN;
    s.s_spin = in.phi * in.G * c2 * c * C.C23 / muN;
    return s;
}

CalibrationParams calibration_for(const ContactInput& in)
{
    (void)in;
    return CalibrationParams{};
}

} // namespace creepwork
