// The solver object: one per grid, holding the models of the contact
// (contact/contact_model.hpp; the grid's first model made with the solver,
// the others on first use or by prepare()), running each solve on the model
// the input asks for, and exporting the fields of the last solve in the
// caller's layout (contact/fields.hpp). The models a solver can make are
// registered in one place, by grid and model: make_model() in solver.cpp.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "calibrated/calibrated_model.hpp"
#include "contact/contact_model.hpp"
#include "contact/fields.hpp"
#include "contact/jacobian.hpp"
#include "contact/params.hpp"
#include "exact/exact_model.hpp"
#include "fastsim/fastsim_model.hpp"
#include "gap/gap_exact_model.hpp"
#include "gap/gap_fastsim_model.hpp"

namespace creepwork {

class Solver {
public:
    // Makes the grid's first model: FASTSIM on the ellipse's grids; on a gap
    // grid (GridKind::gap) the exact model of any contact shape (so the
    // grid's origin and spacing are checked here), FASTSIM's model of any
    // contact shape (gap/gap_fastsim_model.hpp) on first use or by
    // prepare(). The calibrated model does not run on a gap grid.
    explicit Solver(const GridSpec& grid);
    // The same with the model `first` as the grid's first model (made with
    // the solver, which so checks the grid); FASTSIM on a gap grid then
    // makes its exact normal problem's memory on its first solve by the
    // exact method, or by prepare(). Throws Error(invalid_input) when the
    // model cannot run on this grid.
    Solver(const GridSpec& grid, ModelKind first);

    // Throws Error naming a bad input; the previous solution is then marked
    // absent. A model other than the grid's first is made on its first solve
    // unless prepare() made it before.
    const SolveTotals& solve(const ContactInput& input, SolveMode mode = SolveMode::full);
    // The same solve and the Jacobian of its Fx, Fy, Mz, W_macro with
    // respect to xi_x, xi_y, phi, N (contact/jacobian.hpp;
    // doc/theory/jacobians.md), every model: FASTSIM by forward differentiation of the
    // march, the calibrated model along its setup's directions
    // (calibrated_model.hpp), the exact model by exact_model.hpp's method.
    // *jacobian is written only on success.
    const SolveTotals& solve_jacobian(const ContactInput& input, SolveMode mode,
                                      Jacobian& jacobian);

    // Makes a model's memory now, so that its solves allocate nothing
    // (the grid's first model is made with the solver). Throws Error(invalid_input) when
    // the model is unknown or cannot run on this grid (exact: needs the
    // uniform or a gap grid; calibrated: not a gap grid) and
    // Error(grid_out_of_range) beyond its grid limit.
    void prepare(ModelKind model);
    // The exact model, if made (diagnostics of its last solve: info()).
    const ExactModel* exact_model() const;
    // On a gap grid: the exact model of any contact shape.
    const GapExactModel* gap_model() const;
    // On a gap grid: dN/d(approach) [N/m] at the last solve's normal
    // solution, by its normal method (normal/gap_normal.hpp); 0 on the
    // ellipse's grids or without a solution. Throws Error(not_converged)
    // if the exact normal problem's linear solve fails.
    double normal_force_by_approach();
    // The separate patches of the last solve: on a gap grid each 4-connected
    // patch, otherwise the contact as one patch (none when nothing touches).
    const std::vector<PatchTotals>& patches() const;
    // The calibrated model, made on first use (the fitting tool solves it
    // with its own parameters).
    CalibratedModel& calibrated_model();

    // The grid's size and kind; on the ellipse's grids also its geometry
    // (a gap grid's contact is the caller's gap).
    const ContactGrid& grid() const { return *grid_; }
    const SolveTotals& totals() const { return totals_; }
    bool has_solution() const { return solved_; }
    bool has_work() const { return solved_ && mode_ == SolveMode::full; }
    // Marks the last solution absent: the C ABI does so when it rejects a
    // solve before reaching solve() (mode, struct sizes, enumerations).
    void discard()
    {
        solved_ = false;
        view_made_ = false;
    }
    static bool needs_work(Field f) { return field_needs_work(f); }

    // Element-wise factors on the friction coefficient of the following
    // solves (contact/friction_law.hpp: nx*ny values >= 0 at [i + j*nx],
    // copied; friction that depends on the temperature), or none (null, the
    // default: every solve bitwise without). The exact model on every grid
    // and FASTSIM on the ellipse's grids (Coulomb's law or a local law) take
    // them; another model's solve refuses them by name. Under Coulomb's law the totals' mu_min, mu_max are then the
    // range of mu times the factor over the slipping elements. Allocates on
    // the first call only.
    void set_friction_factors(const double* factor);
    bool has_friction_factors() const { return has_factors_; }

    // The kernel of the models' SIMD marches: best_kernel_isa() unless set.
    // Every kernel gives bitwise the same results; set_kernel_isa is for
    // tests and benchmarks, applies to every model (also those made later)
    // and throws Error(invalid_input) when this CPU cannot run it.
    KernelIsa kernel_isa() const { return isa_; }
    void set_kernel_isa(KernelIsa isa);

    // The last solve per element (contact/solved_contact.hpp), which the
    // exports below and the post-processors (wear, temperature, damage)
    // read. Made by the model on the first read after a solve and kept
    // until a call that may change the models (a solver is used by one
    // thread at a time): a dozen fields read make one view. Preconditions
    // (checked by the caller): has_solution(), and has_work() for fields
    // that need it.
    const SolvedContact& solved() const
    {
        if (!view_made_) {
            view_ = last_->solved();
            view_made_ = true;
        }
        return view_;
    }
    // out[i + j*nx] for i < nx, j < ny.
    void copy_field(Field f, double* out) const { export_field(solved(), f, out); }
    // out[i + j*nx] += scale * field: accumulation without temporaries.
    void add_field(Field f, double scale, double* out) const
    {
        creepwork::add_field(solved(), f, scale, out);
    }
    void copy_state(int* out) const { export_state(solved(), out); }
    // Per strip j < ny: strip centre y [m], work per unit width [J/m per m],
    // and the equal-area parabola at y.
    void copy_profile(double* y, double* work, double* parabola) const
    {
        export_profile(solved(), totals_.W_consistent, y, work, parabola);
    }
    // Per strip j < ny of the last solve: centre y [m] and width [m].
    void copy_strips(double* y, double* width) const;

private:
    const SolveTotals& solve_impl(const ContactInput& input, SolveMode mode, Jacobian* jacobian);
    // The model of this kind, made (and registered) on first use.
    ContactModel& model(ModelKind kind);
    ContactModel* find(ModelKind kind) const;

    std::shared_ptr<const ContactGrid> grid_; // shared with the march models
    std::vector<std::pair<ModelKind, std::unique_ptr<ContactModel>>> models_;
    KernelIsa isa_;                   // of every model's kernels
    ContactModel* last_ = nullptr;    // the model of the last solve (its fields are exported)
    std::vector<PatchTotals> one_patch_; // of a model without patches: the contact, if any
    SolveTotals totals_;
    void factor_range(const SolvedContact& view, SolveTotals& t);
    std::vector<double> factors_; // set_friction_factors' copy
    std::vector<int> factor_state_; // the states, for the range of mu under the factors
    bool has_factors_ = false;
    SolveMode mode_ = SolveMode::full;
    bool solved_ = false;
    mutable SolvedContact view_; // of last_, valid while view_made_
    mutable bool view_made_ = false;
};

} // namespace creepwork
