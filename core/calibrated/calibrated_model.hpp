// The calibrated simplified theory (CW_MODEL_CALIBRATED): Kalker's strip
// march (march/) with
//  - the spin part of the longitudinal slip on the moment-consistent
//    flexibility L_M = 8b/(15 G C33) instead of L3, so that the linear creep
//    moment is Kalker's C33 while Fx and Fy stay Kalker's
//    (moment_flexibility.hpp);
//  - the factors on the normalised creepages, a lateral modulation of the
//    rigid slip (edge gain) and a traction bound blended between the
//    pressure laws (blended_bound.hpp), taken from a small table fitted to
//    this library's exact model over a training set (calibration_table.hpp;
//    doc/theory/calibrated.md);
//  - on the uniform grid, each strip marched from where it enters the
//    ellipse (MarchGeometry::march_from_leading_edges).
// Everything else -- grids, fields, both work maps, the lateral profile --
// is the march's (march_model.hpp), so it costs what FASTSIM costs.
#pragma once

#include "calibrated/blended_bound.hpp"
#include "calibrated/calibration_params.hpp"
#include "calibrated/march_directional.hpp"
#include "contact/params.hpp"
#include "march/march_model.hpp"

namespace creepwork {

// FASTSIM's setup with the calibrated model's changes (calibrated_setup in
// calibrated_model.cpp): the kinematics in march, and the two knobs the
// march itself does not know.
struct CalibratedSetup {
    ModelSetup march;
    double edge_gain = 0;   // CalibrationParams::edge_gain
    double bound_blend = 0; // in [0, kMaxBoundBlend]; parabolic pressure only
};

// The rigid slip of strips [first, last) of the march with the calibrated
// model's lateral modulation: both components of strip Y multiplied by
// (1 + edge_gain Y^2) / (1 + edge_gain / 5), which leaves the linear forces
// unchanged and moves slip towards the lateral edges.
void calibrated_rigid_slip(const ContactGrid& grid, const CalibratedSetup& setup, double* wx,
                           double* wy, int first, int last);

class CalibratedModel : public MarchModel {
public:
    explicit CalibratedModel(const GridSpec& grid);
    explicit CalibratedModel(std::shared_ptr<const ContactGrid> grid); // a solver's grid

    // Throws Error(invalid_input) naming a bad input (the model needs the
    // flexibilities from G and nu: its table is in Kalker's normalisation).
    SolveTotals solve(const ContactInput& input, SolveMode mode) override;
    // With given parameters instead of the table's (the fitting tool).
    SolveTotals solve_with(const ContactInput& input, SolveMode mode,
                           const CalibrationParams& params);
    // solve() and the derivatives of Fx, Fy, Mz by xi_x, xi_y, phi, N, with
    // the table's parameters moving with them: the march differentiated
    // exactly along the setup's derivatives by the creepages
    // (set_directions), N by the model's homogeneity. Throws
    // Error(invalid_input) for normal_force = 0 with mu > 0.
    SolveTotals solve_jacobian(const ContactInput& input, SolveMode mode,
                               Jacobian& jacobian) override;

private:
    // begin() with the setup's bound and edge gain.
    void begin_calibrated(const CalibratedSetup& setup);
    void set_directions(const ContactInput& input, const CalibratedSetup& setup);

    BlendedBound bound_;
    MarchDirections directions_;
    Eigen::ArrayXd scratch_wx_, scratch_wy_; // per strip, set_directions()
};

} // namespace creepwork
