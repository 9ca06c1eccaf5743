#include "calibrated/calibrated_model.hpp"

#include <algorithm>
#include <cmath>

#include "calibrated/calibration_table.hpp"
#include "calibrated/moment_flexibility.hpp"
#include "contact/contact_input.hpp"
#include "contact/error.hpp"
#include "fastsim/bound_shape.hpp"
#include "fastsim/fastsim_setup.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Kalker's linear theory couples the lateral creepage to the moment:
// Mz = +G c^3 C23 eta (c^2 = ab; spin: Mz = -G c^4 C33 phi, on the wheel).
// FASTSIM's march gives (continuum, no slip) +(3 pi/32) G a^2 b C22 eta
// instead (the moment of p_y = eta (a(y) - x)/L2, L2 = 8a/(3 C22 G);
// test_core_linear_theory). The difference is supplied, as L_M does for
// spin, by an x-slip term odd in y that adds nothing to Fx or Fy: the one of
// an extra spin phi_e = -kappa eta on L_M, kappa = (c^3 C23 - (3 pi/32)
// a^2 b C22) / (c^4 C33). Returned in the units of kin.cx (from kin.uy,
// which already holds eta with its normalisation).
double lateral_moment_term(const ModelSetup& s, double L_M)
{
    const double a = s.a, b = s.b, c2 = a * b, c = std::sqrt(c2);
    const CreepCoefficients& C = s.C;
    const double kappa = (c2 * c * C.C23 - 3.0 * kPi / 32.0 * a * a * b * C.C22) / (c2 * c2 * C.C33);
    return -b * kappa * s.kin.uy * (s.L2 / L_M);
}

// Each rigid-slip component's effective flexibility L_i / k_i (k_i its
// saturation factor) -> (L_i / k_i)^(1-h) Lc^h (calibration_params.hpp): the
// component, already multiplied by k_i, is multiplied by (L_i / (k_i Lc))^h.
// The factors are equalised with the flexibilities because towards full
// sliding any difference between components turns the traction away from
// the rigid slip, whichever its origin.
void equalise_flexibilities(ModelSetup& s, const ContactInput& in, double L_M,
                            const CalibrationParams& p)
{
    const double h = p.equalise;
    const double L[4] = {s.L1 / p.k_long, s.L2 / p.k_lat, L_M / p.k_spin_x, s.L3 / p.k_spin_y};
    const NormalisedCreepage n = normalised_creepage(in);
    const double w[3] = {std::fabs(n.s_long), std::fabs(n.s_lat), std::fabs(n.s_spin)};
    const double total = w[0] + w[1] + w[2];
    if (!(total > 0.0) || !std::isfinite(total)) return;
    const double log_c = (w[0] * std::log(L[0]) + w[1] * std::log(L[1]) +
                          w[2] * 0.5 * (std::log(L[2]) + std::log(L[3]))) / total;
    auto factor = [&](double Li) { return std::exp(h * (std::log(Li) - log_c)); };
    s.kin.ux *= factor(L[0]);
    s.kin.uy *= factor(L[1]);
    s.kin.cx *= factor(L[2]);
    s.kin.cy *= factor(L[3]);
}

} // namespace

CalibratedModel::CalibratedModel(const GridSpec& grid) : march_(grid)
{
    march_.reserve_blended_bound(); // its solves allocate nothing
    march_.march_from_leading_edge();
}

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
    double L_M = s.L3;
    if (in.flexibility == FlexibilitySource::kalker_from_material) {
        L_M = moment_consistent_flexibility(s.b, in.G, s.C.C33);
        s.kin.cx *= s.L3 / L_M;
        s.kin.cx += params.lateral_moment * lateral_moment_term(s, L_M);
    }
    s.kin.ux *= params.k_long;
    s.kin.uy *= params.k_lat;
    s.kin.cx *= params.k_spin_x;
    s.kin.cy *= params.k_spin_y;
    if (in.flexibility == FlexibilitySource::kalker_from_material && params.equalise > 0.0)
        equalise_flexibilities(s, in, L_M, params);
    s.kin.edge_gain = params.edge_gain;
    if (in.pressure == PressureKind::parabolic)
        s.kin.bound_blend = std::max(-kMaxBoundBlend, std::min(kMaxBoundBlend, params.bound_blend));
    SolveTotals t = march_.solve_setup(s, in, mode);
    t.model = ModelKind::calibrated;
    return t;
}

} // namespace creepwork
