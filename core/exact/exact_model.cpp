#include "exact/exact_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/contact_input.hpp"
#include "contact/error.hpp"
#include "contact/friction_law.hpp"
#include "contact/number_text.hpp"
#include "contact/kalker_coefficients.hpp"
#include "exact/exact_work.hpp"
#include "exact/tangential_solve.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The normal problem: max |gap| / approach on the contact set, and bounds.
constexpr double kNormalTolerance = 1e-10;
constexpr int kNormalMaxIterations = 500;
} // namespace

// The level's convolution serves its normal problem too.
ExactModel::Level::Level(int nx_, int ny_)
    : TangentialLevel(nx_, ny_, ConvolutionUse::both), normal(nx_, ny_)
{
}

// The model's steps of the tangential solve (tangential_solve.hpp).
struct ExactModel::Steps {
    ExactModel& m;
    const ContactInput& in;
    double ratio; // a / b
    TangentialLevel& level(int l) { return *m.levels_[l]; }
    void prepare(int l)
    {
        Level& L = *m.levels_[l];
        m.solve_normal(L, ratio, in.warm_start, "coarse");
        m.set_bound(L, L.normal.pressure());
        m.set_rigid_slip(L);
    }
    void first_guess(int l) { m.fastsim_start(*m.levels_[l], ratio, in.nu, in.G, in.a, in.b); }
    void interpolate(int l) { m.interpolate(*m.levels_[l + 1], *m.levels_[l]); }
    void predict() { m.predict_start(ratio, in.nu); }
};

ExactModel::ExactModel(const GridSpec& grid)
    : nx_(grid.nx), ny_(grid.ny), box_scale_(grid.box_scale)
{
    if (grid.kind != GridKind::uniform)
        throw Error(ErrorKind::invalid_input,
                    "grid kind = kalker_strips is invalid for model = exact: Kalker's exact "
                    "theory runs on the uniform grid (CW_GRID_UNIFORM)");
    auto check = [](const char* name, int v) {
        if (v < 1 || v > kMaxExactCells)
            throw Error(ErrorKind::grid_out_of_range,
                        std::string(name) + " = " + std::to_string(v) + " is outside 1 ... " +
                            std::to_string(kMaxExactCells) + " for model = exact");
    };
    check("nx", grid.nx);
    check("ny", grid.ny);
    if (!(grid.box_scale >= 1.0 && grid.box_scale <= kMaxBoxScale))
        throw Error(ErrorKind::grid_out_of_range,
                    "box_scale = " + number_text(grid.box_scale) + " is outside [1, 100]");
    int nx = nx_, ny = ny_;
    levels_.push_back(std::make_unique<Level>(nx, ny));
    levels_.front()->tangential.reserve_coarse(); // the warm steps' (the finest level's)
    while (coarser(nx, ny)) levels_.push_back(std::make_unique<Level>(nx, ny));
    const size_t n = static_cast<size_t>(nx_) * ny_;
    history_.resize(n);
    paper_.assign(n, 0.0);
    tangent_w_.assign(n, SteadyRolling::Complex(0.0, 0.0));
    tangent_yield_.assign(n, 0.0);
    consistent_.assign(n, 0.0);
    profile_.assign(ny_, 0.0);
    x_column_.assign(nx_, 0.0);
    y_row_.assign(ny_, 0.0);
    row_d_.assign(ny_, 0.0);
    row_pool_.assign(ny_, 0.0);
}

ExactModel::~ExactModel() = default;

void ExactModel::set_kernel_isa(KernelIsa isa)
{
    for (auto& L : levels_) L->conv.set_kernel_isa(isa);
}

void ExactModel::solve_normal(Level& L, double ratio, bool warm, const char* which)
{
    const double nu = L.conv.nu();
    if (L.normal_valid && L.normal_ratio == ratio && L.normal_nu == nu &&
        (warm || L.normal_cold))
        return;
    const bool start = warm && L.normal_valid;
    const NormalSolveInfo ni =
        L.normal.solve(L.geom, L.conv, start, kNormalTolerance, kNormalMaxIterations);
    info_.normal_iterations += ni.iterations;
    L.normal_valid = ni.converged && L.normal.n_contact() > 0;
    if (!L.normal_valid)
        throw Error(ErrorKind::not_converged,
                    std::string("the normal problem on the ") + which +
                        " grid did not converge (residual " + number_text(ni.residual) +
                        " after " + std::to_string(ni.iterations) + " iterations)");
    L.normal_cold = !start;
    L.normal_ratio = ratio;
    L.normal_nu = nu;
}

void ExactModel::set_rigid_slip(Level& L) const
{
    // w = (xi - phi y, eta + phi (x + spin_offset dx)) at element centres,
    // over mu p0 / G; lengths in this level's dx (c_phi is per finest dx).
    const double h = L.geom.alpha > 0.0 ? levels_[0]->geom.alpha / L.geom.alpha : 1.0;
    const double cphi = setup_.c_phi * h;
    std::vector<SteadyRolling::Complex>& w = L.tangential.rigid_slip();
    for (int j = 0; j < L.ny; ++j)
        for (int i = 0; i < L.nx; ++i)
            w[i + L.nx * j] = {setup_.c_xi - cphi * L.geom.Y(j),
                               setup_.c_eta + cphi * (L.geom.X(i) + setup_.spin_offset)};
}

void ExactModel::set_bound(TangentialLevel& L, const std::vector<double>& pressure) const
{
    std::vector<double>& g = L.tangential.bound();
    // Hardening or softening: the yield is the sweep's (set_yield), not a cap.
    const double cap = setup_.yield_k != 0.0 ? 0.0 : setup_.yield;
    for (size_t k = 0; k < g.size(); ++k)
        g[k] = cap > 0.0 && pressure[k] > cap ? cap : pressure[k];
}

// The layer on every level: the compliance per level's dx (dx = a / alpha),
// the yield stress in traction units, its hardening per level's dx.
void ExactModel::set_layer(const ContactInput& in)
{
    if (in.tau_c0 > 0.0 && law_.active())
        reject_input("tau_c0", in.tau_c0,
                     "must be 0 with a friction law of the slip speed: the layer's yield "
                     "takes Coulomb's law (friction_law = coulomb)");
    Setup& s = setup_;
    s.layer = in.layer_h > 0.0 ? in.layer_h / in.layer_G * in.G / s.dx : 0.0;
    s.yield = in.tau_c0 > 0.0 && s.traction_scale > 0.0 ? in.tau_c0 / s.traction_scale : 0.0;
    s.yield_k = s.yield > 0.0 ? in.k_tau * s.dx / in.G : 0.0;
    if (!std::isfinite(s.layer) || !std::isfinite(s.yield) || !std::isfinite(s.yield_k))
        throw Error(ErrorKind::invalid_input,
                    "layer_h / layer_G, tau_c0 or k_tau is so extreme that the layer overflows");
    const double alpha0 = levels_[0]->geom.alpha;
    for (auto& L : levels_) {
        L->tangential.set_layer(s.layer * (L->geom.alpha / alpha0));
        L->tangential.set_yield(s.yield, s.yield_k * (alpha0 / L->geom.alpha));
    }
}

// Kalker's simplified theory as a first guess on the coarsest grid: march
// each row from the leading edge, q += -dx w / (L G) per element (L1, L2 for
// creepage, L3 for spin), clipped to the bound.
void ExactModel::fastsim_start(Level& L, double ratio, double nu, double G, double a,
                               double b) const
{
    const CreepCoefficients C = kalker_coefficients(ratio, nu);
    const Flexibilities F = kalker_flexibilities(a, b, G, C);
    const double dx = 2.0 * box_scale_ * a / L.nx;
    const double l1 = dx / (F.L1 * G), l2 = dx / (F.L2 * G), l3 = dx / (F.L3 * G);
    const double h = levels_[0]->geom.alpha / L.geom.alpha;
    const double cphi = setup_.c_phi * h;
    simplified_march(
        L, l1, l2, l3, setup_.c_xi, setup_.c_eta, cphi, [&](int i) { return L.geom.X(i); },
        [&](int j) { return L.geom.Y(j); });
}

// Bilinear interpolation of the coarse traction at the fine element centres
// (both grids cover the same box), then clipped by the fine solver.
void ExactModel::interpolate(const Level& C, Level& F) const
{
    interpolate_traction(
        C, F, [&](int i) { return (i + 0.5) / F.nx * C.nx - 0.5; },
        [&](int j) { return (j + 0.5) / F.ny * C.ny - 0.5; });
}

// Warm start: the secant prediction of creepage_history.hpp (the history is
// dropped when a/b, nu or the spin offset change).
void ExactModel::predict_start(double ratio, double nu)
{
    const double key[CreepageHistory::kKey] = {ratio, nu, setup_.spin_offset, setup_.layer};
    const double c[3] = {setup_.c_xi, setup_.c_eta, setup_.c_phi};
    history_.predict(key, c, levels_[0]->tangential.traction());
}

void ExactModel::remember(double ratio, double nu)
{
    const double key[CreepageHistory::kKey] = {ratio, nu, setup_.spin_offset, setup_.layer};
    const double c[3] = {setup_.c_xi, setup_.c_eta, setup_.c_phi};
    history_.remember(key, c, levels_[0]->tangential.traction(), 1.0,
                      levels_[0]->tangential.state().data());
}

void ExactModel::set_law(const SlipSpeedLaw& law, double V)
{
    if (law_.set(law, V)) has_previous_ = false; // the warm start's history is the last law's
}

void ExactModel::validate(const ContactInput& in) const
{
    validate_contact_input(in);
    if (in.flexibility != FlexibilitySource::kalker_from_material)
        throw Error(ErrorKind::invalid_input,
                    "flexibility = given is invalid for model = exact: the exact theory needs "
                    "the material (G, nu), not L1, L2, L3");
    const double tolerance = in.tolerance > 0.0 ? in.tolerance : kExactDefaultTolerance;
    if (tolerance < 1e-13)
        reject_input("tolerance", in.tolerance,
                     "must be 0 (the default, 1e-8) or in [1e-13, 1) for model = exact: "
                     "double precision cannot resolve less");
}

void ExactModel::set_up(const ContactInput& in, SolveMode mode)
{
    const double ratio = in.a / in.b;
    Setup& s = setup_;
    s = Setup{};
    s.direction = in.rolling_direction;
    s.a = in.a;
    s.b = in.b;
    s.dx = 2.0 * box_scale_ * in.a / nx_;
    s.dy = 2.0 * box_scale_ * in.b / ny_;
    s.p0 = 3.0 * in.normal_force / (2.0 * kPi * in.a * in.b);
    s.traction_scale = law_.traction_scale(in, s.p0);
    s.xi = s.direction * in.xi_x;
    s.eta = in.xi_y;
    s.phi = s.direction * in.phi;
    s.spin_offset = in.spin_offset >= 0.0 ? in.spin_offset : kExactDefaultSpinOffset;
    s.full = mode == SolveMode::full;
    if (!std::isfinite(s.dx * s.dy * s.p0 * s.traction_scale))
        throw Error(ErrorKind::invalid_input,
                    "a, b or normal_force are so extreme that the grid or the pressure "
                    "overflows");

    for (auto& L : levels_) {
        L->geom = ExactGeometry(L->nx, L->ny, box_scale_, ratio);
        L->conv.set_coefficients(L->geom.rho, in.nu);
    }
    const ExactGeometry& geom = levels_[0]->geom;
    for (int i = 0; i < nx_; ++i) x_column_[i] = geom.X(i) * s.dx;
    for (int j = 0; j < ny_; ++j) y_row_[j] = geom.Y(j) * s.dx;
}

// The rigid slip over mu p0 / G, with phi per element length dx; without
// friction or load the rigid slip itself.
void ExactModel::set_normalised_creepages(double G)
{
    Setup& s = setup_;
    const double inv = s.traction_scale > 0.0 ? G / s.traction_scale : 0.0;
    double cx = s.xi * inv, cy = s.eta * inv, cp = s.phi * s.dx * inv;
    s.slip_scale = s.traction_scale > 0.0 ? s.traction_scale / G : 1.0;
    if (!(s.traction_scale > 0.0)) { // no friction or no load: report the rigid slip
        cx = s.xi;
        cy = s.eta;
        cp = s.phi * s.dx;
    }
    limit_rigid_slip(cx, cy, cp, nx_, s.slip_scale);
    s.c_xi = cx;
    s.c_eta = cy;
    s.c_phi = cp;
}

SolveTotals ExactModel::solve(const ContactInput& in, SolveMode mode)
{
    const bool had_previous = has_previous_;
    has_previous_ = false; // until this solve succeeds
    if (!had_previous) history_.clear();
    info_ = ExactSolveInfo{};
    validate(in);
    const double tolerance = in.tolerance > 0.0 ? in.tolerance : kExactDefaultTolerance;
    const int max_steps = in.max_iterations > 0 ? in.max_iterations : kExactDefaultMaxIterations;
    set_up(in, mode);

    Level& fine = *levels_[0];
    const double ratio = in.a / in.b;
    const bool loaded = in.normal_force > 0.0;
    if (loaded) solve_normal(fine, ratio, in.warm_start, "finest");
    set_normalised_creepages(in.G);
    law_.apply(levels_, setup_.slip_scale,
               [&](const Level& L) { return 2.0 * box_scale_ * in.a / L.nx; });
    set_layer(in);

    if (factor_ && setup_.yield > 0.0)
        reject_input("tau_c0", setup_.yield * setup_.traction_scale,
                     "must be 0 with friction that depends on the temperature: the layer's "
                     "yield takes one coefficient");
    std::vector<double>& g = fine.tangential.bound();
    if (loaded)
        set_bound(fine, fine.normal.pressure());
    else
        std::fill(g.begin(), g.end(), 0.0);
    scale_bounds(ElementFriction{factor_, nx_, setup_.direction < 0}, g.data(), nx_, ny_);
    // (With no friction g is the contact set for slide_freely, not a bound.)
    set_rigid_slip(fine);

    // No load: no contact. No friction: no traction, and the contact slips
    // with the rigid slip. Without creepage the solution is zero traction,
    // exactly.
    const Setup& s = setup_;
    const bool trivial = !loaded || !(s.traction_scale > 0.0);
    const bool rolling_freely = s.c_xi == 0.0 && s.c_eta == 0.0 && s.c_phi == 0.0;
    Steps steps{*this, in, ratio};
    const SteadyRollingInfo ti = solve_tangential(
        steps, static_cast<int>(levels_.size()),
        tangential_start(trivial, rolling_freely, in.warm_start && had_previous), tolerance,
        max_steps, info_);

    law_.diagnose(levels_, levels_.size(), info_);
    SolveTotals t = totals(in, ti);
    if (s.full) add_work(t);
    has_previous_ = !trivial;
    if (!trivial && !rolling_freely) remember(ratio, in.nu);
    return t;
}

// Totals in the caller's frame, summed element by element in a fixed order.
SolveTotals ExactModel::totals(const ContactInput& in, const SteadyRollingInfo& ti) const
{
    const Level& fine = *levels_[0];
    const Setup& s = setup_;
    const bool loaded = in.normal_force > 0.0;
    const std::vector<SteadyRolling::Complex>& q = fine.tangential.traction();
    const std::vector<signed char>& state = fine.tangential.state();
    const std::vector<double>& qn = fine.normal.pressure();
    const double T = s.traction_scale, area = s.dx * s.dy;
    double fx = 0.0, fy = 0.0, mz = 0.0, pmax = 0.0;
    int n_contact = 0, n_slip = 0;
    for (int j = 0; j < ny_; ++j) {
        const double y = fine.geom.Y(j) * s.dx;
        for (int i = 0; i < nx_; ++i) {
            const int k = i + nx_ * j;
            const double x = fine.geom.X(i) * s.dx; // rolling frame
            fx += q[k].real();
            fy += q[k].imag();
            mz += x * q[k].imag() - y * q[k].real();
            if (loaded && qn[k] > 0.0) {
                ++n_contact;
                n_slip += state[k] == 2;
                pmax = std::max(pmax, qn[k]);
            }
        }
    }
    SolveTotals t;
    t.model = ModelKind::exact;
    t.Fx = s.direction * T * area * fx;
    t.Fy = T * area * fy;
    t.Mz = s.direction * T * area * mz;
    t.W_macro = -(t.Fx * in.xi_x + t.Fy * in.xi_y + t.Mz * in.phi);
    t.n_contact = n_contact;
    t.n_slip = n_slip;
    t.n_adhesion = n_contact - n_slip;
    t.adhesion_fraction = n_contact > 0 ? double(t.n_adhesion) / n_contact : 0.0;
    t.a = in.a;
    t.b = in.b;
    const CreepCoefficients C = kalker_coefficients(in.a / in.b, in.nu);
    const Flexibilities F = kalker_flexibilities(in.a, in.b, in.G, C);
    t.C11 = C.C11;
    t.C22 = C.C22;
    t.C23 = C.C23;
    t.C33 = C.C33;
    t.L1 = F.L1;
    t.L2 = F.L2;
    t.L3 = F.L3;
    t.p_max = s.p0 * pmax;
    t.approach = loaded ? fine.normal.approach() * s.p0 * s.dx / in.G : 0.0;
    t.iterations = ti.newton_steps;
    t.residual = ti.residual;
    return t;
}

// The work maps and their totals (full mode).
void ExactModel::add_work(SolveTotals& t)
{
    Level& fine = *levels_[0];
    const Setup& s = setup_;
    ExactWorkInput w;
    w.nx = nx_;
    w.ny = ny_;
    w.q = fine.tangential.traction().data();
    w.s = fine.tangential.slip().data();
    w.w = fine.tangential.rigid_slip().data();
    w.state = fine.tangential.state().data();
    w.traction_scale = s.traction_scale;
    w.slip_scale = s.slip_scale;
    w.area = s.dx * s.dy;
    w.dy = s.dy;
    w.b = s.b;
    w.y0 = fine.geom.Y(0) * s.dx;
    w.W_macro = t.W_macro;
    set_work_totals(exact_work(w, paper_.data(), consistent_.data(), profile_.data(),
                               row_d_.data(), row_pool_.data()),
                    t);
}

} // namespace creepwork
