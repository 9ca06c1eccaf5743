#include "gap/gap_exact_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/contact_input.hpp"
#include "contact/error.hpp"
#include "contact/friction_law.hpp"
#include "contact/number_text.hpp"
#include "contact/kalker_coefficients.hpp"
#include "halfspace/cell_box.hpp"
#include "exact/exact_work.hpp"
#include "exact/tangential_solve.hpp"

namespace creepwork {
GapExactModel::Level::Level(int nx_, int ny_)
    : TangentialLevel(nx_, ny_, ConvolutionUse::tangential)
{
}

// The model's steps of the tangential solve (exact/tangential_solve.hpp).
struct GapExactModel::Steps {
    GapExactModel& m;
    const ContactInput& in;
    TangentialLevel& level(int l) { return *m.levels_[l]; }
    void prepare(int l)
    {
        Level& L = *m.levels_[l];
        L.conv.set_size(L.nx, L.ny);
        L.tangential.set_size(L.nx, L.ny);
        L.conv.set_coefficients(L.dy / L.dx, in.nu);
        m.sample_bound(*m.levels_[0], L);
        m.set_rigid_slip(L);
    }
    void first_guess(int l) { m.march_start(*m.levels_[l], in.nu, in.G); }
    void interpolate(int l) { m.interpolate(*m.levels_[l + 1], *m.levels_[l]); }
    void predict() { m.predict_start(in.nu); }
};

GapExactModel::GapExactModel(const GridSpec& grid)
    : grid_(checked_gap_grid(grid)), nx_(grid.nx), ny_(grid.ny),
      normal_(grid, GapNormalOptions{true, true}), labels_(grid.nx, grid.ny)
{
    int nx = nx_, ny = ny_;
    levels_.push_back(std::make_unique<Level>(nx, ny));
    levels_.front()->tangential.reserve_coarse(); // the warm steps' (the finest level's)
    while (coarser(nx, ny)) levels_.push_back(std::make_unique<Level>(nx, ny));
    const size_t n = static_cast<size_t>(nx_) * ny_;
    for (auto* v : {&traction_, &slip_, &rigid_, &tangent_w_}) v->assign(n, 0.0);
    dp_dN_.assign(n, 0.0);
    dg_.assign(n, 0.0);
    state_.assign(n, 0);
    for (auto* v : {&paper_, &consistent_}) v->assign(n, 0.0);
    in_contact_.assign(n, 0);
    history_.resize(n);
    for (auto* v : {&profile_, &row_d_, &row_pool_}) v->assign(ny_, 0.0);
    gap_centres(grid_, x_column_, y_row_);
    // At most one patch per two elements (4-connected components of a
    // checkerboard's contact elements).
    patches_.reserve(n / 2 + 1);
}

GapExactModel::~GapExactModel() = default;

void GapExactModel::set_kernel_isa(KernelIsa isa)
{
    normal_.set_kernel_isa(isa);
    for (auto& L : levels_) L->conv.set_kernel_isa(isa);
}

void GapExactModel::validate(const ContactInput& in) const
{
    if (in.model != ModelKind::exact)
        throw Error(ErrorKind::invalid_input,
                    "model = " + std::string(in.model == ModelKind::fastsim ? "fastsim"
                                                                            : "calibrated") +
                        " is invalid on a gap grid: a contact of any shape is solved by the "
                        "exact model (model = exact)");
    if (in.flexibility != FlexibilitySource::kalker_from_material)
        throw Error(ErrorKind::invalid_input,
                    "flexibility = given is invalid for model = exact: the exact theory needs "
                    "the material (G, nu), not L1, L2, L3");
    validate_gap_input(in, static_cast<size_t>(nx_) * ny_, normal_.kernel_isa());
    if (in.tau_c0 != 0.0 || in.k_tau != 0.0)
        reject_input(in.tau_c0 != 0.0 ? "tau_c0" : "k_tau", in.tau_c0 != 0.0 ? in.tau_c0 : in.k_tau,
                     "must be 0 on a gap grid: the exact model there takes the interface "
                     "layer's elastic compliance (layer_h, layer_G) only");
    require_non_negative("tolerance", in.tolerance);
    if (in.tolerance != 0.0 && !(in.tolerance >= 1e-13 && in.tolerance < 1.0))
        reject_input("tolerance", in.tolerance,
                     "must be 0 (the default, 1e-8) or in [1e-13, 1) for model = exact: "
                     "double precision cannot resolve less");
    if (in.max_iterations < 0)
        reject_input("max_iterations", in.max_iterations, "must be >= 0 (0: the model's default)");
}

void GapExactModel::set_rigid_slip(Level& L) const
{
    // w = (xi - phi y, eta + phi (x + spin_offset dx)) at element centres, in
    // units of mu p_max / G (setup_: already divided), rolling frame.
    const Setup& s = setup_;
    std::vector<SteadyRolling::Complex>& w = L.tangential.rigid_slip();
    for (int j = 0; j < L.ny; ++j) {
        const double y = L.y0 + j * L.dy;
        for (int i = 0; i < L.nx; ++i) {
            const double x = L.x0 + i * L.dx;
            w[i + L.nx * j] = {s.xi - s.phi * y, s.eta + s.phi * (x + s.spin_offset * L.dx)};
        }
    }
}

// Bilinear interpolation of the fine bound at the coarse element centres.
void GapExactModel::sample_bound(Level& F, Level& C) const
{
    const std::vector<double>& gf = F.tangential.bound();
    std::vector<double>& gc = C.tangential.bound();
    for (int j = 0; j < C.ny; ++j) {
        const double ty = std::min(std::max((C.y0 + j * C.dy - F.y0) / F.dy, 0.0), F.ny - 1.0);
        const int j0 = std::min(static_cast<int>(ty), F.ny - 2);
        const double fy = ty - j0;
        for (int i = 0; i < C.nx; ++i) {
            const double tx =
                std::min(std::max((C.x0 + i * C.dx - F.x0) / F.dx, 0.0), F.nx - 1.0);
            const int i0 = std::min(static_cast<int>(tx), F.nx - 2);
            const double fx = tx - i0;
            const double* g = gf.data() + i0 + static_cast<size_t>(F.nx) * j0;
            gc[i + C.nx * j] = (1.0 - fy) * ((1.0 - fx) * g[0] + fx * g[1]) +
                               fy * ((1.0 - fx) * g[F.nx] + fx * g[F.nx + 1]);
        }
    }
}

// Bilinear interpolation of the coarse traction at the fine element centres
// (clipped to the fine bound by the fine solver).
void GapExactModel::interpolate(const Level& C, Level& F) const
{
    interpolate_traction(
        C, F, [&](int i) { return (F.x0 + i * F.dx - C.x0) / C.dx; },
        [&](int j) { return (F.y0 + j * F.dy - C.y0) / C.dy; });
}

// Kalker's simplified theory as the first guess on the coarsest grid: each
// row marched from its leading edge, restarting behind every gap in the
// contact, with the flexibilities of one ellipse: the patches' equivalent
// ellipses (semi-axes twice the root-mean-square extent of their elements)
// averaged by area.
void GapExactModel::march_start(Level& L, double nu, double G)
{
    const int count = labels_.count();
    double a = 0.0, b = 0.0, weight = 0.0;
    for (int p = 0; p < count; ++p) {
        double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0;
        for (int j = 0; j < ny_; ++j)
            for (int i = 0; i < nx_; ++i) { // rolling frame
                if (labels_.of(caller_index(i) + nx_ * j) != p) continue;
                const double x = i * grid_.dx, y = j * grid_.dy;
                n += 1.0;
                sx += x;
                sy += y;
                sxx += x * x;
                syy += y * y;
            }
        const double vx = std::max(sxx / n - (sx / n) * (sx / n), 0.0) + grid_.dx * grid_.dx / 12;
        const double vy = std::max(syy / n - (sy / n) * (sy / n), 0.0) + grid_.dy * grid_.dy / 12;
        a += n * 2.0 * std::sqrt(vx);
        b += n * 2.0 * std::sqrt(vy);
        weight += n;
    }
    a /= weight;
    b /= weight;
    const double ratio = std::min(std::max(a / b, kMinAspect), kMaxAspect);
    const Flexibilities F = kalker_flexibilities(a, b, G, kalker_coefficients(ratio, nu));
    const double l1 = L.dx / (F.L1 * G), l2 = L.dx / (F.L2 * G), l3 = L.dx / (F.L3 * G);
    const Setup& s = setup_;
    simplified_march(
        L, l1, l2, l3, s.xi, s.eta, s.phi, [&](int i) { return L.x0 + i * L.dx; },
        [&](int j) { return L.y0 + j * L.dy; });
}

// The smallest box of the grid holding the contact (pressure > 0; without
// contact the whole grid), in the rolling frame, is level 0; the coarser
// levels cover it with half as many cells per direction each while both
// keep kMinCoarseCells (made ready by the cold start, which alone uses them).
void GapExactModel::set_box(const GridConvolution& coefficients)
{
    const std::vector<double>& pressure = normal_.pressure();
    const CellBox box = cell_box(nx_, ny_, [&](std::size_t k) { return pressure[k] > 0.0; });
    const int i0 = box.i0, j0 = box.j0;
    box_i0_ = i0;
    box_j0_ = j0;
    const double left = (setup_.direction > 0 ? grid_.x0 - 0.5 * grid_.dx
                                              : -(grid_.x0 + (nx_ - 0.5) * grid_.dx)) +
                        i0 * grid_.dx;
    const double bottom = grid_.y0 - 0.5 * grid_.dy + j0 * grid_.dy;
    int nx = box.nx, ny = box.ny;
    const int bx = nx, by = ny;
    Level& fine = *levels_[0];
    fine.nx = nx;
    fine.ny = ny;
    fine.conv.set_size(nx, ny);
    fine.tangential.set_size(nx, ny);
    fine.conv.copy_coefficients(coefficients);
    // The normal problem's last products ran on this box (the contact set's):
    // their spectra alpha and K33 are this one's.
    if (const GridConvolution* box_conv = normal_.box_convolution())
        fine.conv.copy_pair_spectra(*box_conv);
    fine.dx = grid_.dx;
    fine.dy = grid_.dy;
    n_levels_ = 1;
    while (n_levels_ < static_cast<int>(levels_.size()) && coarser(nx, ny)) {
        Level& L = *levels_[n_levels_++];
        L.nx = nx;
        L.ny = ny;
        L.dx = grid_.dx * bx / nx;
        L.dy = grid_.dy * by / ny;
    }
    for (int l = 0; l < n_levels_; ++l) {
        Level& L = *levels_[l];
        L.x0 = left + 0.5 * L.dx;
        L.y0 = bottom + 0.5 * L.dy;
    }
}

void GapExactModel::scatter_box()
{
    Level& F = *levels_[0];
    std::fill(traction_.begin(), traction_.end(), 0.0);
    std::fill(slip_.begin(), slip_.end(), 0.0);
    std::fill(rigid_.begin(), rigid_.end(), 0.0);
    std::fill(state_.begin(), state_.end(), 0);
    const auto& q = F.tangential.traction();
    const auto& sl = F.tangential.slip();
    const auto& w = F.tangential.rigid_slip();
    const auto& st = F.tangential.state();
    for (int j = 0; j < F.ny; ++j)
        for (int i = 0; i < F.nx; ++i) {
            const size_t b = i + static_cast<size_t>(F.nx) * j;
            const size_t k = box_i0_ + i + static_cast<size_t>(nx_) * (box_j0_ + j);
            traction_[k] = q[b];
            slip_[k] = sl[b];
            rigid_[k] = w[b];
            state_[k] = st[b];
        }
}

void GapExactModel::label_patches(SolveTotals& t)
{
    // Caller's layout.
    const std::vector<double>& pressure = normal_.pressure();
    for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i)
            in_contact_[i + nx_ * j] = pressure[caller_index(i) + nx_ * j] > 0.0;
    t.n_patches = labels_.label(in_contact_.data());
}

// The rigid slip over mu p_max / G (the rigid slip itself without friction
// or load), scaled down together beyond the largest normalised creepage.
void GapExactModel::set_normalised_creepages(const ContactInput& in)
{
    Setup& s = setup_;
    const double T = s.traction_scale;
    const double inv = T > 0.0 ? in.G / T : 1.0;
    s.slip_scale = T > 0.0 ? T / in.G : 1.0;
    s.xi = s.direction * in.xi_x * inv;
    s.eta = in.xi_y * inv;
    s.phi = s.direction * in.phi * inv;
    const double reach = std::max({std::fabs(grid_.x0), std::fabs(grid_.x0 + nx_ * grid_.dx),
                                   std::fabs(grid_.y0), std::fabs(grid_.y0 + ny_ * grid_.dy)});
    limit_rigid_slip(s.xi, s.eta, s.phi, reach, s.slip_scale);
}

// Warm start: traction_ holds the last solution on the whole grid, the start
// on this solve's box once predicted along the creepages' drift (the
// history, kept as physical tractions, outlives changes of the gap or the
// load: a vehicle loop's gap drifts with its creepages, and the secant step
// follows both; measured on N07_wide, 37.5 -> 24.5 FFT products a step with
// the gap drifting).
void GapExactModel::predict_start(double nu)
{
    const Setup& s = setup_;
    const double T = s.traction_scale;
    const double key[CreepageHistory::kKey] = {nu, s.spin_offset, double(s.direction), s.layer};
    const double c[3] = {s.xi, s.eta, s.phi};
    if (!history_.predict(key, c, traction_, 1.0 / T)) {
        const double f = previous_traction_scale_ / T;
        for (auto& v : traction_) v *= f;
    }
    Level& fine = *levels_[0];
    std::vector<SteadyRolling::Complex>& q = fine.tangential.traction();
    for (int j = 0; j < fine.ny; ++j)
        for (int i = 0; i < fine.nx; ++i)
            q[i + static_cast<size_t>(fine.nx) * j] =
                traction_[box_i0_ + i + static_cast<size_t>(nx_) * (box_j0_ + j)];
}

void GapExactModel::remember(double nu)
{
    const Setup& s = setup_;
    const double key[CreepageHistory::kKey] = {nu, s.spin_offset, double(s.direction), s.layer};
    const double c[3] = {s.xi, s.eta, s.phi};
    history_.remember(key, c, traction_, s.traction_scale, state_.data());
}

void GapExactModel::set_law(const SlipSpeedLaw& law, double V)
{
    if (law_.set(law, V)) has_previous_ = false; // the warm start's history is the last law's
}

SolveTotals GapExactModel::solve(const ContactInput& in, SolveMode mode)
{
    const bool had_previous = has_previous_;
    has_previous_ = false; // until this solve succeeds
    info_ = GapExactSolveInfo{};
    validate(in);
    const double tolerance = in.tolerance > 0.0 ? in.tolerance : kExactDefaultTolerance;
    const int max_steps = in.max_iterations > 0 ? in.max_iterations : kExactDefaultMaxIterations;

    Setup& s = setup_;
    s = Setup{};
    s.direction = in.rolling_direction;
    s.spin_offset = in.spin_offset >= 0.0 ? in.spin_offset : kExactDefaultSpinOffset;
    s.full = mode == SolveMode::full;
    s.G = in.G;

    const bool warm = in.warm_start && had_previous;
    const GapNormalInfo& ni = normal_.solve(in, warm);
    info_.normal_iterations = ni.normal_iterations;
    info_.normal_products = ni.normal_products;
    info_.semi_hertz_iterations = ni.semi_hertz_iterations;
    info_.normal_reused = ni.reused;
    const std::vector<double>& pressure = normal_.pressure();
    double p_ref = 0.0;
    for (double p : pressure) p_ref = std::max(p_ref, p);
    s.loaded = p_ref > 0.0;
    s.p_ref = p_ref;
    s.traction_scale = law_.traction_scale(in, p_ref);
    SolveTotals t;
    label_patches(t);
    set_box(normal_.half_space(in.nu));
    set_normalised_creepages(in);
    law_.apply(levels_, s.slip_scale, [](const Level& L) { return L.dx; });
    // The layer in the normalised units of each level: (h / G3) G / dx.
    s.layer = in.layer_h > 0.0 ? in.layer_h / in.layer_G : 0.0;
    if (!std::isfinite(s.layer * in.G / grid_.dx))
        throw Error(ErrorKind::invalid_input, "layer_h / layer_G is so extreme that the layer overflows");
    for (auto& L : levels_) L->tangential.set_layer(L->dx > 0.0 ? s.layer * in.G / L->dx : 0.0);

    Level& fine = *levels_[0];
    std::vector<double>& g = fine.tangential.bound();
    for (int j = 0; j < fine.ny; ++j)
        for (int i = 0; i < fine.nx; ++i) {
            const double p = pressure[box_i0_ + i + static_cast<size_t>(nx_) * (box_j0_ + j)];
            g[i + static_cast<size_t>(fine.nx) * j] = s.loaded ? p / p_ref : 0.0;
        }
    scale_bounds(box_friction(), g.data(), fine.nx, fine.ny);
    set_rigid_slip(fine);
    const bool trivial = !s.loaded || !(s.traction_scale > 0.0);
    const bool rolling_freely = s.xi == 0.0 && s.eta == 0.0 && s.phi == 0.0;
    if (!had_previous) history_.clear();
    Steps steps{*this, in};
    const SteadyRollingInfo ti =
        solve_tangential(steps, n_levels_, tangential_start(trivial, rolling_freely, warm),
                         tolerance, max_steps, info_);
    scatter_box();
    law_.diagnose(levels_, static_cast<size_t>(n_levels_), info_);

    set_totals(in, t);
    t.iterations = ti.newton_steps;
    t.residual = ti.residual;
    if (s.full) add_work(t);
    has_previous_ = !trivial;
    if (!trivial) previous_traction_scale_ = s.traction_scale;
    if (!trivial && !rolling_freely) remember(in.nu);
    return t;
}

// Totals and patches in the caller's frame, element by element in the
// caller's layout; the contact's extent.
void GapExactModel::set_totals(const ContactInput& in, SolveTotals& t)
{
    Setup& s = setup_;
    const std::vector<double>& pressure = normal_.pressure();
    const std::vector<signed char>& state = state_;
    const std::vector<SteadyRolling::Complex>& qa = traction_;
    const double area = grid_.dx * grid_.dy, d = s.direction, T = s.traction_scale;
    patches_.assign(labels_.count(), PatchTotals{});
    double y_lo = 0.0, y_hi = 0.0, x_lo = 0.0, x_hi = 0.0;
    bool first = true;
    for (int j = 0; j < ny_; ++j) {
        const double y = grid_.y0 + j * grid_.dy;
        for (int i = 0; i < nx_; ++i) {
            const int c = i + nx_ * j, k = caller_index(i) + nx_ * j;
            const int p = labels_.of(c);
            if (p < 0) continue;
            const double x = grid_.x0 + i * grid_.dx;
            const double px = d * T * qa[k].real() * area, py = T * qa[k].imag() * area;
            PatchTotals& P = patches_[p];
            ++P.n_contact;
            P.n_slip += state[k] == 2;
            P.x_centroid += x;
            P.y_centroid += y;
            P.Fx += px;
            P.Fy += py;
            P.Mz += x * py - y * px;
            P.Fn += pressure[k] * area;
            P.p_max = std::max(P.p_max, pressure[k]);
            if (first) {
                x_lo = x_hi = x;
                y_lo = y_hi = y;
                first = false;
            }
            x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
            y_lo = std::min(y_lo, y), y_hi = std::max(y_hi, y);
        }
    }
    t.model = ModelKind::exact;
    for (PatchTotals& P : patches_) {
        P.n_adhesion = P.n_contact - P.n_slip;
        P.x_centroid /= P.n_contact;
        P.y_centroid /= P.n_contact;
        P.W_macro = -(P.Fx * in.xi_x + P.Fy * in.xi_y + P.Mz * in.phi);
    }
    add_patch_totals(patches_, in, t);
    // Half the extent of the contact along x and y (element edges).
    t.a = first ? 0.0 : 0.5 * (x_hi - x_lo + grid_.dx);
    t.b = first ? 0.0 : 0.5 * (y_hi - y_lo + grid_.dy);
    s.y_mid = first ? 0.0 : 0.5 * (y_lo + y_hi);
    s.half_width = t.b;
    t.p_max = s.p_ref;
    t.approach = normal_.approach();
    // The normal force: the pressures summed in the layout's order.
    double total = 0.0;
    for (double p : pressure) total += p;
    t.normal_force = total * grid_.dx * grid_.dy;
}

// The work maps and their totals (full mode).
void GapExactModel::add_work(SolveTotals& t)
{
    const Setup& s = setup_;
    ExactWorkInput w;
    w.nx = nx_;
    w.ny = ny_;
    w.q = traction_.data();
    w.s = slip_.data();
    w.w = rigid_.data();
    w.state = state_.data();
    w.traction_scale = s.traction_scale;
    w.slip_scale = s.slip_scale;
    w.area = grid_.dx * grid_.dy;
    w.dy = grid_.dy;
    w.b = s.half_width > 0.0 ? s.half_width : grid_.dy;
    w.y0 = grid_.y0 - s.y_mid;
    w.W_macro = t.W_macro;
    set_work_totals(exact_work(w, paper_.data(), consistent_.data(), profile_.data(),
                               row_d_.data(), row_pool_.data()),
                    t);
}

} // namespace creepwork
