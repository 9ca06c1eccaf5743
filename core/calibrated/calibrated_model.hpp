// The calibrated simplified theory (CW_MODEL_CALIBRATED): FASTSIM's march
// (fastsim/) with
//  - the spin part of the longitudinal slip on the moment-consistent
//    flexibility L_M = 8b/(15 G C33) instead of L3, so that the linear creep
//    moment is Kalker's C33 while Fx and Fy stay Kalker's
//    (moment_flexibility.hpp);
//  - the pressure, traction bound and factors on the normalised creepages
//    taken from a small table fitted to this library's exact model over a
//    training set (calibration_table.hpp; README "Calibrated model").
// Everything else -- grids, fields, both work maps, the lateral profile --
// is FASTSIM's, so it costs what FASTSIM costs. Plain FASTSIM is untouched.
#pragma once

#include "calibrated/calibration_params.hpp"
#include "contact/fields.hpp"
#include "contact/params.hpp"
#include "fastsim/fastsim_model.hpp"

namespace creepwork {

class CalibratedModel {
public:
    explicit CalibratedModel(const GridSpec& grid);

    // Throws Error(invalid_input) naming a bad input (the model needs the
    // flexibilities from G and nu: its table is in Kalker's normalisation).
    SolveTotals solve(const ContactInput& input, SolveMode mode);
    // With given parameters instead of the table's (the fitting tool).
    SolveTotals solve_with(const ContactInput& input, SolveMode mode,
                           const CalibrationParams& params);

    const ContactGrid& grid() const { return march_.grid(); }
    void copy_field(Field f, double* out) const { march_.copy_field(f, out); }
    void add_field(Field f, double scale, double* out) const { march_.add_field(f, scale, out); }
    void copy_state(int* out) const { march_.copy_state(out); }
    void copy_profile(double W, double* y, double* work, double* parabola) const
    {
        march_.copy_profile(W, y, work, parabola);
    }

private:
    FastsimModel march_;
};

} // namespace creepwork
