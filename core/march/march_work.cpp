#include "march/march_work.hpp"

#include <algorithm>
#include <cmath>

#include "contact/fp_safe.hpp"
#include "march/march_step.hpp"

namespace creepwork {

void WorkState::resize(int n_elements, int ny)
{
    // The kernels' layout: [m * stride + j], stride = padded_strips(ny).
    const int stride = padded_strips(ny);
    const Eigen::Index n = static_cast<Eigen::Index>(ny > 0 ? n_elements / ny : 0) * stride;
    slip_x.setZero(n);
    slip_y.setZero(n);
    paper.setZero(n);
    consistent.setZero(n);
    strip_dissipation.setZero(stride);
    strip_loss.setZero(stride);
    strip_pool.setZero(stride);
    strip_paper.setZero(stride);
    strip_work.setZero(stride);
    profile.setZero(stride);
    width.setZero(stride);
    rigid_slip_x.setZero(stride);
    rigid_slip_y.setZero(stride);
    paper_spin_x.setZero(stride);
    neg_area_T.setZero(stride);
    ratio.setZero(stride);
}

namespace {

// Everything the work pass reads and writes besides the march's view (its
// geometry and (q', f)); per-element pointers point at element 0 of the
// kernels' layout [m * stride + j].
struct WorkArgs {
    MarchView march;
    double a = 0, T = 0, half_T = 0, TL1 = 0, TL2 = 0, L1T = 0, L2T = 0, eta = 0, spin_y = 0,
           phi = 0;
    // Per strip.
    const double *width = nullptr, *rigid_slip_x = nullptr, *rigid_slip_y = nullptr,
                 *paper_spin_x = nullptr, *neg_area_T = nullptr;
    // Per element, out.
    double *slip_x = nullptr, *slip_y = nullptr, *paper = nullptr, *dissipation = nullptr;
    // Per strip, out.
    double *loss = nullptr, *strip_dissipation = nullptr, *strip_paper = nullptr;
};

// The work of W strips from strip j0, element by element along the march
// (p' = f q' as the march computed it; p'_prev the element before):
//  - micro-slip s = w + (u - u_prev)/h with u = L p (zero in adhesion by
//    construction, so only computed in slip);
//  - the numerical dissipation 1/2 dp L dp of the step (an exterior element
//    after the strip's last contact element releases the exit energy here);
//  - friction dissipation D = -p.(u - u*) dy = T^2 f (1 - f) q'.L q' dy >= 0;
//  - the paper's eq. 36 as printed: element force x translational
//    micro-slip + element moment x spin, the moment taken about the
//    element's own position (eq. 28), i.e. force x (s - s_spin + phi e_z x r)
//    with s_spin the model's scaled-spin slip at the slip point x' and r the
//    element centre. On Kalker's strip grid x' is half a step ahead of the
//    centre; taking the spin there instead changes W_micro by tens of per
//    cent on coarse grids and does not reproduce the paper's Table 1. In
//    adhesion s = 0 and the same formula
//    holds (the translational slip is then minus the model's spin slip).
// Exterior elements never slip (q' = g = 0), so "slip" means inside, f < 1.
// Nothing here feeds the next element but p', so the steps overlap freely.
template <int W>
CREEPWORK_INLINE void work_strips(const WorkArgs& A, int j0)
{
    using V = simd::Vec<W>;
    // Locals, not A's fields: the stores below may alias anything.
    const int nx = A.march.nx;
    const long stride = A.march.stride;
    const MarchRows rows(A.march, j0);
    const double *x_slip = rows.x_slip, *x_centre = rows.x_centre, *step = rows.step,
                 *inside = rows.inside;
    const double *qx = rows.qx, *qy = rows.qy, *factor = rows.factor;
    double *slip_x = A.slip_x + j0, *slip_y = A.slip_y + j0, *paper = A.paper + j0,
           *dissipation = A.dissipation + j0;
    const V zero = simd::broadcast<W>(0.0), one = simd::broadcast<W>(1.0);
    const V a = simd::broadcast<W>(A.a), T = simd::broadcast<W>(A.T);
    const V half_T = simd::broadcast<W>(A.half_T), TL1 = simd::broadcast<W>(A.TL1),
            TL2 = simd::broadcast<W>(A.TL2), L1T = simd::broadcast<W>(A.L1T),
            L2T = simd::broadcast<W>(A.L2T), eta = simd::broadcast<W>(A.eta),
            spin_y = simd::broadcast<W>(A.spin_y), phi = simd::broadcast<W>(A.phi);
    const V dy = simd::load<W>(A.width + j0), wsx = simd::load<W>(A.rigid_slip_x + j0),
            wsy = simd::load<W>(A.rigid_slip_y + j0),
            psx = simd::load<W>(A.paper_spin_x + j0), nat = simd::load<W>(A.neg_area_T + j0);
    V px_prev = zero, py_prev = zero, loss = zero, diss = zero, spaper = zero;
    for (int m = 0; m < nx; ++m) {
        const long e = m * stride;
        const V f = simd::load<W>(factor + e), in = simd::load<W>(inside + e);
        const V q_x = simd::load<W>(qx + e), q_y = simd::load<W>(qy + e);
        const V px = f * q_x, py = f * q_y;
        const V dpx = px - px_prev, dpy = py - py_prev;
        loss += half_T * (TL1 * dpx * dpx + TL2 * dpy * dpy) * dy;
        const V xp = a * simd::load<W>(x_slip + e); // slip point x' [m]
        const auto slip = f < one;
        const V slipping = slip ? one : zero;
        V sx = zero, sy = zero, d = zero;
        if (simd::max_lane(slipping) > 0.0) {
            const V hp = a * simd::load<W>(step + e); // step [m]
            sx = slip ? wsx + L1T * dpx / hp : zero;
            sy = slip ? wsy + spin_y * xp + L2T * dpy / hp : zero;
            d = slip ? T * f * (one - f) * (TL1 * q_x * q_x + TL2 * q_y * q_y) * dy : zero;
        }
        // The translational y-slip leaves out the whole model spin slip,
        // the spin-offset part (wsy - eta, exactly 0 without one) included.
        const V xc = a * simd::load<W>(x_centre + e); // element centre x [m]
        const V w = in != zero ? nat * (px * (sx - psx) +
                                        py * (sy - (wsy - eta) - spin_y * xp + phi * xc))
                               : zero;
        simd::store<W>(slip_x + e, sx);
        simd::store<W>(slip_y + e, sy);
        simd::store<W>(dissipation + e, d);
        simd::store<W>(paper + e, w);
        diss += d;
        spaper += w;
        px_prev = px;
        py_prev = py;
    }
    simd::store<W>(A.loss + j0, loss);
    simd::store<W>(A.strip_dissipation + j0, diss);
    simd::store<W>(A.strip_paper + j0, spaper);
}

struct WorkKernel : KernelWidths {
    template <int W>
    CREEPWORK_INLINE static void run(const WorkArgs& A)
    {
        for (int j0 = A.march.first; j0 < A.march.last; j0 += W) work_strips<W>(A, j0);
    }
};

// The map from D_k: c_k = (D_k ratio_j) balance, and each strip's sum.
// When balance = W_macro/total is not a normal number (inputs far beyond the
// creepage cap), it is applied as (D_k ratio_j / total) W_macro instead,
// which cannot underflow as a whole.
struct ScaleArgs {
    int nx = 0, ny = 0, stride = 0;
    bool divide = false;
    double balance = 0, total = 0, W_macro = 0;
    const double* ratio = nullptr;           // per strip
    double *consistent = nullptr, *strip_work = nullptr; // per element, per strip
};

template <int W, bool kDivide>
CREEPWORK_INLINE void scale_strips(const ScaleArgs& A)
{
    using V = simd::Vec<W>;
    const V balance = simd::broadcast<W>(A.balance);
    const V total = simd::broadcast<W>(A.total), macro = simd::broadcast<W>(A.W_macro);
    for (int j0 = 0; j0 < A.ny; j0 += W) {
        const V ratio = simd::load<W>(A.ratio + j0);
        V sum = simd::broadcast<W>(0.0);
        for (int m = 0; m < A.nx; ++m) {
            double* c = A.consistent + static_cast<long>(m) * A.stride + j0;
            const V v = kDivide ? simd::load<W>(c) * ratio / total * macro
                                : simd::load<W>(c) * ratio * balance;
            simd::store<W>(c, v);
            sum += v;
        }
        simd::store<W>(A.strip_work + j0, sum);
    }
}

struct ScaleKernel : KernelWidths {
    template <int W>
    CREEPWORK_INLINE static void run(const ScaleArgs& A)
    {
        if (A.divide)
            scale_strips<W, true>(A);
        else
            scale_strips<W, false>(A);
    }
};

// Each strip's pool: its own dissipation and losses, plus the losses of
// strips without slip, handed to the nearest strip(s) with slip (split
// evenly on a tie). Returns false when no strip slips at all.
bool fill_pools(Eigen::Index ny, WorkState& w)
{
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
// element (which the state map calls adhesion; flagged kWorkUnresolved; a
// strip of several segments puts all of it on its last segment's).
// Returns the total put there.
double put_losses_on_trailing_elements(const MarchGeometry& geo, WorkState& w)
{
    const int nx = geo.nx, ny = geo.ny;
    double total = 0.0;
    for (int j = 0; j < ny; ++j) {
        for (int m = nx - 1; m >= 0; --m) {
            const Eigen::Index p = static_cast<Eigen::Index>(m) * geo.stride + j;
            if (geo.inside[p] != 0.0) {
                w.consistent[p] = w.strip_loss[j];
                total += w.strip_loss[j];
                break;
            }
        }
    }
    return total;
}

// The profile and its distance to the equal-area parabola. Written without
// library calls (fmax is not inlined); the ternaries are fmax for the
// non-NaN values met here, the parabola is lateral_parabola() (contact/solved_contact.hpp) with its
// per-call constant 0.75 W / b hoisted.
void lateral_profile(const MarchGeometry& geo, const ContactGrid& grid, const ModelSetup& s,
                     double W, WorkState& w, WorkTotals& t)
{
    const int ny = grid.ny();
    const double b = s.b;
    const double* y_width = grid.y_width().data();
    const double* strip_work = w.strip_work.data();
    double* profile = w.profile.data();
    double peak = 0.0;
    for (int j = 0; j < ny; ++j) {
        const double v = strip_work[j] / (b * y_width[j]);
        profile[j] = v;
        peak = v > peak ? v : peak;
    }
    if (!(peak > 0.0)) return;
    // Differences relative to the peak before squaring: the squares of
    // absolute differences overflow once the work passes ~1e154 J/m.
    const double height = 0.75 * W / b;
    double max_diff = 0.0, sum_sq = 0.0;
    int count = 0;
    for (int j = 0; j < ny; ++j) {
        if (geo.strip_contacts[j] == 0) continue;
        const double yb = b * grid.y_centre()[j] / b;
        const double r = 1.0 - yb * yb;
        const double d = (profile[j] - (r > 0.0 ? height * r : 0.0)) / peak;
        const double ad = d < 0.0 ? -d : d;
        max_diff = ad > max_diff ? ad : max_diff;
        sum_sq += d * d;
        ++count;
    }
    if (count > 0) {
        t.profile_max_diff = max_diff;
        t.profile_rms_diff = std::sqrt(sum_sq / count);
    }
}

// march_with_work(), with the march (march_too) or after it.
void work_pass(const MarchGeometry& geo, const double* bound, const ContactGrid& grid,
               const ModelSetup& s, MarchState& st, WorkState& w, KernelIsa isa, bool march_too)
{
    const int ny = grid.ny();
    const double T = s.traction_scale;
    // Spin in the model's rigid slip is scaled by L1/L3, L2/L3 (Kalker 1982).
    const double spin_x_model = s.phi * s.L1 / s.L3, spin_y_model = s.phi * s.L2 / s.L3;
    for (int j = 0; j < ny; ++j) {
        const double y = s.b * grid.y_centre()[j];
        w.width[j] = s.b * grid.y_width()[j];
        w.rigid_slip_x[j] = s.xi - spin_x_model * y;
        // The march's spin offset (CONTACT's facphi), in metres; exactly eta
        // without one.
        w.rigid_slip_y[j] =
            s.kin.spin_offset > 0.0
                ? s.eta + spin_y_model * (s.a * s.kin.spin_offset * grid.x_length()[j])
                : s.eta;
        w.paper_spin_x[j] = (s.phi - spin_x_model) * y;
        const double area = s.a * s.b * grid.x_length()[j] * grid.y_width()[j];
        w.neg_area_T[j] = -area * T;
    }
    WorkArgs A;
    A.a = s.a;
    A.T = T;
    A.half_T = 0.5 * T;
    A.TL1 = T * s.L1;
    A.TL2 = T * s.L2;
    A.L1T = s.L1 * T;
    A.L2T = s.L2 * T;
    A.eta = s.eta;
    A.spin_y = spin_y_model;
    A.phi = s.phi;
    A.width = w.width.data();
    A.rigid_slip_x = w.rigid_slip_x.data();
    A.rigid_slip_y = w.rigid_slip_y.data();
    A.paper_spin_x = w.paper_spin_x.data();
    A.neg_area_T = w.neg_area_T.data();
    A.slip_x = w.slip_x.data();
    A.slip_y = w.slip_y.data();
    A.paper = w.paper.data();
    A.dissipation = w.consistent.data();
    A.loss = w.strip_loss.data();
    A.strip_dissipation = w.strip_dissipation.data();
    A.strip_paper = w.strip_paper.data();
    // Block by block, so that the work pass finds the march's output in cache.
    for (int first = 0; first < ny; first += kStripBlock) {
        A.march = march_view(geo, bound, s.kin.cy, st, first, std::min(ny, first + kStripBlock));
        if (march_too) march(A.march, isa);
        run_kernel<WorkKernel>(isa, A);
    }
    // The elastic energy carried out of the trailing edge.
    for (int j = 0; j < ny; ++j) {
        const double px = st.px[j], py = st.py[j];
        w.strip_loss[j] += 0.5 * T * (T * s.L1 * px * px + T * s.L2 * py * py) * s.b *
                           grid.y_width()[j];
    }
}

} // namespace

void march_with_work(const MarchGeometry& geo, const double* bound, const ContactGrid& grid,
                     const ModelSetup& s, MarchState& st, WorkState& w, KernelIsa isa)
{
    work_pass(geo, bound, grid, s, st, w, isa, true);
}

void work_of_march(const MarchGeometry& geo, const double* bound, const ContactGrid& grid,
                   const ModelSetup& s, MarchState& st, WorkState& w, KernelIsa isa)
{
    work_pass(geo, bound, grid, s, st, w, isa, false);
}

WorkTotals distribute_work(const MarchGeometry& geo, const ContactGrid& grid,
                           const ModelSetup& setup, double W_macro, WorkState& w, KernelIsa isa)
{
    WorkTotals t;
    const int ny = grid.ny();
    for (int j = 0; j < ny; ++j) t.W_micro_paper += w.strip_paper[j];

    double total = 0.0;
    if (fill_pools(ny, w)) {
        for (int j = 0; j < ny; ++j) {
            const double d = w.strip_dissipation[j];
            w.ratio[j] = quotient_if_positive(w.strip_pool[j], d); // vectorised: fp_safe.hpp
            total += w.strip_pool[j];
        }
    } else {
        total = put_losses_on_trailing_elements(geo, w);
        w.ratio.setOnes();
        t.flags |= kWorkUnresolved;
    }

    double balance = 0.0;
    if (W_macro > 0.0 && total > 0.0) {
        t.balance = balance = W_macro / total;
    } else if (W_macro != 0.0 || total > 0.0) {
        // Nothing to distribute, or a macro power that is not dissipative
        // (possible only through the three-flexibility defect, or rounding):
        // the map is zero.
        t.flags |= kWorkNonPositive;
        t.balance = 0.0;
    }
    const bool divide = balance > 0.0 ? balance < 2.2250738585072014e-308  // DBL_MIN
                                      : W_macro > 0.0 && total > 0.0;
    ScaleArgs A;
    A.nx = geo.nx;
    A.ny = ny;
    A.stride = geo.stride;
    A.divide = divide;
    A.balance = balance;
    A.total = total;
    A.W_macro = W_macro;
    A.ratio = w.ratio.data();
    A.consistent = w.consistent.data();
    A.strip_work = w.strip_work.data();
    run_kernel<ScaleKernel>(isa, A);
    for (int j = 0; j < ny; ++j) t.W_consistent += w.strip_work[j];
    lateral_profile(geo, grid, setup, t.W_consistent, w, t);
    return t;
}

} // namespace creepwork
