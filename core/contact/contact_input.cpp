#include "contact/contact_input.hpp"

#include <cmath>
#include <string>

#include "contact/error.hpp"
#include "contact/number_text.hpp"

namespace creepwork {

[[noreturn]] void reject_input(const char* name, double value, const char* rule)
{
    throw Error(ErrorKind::invalid_input,
                std::string(name) + " = " + number_text(value) + " is invalid: " + rule);
}

void require_finite(const char* name, double v)
{
    if (!std::isfinite(v)) reject_input(name, v, "must be a finite number");
}

void require_positive(const char* name, double v)
{
    require_finite(name, v);
    if (!(v > 0.0)) reject_input(name, v, "must be > 0");
}

void require_non_negative(const char* name, double v)
{
    require_finite(name, v);
    if (!(v >= 0.0)) reject_input(name, v, "must be >= 0");
}

void validate_contact_input(const ContactInput& in)
{
    require_positive("a", in.a);
    require_positive("b", in.b);
    const double ratio = in.a / in.b;
    if (!(ratio >= kMinAspect && ratio <= kMaxAspect))
        reject_input("a/b", ratio, "must lie in [1e-3, 1e3] (range of Kalker's coefficients)");
    require_non_negative("normal_force", in.normal_force);
    validate_friction_input(in);
    if (in.flexibility == FlexibilitySource::kalker_from_material) {
        require_positive("G", in.G);
        require_finite("nu", in.nu);
        if (!(in.nu >= 0.0 && in.nu <= 0.5)) reject_input("nu", in.nu, "must lie in [0, 0.5]");
    } else if (in.flexibility == FlexibilitySource::given) {
        require_positive("L1", in.L1);
        require_positive("L2", in.L2);
        require_positive("L3", in.L3);
    } else {
        reject_input("flexibility", static_cast<double>(in.flexibility), "unknown flexibility source");
    }
    require_finite("xi_x", in.xi_x);
    require_finite("xi_y", in.xi_y);
    require_finite("phi", in.phi);
    if (in.pressure != PressureKind::parabolic && in.pressure != PressureKind::elliptic)
        reject_input("pressure", static_cast<double>(in.pressure), "unknown pressure law");
    if (in.rolling_direction != 1 && in.rolling_direction != -1)
        reject_input("rolling_direction", in.rolling_direction, "must be +1 or -1");
    if (in.model != ModelKind::fastsim && in.model != ModelKind::exact &&
        in.model != ModelKind::calibrated)
        reject_input("model", static_cast<double>(in.model), "unknown model");
    require_non_negative("tolerance", in.tolerance);
    if (!(in.tolerance < 1.0)) reject_input("tolerance", in.tolerance, "must be < 1 (relative)");
    if (in.max_iterations < 0)
        reject_input("max_iterations", in.max_iterations, "must be >= 0 (0: the model's default)");
    require_finite("spin_offset", in.spin_offset);
    if (in.spin_offset > 1.0)
        reject_input("spin_offset", in.spin_offset,
                     "must lie in [0, 1] (a fraction of the element length), or be negative "
                     "for the model's default");
}

void validate_friction_input(const ContactInput& in)
{
    require_non_negative("mu", in.mu);
    require_finite("V", in.V);
    if (!(in.V >= 0.0))
        reject_input("V", in.V, "must be >= 0 (the rolling speed [m/s]; 0: not given)");
    // Coulomb's law reads none of the rest: its defaults are never checked,
    // so a caller's params cut before them solve as they always did.
    const FrictionLaw law = in.friction_law;
    if (law != FrictionLaw::coulomb && law != FrictionLaw::linear &&
        law != FrictionLaw::rational && law != FrictionLaw::exponential)
        reject_input("friction_law", static_cast<double>(law),
                     "must be coulomb (0), linear (2), rational (3) or exponential (4)");
    if (in.friction_speed != FrictionSpeed::local && in.friction_speed != FrictionSpeed::global)
        reject_input("friction_speed", static_cast<double>(in.friction_speed),
                     "must be local (0) or global (1)");
    if (law != FrictionLaw::coulomb) {
        require_non_negative("mu_e1", in.mu_e1);
        require_non_negative("mu_e2", in.mu_e2);
        if (in.mu_e1 > 0.0) require_positive("s_h1", in.s_h1);
        if (in.mu_e2 > 0.0) require_positive("s_h2", in.s_h2);
        if (!(in.V > 0.0))
            reject_input("V", in.V,
                         "must be > 0 (the rolling speed [m/s]): a friction law of the slip "
                         "speed needs it");
    }
    if (in.friction_speed == FrictionSpeed::global) {
        require_positive("k0", in.k0);
        require_finite("alpha_inf", in.alpha_inf);
        if (!(in.alpha_inf >= 0.0 && in.alpha_inf <= 1.0))
            reject_input("alpha_inf", in.alpha_inf, "must lie in [0, 1]");
        require_non_negative("beta", in.beta);
    }
    require_non_negative("memory_distance", in.memory_distance);
    require_non_negative("memory_s0", in.memory_s0);
    if (in.memory_distance > 0.0 && in.friction_speed != FrictionSpeed::local)
        reject_input("memory_distance", in.memory_distance,
                     "friction memory needs friction_speed = local (each element's slip speed)");
}

void validate_layer_input(const ContactInput& in)
{
    require_non_negative("layer_h", in.layer_h);
    require_non_negative("layer_G", in.layer_G);
    require_non_negative("tau_c0", in.tau_c0);
    require_finite("k_tau", in.k_tau);
    if (in.layer_h > 0.0 && !(in.layer_G > 0.0))
        reject_input("layer_G", in.layer_G,
                     "must be > 0 [Pa] when layer_h > 0 (the layer's shear modulus G3)");
    if (in.k_tau != 0.0 && !(in.tau_c0 > 0.0))
        reject_input("k_tau", in.k_tau,
                     "needs tau_c0 > 0 (the yield stress it hardens or softens) [Pa/m]");
}

const char* layer_input_name(const ContactInput& in)
{
    if (in.layer_h != 0.0) return "layer_h";
    if (in.tau_c0 != 0.0) return "tau_c0";
    if (in.k_tau != 0.0) return "k_tau";
    return nullptr;
}

void validate_grid_input(const GridSpec& grid, const ContactInput& in)
{
    if (grid.kind == GridKind::gap) return;
    if (in.gap)
        throw Error(ErrorKind::invalid_input,
                    "gap is given but the grid is not a gap grid (CW_GRID_GAP)");
    if (in.normal_load != NormalLoad::force)
        throw Error(ErrorKind::invalid_input,
                    "normal_load = approach needs a gap grid (CW_GRID_GAP)");
    if (in.normal_method != NormalMethod::exact)
        throw Error(ErrorKind::invalid_input,
                    "normal_method = semi_hertz needs a gap grid (CW_GRID_GAP)");
}

} // namespace creepwork
