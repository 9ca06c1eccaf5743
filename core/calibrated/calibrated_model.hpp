// The calibrated simplified theory (CW_MODEL_CALIBRATED): FASTSIM's march
// (fastsim/) with
//  - the spin part of the longitudinal slip on the moment-consistent
//    flexibility L_M = 8b/(15 G C33) instead of L3, so that the linear creep
//    moment is Kalker's C33 while Fx and Fy stay Kalker's
//    (moment_flexibility.hpp);
//  - the pressure, traction bound and factors on the normalised creepages
//    taken from a small table fitted to this library's exact model over a
//    training set (calibration_table.hpp; doc/theory/calibrated.md).
// Everything else -- grids, fields, both work maps, the lateral profile --
// is FASTSIM's, so it costs what FASTSIM costs. Plain FASTSIM is untouched.
#pragma once

#include "calibrated/calibration_params.hpp"
#include "contact/fields.hpp"
#include "contact/jacobian.hpp"
#include "contact/params.hpp"
#include "fastsim/fastsim_model.hpp"
#include "calibrated/march_directional.hpp"

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
    // solve() and the derivatives of Fx, Fy, Mz (rows jac_Fx..jac_Mz; the
    // W_macro row is the solver's) by xi_x, xi_y, phi, N, with the table's
    // parameters moving with them: the march differentiated exactly along
    // the setup's derivatives by the creepages (set_directions), N by the
    // model's homogeneity. Totals bitwise those of
    // solve(). Throws Error(invalid_input) for normal_force = 0 with mu > 0.
    SolveTotals solve_jacobian(const ContactInput& input, SolveMode mode, Jacobian& jacobian);

    const ContactGrid& grid() const { return march_.grid(); }
    // The march's kernel (tests: every kernel gives bitwise the same results).
    void set_kernel_isa(KernelIsa isa) { march_.set_kernel_isa(isa); }
    void copy_field(Field f, double* out) const { march_.copy_field(f, out); }
    void add_field(Field f, double scale, double* out) const { march_.add_field(f, scale, out); }
    void copy_state(int* out) const { march_.copy_state(out); }
    void copy_profile(double W, double* y, double* work, double* parabola) const
    {
        march_.copy_profile(W, y, work, parabola);
    }

private:
    void set_directions(const ContactInput& input, const ModelSetup& setup);

    FastsimModel march_;
    MarchDirections directions_;
    Eigen::ArrayXd scratch_wx_, scratch_wy_; // per strip, set_directions()
};

} // namespace creepwork
