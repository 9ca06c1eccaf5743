// The solver object: one per grid, holding every model of the contact
// (fastsim/, and the models that need more memory, made on first use or by
// prepare()), dispatching each solve to the model the input asks for, and
// exporting the fields of the last solve in the caller's layout
// (contact/fields.hpp).
#pragma once

#include <memory>

#include "contact/fields.hpp"
#include "calibrated/calibrated_model.hpp"
#include "contact/jacobian.hpp"
#include "contact/params.hpp"
#include "exact/exact_model.hpp"
#include "fastsim/fastsim_model.hpp"

namespace creepwork {

class Solver {
public:
    explicit Solver(const GridSpec& grid);

    // Throws Error naming a bad input; the previous solution is then marked
    // absent. The exact model is made on its first solve unless prepare()
    // made it before.
    const SolveTotals& solve(const ContactInput& input, SolveMode mode = SolveMode::full);
    // The same solve and the Jacobian of its Fx, Fy, Mz, W_macro with
    // respect to xi_x, xi_y, phi, N (contact/jacobian.hpp; doc/theory/jacobians.md).
    // FASTSIM: forward mode through the march; exact: exact_model.hpp;
    // calibrated: forward mode along the directions its setup moves in
    // (calibrated_model.hpp). *jacobian is written only on success.
    const SolveTotals& solve_jacobian(const ContactInput& input, SolveMode mode,
                                      Jacobian& jacobian);

    // Makes a model's memory now, so that its solves allocate nothing
    // (FASTSIM's is made with the solver). Throws Error(invalid_input) when
    // the model cannot run on this grid (exact: needs the uniform grid) and
    // Error(grid_out_of_range) beyond its grid limit.
    void prepare(ModelKind model);
    // The exact model, if made (diagnostics of its last solve: info()).
    const ExactModel* exact_model() const { return exact_.get(); }
    // The calibrated model, made on first use (the fitting tool solves it
    // with its own parameters).
    CalibratedModel& calibrated_model();

    const ContactGrid& grid() const { return fastsim_.grid(); }
    const SolveTotals& totals() const { return totals_; }
    bool has_solution() const { return solved_; }
    bool has_work() const { return solved_ && mode_ == SolveMode::full; }
    // Marks the last solution absent: the C ABI does so when it rejects a
    // solve before reaching solve() (mode, struct sizes, enumerations).
    void discard() { solved_ = false; }
    static bool needs_work(Field f) { return field_needs_work(f); }

    // The FASTSIM kernel in use: best_kernel_isa() unless set. Every kernel
    // gives bitwise the same results; set_kernel_isa is for tests and
    // benchmarks and throws Error(invalid_input) when this CPU cannot run it.
    KernelIsa kernel_isa() const { return fastsim_.kernel_isa(); }
    void set_kernel_isa(KernelIsa isa) { fastsim_.set_kernel_isa(isa); }

    // out[i + j*nx] for i < nx, j < ny. Preconditions (checked by the
    // caller): has_solution(), and has_work() for fields that need it.
    void copy_field(Field f, double* out) const;
    // out[i + j*nx] += scale * field: accumulation without temporaries.
    void add_field(Field f, double scale, double* out) const;
    void copy_state(int* out) const;
    // Per strip j < ny: strip centre y [m], work per unit width [J/m per m],
    // and the equal-area parabola at y.
    void copy_profile(double* y, double* work, double* parabola) const;

private:
    const SolveTotals& solve_impl(const ContactInput& input, SolveMode mode, Jacobian* jacobian);
    FastsimModel fastsim_;
    std::unique_ptr<ExactModel> exact_;
    std::unique_ptr<CalibratedModel> calibrated_;
    bool exact_last() const; // the last solve (and so the fields) is the exact model's
    bool calibrated_last() const;
    ModelKind last_model_ = ModelKind::fastsim;
    SolveTotals totals_;
    SolveMode mode_ = SolveMode::full;
    bool solved_ = false;
};

} // namespace creepwork
