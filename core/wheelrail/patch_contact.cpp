#include "wheelrail/patch_contact.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "contact/contact_input.hpp"
#include "contact/error.hpp"
#include "contact/number_text.hpp"
#include "friction/friction_memory.hpp"
#include "wheelrail/hertz_patch.hpp"

namespace creepwork::wheelrail {

namespace {

// [-] the exact model's tangential tolerance at a force balance's trial
// heights (doc/dev/decisions.md: a looser one misses the force's tolerance
// more often at the final solve)
constexpr double kTrialTolerance = 1e-5;
// [-] the exact normal problem's tolerance there (its own is 1e-10): the
// trial forces stay within about 1e-7 of the load, below the balance's
// 1e-6, and the final solve solves it again from the trial's pressure
// (doc/dev/decisions.md)
constexpr double kTrialNormalTolerance = 1e-6;

void check_setting(const char* name, double v, double lo, double hi)
{
    if (!(std::isfinite(v) && v >= lo && v <= hi))
        throw Error(ErrorKind::invalid_input, std::string("wheel/rail contact: ") + name + " must lie in [" +
                                                  number_text(lo) + ", " + number_text(hi) + "], got " +
                                                  number_text(v));
}

} // namespace

PatchContact::PatchContact(const PatchContactSettings& s) : settings_(s)
{
    check_setting("mu", s.mu, 0.0, 10.0);
    check_setting("G", s.G, 1e3, 1e15);
    check_setting("nu", s.nu, 0.0, 0.5);
    check_setting("tolerance", s.tolerance, 0.0, 0.1);
    if (s.model != ModelKind::exact && s.model != ModelKind::fastsim)
        throw Error(ErrorKind::invalid_input, "wheel/rail contact: the model must be the exact model or FASTSIM");
    // Memory and layer once for every patch, by the checks a single contact's solve makes.
    check_friction_memory({s.memory_distance, s.memory_s0});
    ContactInput layer;
    layer.layer_h = s.layer_h;
    layer.layer_G = s.layer_G;
    layer.tau_c0 = s.tau_c0;
    layer.k_tau = s.k_tau;
    validate_layer_input(layer);
    if (const char* name = layer_input_name(layer); name && s.model != ModelKind::exact)
        throw Error(ErrorKind::invalid_input, std::string("wheel/rail contact: ") + name +
                                                  ": an interface layer needs the exact model "
                                                  "(FASTSIM on a patch has none)");
}

Solver& PatchContact::solver_for(std::size_t k, int nx, int ny, double dx, double dy)
{
    const Key key{k, nx, ny, dx, dy};
    auto it = solvers_.find(key);
    if (it == solvers_.end()) {
        GridSpec g;
        g.kind = GridKind::gap;
        g.nx = nx;
        g.ny = ny;
        g.dx = dx;
        g.dy = dy;
        it = solvers_.emplace(key, std::make_unique<Solver>(g, settings_.model)).first;
    }
    return *it->second;
}

namespace {

// The elements kept along one direction: every f-th, counted from whole
// multiples of f steps from the reference point (element centres at
// (lo + i) step); first kept index and count.
std::pair<int, int> kept(int lo, int n, int f)
{
    int first = ((-lo) % f + f) % f;
    return {first, first < n ? (n - 1 - first) / f + 1 : 0};
}

} // namespace

const PatchSolution& PatchContact::solve(const ContactPatch& p, std::size_t k, bool forces_only, double tolerance,
                                         double normal_tolerance)
{
    const std::size_t n = static_cast<std::size_t>(p.nx) * static_cast<std::size_t>(p.ny);
    if (p.nx <= 0 || p.ny <= 0 || p.h.size() != n || !(p.dx > 0.0 && p.ds > 0.0))
        throw Error(ErrorKind::invalid_input, "wheel/rail contact: the patch has no undeformed distance grid");
    // A grid longer than the exact model takes (kMaxExactCells per
    // direction; a very deep trial height of the force balance) keeps every
    // f-th element.
    int f = 1;
    while ((p.nx + f - 1) / f > kMaxExactCells || (p.ny + f - 1) / f > kMaxExactCells) f *= 2;
    const auto [i0, nx] = kept(static_cast<int>(std::lround(p.x0 / p.dx)), p.nx, f);
    const auto [j0, ny] = kept(static_cast<int>(std::lround(p.s0 / p.ds)), p.ny, f);
    if (nx < kMinGapCells || ny < kMinGapCells)
        throw Error(ErrorKind::invalid_input, "wheel/rail contact: the patch grid has fewer than 3 elements "
                                              "in a direction");
    const double dx = f * p.dx, dy = f * p.ds;
    // creepwork's patch frame: x_cw = x, y_cw = -s, z_cw = -n (doc/wheelrail.md)
    gap_.resize(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            gap_[i + nx * j] = p.h[(i0 + f * i) + p.nx * (j0 + f * (ny - 1 - j))];
    // element (0, 0) from the reference point
    const double x0 = p.x0 + i0 * p.dx, y0 = -(p.s0 + (j0 + f * (ny - 1)) * p.ds);
    const double xi = -p.cksi, eta = p.ceta, phi = p.cphi;

    ContactInput in;
    in.model = settings_.model;
    in.normal_method = settings_.normal_method;
    in.gap = gap_.data();
    in.gap_len = gap_.size();
    in.normal_load = NormalLoad::approach;
    in.approach = 0.0; // the grid's datum is the wheelset's height
    in.mu = settings_.mu;
    if (settings_.friction_law != FrictionLaw::coulomb) {
        // the law takes the slip speed from the patch's rolling speed
        if (!(p.veloc > 0.0))
            throw Error(ErrorKind::invalid_input,
                        "wheel/rail contact: friction_law needs the rolling speed: the patch's veloc is " +
                            number_text(p.veloc) + " m/s (give the wheelset a forward speed vs)");
        in.friction_law = settings_.friction_law;
        in.mu_e1 = settings_.mu_e1;
        in.s_h1 = settings_.s_h1;
        in.mu_e2 = settings_.mu_e2;
        in.s_h2 = settings_.s_h2;
        in.V = p.veloc;
        in.memory_distance = settings_.memory_distance;
        in.memory_s0 = settings_.memory_s0;
    }
    in.layer_h = settings_.layer_h;
    in.layer_G = settings_.layer_G;
    in.tau_c0 = settings_.tau_c0;
    in.k_tau = settings_.k_tau;
    in.G = settings_.G;
    in.nu = settings_.nu;
    in.tolerance = tolerance > 0.0 ? tolerance : settings_.tolerance;
    in.normal_tolerance = normal_tolerance;
    in.rolling_direction = p.forward ? 1 : -1;
    // the rigid slip about the reference point on a grid whose element
    // (0, 0) is the origin: (xi - phi (y' + y0), eta + phi (x' + x0))
    in.xi_x = xi - phi * y0;
    in.xi_y = eta + phi * x0;
    in.phi = phi;
    Solver& s = solver_for(k, nx, ny, dx, dy);
    last_solver_ = &s;
    const SolveTotals& t = s.solve(in, forces_only ? SolveMode::forces_only : settings_.mode);

    PatchSolution& r = last_;
    r.fn = t.normal_force;
    r.fx = -t.Fx;
    r.fs = t.Fy;
    r.mn = t.Mz + x0 * t.Fy - y0 * t.Fx; // about the reference point
    r.p_max = t.p_max;
    r.approach = p.approach;
    r.n_contact = t.n_contact;
    r.n_adhesion = t.n_adhesion;
    r.n_slip = t.n_slip;
    r.coarsening = f;
    r.track = track_forces(p, {r.fn, r.fx, r.fs});
    r.solver = &s;
    r.nx = nx;
    r.ny = ny;
    r.x0 = x0;
    r.y0 = y0;
    r.dx = dx;
    r.dy = dy;
    return r;
}

WheelRailContact::WheelRailContact(WheelRailGeometry geometry, const PatchContactSettings& settings)
    : geometry_(std::move(geometry)), contact_(settings)
{
}

// The solution at the geometry's state: its patches solved in the settings'
// mode, or (solved) as the balance's last evaluation solved them.
void WheelRailContact::collect(int evaluations, bool solved)
{
    const WheelRailState& st = geometry_.state();
    solution_.z = st.position.z;
    solution_.evaluations = evaluations;
    solution_.patches.clear();
    solution_.total = {};
    for (std::size_t k = 0; k < st.patches.size(); ++k) {
        const PatchSolution& s = solved ? evaluated_.at(k) : contact_.solve(st.patches[k], k);
        solution_.patches.push_back(s);
        solution_.total.fx += s.track.fx;
        solution_.total.fy += s.track.fy;
        solution_.total.fz += s.track.fz;
    }
}

const WheelRailSolution& WheelRailContact::solve_position(const WheelsetPosition& position,
                                                          const WheelsetVelocity& velocity)
{
    geometry_.evaluate(position, velocity);
    balanced_ = 0; // extrapolate only across consecutive force balances
    collect(1, false);
    return solution_;
}

// The fast model (FASTSIM with the semi-Hertzian normal problem, forces
// only) costs a few per cent of an exact balance and finds a height whose
// exact vertical force is within about 1e-3 of the load on the
// tread (the Hertz estimate's height misses flange contacts by up to 70 %:
// no tangential force, one curvature), so that the exact balance takes
// about one Newton step fewer (doc/dev/decisions.md). If the fast balance
// fails, the Hertz estimate's height; if that fails, the start given (the
// exact balance reports its own failure).
double WheelRailContact::exact_start(double fz, const WheelsetPosition& start, const WheelsetVelocity& velocity,
                                     const VerticalForceOptions& options)
{
    try {
        if (!start_) {
            PatchContactSettings f = contact_.settings();
            f.model = ModelKind::fastsim;
            f.normal_method = NormalMethod::semi_hertz;
            f.mode = SolveMode::forces_only;
            f.tolerance = 0.0;
            f.layer_h = f.layer_G = 0.0; // the fast model has no layer; a start needs none
            start_ = std::make_unique<PatchContact>(f);
        }
        const PatchSolver fast = [this](std::size_t k, const ContactPatch& p) {
            const PatchSolution& s = start_->solve(p, k, true);
            return PatchForces{s.fn, s.fx, s.fs, start_->normal_force_by_approach()};
        };
        return solve_vertical_position(geometry_, fz, start, velocity, fast, options).z;
    } catch (const Error&) {
    }
    try {
        const HertzPatchEstimate hertz{contact_.settings().G, contact_.settings().nu};
        return solve_vertical_position(geometry_, fz, start, velocity, hertz, options).z;
    } catch (const Error&) {
        return start.z;
    }
}

const WheelRailSolution& WheelRailContact::solve_force(double fz, const WheelsetPosition& position,
                                                       const WheelsetVelocity& velocity,
                                                       const VerticalForceOptions& options)
{
    // The exact normal problem's derivative costs a linear solve (about 15 %
    // of an exact patch solve): the exact model takes it at the first height
    // only, for the first Newton step, and secant steps after it
    // (doc/dev/decisions.md); the fast model's closed form at every height.
    const PatchContactSettings& set = contact_.settings();
    const bool exact = set.normal_method == NormalMethod::exact;
    int evaluation = -1;
    // The exact model's tangential problem is solved to a looser tolerance
    // at the heights tried (kTrialTolerance) and to the settings' at a
    // height whose trial force meets the balance's tolerance, in the
    // settings' mode (from the trial's solution: the same gap keeps the
    // normal solution), which decides; the fast model has no tolerance and
    // solves once per height.
    const bool staged = set.model == ModelKind::exact;
    const double trial_tolerance =
        staged ? std::max(kTrialTolerance, set.tolerance > 0.0 ? set.tolerance : kExactDefaultTolerance) : 0.0;
    const PatchSolver solver = [this, exact, staged, trial_tolerance, &evaluation](std::size_t k,
                                                                                 const ContactPatch& p) {
        if (k == 0) {
            ++evaluation;
            evaluated_.clear();
        }
        const PatchSolution& s = contact_.solve(p, k, true, trial_tolerance, staged ? kTrialNormalTolerance : 0.0);
        if (!staged) evaluated_.push_back(s);
        const bool slope = !exact || evaluation == 0;
        return PatchForces{s.fn, s.fx, s.fs, slope ? contact_.normal_force_by_approach() : 0.0};
    };
    const PatchSolver final = [this](std::size_t k, const ContactPatch& p) {
        if (k == 0) evaluated_.clear();
        const PatchSolution& s = contact_.solve(p, k);
        evaluated_.push_back(s);
        return PatchForces{s.fn, s.fx, s.fs, 0.0};
    };
    // The exact balance starts from the fast model's height (exact_start);
    // the fast model from the position given.
    // A host that passes back the last height drifts: its next height is
    // extrapolated from the last two (z is smooth in the host's time).
    WheelsetPosition start = position;
    if (balanced_ >= 2 && position.z == balance_z_[1]) start.z = 2.0 * balance_z_[1] - balance_z_[0];
    if (set.model == ModelKind::exact) start.z = exact_start(fz, start, velocity, options);
    const VerticalForceSolution v =
        staged ? solve_vertical_position(geometry_, fz, start, velocity, solver, final, options)
               : solve_vertical_position(geometry_, fz, start, velocity, solver, options);
    balance_z_[0] = balance_z_[1];
    balance_z_[1] = v.z;
    ++balanced_;
    // The geometry is left at the solution, and its patches' last solves
    // are the answer: the exact model's final solves in the settings' mode,
    // the fast model's last evaluation (a FASTSIM solve is a function of its
    // inputs: solving again gives the same bits) unless the settings ask
    // for every field.
    collect(v.evaluations, staged || set.mode == SolveMode::forces_only);
    return solution_;
}

} // namespace creepwork::wheelrail
