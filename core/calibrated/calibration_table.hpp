// The fitted table of the calibrated model: its parameters as functions of
// a/b and of the creepages normalised by their saturation values.
//
// Form: every factor of CalibrationParams is k = 1 + alpha g(s), with
// s = |(s_long, s_lat, s_spin)| the normalised creepage and g(s) = s/(1+s),
// so the linear limit (s -> 0) is untouched (Kalker's C11, C22, C23 and,
// through L_M and the lateral-moment term, both moments); the lateral-moment
// term fades as 1/(1 + (fade s)^2)^2 and the flexibilities are equalised with
// h = min(1, equalise s) (linear in s, so that it reaches 1 towards full
// sliding, where the tractions oppose the rigid slip), the rigid slip modulated across the strips with
// edge_gain = edge g(s), and the traction bound blended from the parabolic
// law towards the elliptic one by blend s^2/(blend_half^2 + s^2); alpha,
// fade, equalise, edge, blend and blend_half from the table, linear in
// ln(a/b) between its nodes and constant beyond them. The pressure scale is
// the parabolic law's.
// The alphas were fitted by creepwork_calibration fit (tools/calibration/)
// on the training set only; calibration_table_data.cpp is its output.
#pragma once

#include "calibrated/calibration_params.hpp"
#include "contact/params.hpp"

namespace creepwork {

// Creepages as fractions of the ones at which Kalker's linear theory reaches
// mu N: xi_x G c^2 C11 / (mu N), xi_y G c^2 C22 / (mu N), phi G c^3 C23 /
// (mu N), c = sqrt(ab). Zero when mu N = 0.
struct NormalisedCreepage {
    double s_long = 0, s_lat = 0, s_spin = 0;
};
NormalisedCreepage normalised_creepage(const ContactInput& in);

// One node of the table.
struct CalibrationNode {
    double a_over_b;
    double alpha_long, alpha_lat, alpha_spin_x, alpha_spin_y;
    double fade;     // lateral-moment weight 1/(1 + (fade s)^2)^2
    double equalise; // flexibility equalisation h = min(1, equalise s)
    double edge;     // lateral modulation edge_gain = edge g(s)
    // Traction bound blend (blended_bound.hpp) blend s^2/(blend_half^2
    // + s^2): the parabolic law at small slip, towards the elliptic law as
    // the slip zone grows.
    double blend, blend_half;
};
constexpr int kCalibrationNodes = 5;
extern const CalibrationNode kCalibrationTable[kCalibrationNodes]; // ascending a/b

// The parameters of one node's alphas at normalised creepage s.
CalibrationParams calibration_params(const CalibrationNode& alphas, const NormalisedCreepage& s);
// The alphas of table (kCalibrationNodes nodes, ascending a/b) at a/b:
// every member linear in ln(a/b) between nodes, constant beyond them. The
// fit (tools/calibration/) reads its trial tables through this too.
CalibrationNode calibration_node(const CalibrationNode* table, double a_over_b);
// The built-in table's alphas at a/b.
inline CalibrationNode calibration_node(double a_over_b)
{
    return calibration_node(kCalibrationTable, a_over_b);
}

// The parameters for one contact (a valid input, flexibilities from G, nu).
CalibrationParams calibration_for(const ContactInput& in);

} // namespace creepwork
