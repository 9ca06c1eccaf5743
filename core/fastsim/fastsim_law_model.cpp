#include "fastsim/fastsim_law_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "contact/error.hpp"
#include "fastsim/fastsim_jacobian.hpp"
#include "fastsim/march_law.hpp"
#include "friction/local_slip.hpp"

namespace creepwork {

FastsimLawModel::FastsimLawModel(const GridSpec& grid)
    : FastsimLawModel(std::make_shared<const ContactGrid>(grid))
{
}

FastsimLawModel::FastsimLawModel(std::shared_ptr<const ContactGrid> grid)
    : MarchModel(std::move(grid))
{
    tangent_.resize(geometry());
    const int stride = geometry().stride;
    tangent_.sum_px.setZero(kLawTangents * stride);
    tangent_.sum_py.setZero(kLawTangents * stride);
    tangent_.sum_x_py.setZero(kLawTangents * stride);
    ratio_min_.setZero(stride);
    ratio_max_.setZero(stride);
    strip_iterations_.setZero(stride);
}

void FastsimLawModel::set_law(const SlipSpeedLaw& law, double V)
{
    check_slip_speed_law(law);
    if (!(std::isfinite(V) && V > 0.0))
        throw Error(ErrorKind::invalid_input,
                    "V (the rolling speed) must be finite and > 0 [m/s] for a law of the slip speed");
    law_ = law;
    V_ = V;
}

void FastsimLawModel::prepare(const ContactInput& input)
{
    if (V_ <= 0.0) throw Error(ErrorKind::invalid_input, "V: no friction law set (set_law)");
    input_ = input;
    input_.mu = static_friction(law_);
    const ModelSetup setup =
        make_model_setup(input_, discrete_load_of(discrete_load(), input_.pressure));
    begin(setup, geometry().shape(setup.pressure).data(), geometry().max_shape(setup.pressure));
}

SolveTotals FastsimLawModel::solve(const ContactInput& input, SolveMode mode)
{
    prepare(input);
    if (memory_.distance > 0.0)
        march_with_memory();
    else
        march_with_law(false);
    if (mode == SolveMode::full) work_of_march();
    return totals(input_, mode, ModelKind::fastsim);
}

void FastsimLawModel::set_memory(const FrictionMemory& memory)
{
    check_friction_memory(memory);
    memory_ = memory;
}

SolveTotals FastsimLawModel::solve_jacobian(const ContactInput& input, SolveMode mode,
                                            Jacobian& jacobian)
{
    if (memory_.distance > 0.0)
        throw Error(ErrorKind::invalid_input,
                    "memory_distance: FASTSIM with friction memory has no Jacobian");
    prepare(input);
    march_with_law(true);
    if (mode == SolveMode::full) work_of_march();
    Jacobian J = fastsim_jacobian(input_, setup(), grid(), march_state(), tangent_);
    // The slip-speed factor c is proportional to the traction unit T, which
    // N moves (T = mu_s p0, p0 proportional to N): the column of N gains
    // frame_i T dPhi_i/dln T (dT/dN)/T.
    if (input_.mu > 0.0 && input_.normal_force > 0.0) {
        StripTangents tau;
        const int stride = geometry().stride;
        Eigen::ArrayXd zero = Eigen::ArrayXd::Zero(kStripTangents * stride);
        Eigen::ArrayXd px = zero, py = zero, xpy = zero;
        px.head(stride) = tangent_.sum_px.segment(kTangents * stride, stride);
        py.head(stride) = tangent_.sum_py.segment(kTangents * stride, stride);
        xpy.head(stride) = tangent_.sum_x_py.segment(kTangents * stride, stride);
        tau.sum_px = px.data();
        tau.sum_py = py.data();
        tau.sum_x_py = xpy.data();
        tau.stride = geometry().stride;
        double Phi[3], dPhi[3][kStripTangents];
        scaled_forces(grid(), setup().a, setup().b, march_state(), tau, Phi, dPhi);
        const double d = setup().direction, frame[3] = {d, 1.0, d};
        const double dT_dN = input_.mu * setup().pressure_per_force;
        for (int i = 0; i < 3; ++i) J.d[i][3] += frame[i] * dPhi[i][0] * dT_dN;
    }
    jacobian = J;
    return totals(input_, mode, ModelKind::fastsim);
}

// A falling law: the SIMD kernel (march_law.hpp), then the per-strip
// outputs reduced. Coulomb's law (or mu_s = 0): FASTSIM's own march and
// tangent march, whose tractions do not depend on T (the ln T row is 0).
void FastsimLawModel::march_with_law(bool tangents)
{
    const MarchGeometry& geo = geometry();
    const ModelSetup& s = setup();
    const double mu_s = static_friction(law_);
    mu_min_ = mu_max_ = mu_s;
    iterations_ = 0;
    if (law_.kind == SlipSpeedLawKind::coulomb || mu_s == 0.0) {
        if (tangents) {
            march_tangent(view(), grid(), s, tangent_, kernel_isa());
            const int stride = geo.stride;
            tangent_.sum_px.segment(kTangents * stride, stride).setZero();
            tangent_.sum_py.segment(kTangents * stride, stride).setZero();
            tangent_.sum_x_py.segment(kTangents * stride, stride).setZero();
        } else {
            march();
        }
        return;
    }
    LawMarch A;
    A.view = view();
    A.law = law_;
    A.L1 = s.L1;
    A.L2 = s.L2;
    A.slip_speed_scale = V_ * s.traction_scale / s.a;
    A.ratio_min = ratio_min_.data();
    A.ratio_max = ratio_max_.data();
    A.iterations = strip_iterations_.data();
    if (tangents) {
        set_kappa_slip(grid(), s, tangent_);
        A.a = s.a;
        A.kappa_wx = tangent_.kappa_wx.data();
        A.kappa_wy = tangent_.kappa_wy.data();
        A.sum_px = tangent_.sum_px.data();
        A.sum_py = tangent_.sum_py.data();
        A.sum_x_py = tangent_.sum_x_py.data();
    }
    march_law(A, kernel_isa());
    double lo = 2.0, hi = -1.0, evaluations = 0.0;
    for (int j = 0; j < geo.ny; ++j) {
        lo = std::min(lo, ratio_min_[j]);
        hi = std::max(hi, ratio_max_[j]);
        evaluations += strip_iterations_[j];
    }
    if (hi >= 0.0) {
        mu_min_ = mu_s * lo;
        mu_max_ = mu_s * hi;
    }
    iterations_ = static_cast<int>(evaluations);
}

// With memory: the march of march_step.hpp one element at a time, each
// slipping element solved by local_slip() under its MemoryElement.
void FastsimLawModel::march_with_memory()
{
    const MarchGeometry& geo = geometry();
    MarchState& st = march_state();
    const ModelSetup& s = setup();
    const double* bound = march_bound(); // with the element-wise factors
    const double mu_s = static_friction(law_);
    const double T = s.traction_scale; // traction unit of q' [Pa]
    mu_min_ = mu_max_ = mu_s;
    iterations_ = 0;
    bool any_slip = false;
    for (int j = 0; j < geo.ny; ++j) {
        double px = 0.0, py = 0.0, sum_px = 0.0, sum_py = 0.0, sum_x_py = 0.0, slips = 0.0;
        double mu_prev = mu_s;   // Newton's start: the strip's last slipping element's mu
        double mu_memory = mu_s; // the previous element's mu (mu_s before the strip)
        for (int m = 0; m < geo.nx; ++m) {
            const Eigen::Index p = static_cast<Eigen::Index>(m) * geo.stride + j;
            const double h = geo.step[p], in = geo.inside[p];
            if (in == 0.0) mu_memory = mu_s; // each contact segment from its leading edge
            const double qx = in * (px - h * st.wx[j]);
            const double qy = in * (py - h * (st.wy[j] + s.kin.cy * geo.x_slip[p]));
            const double P = std::sqrt(qx * qx + qy * qy);
            double f = 1.0;
            // The element's law is mu_m, and its coefficient at s = 0 decides slip.
            const MemoryElement element{&law_, memory_, h * s.a / V_, mu_memory};
            const double mu_at_rest = in != 0.0 ? friction_value(element, 0.0).mu : mu_s;
            if (in != 0.0) mu_memory = mu_at_rest;
            if (P > bound[p] * (mu_at_rest / mu_s)) {
                // Slip speed per unit of q' lost: V |(L1 q_x, L2 q_y)| / |q'| T / (h a).
                const double lx = s.L1 * qx, ly = s.L2 * qy;
                const double Lq = std::sqrt(lx * lx + ly * ly);
                const double c = V_ * Lq / P * T / (h * s.a);
                const LocalSlip r = local_slip(element, P, bound[p] / mu_s, c, mu_prev);
                mu_prev = r.mu;
                mu_memory = r.mu;
                f = r.t / P;
                iterations_ += r.iterations;
                if (!any_slip) mu_min_ = mu_max_ = r.mu;
                any_slip = true;
                mu_min_ = std::min(mu_min_, r.mu);
                mu_max_ = std::max(mu_max_, r.mu);
                slips += 1.0;
            }
            st.qx[p] = qx;
            st.qy[p] = qy;
            st.factor[p] = f;
            px = f * qx;
            py = f * qy;
            sum_px += px;
            sum_py += py;
            sum_x_py += geo.x_centre[p] * py;
        }
        st.px[j] = px;
        st.py[j] = py;
        st.sum_px[j] = sum_px;
        st.sum_py[j] = sum_py;
        st.sum_x_py[j] = sum_x_py;
        st.slip_count[j] = slips;
    }
}

} // namespace creepwork
