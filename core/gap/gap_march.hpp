// Kalker's simplified theory (FASTSIM) on a contact of any shape: every
// contact segment of every grid row (a run of elements with pressure > 0
// along x) is marched from its own leading edge (+x, element nx - 1 side)
// towards the trailing edge, starting from zero traction, with the traction
// bound mu pz per element. Each element's flexibilities and spin centre are
// those of the patch it belongs to (gap_fastsim_model.hpp says how they are
// chosen). The step is one element length dx and the rigid slip is taken at
// the element centre (CONTACT's discretisation of FASTSIM, as the uniform
// grid's march/march.hpp), so on an elliptic patch with the ellipse's own
// flexibilities this is that march.
//
// Per element, with omega the rigid slip over flexibility of its patch,
//   omega_x = (xi - phi yc) / L1 - phi (y - yc) / L3,
//   omega_y = (eta + phi xc) / L2 + phi (x + spin_offset dx - xc) / L3,
// the elastic predictor is q = p_prev - dx omega, and p = q, or
// p = mu pz q / |q| when |q| > mu pz (slip). The translation of the patch
// (its creepage, including the spin's own translation phi (-yc, xc) of a
// patch away from the origin) goes over L1, L2 and only the rotation about
// the patch's centre over L3: Kalker's flexibilities separate the two about
// the ellipse's centre, and a patch is treated as its own ellipse.
//
// For the work bookkeeping (exact/exact_work.hpp) the march also gives the
// model's rigid slip w = (L1 omega_x, L2 omega_y) and micro-slip
// s = (L1, L2) (omega + (p - p_prev) / dx), zero in adhesion, with
// -p.s >= 0 in slip; along each segment -sum p.w dx = sum -p.s dx +
// 1/2 sum dp.L dp + 1/2 p_e.L p_e (march/march_work.hpp's identity).
#pragma once

#include <complex>

#include "contact/friction_law.hpp"

namespace creepwork {

// One patch's flexibilities [m/Pa] and spin centre [m] (rolling frame).
struct GapMarchPatch {
    double L1 = 0, L2 = 0, L3 = 0;
    double xc = 0, yc = 0;
};

struct GapMarchInput {
    int nx = 0, ny = 0;
    double x0 = 0, y0 = 0, dx = 0, dy = 0; // element (i, j) at (x0 + i dx, y0 + j dy), rolling frame
    const double* pressure = nullptr;      // [i + nx j] [Pa]; contact where > 0
    const int* patch = nullptr;            // [i + nx j]: index into patches where pressure > 0
    const GapMarchPatch* patches = nullptr;
    CoulombLaw law;                        // the friction law (its mu)
    double xi = 0, eta = 0, phi = 0;       // rolling frame [-, -, 1/m]
    double spin_offset = 0;                // fraction of dx, >= 0
    // Optional, per row j: the first and last contact element (rolling
    // frame; last < first in a row without contact). Given, the march
    // steps over each group of rows' contact extent alone and fills the
    // rest of the row with zeros; null, it steps over every element.
    const int* row_first = nullptr;
    const int* row_last = nullptr;
};

// Rolling frame; Mz about the frame's origin.
struct GapMarchTotals {
    double Fx = 0, Fy = 0, Mz = 0; // [N, N, N m]
    double Fn = 0, p_max = 0;      // [N, Pa]
    int n_contact = 0, n_slip = 0;
};

// Per element [i + nx j], rolling frame; written everywhere (0 outside).
// slip and rigid may be null (not computed: the forces alone).
struct GapMarchOutput {
    std::complex<double>* p = nullptr;     // traction on the wheel [Pa]
    std::complex<double>* slip = nullptr;  // micro-slip s [-]
    std::complex<double>* rigid = nullptr; // the model's rigid slip w [-]
    signed char* state = nullptr;          // 0 exterior, 1 adhesion, 2 slip
    // Per patch, added to (the caller zeroes them first).
    GapMarchTotals* patch_totals = nullptr;
};

// Allocates nothing.
void gap_march(const GapMarchInput& in, const GapMarchOutput& out);

} // namespace creepwork
