// What every model that finds its tractions by Kalker's strip march shares
// (FASTSIM, the calibrated model): the grid in the kernels' layout, the
// march and work state, the kernel ISA, the totals and the export of the
// fields. A model built on it makes its setup (the normalised kinematics,
// march_setup.hpp) and its traction bound per element, calls begin(), then
// march() or march_with_work() and its own Jacobian march, then totals().
//
// The fields are not stored in the caller's layout: the march keeps the trial
// traction q' and the factor f (p' = f q') in march order, handed out as the
// view's strips layout (solved(), contact/solved_contact.hpp), and each field
// is computed from them while it is copied out (contact/solved_strips.cpp).
#pragma once

#include <memory>
#include <vector>

#include "contact/contact_grid.hpp"
#include "contact/contact_model.hpp"
#include "march/march.hpp"
#include "march/march_geometry.hpp"
#include "march/march_setup.hpp"
#include "march/march_step.hpp"
#include "march/march_work.hpp"
#include "simd/kernel_isa.hpp"

namespace creepwork {

class MarchModel : public ContactModel {
public:
    const ContactGrid& grid() const { return *grid_; }
    KernelIsa kernel_isa() const { return isa_; }
    // Throws Error(invalid_input) when this CPU cannot run isa.
    void set_kernel_isa(KernelIsa isa) override;

    SolvedContact solved() const override;

protected:
    explicit MarchModel(const GridSpec& grid); // on a grid of its own
    // On a grid shared with other models (a solver's).
    explicit MarchModel(std::shared_ptr<const ContactGrid> grid);

    // One solve: the setup and the traction bound (per element, the
    // kernels' layout, in units of setup.pressure_scale; largest value
    // bound_max), which must outlive the solve's exports. Sets every
    // strip's rigid slip from setup.kin (march_state().wx, wy: a model may
    // adjust them before marching). With element-wise friction factors
    // (take_friction_factors) the march's bound is bound times each
    // element's factor and bound stays the pressure the fields report.
    void begin(const ModelSetup& setup, const double* bound, double bound_max);
    // The element-wise factors on the coefficient of the next solves
    // (contact/friction_law.hpp, ElementFriction; null: none), for a model
    // whose set_friction_factors takes them.
    void take_friction_factors(const double* factor) { factor_ = factor; }
    // The march's traction bound of this solve (begin()'s, with the factors).
    const double* march_bound() const { return bound_; }
    // The plain march, or the march with the work of every element (full mode).
    void march();
    void march_with_work();
    // The work of every element of a march the model did with its own
    // kernel (march_work.hpp, work_of_march).
    void work_of_march();
    // The view of every strip for a model's own kernels (a Jacobian march).
    MarchView view()
    {
        return march_view(geometry_, bound_, setup_.kin.cy, state_, 0, grid_->ny());
    }
    // Totals of the march just done, reported as model; full mode also
    // distributes the work.
    SolveTotals totals(const ContactInput& input, SolveMode mode, ModelKind model);

    // The load the grid carries per unit pressure scale (exact_load).
    const DiscreteLoad& discrete_load() const { return load_; }
    const ModelSetup& setup() const { return setup_; }
    const MarchGeometry& geometry() const { return geometry_; }
    MarchGeometry& geometry() { return geometry_; }
    const MarchState& march_state() const { return state_; }
    MarchState& march_state() { return state_; }

private:
    std::shared_ptr<const ContactGrid> grid_;
    MarchGeometry geometry_; // the grid in the kernels' layout
    MarchState state_;
    WorkState work_;
    ModelSetup setup_;
    const double* bound_ = nullptr;    // the march's
    const double* pressure_ = nullptr; // begin()'s bound: the pressure shape
    double bound_max_ = 0;
    const double* factor_ = nullptr;   // the caller's, or null
    std::vector<double> factored_;     // bound times the factors (kernels' layout)
    KernelIsa isa_ = KernelIsa::baseline;
    DiscreteLoad load_;
};

} // namespace creepwork
