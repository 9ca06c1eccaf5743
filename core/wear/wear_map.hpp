// The wear of one solved contact, element by element and strip by strip: a
// pure function of the per-element fields every model exports (area, pz,
// px, py, sx, sy, a work map) and the strip geometry of the grid. No
// allocation, no state.
//
// Per element e in strip j (width dy_j), with its frictional work per
// rolled distance W_e [J/m] (from the source chosen, negative parts -> 0):
//   work density   T_gamma/A = W_e / A_e                      [Pa]
//   sliding        s_e = W_e / (|p_e| A_e)  (consistent, paper: the slip
//                  that dissipates W_e under the element's traction; in
//                  slip |p| = mu pz, so this is W_e/(mu N_e)), or |s_e|
//                  (source slip: the model's micro-slip)          [-]
//   rate           USFD K(T_gamma/A); Archard rho k p s_e / H  [kg/m^3]
//   mass           rate A_e pass_length  (mass per pass)         [kg]
//   depth          rate A_e / (rho dy_j)   (depth per pass)      [m]
// A material point of strip j crosses element e while the contact rolls
// the element's length dx_e = A_e/dy_j, and loses rate dx_e / rho of depth
// there; summed along the strip that is the depth it loses per pass
// through the contact: per axle passage (rail) or per wheel revolution
// (wheel; per rolled distance: divide by 2 pi R). The mass per rolled
// distance is rate A_e [kg/m]: per metre of rail per axle passage, or x 2 pi R
// per wheel revolution (pass_length chooses which the "mass per pass" is).
#pragma once

#include "wear/wear_law.hpp"

namespace creepwork::wear {

// Inputs: per element [i + j*nx] (nx*ny values), per strip j (ny values).
struct ContactFields {
    int nx = 0, ny = 0;
    double b = 0.0;                  // lateral semi-axis [m] (for the parabola)
    const double* area = nullptr;    // [m^2], 0 outside the contact
    const double* pz = nullptr;      // [Pa]
    const double* px = nullptr;      // [Pa]
    const double* py = nullptr;      // [Pa]
    const double* sx = nullptr;      // [-] (source slip, and Archard with it)
    const double* sy = nullptr;      // [-]
    const double* work = nullptr;    // [J/m] (sources consistent and paper)
    const double* strip_y = nullptr;     // strip centre [m]
    const double* strip_width = nullptr; // strip width [m], > 0
};

// Outputs: per element (nx*ny) and per strip (ny); each may be null.
struct WearFields {
    double* rate = nullptr;          // [kg/m^3] mass per area per rolled distance
    double* depth = nullptr;         // [m] per pass
    double* mass = nullptr;          // [kg] per pass (x pass_length)
    double* work_density = nullptr;  // T_gamma/A [Pa]
    double* sliding = nullptr;       // s_e [-]
    int* regime = nullptr;           // kRegime*
    double* strip_depth = nullptr;   // [m] per pass, sum over the strip
    double* strip_parabola = nullptr; // [m] per pass: the same worn volume as an
                                      // equal-area parabola over [-b, b], averaged
                                      // over each strip (the paper's assumption)
};

struct WearTotals {
    double mass_per_distance = 0;  // [kg/m] sum rate A_e
    double mass_per_pass = 0;      // [kg]   x pass_length
    double volume_per_distance = 0; // [m^3/m] mass_per_distance / rho
    double max_depth = 0;          // [m] largest strip depth per pass
    double work = 0;               // [J/m] frictional work the law was fed with
    double regime_area[kRegimeCount] = {0, 0, 0, 0}; // [m^2] area in regime 1..4
};

// Throws Error(invalid_input) for a bad law, Error(numeric_failure) if a
// result is not finite (it cannot be for validated laws and finite fields).
WearTotals wear_map(const ContactFields& in, const WearLaw& law, const WearFields& out);

// The average over [lo, hi] of the equal-volume parabola (3 V/(4 b))(1 -
// y^2/b^2), zero outside [-b, b]: V [m^2] the worn cross-section, b > 0.
double parabola_strip_average(double V, double b, double lo, double hi);

} // namespace creepwork::wear
