#include "model_setup.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "error.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void reject(const char* name, double value, const char* rule)
{
    std::ostringstream msg;
    msg.precision(17);
    msg << name << " = " << value << " is invalid: " << rule;
    throw Error(ErrorKind::invalid_input, msg.str());
}

void require_finite(const char* name, double v)
{
    if (!std::isfinite(v)) reject(name, v, "must be a finite number");
}

void require_positive(const char* name, double v)
{
    require_finite(name, v);
    if (!(v > 0.0)) reject(name, v, "must be > 0");
}

void require_non_negative(const char* name, double v)
{
    require_finite(name, v);
    if (!(v >= 0.0)) reject(name, v, "must be >= 0");
}

void validate(const ContactInput& in)
{
    require_positive("a", in.a);
    require_positive("b", in.b);
    const double ratio = in.a / in.b;
    if (!(ratio >= kMinAspect && ratio <= kMaxAspect))
        reject("a/b", ratio, "must lie in [1e-3, 1e3] (range of Kalker's coefficients)");
    require_non_negative("normal_force", in.normal_force);
    require_non_negative("mu", in.mu);
    if (in.flexibility == FlexibilitySource::kalker_from_material) {
        require_positive("G", in.G);
        require_finite("nu", in.nu);
        if (!(in.nu >= 0.0 && in.nu <= 0.5)) reject("nu", in.nu, "must lie in [0, 0.5]");
    } else if (in.flexibility == FlexibilitySource::given) {
        require_positive("L1", in.L1);
        require_positive("L2", in.L2);
        require_positive("L3", in.L3);
    } else {
        reject("flexibility", static_cast<double>(in.flexibility), "unknown flexibility source");
    }
    require_finite("xi_x", in.xi_x);
    require_finite("xi_y", in.xi_y);
    require_finite("phi", in.phi);
    if (in.pressure != PressureKind::parabolic && in.pressure != PressureKind::elliptic)
        reject("pressure", static_cast<double>(in.pressure), "unknown pressure law");
    if (in.rolling_direction != 1 && in.rolling_direction != -1)
        reject("rolling_direction", in.rolling_direction, "must be +1 or -1");
}

} // namespace

ModelSetup make_model_setup(const ContactInput& in)
{
    validate(in);
    ModelSetup s;
    s.a = in.a;
    s.b = in.b;
    const double p0 = in.pressure == PressureKind::parabolic
                          ? 2.0 * in.normal_force / (kPi * in.a * in.b)
                          : 3.0 * in.normal_force / (2.0 * kPi * in.a * in.b);
    s.pressure = in.pressure;
    s.pressure_scale = p0;
    s.traction_scale = in.mu * p0;
    if (in.flexibility == FlexibilitySource::kalker_from_material) {
        s.C = kalker_coefficients(in.a / in.b, in.nu);
        const Flexibilities L = kalker_flexibilities(in.a, in.b, in.G, s.C);
        s.L1 = L.L1;
        s.L2 = L.L2;
        s.L3 = L.L3;
    } else {
        s.L1 = in.L1;
        s.L2 = in.L2;
        s.L3 = in.L3;
    }
    if (!std::isfinite(s.L1 * s.L2 * s.L3) || !std::isfinite(s.traction_scale))
        throw Error(ErrorKind::invalid_input,
                    "G, L1..L3, normal_force or a, b are so extreme that the flexibilities or "
                    "the pressure overflow");

    // Mirror x when rolling towards -x: the model always marches from x' = +a.
    s.direction = in.rolling_direction;
    s.xi = s.direction * in.xi_x;
    s.eta = in.xi_y;
    s.phi = s.direction * in.phi;

    // Rigid slip over flexibility, before division by mu*p0 (paper eqs. 22-25).
    double n[4] = {s.a * s.xi / s.L1, s.a * s.eta / s.L2, s.a * s.b * s.phi / s.L3,
                   s.a * s.a * s.phi / s.L3};
    const double largest = std::max({std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2]),
                                     std::fabs(n[3])});
    if (!std::isfinite(largest))
        throw Error(ErrorKind::invalid_input,
                    "xi_x, xi_y or phi is so large that the rigid slip overflows");
    double divisor = s.traction_scale;
    if (largest > kMaxNormalisedCreepage * divisor) divisor = largest / kMaxNormalisedCreepage;
    if (divisor > 0.0) {
        s.kin.ux = n[0] / divisor;
        s.kin.uy = n[1] / divisor;
        s.kin.cx = n[2] / divisor;
        s.kin.cy = n[3] / divisor;
    }
    return s;
}

} // namespace creepwork
