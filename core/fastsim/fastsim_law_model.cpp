#include "fastsim/fastsim_law_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "contact/error.hpp"
#include "fastsim/fastsim_jacobian.hpp"
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
    tau_px_.setZero(geometry().stride);
    tau_py_.setZero(geometry().stride);
    tau_x_py_.setZero(geometry().stride);
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

void FastsimLawModel::prepare(const ContactInput& input, SolveMode mode)
{
    if (mode == SolveMode::full)
        throw Error(ErrorKind::invalid_input,
                    "mode: FASTSIM with a law of the slip speed gives forces only (no work map)");
    if (V_ <= 0.0) throw Error(ErrorKind::invalid_input, "V: no friction law set (set_law)");
    input_ = input;
    input_.mu = static_friction(law_);
    const ModelSetup setup =
        make_model_setup(input_, discrete_load_of(discrete_load(), input_.pressure));
    begin(setup, geometry().shape(setup.pressure).data(), geometry().max_shape(setup.pressure));
}

SolveTotals FastsimLawModel::solve(const ContactInput& input, SolveMode mode)
{
    prepare(input, mode);
    march_with_law(false);
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
    prepare(input, mode);
    march_with_law(true);
    Jacobian J = fastsim_jacobian(input_, setup(), grid(), march_state(), tangent_);
    // The slip-speed factor c is proportional to the traction unit T, which
    // N moves (T = mu_s p0, p0 proportional to N): the column of N gains
    // frame_i T dPhi_i/dln T (dT/dN)/T.
    if (input_.mu > 0.0 && input_.normal_force > 0.0) {
        StripTangents tau;
        Eigen::ArrayXd zero = Eigen::ArrayXd::Zero(kStripTangents * geometry().stride);
        Eigen::ArrayXd px = zero, py = zero, xpy = zero;
        px.head(geometry().stride) = tau_px_;
        py.head(geometry().stride) = tau_py_;
        xpy.head(geometry().stride) = tau_x_py_;
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

// The march of march_step.hpp, one element at a time, with the law's
// projection in slipping elements; with tangents also the derivatives of
// each traction by k = ux, uy, kappa (march_tangent.hpp) and by ln T.
void FastsimLawModel::march_with_law(bool tangents)
{
    constexpr int K = kTangents + 1; // ux, uy, kappa, ln T
    const MarchGeometry& geo = geometry();
    MarchState& st = march_state();
    const ModelSetup& s = setup();
    const double* bound = geo.shape(s.pressure).data();
    const double mu_s = static_friction(law_);
    const double T = s.traction_scale; // traction unit of q' [Pa]
    mu_min_ = mu_max_ = mu_s;
    iterations_ = 0;
    bool any_slip = false;
    for (int j = 0; j < geo.ny; ++j) {
        double px = 0.0, py = 0.0, sum_px = 0.0, sum_py = 0.0, sum_x_py = 0.0, slips = 0.0;
        double mu_prev = mu_s;   // Newton's start: the strip's last slipping element's mu
        double mu_memory = mu_s; // memory: the previous element's mu (mu_s before the strip)
        // Tangents: dp and the strip sums, dw of kappa (-b Y, a (X_slip + offset dX)).
        double dpx[K] = {}, dpy[K] = {}, tsx[K] = {}, tsy[K] = {}, tsxy[K] = {};
        const double kwx = -s.b * grid().y_centre()[j];
        const double kwy = s.kin.spin_offset > 0.0 ? s.a * s.kin.spin_offset * grid().x_length()[j]
                                                    : 0.0;
        for (int m = 0; m < geo.nx; ++m) {
            const Eigen::Index p = static_cast<Eigen::Index>(m) * geo.stride + j;
            const double h = geo.step[p], in = geo.inside[p];
            if (in == 0.0) mu_memory = mu_s; // each contact segment from its leading edge
            const double qx = in * (px - h * st.wx[j]);
            const double qy = in * (py - h * (st.wy[j] + s.kin.cy * geo.x_slip[p]));
            const double P = std::sqrt(qx * qx + qy * qy);
            double f = 1.0;
            double dqx[K], dqy[K];
            if (tangents) {
                const double dwx[K] = {1.0, 0.0, kwx, 0.0};
                const double dwy[K] = {0.0, 1.0, kwy + s.a * geo.x_slip[p], 0.0};
                for (int k = 0; k < K; ++k) {
                    dqx[k] = in * (dpx[k] - h * dwx[k]);
                    dqy[k] = in * (dpy[k] - h * dwy[k]);
                }
            }
            // With memory the element's law is mu_m, and its coefficient at
            // s = 0 decides slip; without, mu_s and the bound itself.
            const bool memory = memory_.distance > 0.0 && in != 0.0;
            const MemoryElement element{&law_, memory_, h * s.a / V_, mu_memory};
            const double mu_at_rest = memory ? friction_value(element, 0.0).mu : mu_s;
            if (memory) mu_memory = mu_at_rest;
            if (P > bound[p] * (mu_at_rest / mu_s)) {
                // Slip speed per unit of q' lost: V |(L1 q_x, L2 q_y)| / |q'| T / (h a).
                const double lx = s.L1 * qx, ly = s.L2 * qy;
                const double Lq = std::sqrt(lx * lx + ly * ly);
                const double c = V_ * Lq / P * T / (h * s.a);
                const LocalSlip r = memory ? local_slip(element, P, bound[p] / mu_s, c, mu_prev)
                                           : local_slip(law_, P, bound[p] / mu_s, c, mu_prev);
                mu_prev = r.mu;
                if (memory) mu_memory = r.mu;
                f = r.t / P;
                iterations_ += r.iterations;
                if (!any_slip) mu_min_ = mu_max_ = r.mu;
                any_slip = true;
                mu_min_ = std::min(mu_min_, r.mu);
                mu_max_ = std::max(mu_max_, r.mu);
                slips += 1.0;
                if (tangents)
                    for (int k = 0; k < K; ++k) {
                        const double dP = (qx * dqx[k] + qy * dqy[k]) / P;
                        const double dLq = (s.L1 * lx * dqx[k] + s.L2 * ly * dqy[k]) / Lq;
                        const double dc = c * (dLq / Lq - dP / P) + (k == kTangents ? c : 0.0);
                        const double dt = r.dt_dP * dP + r.dt_dc * dc;
                        const double df = (dt - f * dP) / P;
                        dpx[k] = df * qx + f * dqx[k];
                        dpy[k] = df * qy + f * dqy[k];
                    }
            } else if (tangents) {
                for (int k = 0; k < K; ++k) {
                    dpx[k] = dqx[k];
                    dpy[k] = dqy[k];
                }
            }
            st.qx[p] = qx;
            st.qy[p] = qy;
            st.factor[p] = f;
            px = f * qx;
            py = f * qy;
            sum_px += px;
            sum_py += py;
            sum_x_py += geo.x_centre[p] * py;
            if (tangents)
                for (int k = 0; k < K; ++k) {
                    tsx[k] += dpx[k];
                    tsy[k] += dpy[k];
                    tsxy[k] += geo.x_centre[p] * dpy[k];
                }
        }
        st.px[j] = px;
        st.py[j] = py;
        st.sum_px[j] = sum_px;
        st.sum_py[j] = sum_py;
        st.sum_x_py[j] = sum_x_py;
        st.slip_count[j] = slips;
        if (tangents) {
            for (int k = 0; k < kTangents; ++k) {
                tangent_.sum_px[k * geo.stride + j] = tsx[k];
                tangent_.sum_py[k * geo.stride + j] = tsy[k];
                tangent_.sum_x_py[k * geo.stride + j] = tsxy[k];
            }
            tau_px_[j] = tsx[kTangents];
            tau_py_[j] = tsy[kTangents];
            tau_x_py_[j] = tsxy[kTangents];
        }
    }
}

} // namespace creepwork
