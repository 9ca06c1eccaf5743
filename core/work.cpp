#include "work.hpp"

#include <cmath>

namespace creepwork {

void WorkState::resize(int n_elements, int ny)
{
    slip_x.setZero(n_elements);
    slip_y.setZero(n_elements);
    paper.setZero(n_elements);
    consistent.setZero(n_elements);
    strip_dissipation.setZero(ny);
    strip_loss.setZero(ny);
    strip_pool.setZero(ny);
    profile.setZero(ny);
    running_px.setZero(ny);
    running_py.setZero(ny);
}

double equal_area_parabola(double W, double b, double y)
{
    const double r = 1.0 - (y / b) * (y / b);
    return r > 0.0 ? 0.75 * W / b * r : 0.0;
}

namespace {

// Walk every strip once: micro-slip, the paper's work, each element's
// friction dissipation D_k (kept in work.consistent until it is distributed)
// and each strip's numerical and trailing-edge losses.
void account_strips(const ContactGrid& grid, const ModelSetup& s, const MarchState& st,
                    WorkState& w)
{
    const int nx = grid.nx(), ny = grid.ny();
    const double T = s.traction_scale;
    const double TL1 = T * s.L1, TL2 = T * s.L2;
    // Spin in the model's rigid slip is scaled by L1/L3, L2/L3 (Kalker 1982).
    const double spin_x_model = s.phi * s.L1 / s.L3, spin_y_model = s.phi * s.L2 / s.L3;
    w.running_px.setZero();
    w.running_py.setZero();
    w.strip_dissipation.setZero();
    w.strip_loss.setZero();

    for (int m = 0; m < nx; ++m) {
        for (int j = 0; j < ny; ++j) {
            const Eigen::Index k = static_cast<Eigen::Index>(m) * ny + j;
            const double f = st.factor[k];
            const double pxn = f * st.qx[k], pyn = f * st.qy[k];
            const double dpx = pxn - w.running_px[j], dpy = pyn - w.running_py[j];
            const double dy = s.b * grid.y_width()[j];
            // Numerical dissipation of the step; an exterior element after the
            // strip's last contact element releases the exit energy here.
            w.strip_loss[j] += 0.5 * T * (TL1 * dpx * dpx + TL2 * dpy * dpy) * dy;

            const bool inside = grid.in_contact()[k] != 0.0;
            const double y = s.b * grid.y_centre()[j];
            const double xs = s.a * grid.x_slip()[k];
            double sx = 0.0, sy = 0.0, dissipation = 0.0;
            if (inside && f < 1.0) {
                // s = w + (u - u_prev)/h with u = L p: zero in adhesion by construction.
                const double h = s.a * grid.step()[k];
                sx = s.xi - spin_x_model * y + s.L1 * T * dpx / h;
                sy = s.eta + spin_y_model * xs + s.L2 * T * dpy / h;
                // -p.(u - u*) dy = T^2 f (1 - f) q'.L q' dy >= 0.
                dissipation = T * f * (1.0 - f) *
                              (TL1 * st.qx[k] * st.qx[k] + TL2 * st.qy[k] * st.qy[k]) * dy;
            }
            w.slip_x[k] = sx;
            w.slip_y[k] = sy;
            w.consistent[k] = dissipation;
            w.strip_dissipation[j] += dissipation;

            // Paper eq. 36 read as element force x physical micro-slip: the
            // model's micro-slip with its scaled spin replaced by the true one.
            double paper = 0.0;
            if (inside) {
                const double area = s.a * s.b * grid.x_length()[j] * grid.y_width()[j];
                const double phys_x = sx - (s.phi - spin_x_model) * y;
                const double phys_y = sy + (s.phi - spin_y_model) * xs;
                paper = -area * T * (pxn * phys_x + pyn * phys_y);
            }
            w.paper[k] = paper;
            w.running_px[j] = pxn;
            w.running_py[j] = pyn;
        }
    }
    for (int j = 0; j < ny; ++j) {
        const double px = w.running_px[j], py = w.running_py[j];
        w.strip_loss[j] += 0.5 * T * (TL1 * px * px + TL2 * py * py) * s.b * grid.y_width()[j];
    }
}

// Each strip's pool: its own dissipation and losses, plus the losses of
// strips without slip, handed to the nearest strip(s) with slip (split
// evenly on a tie). Returns false when no strip slips at all.
bool fill_pools(WorkState& w)
{
    const Eigen::Index ny = w.strip_pool.size();
    bool any_slip = false;
    for (Eigen::Index j = 0; j < ny; ++j) {
        const bool slips = w.strip_dissipation[j] > 0.0;
        any_slip = any_slip || slips;
        w.strip_pool[j] = slips ? w.strip_dissipation[j] + w.strip_loss[j] : 0.0;
    }
    if (!any_slip) return false;
    for (Eigen::Index j = 0; j < ny; ++j) {
        if (w.strip_dissipation[j] > 0.0 || w.strip_loss[j] == 0.0) continue;
        Eigen::Index below = j - 1, above = j + 1;
        while (below >= 0 && !(w.strip_dissipation[below] > 0.0)) --below;
        while (above < ny && !(w.strip_dissipation[above] > 0.0)) ++above;
        const bool has_below = below >= 0, has_above = above < ny;
        const Eigen::Index d_below = j - below, d_above = above - j;
        if (has_below && has_above && d_below == d_above) {
            w.strip_pool[below] += 0.5 * w.strip_loss[j];
            w.strip_pool[above] += 0.5 * w.strip_loss[j];
        } else if (has_below && (!has_above || d_below < d_above)) {
            w.strip_pool[below] += w.strip_loss[j];
        } else {
            w.strip_pool[above] += w.strip_loss[j];
        }
    }
    return true;
}

// No element slips: the energy is released in slip zones thinner than one
// element at the trailing edge, so it goes to each strip's last contact
// element (which the state map calls adhesion; flagged kWorkUnresolved).
void put_losses_on_trailing_elements(const ContactGrid& grid, WorkState& w)
{
    const int nx = grid.nx(), ny = grid.ny();
    for (int j = 0; j < ny; ++j) {
        for (int m = nx - 1; m >= 0; --m) {
            const Eigen::Index k = static_cast<Eigen::Index>(m) * ny + j;
            if (grid.in_contact()[k] != 0.0) {
                w.consistent[k] = w.strip_loss[j];
                break;
            }
        }
    }
}

void lateral_profile(const ContactGrid& grid, const ModelSetup& s, double W, WorkState& w,
                     WorkTotals& t)
{
    const int nx = grid.nx(), ny = grid.ny();
    w.profile.setZero();
    for (int m = 0; m < nx; ++m)
        for (int j = 0; j < ny; ++j)
            w.profile[j] += w.consistent[static_cast<Eigen::Index>(m) * ny + j];
    double peak = 0.0;
    for (int j = 0; j < ny; ++j) {
        w.profile[j] /= s.b * grid.y_width()[j];
        peak = std::fmax(peak, w.profile[j]);
    }
    double max_diff = 0.0, sum_sq = 0.0;
    int count = 0;
    for (int j = 0; j < ny; ++j) {
        if (grid.contact_count()[j] == 0) continue;
        const double d =
            w.profile[j] - equal_area_parabola(W, s.b, s.b * grid.y_centre()[j]);
        max_diff = std::fmax(max_diff, std::fabs(d));
        sum_sq += d * d;
        ++count;
    }
    if (peak > 0.0 && count > 0) {
        t.profile_max_diff = max_diff / peak;
        t.profile_rms_diff = std::sqrt(sum_sq / count) / peak;
    }
}

} // namespace

WorkTotals compute_work(const ContactGrid& grid, const ModelSetup& setup, const MarchState& march,
                        double W_macro, WorkState& w)
{
    WorkTotals t;
    account_strips(grid, setup, march, w);
    const Eigen::Index n = w.consistent.size();
    const int ny = grid.ny();

    for (Eigen::Index k = 0; k < n; ++k) t.W_micro_paper += w.paper[k];

    if (fill_pools(w)) {
        for (Eigen::Index k = 0; k < n; ++k) {
            const Eigen::Index j = k % ny;
            if (w.consistent[k] > 0.0)
                w.consistent[k] *= w.strip_pool[j] / w.strip_dissipation[j];
        }
    } else {
        put_losses_on_trailing_elements(grid, w);
        t.flags |= kWorkUnresolved;
    }

    double total = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) total += w.consistent[k];
    if (W_macro > 0.0 && total > 0.0) {
        t.balance = W_macro / total;
        for (Eigen::Index k = 0; k < n; ++k) w.consistent[k] *= t.balance;
        for (Eigen::Index k = 0; k < n; ++k) t.W_consistent += w.consistent[k];
    } else {
        // Nothing to distribute, or a macro power that is not dissipative
        // (possible only through the three-flexibility defect, or rounding).
        if (W_macro != 0.0 || total > 0.0) {
            t.flags |= kWorkNonPositive;
            t.balance = 0.0;
        }
        w.consistent.setZero();
    }
    lateral_profile(grid, setup, t.W_consistent, w, t);
    return t;
}

} // namespace creepwork
