#include "march/march_setup.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "contact/contact_input.hpp"
#include "contact/error.hpp"
#include "contact/friction_law.hpp"
#include "contact/flexibility_blending.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;

} // namespace

DiscreteLoad discrete_load(const ContactGrid& grid)
{
    DiscreteLoad load;
    const Eigen::ArrayXd& P = grid.pressure_shape(PressureKind::parabolic);
    const Eigen::ArrayXd& E = grid.pressure_shape(PressureKind::elliptic);
    const int ny = grid.ny();
    for (int j = 0; j < ny; ++j) {
        double p = 0.0, e = 0.0;
        for (int m = 0; m < grid.nx(); ++m) {
            const Eigen::Index k = static_cast<Eigen::Index>(m) * ny + j;
            p += P[k];
            e += E[k];
        }
        const double area = grid.x_length()[j] * grid.y_width()[j];
        load.parabolic += area * p;
        load.elliptic += area * e;
    }
    return load;
}

double discrete_load_of(const DiscreteLoad& load, PressureKind pressure)
{
    return pressure == PressureKind::parabolic ? load.parabolic : load.elliptic;
}

ModelSetup make_model_setup(const ContactInput& in, double load)
{
    validate_contact_input(in);
    ModelSetup s;
    s.a = in.a;
    s.b = in.b;
    double p0 = 0.0;
    if (in.exact_load) {
        if (!(load > 0.0))
            throw Error(ErrorKind::invalid_input,
                        "exact_load = 1: the grid has no contact element to carry the load");
        s.pressure_per_force = 1.0 / (in.a * in.b * load);
        p0 = in.normal_force * s.pressure_per_force;
    } else if (in.pressure == PressureKind::parabolic) {
        s.pressure_per_force = 2.0 / (kPi * in.a * in.b);
        p0 = 2.0 * in.normal_force / (kPi * in.a * in.b);
    } else {
        s.pressure_per_force = 3.0 / (2.0 * kPi * in.a * in.b);
        p0 = 3.0 * in.normal_force / (2.0 * kPi * in.a * in.b);
    }
    s.pressure = in.pressure;
    s.pressure_scale = p0;
    s.traction_scale = traction_bound(friction_law(in), p0);
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
    if (in.flexibility_blending) {
        const Flexibilities L = blend_flexibilities({s.L1, s.L2, s.L3}, in.a, in.b, in.mu,
                                                    in.normal_force, in.xi_x, in.xi_y, in.phi);
        s.L1 = L.L1;
        s.L2 = L.L2;
        s.L3 = L.L3;
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
    s.kin_divisor = divisor;
    if (divisor > 0.0) {
        s.kin.ux = n[0] / divisor;
        s.kin.uy = n[1] / divisor;
        s.kin.cx = n[2] / divisor;
        s.kin.cy = n[3] / divisor;
    }
    // FASTSIM's default is Kalker's: no offset (params.hpp).
    s.kin.spin_offset = in.spin_offset >= 0.0 ? in.spin_offset : 0.0;
    return s;
}

} // namespace creepwork
