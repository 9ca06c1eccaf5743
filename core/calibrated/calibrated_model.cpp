#include "calibrated/calibrated_model.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "calibrated/calibration_table.hpp"
#include "calibrated/moment_flexibility.hpp"
#include "contact/contact_input.hpp"
#include "contact/error.hpp"
#include "contact/jacobian_load.hpp"
#include "march/march_setup.hpp"

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

void validate_calibrated_input(const ContactInput& input)
{
    validate_contact_input(input);
    if (input.flexibility != FlexibilitySource::kalker_from_material)
        throw Error(ErrorKind::invalid_input,
                    "model = calibrated needs flexibility = kalker_from_material (G and nu): "
                    "its table is fitted in Kalker's normalisation");
}

// The grid's load per unit pressure scale under the traction bound of the
// blend (blended_bound.hpp: linear in the blend), and its derivative by the
// blend.
double blended_load(const DiscreteLoad& load, double blend)
{
    return (1.0 - blend) * load.parabolic + blend * 0.75 * load.elliptic;
}
double blended_load_slope(const DiscreteLoad& load) { return 0.75 * load.elliptic - load.parabolic; }

// FASTSIM's setup of input with the calibrated changes of params; load is the
// grid's (read with exact_load: the pressure scale then makes the blended
// bound carry N exactly).
CalibratedSetup calibrated_setup(const ContactInput& input, const CalibrationParams& params,
                                 const DiscreteLoad& load)
{
    ContactInput in = input;
    in.pressure = params.pressure;
    in.flexibility_blending = false; // the table replaces CONTACT's blending
    CalibratedSetup cs;
    if (in.pressure == PressureKind::parabolic)
        cs.bound_blend = std::max(0.0, std::min(kMaxBoundBlend, params.bound_blend));
    ModelSetup& s = cs.march;
    s = make_model_setup(in, in.pressure == PressureKind::parabolic
                                 ? blended_load(load, cs.bound_blend)
                                 : load.elliptic);
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
    cs.edge_gain = params.edge_gain;
    return cs;
}

} // namespace

void calibrated_rigid_slip(const ContactGrid& grid, const CalibratedSetup& setup, double* wx,
                           double* wy, int first, int last)
{
    rigid_slip_of_strips(grid, setup.march.kin, wx, wy, first, last);
    const double g = setup.edge_gain;
    if (g == 0.0) return;
    for (int j = first; j < last; ++j) {
        const double Y = grid.y_centre()[j];
        const double m = (1.0 + g * Y * Y) / (1.0 + g / 5.0);
        wx[j] *= m;
        wy[j] *= m;
    }
}

CalibratedModel::CalibratedModel(const GridSpec& grid)
    : CalibratedModel(std::make_shared<const ContactGrid>(grid))
{
}

CalibratedModel::CalibratedModel(std::shared_ptr<const ContactGrid> grid)
    : MarchModel(std::move(grid)), bound_(geometry())
{
    // Its solves, with or without the Jacobian, allocate nothing.
    geometry().march_from_leading_edges(this->grid());
    directions_.resize(this->grid().ny());
    scratch_wx_.setZero(directions_.stride);
    scratch_wy_.setZero(directions_.stride);
}

void CalibratedModel::begin_calibrated(const CalibratedSetup& s)
{
    const PressureKind pressure = s.march.pressure;
    if (s.bound_blend != 0.0) {
        bound_.set(geometry(), s.bound_blend);
        begin(s.march, bound_.data(), bound_.max());
    } else {
        begin(s.march, geometry().shape(pressure).data(), geometry().max_shape(pressure));
    }
    MarchState& state = march_state();
    calibrated_rigid_slip(grid(), s, state.wx.data(), state.wy.data(), 0, grid().ny());
}

SolveTotals CalibratedModel::solve(const ContactInput& input, SolveMode mode)
{
    validate_calibrated_input(input);
    return solve_with(input, mode, calibration_for(input));
}

SolveTotals CalibratedModel::solve_with(const ContactInput& input, SolveMode mode,
                                        const CalibrationParams& params)
{
    begin_calibrated(calibrated_setup(input, params, discrete_load()));
    if (mode == SolveMode::full)
        march_with_work();
    else
        march();
    return totals(input, mode, ModelKind::calibrated);
}

SolveTotals CalibratedModel::solve_jacobian(const ContactInput& input, SolveMode mode,
                                            Jacobian& jacobian)
{
    validate_calibrated_input(input);
    if (input.normal_force == 0.0 && input.mu > 0.0)
        throw zero_load_jacobian_error();
    if (input.mu == 0.0) { // no traction whatever the inputs: all derivatives 0
        jacobian = Jacobian{};
        return solve(input, mode);
    }
    const CalibratedSetup setup = calibrated_setup(input, calibration_for(input), discrete_load());
    set_directions(input, setup);
    begin_calibrated(setup);
    if (mode == SolveMode::full) march_with_work();
    // With work, the directional march repeats the march: the same state, bitwise.
    march_directional(view(), geometry(), directions_, kernel_isa());
    jacobian = directional_jacobian(setup.march, grid(), march_state(), directions_);
    SolveTotals t = totals(input, mode, ModelKind::calibrated);
    if (input.exact_load) {
        // The march's directions hold the creepages' effect on the kinematics
        // and on the bound; with exact_load the traction scale T moves too,
        // as 1 / (the blended bound's load), so F = T Phi gains
        // (dT/T) F = -(dI/I) F along each direction.
        const DiscreteLoad& load = discrete_load();
        const double dlog_load =
            blended_load_slope(load) / blended_load(load, setup.bound_blend);
        const double F[3] = {t.Fx, t.Fy, t.Mz};
        for (int k = 0; k < kMarchDirections; ++k)
            for (int i = 0; i < 3; ++i)
                jacobian.d[i][k] -= dlog_load * directions_.blend[k] * F[i];
    }
    // N: the model is homogeneous of degree 1 in (xi_x, xi_y, phi, N) -- T is
    // proportional to N, and the march and the table see only creepage / N
    // (normalised_creepage, kin = a xi / (L mu p0)) -- so by Euler's identity
    // N dF/dN = F - xi_x dF/dxi_x - xi_y dF/dxi_y - phi dF/dphi, exactly.
    const double F[3] = {t.Fx, t.Fy, t.Mz};
    for (int i = 0; i < 3; ++i)
        jacobian.d[i][jac_N] = (F[i] - input.xi_x * jacobian.d[i][jac_xi_x] -
                                input.xi_y * jacobian.d[i][jac_xi_y] -
                                input.phi * jacobian.d[i][jac_phi]) /
                               input.normal_force;
    return t;
}

// The setup's derivatives by the creepages, by central differences of
// calibrated_setup(): an O(1) chain of smooth closed forms (the table's
// factors, equalisation, fade, edge gain, blend), differenced at 1e-6 of each
// creepage's saturation value, so truncation (~1e-12) and rounding (~1e-10)
// stay far below what the march's own derivative carries. The march is then
// differentiated exactly along them (march_directional.hpp). Kinks of the
// closed forms (|creepage| in the equalisation weights, its cap at 1) get the
// mean of their one-sided slopes.
void CalibratedModel::set_directions(const ContactInput& in, const CalibratedSetup& setup)
{
    const ContactGrid& grid = this->grid();
    const int ny = grid.ny(), stride = directions_.stride;
    const double muN = in.mu * in.normal_force, c2 = in.a * in.b, c = std::sqrt(c2);
    const CreepCoefficients& C = setup.march.C;
    // Saturation creepages (normalised creepage 1), the inputs' scales.
    const double scale[kMarchDirections] = {muN / (in.G * c2 * C.C11), muN / (in.G * c2 * C.C22),
                                            muN / (in.G * c2 * c * C.C23)};
    double ContactInput::*const member[kMarchDirections] = {&ContactInput::xi_x, &ContactInput::xi_y,
                                                            &ContactInput::phi};
    for (int k = 0; k < kMarchDirections; ++k) {
        const double value = in.*member[k];
        // A normal number (hosts may flush subnormals to zero, doc/reference/guarantees.md),
        // so that value +- h differ and the quotient is finite.
        const double h = std::max(1e-6 * std::max(std::fabs(value), scale[k]), 1e-290);
        ContactInput plus = in, minus = in;
        plus.*member[k] = value + h;
        minus.*member[k] = value - h;
        const CalibratedSetup sp = calibrated_setup(plus, calibration_for(plus), discrete_load());
        const CalibratedSetup sm = calibrated_setup(minus, calibration_for(minus), discrete_load());
        const double inv = 1.0 / ((value + h) - (value - h)); // the step as represented
        double* dwx = directions_.wx.data() + k * stride;
        double* dwy = directions_.wy.data() + k * stride;
        calibrated_rigid_slip(grid, sp, dwx, dwy, 0, ny);
        calibrated_rigid_slip(grid, sm, scratch_wx_.data(), scratch_wy_.data(), 0, ny);
        for (int j = 0; j < ny; ++j) {
            dwx[j] = (dwx[j] - scratch_wx_[j]) * inv;
            dwy[j] = (dwy[j] - scratch_wy_[j]) * inv;
        }
        directions_.cy[k] = (sp.march.kin.cy - sm.march.kin.cy) * inv;
        directions_.blend[k] = (sp.bound_blend - sm.bound_blend) * inv;
    }
}

} // namespace creepwork
