#include "fastsim/fastsim_law_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "contact/error.hpp"
#include "friction/local_slip.hpp"

namespace creepwork {

FastsimLawModel::FastsimLawModel(const GridSpec& grid)
    : FastsimLawModel(std::make_shared<const ContactGrid>(grid))
{
}

FastsimLawModel::FastsimLawModel(std::shared_ptr<const ContactGrid> grid)
    : MarchModel(std::move(grid))
{
}

void FastsimLawModel::set_law(const FrictionLaw& law, double V)
{
    check_friction_law(law);
    if (!(std::isfinite(V) && V > 0.0))
        throw Error(ErrorKind::invalid_input,
                    "V (the rolling speed) must be finite and > 0 [m/s] for a law of the slip speed");
    law_ = law;
    V_ = V;
}

SolveTotals FastsimLawModel::solve(const ContactInput& input, SolveMode mode)
{
    if (mode == SolveMode::full)
        throw Error(ErrorKind::invalid_input,
                    "mode: FASTSIM with a law of the slip speed gives forces only (no work map)");
    if (V_ <= 0.0) throw Error(ErrorKind::invalid_input, "V: no friction law set (set_law)");
    ContactInput in = input;
    in.mu = static_friction(law_);
    const ModelSetup setup = make_model_setup(in, discrete_load_of(discrete_load(), in.pressure));
    begin(setup, geometry().shape(setup.pressure).data(), geometry().max_shape(setup.pressure));
    march_with_law();
    return totals(in, mode, ModelKind::fastsim);
}

SolveTotals FastsimLawModel::solve_jacobian(const ContactInput&, SolveMode, Jacobian&)
{
    throw Error(ErrorKind::invalid_input,
                "jacobian: FASTSIM with a law of the slip speed has no Jacobian");
}

// The march of march_step.hpp, one element at a time, with the law's
// projection in slipping elements.
void FastsimLawModel::march_with_law()
{
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
        double mu_prev = mu_s; // Newton's start: the strip's last slipping element's mu
        for (int m = 0; m < geo.nx; ++m) {
            const Eigen::Index p = static_cast<Eigen::Index>(m) * geo.stride + j;
            const double h = geo.step[p], in = geo.inside[p];
            const double qx = in * (px - h * st.wx[j]);
            const double qy = in * (py - h * (st.wy[j] + s.kin.cy * geo.x_slip[p]));
            const double P = std::sqrt(qx * qx + qy * qy);
            double f = 1.0;
            if (P > bound[p]) {
                // Slip speed per unit of q' lost: V |(L1 q_x, L2 q_y)| / |q'| T / (h a).
                const double lx = s.L1 * qx, ly = s.L2 * qy;
                const double c = V_ * std::sqrt(lx * lx + ly * ly) / P * T / (h * s.a);
                const LocalSlip r = local_slip(law_, P, bound[p] / mu_s, c, mu_prev);
                mu_prev = r.mu;
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
