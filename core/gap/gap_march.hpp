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
//
// Under a law of the slip speed (speed_law given) an element slips when
// |q| > mu_s pz (mu_s the law's static coefficient) and keeps q's direction
// with the magnitude t = pz mu(s) at its own slip speed s = c (|q| - t),
// c = V |(L1 q_x, L2 q_y)| / (|q| dx): its micro-slip over the step is the
// elastic predictor's displacement less the one it keeps, (L1, L2) (1 - f)
// q / dx with f = t / |q| (as the ellipse's march under a law,
// fastsim/fastsim_law_model.hpp). The root is friction/local_slip.hpp's,
// started from the segment's last slipping element's mu.
#pragma once

#include <cmath>
#include <complex>

#include "contact/friction_law.hpp"
#include "friction/local_slip.hpp"
#include "friction/slip_speed_law.hpp"

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
    // Optional [i + nx j] [Pa]: the pressure that bounds the tractions, each
    // element's pressure times its friction factor (mu(T)); null: pressure.
    const double* bound_pressure = nullptr;
    const int* patch = nullptr;            // [i + nx j]: index into patches where pressure > 0
    const GapMarchPatch* patches = nullptr;
    CoulombLaw law;                        // the friction law (its mu)
    // A law of the slip speed (null: Coulomb's, law) and the rolling speed
    // V [m/s] > 0 that turns micro-slip into slip speed.
    const SlipSpeedLaw* speed_law = nullptr;
    double V = 0;
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

// Under a law of the slip speed, over the slipping elements: the smallest
// and largest mu (mu_min > mu_max when none slips) and local_slip's steps.
struct GapLawRange {
    double mu_min = HUGE_VAL, mu_max = -HUGE_VAL;
    long iterations = 0;
};

// Element k's pressure pz as its bound sees it (times its friction factor).
inline double bound_pressure(const GapMarchInput& in, std::size_t k, double pz)
{
    return in.bound_pressure ? in.bound_pressure[k] : pz;
}

// One element under in.speed_law (the march's and its tangent's): its
// predictor q of magnitude P, whether it slips, and in slip the factor f
// on q, the slip-speed factor c and local_slip's result.
struct GapLawElement {
    bool slips = false;
    double f = 1.0, P = 0.0, c = 0.0, Lq = 0.0; // Lq = |(L1 q_x, L2 q_y)|
    LocalSlip r;
};

inline GapLawElement gap_law_element(const GapMarchInput& in, double pz, double qx, double qy,
                                     double L1, double L2, double mu_guess)
{
    GapLawElement e;
    const double bound = pz * static_friction(*in.speed_law), n2 = qx * qx + qy * qy;
    if (!(n2 > bound * bound)) return e; // compared squared, as project_traction
    e.slips = true;
    e.P = std::sqrt(n2);
    const double lx = L1 * qx, ly = L2 * qy;
    e.Lq = std::sqrt(lx * lx + ly * ly);
    e.c = in.V * e.Lq / (e.P * in.dx);
    e.r = local_slip(*in.speed_law, e.P, pz, e.c, mu_guess);
    e.f = e.r.t / e.P;
    return e;
}

// Per element [i + nx j], rolling frame; written everywhere (0 outside).
// slip and rigid may be null (not computed: the forces alone).
struct GapMarchOutput {
    std::complex<double>* p = nullptr;     // traction on the wheel [Pa]
    std::complex<double>* slip = nullptr;  // micro-slip s [-]
    std::complex<double>* rigid = nullptr; // the model's rigid slip w [-]
    signed char* state = nullptr;          // 0 exterior, 1 adhesion, 2 slip
    // Per patch, added to (the caller zeroes them first).
    GapMarchTotals* patch_totals = nullptr;
    GapLawRange* law_range = nullptr; // under a law: set (may be null)
};

// Allocates nothing.
void gap_march(const GapMarchInput& in, const GapMarchOutput& out);

} // namespace creepwork
