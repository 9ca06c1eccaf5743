#include "calibrated/calibrated_model.hpp"

#include "calibrated/calibration_table.hpp"
#include "calibrated/moment_flexibility.hpp"
#include "contact/contact_input.hpp"
#include "contact/error.hpp"
#include "fastsim/fastsim_setup.hpp"

namespace creepwork {

CalibratedModel::CalibratedModel(const GridSpec& grid) : march_(grid) {}

SolveTotals CalibratedModel::solve(const ContactInput& input, SolveMode mode)
{
    validate_contact_input(input);
    if (input.flexibility != FlexibilitySource::kalker_from_material)
        throw Error(ErrorKind::invalid_input,
                    "model = calibrated needs flexibility = kalker_from_material (G and nu): "
                    "its table is fitted in Kalker's normalisation");
    return solve_with(input, mode, calibration_for(input));
}

SolveTotals CalibratedModel::solve_with(const ContactInput& input, SolveMode mode,
                                        const CalibrationParams& params)
{
    ContactInput in = input;
    in.pressure = params.pressure;
    in.flexibility_blending = false; // the table replaces CONTACT's blending
    ModelSetup s = make_model_setup(in);
    if (in.flexibility == FlexibilitySource::kalker_from_material) {
        const double L_M = moment_consistent_flexibility(s.b, in.G, s.C.C33);
        s.kin.cx *= s.L3 / L_M;
    }
    s.kin.ux *= params.k_long;
    s.kin.uy *= params.k_lat;
    s.kin.cx *= params.k_spin_x;
    s.kin.cy *= params.k_spin_y;
    SolveTotals t = march_.solve_setup(s, in, mode);
    t.model = ModelKind::calibrated;
    return t;
}

} // namespace creepwork
