// One solved contact, per element: what a model holds after a solve, as
// pointers into its own arrays and the scales between them and the
// caller's units. The models on a grid of their own rows (the exact model,
// the exact and the FASTSIM model on a gap grid) hand it out
// (ContactModel::solved()), and the one field export below reads it: the
// fields, the states, the lateral work profile. Making a view copies
// nothing (a few pointers and scales, made when a field is asked for), so
// a solve that is never read costs nothing more. Post-processors of the
// fields (temperature, damage indices) read the view too:
// CONTRIBUTING.md, "How to add a post-processor".
//
// The view is on the model's grid and in its rolling frame (leading edge
// at +x): element (i, j) of the caller's layout [i + nx j] is the model's
// element k = i' + nx j with i' = i, or i' = nx - 1 - i when rolling
// towards -x (mirrored); the caller's x parts of tractions and slips are
// the model's times the rolling direction.
//
// Each field is one formula of the view (solved_contact.cpp), written in
// the order of operations every model used before, so the outputs keep
// their bits. Fields are appended as laws need them (the slip velocity,
// the local friction coefficient): a member here, its formula in the
// .cpp, and the models that hold it fill it.
//
// The FASTSIM-class models (march/) keep their own blocked SIMD export of
// the march's layout (strips fastest, p = f q'); the view has no form for
// it yet.
#pragma once

#include <complex>

#include "contact/fields.hpp"

namespace creepwork {

struct SolvedContact {
    int nx = 0, ny = 0;
    bool mirrored = false; // rolling towards -x: i' = nx - 1 - i
    double direction = 1.0; // +1, -1: the caller's x parts are the model's times it

    // Element centres, the caller's frame [m]: x_column[i], y_row[j]; an
    // element's area element_area [m^2] (0 outside the contact).
    const double* x_column = nullptr;
    const double* y_row = nullptr;
    double element_area = 0.0;

    // Per model element k: pz = pressure_scale pressure[k] [Pa] (null: no
    // load, 0); the traction on the wheel [Pa], model's frame,
    // traction_scale traction[k]; the state (ElementState).
    const double* pressure = nullptr;
    double pressure_scale = 1.0;
    const std::complex<double>* traction = nullptr;
    double traction_scale = 1.0;
    const signed char* state = nullptr;
    // The micro-slip W/V [-], model's frame, slip_scale slip[k]; null
    // before a full solve. slip_masked: the array holds other values
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

    // The model's element of the caller's (i, j).
    long index(int i, int j) const
    {
        return (mirrored ? nx - 1 - i : i) + static_cast<long>(nx) * j;
    }
};

// The one field export: out[i + nx j] for i < nx, j < ny; add_field adds
// scale times the field. Fields that need the work need a full solve
// (checked by the caller).
void export_field(const SolvedContact& c, Field f, double* out);
void add_field(const SolvedContact& c, Field f, double scale, double* out);
void export_state(const SolvedContact& c, int* out);
// Per row j < ny: centre y [m], the work per unit width and its equal-area
// parabola of total W; null pointers are skipped.
void export_profile(const SolvedContact& c, double W, double* y, double* work,
                    double* parabola);

// (3 W / 4b)(1 - y^2/b^2) inside |y| < b, else 0: the equal-area parabola of
// a lateral work profile of total W (paper Figs. 8-9).
double lateral_parabola(double W, double b, double y);

} // namespace creepwork
