#include "solver.hpp"

#include <cmath>
#include <string>

#include "contact/error.hpp"

namespace creepwork {
namespace {

// The models a solver can make, by ModelKind: a new model is one class
// implementing ContactModel (contact/contact_model.hpp), one ModelKind value
// (contact/params.hpp) and one case here.
std::unique_ptr<ContactModel> make_model(ModelKind kind, const GridSpec& grid)
{
    switch (kind) {
    case ModelKind::fastsim: return std::make_unique<FastsimModel>(grid);
    case ModelKind::exact: return std::make_unique<ExactModel>(grid);
    case ModelKind::calibrated: return std::make_unique<CalibratedModel>(grid);
    }
    throw Error(ErrorKind::invalid_input,
                "model = " + std::to_string(static_cast<int>(kind)) + " is unknown");
}

} // namespace

// The models of a gap grid: the exact model, made with the solver, and
// FASTSIM's, made on first use.
ContactModel& Solver::gap_grid_model(ModelKind kind)
{
    check_gap_model(kind);
    if (kind == ModelKind::exact) return *gap_;
    if (!gap_fastsim_) {
        gap_fastsim_ = std::make_unique<GapFastsimModel>(grid_);
        gap_fastsim_->set_kernel_isa(fastsim_->kernel_isa());
    }
    return *gap_fastsim_;
}

Solver::Solver(const GridSpec& grid) : grid_(grid)
{
    last_ = &model(ModelKind::fastsim);
    fastsim_ = static_cast<FastsimModel*>(last_);
    // A gap grid has one model, made now so that its grid is checked at
    // creation; it is not registered by ModelKind (no other model runs there).
    if (gap_grid()) {
        gap_ = std::make_unique<GapExactModel>(grid);
        last_ = gap_.get();
    }
    one_patch_.reserve(1);
}

ContactModel* Solver::find(ModelKind kind) const
{
    for (const auto& m : models_)
        if (m.first == kind) return m.second.get();
    return nullptr;
}

ContactModel& Solver::model(ModelKind kind)
{
    if (ContactModel* m = find(kind)) return *m;
    std::unique_ptr<ContactModel> made = make_model(kind, grid_);
    if (fastsim_) made->set_kernel_isa(fastsim_->kernel_isa());
    models_.emplace_back(kind, std::move(made));
    return *models_.back().second;
}

void Solver::prepare(ModelKind kind)
{
    if (gap_grid()) {
        gap_grid_model(kind);
        return;
    }
    model(kind);
}

void Solver::check_gap_model(ModelKind kind) const
{
    if (kind != ModelKind::exact && kind != ModelKind::fastsim)
        throw Error(ErrorKind::invalid_input,
                    std::string("model = ") +
                        (kind == ModelKind::calibrated ? "calibrated"
                                                       : std::to_string(static_cast<int>(kind))) +
                        " is invalid on a gap grid: a contact of any shape is solved by the "
                        "exact model (model = exact) or FASTSIM (model = fastsim)");
}

const ExactModel* Solver::exact_model() const
{
    return static_cast<const ExactModel*>(find(ModelKind::exact));
}

CalibratedModel& Solver::calibrated_model()
{
    return static_cast<CalibratedModel&>(model(ModelKind::calibrated));
}

void Solver::set_kernel_isa(KernelIsa isa)
{
    fastsim_->set_kernel_isa(isa); // throws when this CPU cannot run it
    for (const auto& m : models_) m.second->set_kernel_isa(isa);
    if (gap_) gap_->set_kernel_isa(isa);
    if (gap_fastsim_) gap_fastsim_->set_kernel_isa(isa);
}

const SolveTotals& Solver::solve(const ContactInput& input, SolveMode mode)
{
    return solve_impl(input, mode, nullptr);
}

const SolveTotals& Solver::solve_jacobian(const ContactInput& input, SolveMode mode,
                                          Jacobian& jacobian)
{
    Jacobian J;
    solve_impl(input, mode, &J);
    jacobian_work_row(J, totals_.Fx, totals_.Fy, totals_.Mz, input.xi_x, input.xi_y, input.phi);
    for (const auto& row : J.d)
        for (double v : row)
            if (!std::isfinite(v)) {
                solved_ = false;
                throw Error(ErrorKind::numeric_failure,
                            "a Jacobian entry overflowed: the inputs are too extreme for double "
                            "precision");
            }
    jacobian = J;
    return totals_;
}

const SolveTotals& Solver::solve_impl(const ContactInput& input, SolveMode mode,
                                      Jacobian* jacobian)
{
    solved_ = false;
    mode_ = mode;
    if (!gap_grid() && (input.gap || input.normal_load != NormalLoad::force ||
                        input.normal_method != NormalMethod::exact))
        throw Error(ErrorKind::invalid_input,
                    input.gap ? "gap is given but the grid is not a gap grid (CW_GRID_GAP)"
                    : input.normal_load != NormalLoad::force
                        ? "normal_load = approach needs a gap grid (CW_GRID_GAP)"
                        : "normal_method = semi_hertz needs a gap grid (CW_GRID_GAP)");
    ContactModel& m = gap_grid() ? gap_grid_model(input.model) : model(input.model);
    SolveTotals t = jacobian ? m.solve_jacobian(input, mode, *jacobian) : m.solve(input, mode);
    last_ = &m;

    const double checks[] = {t.Fx, t.Fy, t.Mz, t.W_macro, t.W_micro_paper, t.K, t.W_consistent,
                             t.balance_factor, t.profile_max_diff, t.profile_rms_diff};
    for (double v : checks)
        if (!std::isfinite(v))
            throw Error(ErrorKind::numeric_failure,
                        "a result overflowed: the inputs are too extreme for double precision");
    // Off a gap grid the contact is one patch: its totals.
    if (!gap_grid()) {
        t.normal_force = input.normal_force;
        t.n_patches = t.n_contact > 0 ? 1 : 0;
        one_patch_.clear();
        if (t.n_patches) {
            PatchTotals p;
            p.n_contact = t.n_contact;
            p.n_adhesion = t.n_adhesion;
            p.n_slip = t.n_slip;
            p.Fx = t.Fx;
            p.Fy = t.Fy;
            p.Mz = t.Mz;
            p.Fn = t.normal_force;
            p.p_max = t.p_max;
            p.W_macro = t.W_macro;
            one_patch_.push_back(p);
        }
    }
    totals_ = t;
    solved_ = true;
    return totals_;
}

const std::vector<PatchTotals>& Solver::patches() const
{
    const std::vector<PatchTotals>* found = last_->patches();
    return found ? *found : one_patch_;
}

void Solver::copy_strips(double* y, double* width) const
{
    if (gap_) {
        gap_->copy_strips(y, width);
        return;
    }
    // The strip grids are normalised by the semi-axis b of the last solve.
    const ContactGrid& g = grid();
    for (int j = 0; j < g.ny(); ++j) {
        y[j] = totals_.b * g.y_centre()[j];
        width[j] = totals_.b * g.y_width()[j];
    }
}

} // namespace creepwork
