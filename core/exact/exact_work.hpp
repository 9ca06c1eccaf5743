// Frictional work of the exact model (per unit rolling distance, J/m,
// positive for dissipation).
//
// The discrete energy identity. With S = dq w + B p / G (steady_rolling.hpp),
// B = A - A(shift), A symmetric and translation-invariant, p zero outside
// the contact area and dq = dx,
//   W_macro = -(Fx xi + Fy eta + Mz phi)
//           = sum_I D_I + (dx dy / (G dq)) 1/2 dp^T A dp + phi spin_offset dq Fy,
// where D_I = -p_I . S_I dx dy / dq >= 0 is the friction dissipation of
// element I (zero in adhesion, where S = 0), dp_I = p_I - p_(I + e_x) is the
// jump in traction a particle meets from one element to the next (including
// the drop to zero behind the trailing edge) and the last term comes from
// the spin centre offset of the rigid slip (CONTACT's facphi; O(dx)).
// The middle term is the exact theory's numerical dissipation: energy the
// continuum releases in slip zones thinner than an element, which is why
// sum_I D_I (the paper-style map, CONTACT's FRIC_POWER) stays below W_macro
// on any finite grid. (p^T B p = 1/2 dp^T A dp because A is symmetric and
// translation-invariant; tested.)
//
// The energy-consistent map distributes that budget as FASTSIM's does
// (march/march_work.hpp), row by row: each row of elements along x does the
// rigid-slip work W_row = -sum_row p . w dx dy (its share of W_macro less
// the spin-offset term); its slip elements keep their own D_I and share the
// rest E_row = W_row - sum_row D_I in proportion to D_I; a row without slip
// hands it to the nearest row(s) with slip. A row's budget can be negative
// (the elastic field passes energy between rows): such rows get nothing
// extra, and the rows with a positive budget share the total, the numerical
// dissipation sum_row E_row, in proportion to their budgets. Finally one
// balance factor W_macro / (sum_I D_I + numerical dissipation) makes the map
// add up to W_macro. It is >= 0, zero in adhesion, and the balance factor
// differs from 1 only by the spin-offset term (O(dx)).
#pragma once

#include <complex>
#include <vector>

#include "contact/params.hpp"

namespace creepwork {

struct ExactWorkInput {
    int nx = 0, ny = 0;
    // Per element [i + nx j], rolling frame, normalised (steady_rolling.hpp).
    const std::complex<double>* q = nullptr;    // traction / (mu p0)
    const std::complex<double>* s = nullptr;    // slip, in units of slip_scale
    const std::complex<double>* w = nullptr;    // rigid slip, same units
    const signed char* state = nullptr;         // 0 exterior, 1 adhesion, 2 slip
    double traction_scale = 0; // mu p0 [Pa]
    double slip_scale = 0;     // S / dq per unit of s [-]
    double area = 0;           // dx dy [m^2]
    double dy = 0;             // [m]
    double b = 0;              // semi-axis across [m], for the parabola
    double y0 = 0;             // centre y of row 0 [m]
    double W_macro = 0;        // [J/m]
};

struct ExactWorkTotals {
    double W_micro_paper = 0;  // sum of D_I [J/m]
    double W_consistent = 0;
    double balance = 1;
    int flags = 0;             // kWorkUnresolved, kWorkNonPositive (params.hpp)
    double profile_max_diff = 0, profile_rms_diff = 0;
};

// Fills paper (D_I per element), consistent (the energy-consistent map),
// both [i + nx j], and profile (consistent work per unit width per row,
// J/m per m). row_* are scratch of ny doubles. Allocates nothing.
ExactWorkTotals exact_work(const ExactWorkInput& in, double* paper, double* consistent,
                           double* profile, double* row_dissipation, double* row_pool);

// Copies the work totals into a solve's totals (W_micro_paper, K = W_macro /
// W_micro_paper, W_consistent, balance_factor, work_flags, the profile's
// differences from its parabola); t.W_macro must be set.
void set_work_totals(const ExactWorkTotals& work, SolveTotals& t);


} // namespace creepwork
