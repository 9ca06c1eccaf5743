#include "exact/exact_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/contact_input.hpp"
#include "contact/error.hpp"
#include "contact/number_text.hpp"
#include "contact/kalker_coefficients.hpp"
#include "exact/exact_work.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kKrylovDimension = 40;
// Coarse grids: each about half the elements of the next finer one per
// direction, while both directions keep at least this many.
constexpr int kMinCoarseCells = 10;
// Coarse grids only give the next one a start (where the slip zone lies):
// solved this far. Measured on the benchmark contact: 1e-1 needs fewer FFT
// products in all than 1e-2 ... 1e-6 (72 against 80 ... 114 at N = 40).
constexpr double kCoarseTolerance = 1e-1;
// The normal problem: max |gap| / approach on the contact set, and bounds.
constexpr double kNormalTolerance = 1e-10;
constexpr int kNormalMaxIterations = 500;
// Normalised creepages beyond this slide everywhere; they are scaled down
// together (as FASTSIM does, march/march_setup.hpp) so nothing can overflow.
constexpr double kMaxNormalisedCreepage = 1e100;

} // namespace

ExactModel::Level::Level(int nx_, int ny_)
    : nx(nx_), ny(ny_), conv(nx_, ny_), normal(nx_, ny_), tangential(nx_, ny_, kKrylovDimension)
{
}

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
    while ((nx + 1) / 2 >= kMinCoarseCells && (ny + 1) / 2 >= kMinCoarseCells) {
        nx = (nx + 1) / 2;
        ny = (ny + 1) / 2;
        levels_.push_back(std::make_unique<Level>(nx, ny));
    }
    const size_t n = static_cast<size_t>(nx_) * ny_;
    history_.resize(n);
    paper_.assign(n, 0.0);
    tangent_w_.assign(n, SteadyRolling::Complex(0.0, 0.0));
    consistent_.assign(n, 0.0);
    profile_.assign(ny_, 0.0);
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
    const std::vector<double>& g = L.tangential.bound();
    std::vector<SteadyRolling::Complex>& q = L.tangential.traction();
    for (int j = 0; j < L.ny; ++j) {
        SteadyRolling::Complex prev(0.0, 0.0);
        for (int i = L.nx - 1; i >= 0; --i) {
            const int k = i + L.nx * j;
            if (!(g[k] > 0.0)) {
                q[k] = prev = 0.0;
                continue;
            }
            const double X = L.geom.X(i), Y = L.geom.Y(j);
            SteadyRolling::Complex next =
                prev - SteadyRolling::Complex(l1 * setup_.c_xi - l3 * cphi * Y,
                                              l2 * setup_.c_eta + l3 * cphi * X);
            const double m = std::abs(next);
            if (m > g[k]) next *= g[k] / m;
            q[k] = prev = next;
        }
    }
}

// Bilinear interpolation of the coarse traction at the fine element centres
// (both grids cover the same box), then clipped by the fine solver.
void ExactModel::interpolate(const Level& C, Level& F) const
{
    const std::vector<SteadyRolling::Complex>& qc = C.tangential.traction();
    std::vector<SteadyRolling::Complex>& qf = F.tangential.traction();
    for (int j = 0; j < F.ny; ++j) {
        const double ty = (j + 0.5) / F.ny * C.ny - 0.5;
        const int j0 = static_cast<int>(std::floor(ty));
        const double fy = ty - j0;
        for (int i = 0; i < F.nx; ++i) {
            const double tx = (i + 0.5) / F.nx * C.nx - 0.5;
            const int i0 = static_cast<int>(std::floor(tx));
            const double fx = tx - i0;
            SteadyRolling::Complex v(0.0, 0.0);
            for (int dj = 0; dj < 2; ++dj)
                for (int di = 0; di < 2; ++di) {
                    const int ii = std::min(std::max(i0 + di, 0), C.nx - 1);
                    const int jj = std::min(std::max(j0 + dj, 0), C.ny - 1);
                    v += (di ? fx : 1.0 - fx) * (dj ? fy : 1.0 - fy) * qc[ii + C.nx * jj];
                }
            qf[i + F.nx * j] = v;
        }
    }
}

// Warm start: the secant prediction of creepage_history.hpp (the history is
// dropped when a/b, nu or the spin offset change).
void ExactModel::predict_start(double ratio, double nu)
{
    const double key[CreepageHistory::kKey] = {ratio, nu, setup_.spin_offset, 0.0};
    const double c[3] = {setup_.c_xi, setup_.c_eta, setup_.c_phi};
    history_.predict(key, c, levels_[0]->tangential.traction());
}

void ExactModel::remember(double ratio, double nu)
{
    const double key[CreepageHistory::kKey] = {ratio, nu, setup_.spin_offset, 0.0};
    const double c[3] = {setup_.c_xi, setup_.c_eta, setup_.c_phi};
    history_.remember(key, c, levels_[0]->tangential.traction(), 1.0,
                      levels_[0]->tangential.state().data());
}

SolveTotals ExactModel::solve(const ContactInput& in, SolveMode mode)
{
    const bool had_previous = has_previous_;
    has_previous_ = false; // until this solve succeeds
    if (!had_previous) history_.clear();
    info_ = ExactSolveInfo{};
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
    const int max_steps = in.max_iterations > 0 ? in.max_iterations : kExactDefaultMaxIterations;

    Level& fine = *levels_[0];
    const double ratio = in.a / in.b;
    const double nu = in.nu, G = in.G;
    Setup& s = setup_;
    s = Setup{};
    s.direction = in.rolling_direction;
    s.a = in.a;
    s.b = in.b;
    s.dx = 2.0 * box_scale_ * in.a / nx_;
    s.dy = 2.0 * box_scale_ * in.b / ny_;
    s.p0 = 3.0 * in.normal_force / (2.0 * kPi * in.a * in.b);
    s.traction_scale = in.mu * s.p0;
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
        L->conv.set_coefficients(L->geom.rho, nu);
    }

    const bool loaded = in.normal_force > 0.0;
    const bool warm_normal = in.warm_start;
    if (loaded) solve_normal(fine, ratio, warm_normal, "finest");

    // Rigid slip over mu p0 / G, with phi per element length dx.
    const double inv = s.traction_scale > 0.0 ? G / s.traction_scale : 0.0;
    double cx = s.xi * inv, cy = s.eta * inv, cp = s.phi * s.dx * inv;
    s.slip_scale = s.traction_scale > 0.0 ? s.traction_scale / G : 1.0;
    if (!(s.traction_scale > 0.0)) { // no friction or no load: report the rigid slip
        cx = s.xi;
        cy = s.eta;
        cp = s.phi * s.dx;
    }
    const double largest = std::max({std::fabs(cx), std::fabs(cy), std::fabs(cp) * nx_});
    if (!std::isfinite(largest))
        throw Error(ErrorKind::invalid_input,
                    "xi_x, xi_y or phi is so large that the rigid slip overflows");
    if (largest > kMaxNormalisedCreepage) {
        const double f = kMaxNormalisedCreepage / largest;
        cx *= f;
        cy *= f;
        cp *= f;
        s.slip_scale /= f;
    }
    s.c_xi = cx;
    s.c_eta = cy;
    s.c_phi = cp;

    std::vector<double>& g = fine.tangential.bound();
    const std::vector<double>& qn = fine.normal.pressure();
    for (size_t k = 0; k < g.size(); ++k) g[k] = loaded ? qn[k] : 0.0;
    // (With no friction g is the contact set for slide_freely, not a bound.)
    set_rigid_slip(fine);

    // No load: no contact. No friction: no traction, and the contact slips
    // with the rigid slip.
    const bool trivial = !loaded || !(s.traction_scale > 0.0);

    SteadyRollingInfo ti;
    auto cold = [&] {
        const int coarsest = static_cast<int>(levels_.size()) - 1;
        for (int l = coarsest; l >= 0; --l) {
            Level& L = *levels_[l];
            if (l > 0) {
                solve_normal(L, ratio, warm_normal, "coarse");
                std::vector<double>& gl = L.tangential.bound();
                for (size_t k = 0; k < gl.size(); ++k) gl[k] = L.normal.pressure()[k];
                set_rigid_slip(L);
            }
            if (l == coarsest)
                fastsim_start(L, ratio, nu, G, in.a, in.b);
            else
                interpolate(*levels_[l + 1], L);
            ti = L.tangential.solve(L.conv, l == 0 ? tolerance : std::max(tolerance,
                                                                           kCoarseTolerance),
                                    max_steps);
            info_.products += ti.products;
            ++info_.levels_used;
        }
    };
    // Without creepage the solution is zero traction, exactly.
    const bool rolling_freely = cx == 0.0 && cy == 0.0 && cp == 0.0;
    if (rolling_freely && !trivial) {
        std::fill(fine.tangential.traction().begin(), fine.tangential.traction().end(), 0.0);
        ti = fine.tangential.solve(fine.conv, tolerance, max_steps); // one sweep
        info_.products += ti.products;
        info_.levels_used = 1;
    } else if (trivial) {
        fine.tangential.slide_freely(g);
        ti.converged = true;
        info_.levels_used = 1;
    } else if (in.warm_start && had_previous) {
        info_.warm = true;
        predict_start(ratio, nu);
        ti = fine.tangential.solve(fine.conv, tolerance, max_steps, true);
        info_.products += ti.products;
        info_.levels_used = 1;
        if (!ti.converged) {
            info_.retried_cold = true;
            cold();
        }
    } else {
        cold();
    }
    info_.newton_steps = ti.newton_steps;
    require_converged(ti, tolerance);

    // Totals in the caller's frame, summed element by element in a fixed order.
    const std::vector<SteadyRolling::Complex>& q = fine.tangential.traction();
    const std::vector<signed char>& state = fine.tangential.state();
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
    const CreepCoefficients C = kalker_coefficients(ratio, nu);
    const Flexibilities F = kalker_flexibilities(in.a, in.b, G, C);
    t.C11 = C.C11;
    t.C22 = C.C22;
    t.C23 = C.C23;
    t.C33 = C.C33;
    t.L1 = F.L1;
    t.L2 = F.L2;
    t.L3 = F.L3;
    t.p_max = s.p0 * pmax;
    t.approach = loaded ? fine.normal.approach() * s.p0 * s.dx / G : 0.0;
    t.iterations = ti.newton_steps;
    t.residual = ti.residual;

    if (s.full) {
        ExactWorkInput w;
        w.nx = nx_;
        w.ny = ny_;
        w.q = q.data();
        w.s = fine.tangential.slip().data();
        w.w = fine.tangential.rigid_slip().data();
        w.state = state.data();
        w.traction_scale = T;
        w.slip_scale = s.slip_scale;
        w.area = area;
        w.dy = s.dy;
        w.b = in.b;
        w.y0 = fine.geom.Y(0) * s.dx;
        w.W_macro = t.W_macro;
        set_work_totals(exact_work(w, paper_.data(), consistent_.data(), profile_.data(),
                                   row_d_.data(), row_pool_.data()),
                        t);
    }
    has_previous_ = !trivial;
    if (!trivial && !rolling_freely) remember(ratio, nu);
    return t;
}

} // namespace creepwork
