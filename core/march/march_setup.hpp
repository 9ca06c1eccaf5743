// From the caller's ContactInput to the numbers the march needs: validation
// (every error names the input), flexibilities, and Kalker's normalised
// creepages in the rolling frame.
#pragma once

#include "contact/contact_grid.hpp"
#include "contact/kalker_coefficients.hpp"
#include "contact/params.hpp"

namespace creepwork {

// Normalised kinematics of FASTSIM (Kalker 1982; paper eqs. 13-25): tractions
// in units of mu*p0 (p0 = pressure scale of the chosen law), coordinates
// X = x/a, Y = y/b. The rigid slip divided by flexibility, in those units, is
//   (ux - cx * Y,  uy + cy * X).
struct NormalisedKinematics {
    double ux = 0, uy = 0; // a xi/(L1 mu p0), a eta/(L2 mu p0)
    double cx = 0, cy = 0; // a b phi/(L3 mu p0), a^2 phi/(L3 mu p0)
    // CONTACT's facphi: the spin term of the lateral rigid slip is taken
    // spin_offset element lengths ahead of the slip point, towards the
    // leading edge: uy + cy (X + spin_offset dX), dX the strip's element
    // length (x/a). 0 is Kalker's FASTSIM.
    double spin_offset = 0;
};

struct ModelSetup {
    double a = 0, b = 0;
    PressureKind pressure = PressureKind::parabolic;
    double pressure_scale = 0;   // p0 = 2N/(pi a b) (parabolic) or 3N/(2 pi a b) (elliptic),
                                 // or N/(a b I) with exact_load (DiscreteLoad) [Pa]
    double pressure_per_force = 0; // p0 / N [1/m^2]: the derivative the Jacobian needs
    double traction_scale = 0;   // mu * p0 [Pa]
    double L1 = 0, L2 = 0, L3 = 0; // in use: Kalker's or given, blended on request
    CreepCoefficients C{0, 0, 0, 0}; // zero when flexibilities were given
    int direction = 1;           // rolling direction, +1 or -1
    // Creepages in the rolling frame (x' = direction * x).
    double xi = 0, eta = 0, phi = 0;
    NormalisedKinematics kin;
    // kin = (rigid slip over flexibility) / kin_divisor: traction_scale,
    // or larger for creepages beyond kMaxNormalisedCreepage (0 when
    // traction_scale is 0).
    double kin_divisor = 0;
};

// The load a grid carries per unit pressure scale: over the contact elements
// of the grid, the sum of each pressure shape times the element area in
// units of a b. Over the unit disc the shapes integrate to pi/2 (parabolic
// P = 1 - X^2 - Y^2) and 2 pi/3 (elliptic, sqrt(P)); a grid's
// midpoint sums differ from these by up to a few tenths of a per cent, so the
// analytic scale p0 = N/(a b int) gives sum pz dA != N. With exact_load the
// scale is N/(a b sum) instead.
struct DiscreteLoad {
    double parabolic = 0, elliptic = 0;
};
DiscreteLoad discrete_load(const ContactGrid& grid);
// The sum of DiscreteLoad for the pressure law (unblended).
double discrete_load_of(const DiscreteLoad& load, PressureKind pressure);

// Throws Error(invalid_input) naming the first offending input. load: the
// grid's sum for in.pressure (or for the bound in use), read only when
// in.exact_load is set; it must then be > 0.
ModelSetup make_model_setup(const ContactInput& in, double load = 0.0);

// Largest magnitude of a normalised creepage; larger ones are scaled down
// together (direction kept) so that no intermediate can overflow. Such a
// contact slides everywhere; the scaling changes nothing measurable.
constexpr double kMaxNormalisedCreepage = 1e100;

} // namespace creepwork
