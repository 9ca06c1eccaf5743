// The contact problem of each wheel/rail patch solved on its undeformed
// distance grid through creepwork::Solver on a gap grid: by Kalker's exact
// theory (gap/gap_exact_model.hpp) as CONTACT's module 1 solves it, or by the
// fast model, FASTSIM with the semi-Hertzian normal problem
// (gap/gap_fastsim_model.hpp). The
// approach of a patch is its penetration at the wheelset's height (the
// grid's datum, approach 0), the creepages are the patch's own. Results are
// in CONTACT's module-1 conventions (forces on the rail, patch frame; MN
// about the reference point); doc/wheelrail.md gives the mapping onto
// creepwork's convention that is applied here.
//
// A grid longer than the exact model's limit (256 elements per direction)
// is solved on every second (fourth, ...) element.
//
// One solver per patch index and grid shape (nx, ny, dx, ds) is made on
// first use and kept: its grid has element (0, 0) at the origin, and the
// creepages are shifted so that the rigid slip is that about the patch's
// reference point (xi - phi y, eta + phi x is affine in x, y), which lets a
// patch whose grid moves by whole elements reuse the solver and its warm
// start. Per index, so that after a position every patch's solver holds
// that patch's fields (PatchSolution::solver).
#pragma once

#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include "solver.hpp"
#include "wheelrail/vertical_force.hpp"
#include "wheelrail/wheelrail_geometry.hpp"

namespace creepwork::wheelrail {

struct PatchContactSettings {
    double mu = 0.3;     // [-] friction coefficient
    double G = 82e9;     // [Pa] combined shear modulus
    double nu = 0.28;    // [-] combined Poisson's ratio
    double tolerance = 0.0; // relative tolerance of the exact solver (0: its default)
    ModelKind model = ModelKind::exact;          // exact or fastsim
    NormalMethod normal_method = NormalMethod::exact; // the normal problem's method
    SolveMode mode = SolveMode::full;            // full: every field and the work maps
    // A law of the slip speed (contact/params.hpp; either model): mu is then
    // its mu_kin, the slip speed the micro-slip times the patch's rolling
    // speed veloc.
    FrictionLaw friction_law = FrictionLaw::coulomb;
    double mu_e1 = 0.0, s_h1 = 0.0; // [-], [m/s]
    double mu_e2 = 0.0, s_h2 = 0.0; // [-], [m/s]
    // Friction memory (with a law) and the interface layer, ContactInput's
    // fields of the same names: each patch's solve checks and refuses them.
    double memory_distance = 0.0, memory_s0 = 0.0; // [m], [m/s]
    double layer_h = 0.0, layer_G = 0.0, tau_c0 = 0.0, k_tau = 0.0; // [m], [Pa], [Pa], [Pa/m]
};

// One patch's solution, CONTACT's module-1 conventions (SI).
struct PatchSolution {
    double fn = 0, fx = 0, fs = 0; // [N] on the rail, patch frame (x, s, n)
    double mn = 0;                 // [N m] about n through the reference point, on the rail
    double p_max = 0;              // [Pa]
    double approach = 0;           // [m] the rigid overlap -min h
    int n_contact = 0, n_adhesion = 0, n_slip = 0;
    int coarsening = 1;            // every coarsening-th element solved (1: the whole grid)
    TrackForces track;             // [N] on the rail, track coordinates
    // The solver holding this patch's fields, in creepwork's frame (x, y =
    // -s, forces on the wheel; doc/wheelrail.md): its element (i, j) is
    // centred at (x0 + i dx, y0 + j dy) from the reference point.
    const Solver* solver = nullptr;
    int nx = 0, ny = 0;
    double x0 = 0, y0 = 0, dx = 0, dy = 0;
};

class PatchContact {
public:
    // Throws Error(invalid_input) naming a bad setting.
    explicit PatchContact(const PatchContactSettings& settings);

    // The patch at the wheelset height its grid was made for; k is its
    // index in the position's patches. Solved in settings().mode, or forces
    // only when forces_only (the force balance's trial heights); tolerance
    // > 0 replaces the settings' for this solve, normal_tolerance > 0 the
    // exact normal problem's (ContactInput::normal_tolerance). Throws Error
    // naming a bad input or Error(not_converged).
    const PatchSolution& solve(const ContactPatch& patch, std::size_t k = 0, bool forces_only = false,
                               double tolerance = 0.0, double normal_tolerance = 0.0);
    const PatchContactSettings& settings() const { return settings_; }
    // dfn/d(approach) [N/m] of the last patch solved, its normal method's
    // own (Solver::normal_force_by_approach).
    double normal_force_by_approach() { return last_solver_ ? last_solver_->normal_force_by_approach() : 0.0; }
    // Solvers made so far (one per grid shape).
    std::size_t solvers() const { return solvers_.size(); }

private:
    using Key = std::tuple<std::size_t, int, int, double, double>;
    Solver& solver_for(std::size_t k, int nx, int ny, double dx, double dy);

    PatchContactSettings settings_;
    std::map<Key, std::unique_ptr<Solver>> solvers_;
    std::vector<double> gap_; // the patch's h with its rows reversed (y = -s)
    PatchSolution last_;
    Solver* last_solver_ = nullptr;
};

// The solution of a whole wheel position.
struct WheelRailSolution {
    double z = 0;            // [m] wheelset height (CONTACT's Z_WS)
    std::vector<PatchSolution> patches; // as geometry.state().patches
    TrackForces total;       // [N] on the rail, track coordinates
    int evaluations = 0;     // geometry evaluations (1 with the height given)
};

// The wheel/rail chain: geometry, then the exact contact of every patch.
class WheelRailContact {
public:
    WheelRailContact(WheelRailGeometry geometry, const PatchContactSettings& settings);

    // At the given wheelset position (its z is the height).
    const WheelRailSolution& solve_position(const WheelsetPosition& position, const WheelsetVelocity& velocity);
    // With the vertical force on the rail prescribed [N]; position.z is the
    // first guess of the height, unless it is the height the last call
    // returned (a host passing it back) and the two calls before were force
    // balances too: the first guess is then extrapolated linearly from the
    // last two heights.
    const WheelRailSolution& solve_force(double fz, const WheelsetPosition& position,
                                         const WheelsetVelocity& velocity,
                                         const VerticalForceOptions& options = {});

    const WheelRailGeometry& geometry() const { return geometry_; }
    const WheelRailSolution& solution() const { return solution_; }
    PatchContact& patch_contact() { return contact_; }

private:
    void collect(int evaluations, bool solved);
    // The exact balance's first height for the vertical force fz.
    double exact_start(double fz, const WheelsetPosition& start, const WheelsetVelocity& velocity,
                       const VerticalForceOptions& options);

    WheelRailGeometry geometry_;
    PatchContact contact_;
    std::unique_ptr<PatchContact> start_; // the fast model, for the exact model's start
    WheelRailSolution solution_;
    int balanced_ = 0;              // force balances solved since the last solve_position
    double balance_z_[2] = {0, 0};  // the heights of the last two [m]: [1] the last
    std::vector<PatchSolution> evaluated_; // the patches of the balance's current evaluation
};

} // namespace creepwork::wheelrail
