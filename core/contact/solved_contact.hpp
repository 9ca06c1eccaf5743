// One solved contact, per element: what a model holds after a solve, as
// pointers into its own arrays and the scales between them and the
// caller's units. Every model hands it out (ContactModel::solved()), and
// the one field export below reads it: the fields, the states, the lateral
// work profile. Making a view copies nothing (a few pointers and scales,
// made when a field is asked for), so a solve that is never read costs
// nothing more. Post-processors of the fields (wear, temperature, damage
// indices) read the view too: CONTRIBUTING.md, "How to add a
// post-processor".
//
// The view is on the model's grid and in its rolling frame, in one of two
// layouts. Rows (the exact model, both models on a gap grid): element
// (i, j) of the caller's layout [i + nx j] is the model's element
// k = i' + nx j. Strips (the march models, march/: FASTSIM, calibrated):
// k = i' stride + j, strips fastest, lengths normalised by the semi-axes
// and the traction held as p = f q' (SolvedStrips). Either way i' = i, or
// i' = nx - 1 - i when mirrored, and the caller's x parts of tractions and
// slips are the model's times the rolling direction.
//
// Each field is one formula of the view (solved_contact.cpp for rows,
// solved_strips.cpp for strips), written in the order of operations the
// models used before, so the outputs keep their bits. Fields are appended
// as laws need them (the slip velocity, the local friction coefficient): a
// member here, its formula in the .cpp, and the models that hold it fill
// it.
#pragma once

#include <complex>

#include "contact/fields.hpp"
#include "simd/kernel_isa.hpp"

namespace creepwork {

enum class SolvedLayout { rows, strips };

// The strips layout's own members (the march's, march/): positions and
// sizes normalised by the semi-axes, the traction p = f q'. Per model
// element k: x = a x_centre[k], inside[k] != 0 in the contact, the trial
// traction (qx, qy)[k] and its factor factor[k] (slip where < 1), the
// micro-slip (slip_x, slip_y)[k] (0 in adhesion); per strip j: y =
// b y_centre[j], element size a x_length[j] by b y_width[j].
struct SolvedStrips {
    int stride = 0; // k = i' stride + j
    double a = 0.0, b = 0.0;
    const double *x_centre = nullptr, *inside = nullptr;
    const double *y_centre = nullptr, *x_length = nullptr, *y_width = nullptr;
    const double *qx = nullptr, *qy = nullptr, *factor = nullptr;
    const double *slip_x = nullptr, *slip_y = nullptr;
    KernelIsa isa = KernelIsa::baseline; // the blocked export's (bitwise the same on each)
};

struct SolvedContact {
    int nx = 0, ny = 0;
    SolvedLayout layout = SolvedLayout::rows;
    bool mirrored = false; // i' = nx - 1 - i
    double direction = 1.0; // +1, -1: the caller's x parts are the model's times it

    // Rows: element centres, the caller's frame [m]: x_column[i], y_row[j];
    // an element's area element_area [m^2] (0 outside the contact).
    const double* x_column = nullptr;
    const double* y_row = nullptr;
    double element_area = 0.0;

    // Per model element k: pz = pressure_scale pressure[k] [Pa] (null: no
    // load, 0); the traction on the wheel [Pa], model's frame,
    // traction_scale traction[k]; the state (ElementState). Strips: the
    // pressure the same; the traction traction_scale f q' (strips); no
    // state array (it follows from inside and f).
    const double* pressure = nullptr;
    double pressure_scale = 1.0;
    const std::complex<double>* traction = nullptr;
    double traction_scale = 1.0;
    const signed char* state = nullptr;
    // Rows: the micro-slip W/V [-], model's frame, slip_scale slip[k];
    // null before a full solve. slip_masked: the array holds other values
    // outside the slip elements, which read 0.
    const std::complex<double>* slip = nullptr;
    double slip_scale = 1.0;
    bool slip_masked = false;
    // Work maps [J/m] per element; null before a full solve.
    const double *work_paper = nullptr, *work_consistent = nullptr;

    // Per row j: the energy-consistent work per unit width [J/m per m]
    // (null before a full solve); its equal-area parabola over
    // [-profile_b, profile_b] about y = profile_y_mid.
    const double* profile = nullptr;
    double profile_b = 0.0, profile_y_mid = 0.0;

    SolvedStrips strips; // the strips layout's members

    // The model's element of the caller's (i, j).
    long index(int i, int j) const
    {
        const int m = mirrored ? nx - 1 - i : i;
        return layout == SolvedLayout::strips ? static_cast<long>(m) * strips.stride + j
                                              : m + static_cast<long>(nx) * j;
    }
    // The centre y [m] of row j.
    double y(int j) const
    {
        return layout == SolvedLayout::strips ? strips.b * strips.y_centre[j] : y_row[j];
    }
};

// Each layout's export (solved_contact.cpp: rows; solved_strips.cpp:
// strips, blocked and explicitly vectorised on the view's kernel ISA).
void export_rows(const SolvedContact& c, Field f, double* out);
void add_rows(const SolvedContact& c, Field f, double scale, double* out);
void export_rows_state(const SolvedContact& c, int* out);
void export_strips(const SolvedContact& c, Field f, double* out);
void add_strips(const SolvedContact& c, Field f, double scale, double* out);
void export_strips_state(const SolvedContact& c, int* out);

// The one field export, of either layout: out[i + nx j] for i < nx, j < ny;
// add_field adds scale times the field. Fields that need the work need a
// full solve (checked by the caller).
inline void export_field(const SolvedContact& c, Field f, double* out)
{
    if (c.layout == SolvedLayout::strips)
        export_strips(c, f, out);
    else
        export_rows(c, f, out);
}
inline void add_field(const SolvedContact& c, Field f, double scale, double* out)
{
    if (c.layout == SolvedLayout::strips)
        add_strips(c, f, scale, out);
    else
        add_rows(c, f, scale, out);
}
inline void export_state(const SolvedContact& c, int* out)
{
    if (c.layout == SolvedLayout::strips)
        export_strips_state(c, out);
    else
        export_rows_state(c, out);
}
// Per row j < ny: centre y [m], the work per unit width and its equal-area
// parabola of total W; null pointers are skipped.
void export_profile(const SolvedContact& c, double W, double* y, double* work,
                    double* parabola);

// (3 W / 4b)(1 - y^2/b^2) inside |y| < b, else 0: the equal-area parabola of
// a lateral work profile of total W (paper Figs. 8-9).
double lateral_parabola(double W, double b, double y);

} // namespace creepwork
