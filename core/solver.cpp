#include "solver.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/contact_input.hpp"
#include "contact/error.hpp"
#include "fastsim/fastsim_global_slip_model.hpp"
#include "fastsim/fastsim_law_model.hpp"
#include "friction/friction_input.hpp"

namespace creepwork {
namespace {

using Grid = std::shared_ptr<const ContactGrid>;

template <class Model>
std::unique_ptr<ContactModel> on_shared_grid(const Grid& grid)
{
    return std::make_unique<Model>(grid);
}
template <class Model>
std::unique_ptr<ContactModel> on_spec(const Grid& grid)
{
    return std::make_unique<Model>(grid->spec());
}

// The models a solver can make: one row per grid and model. A new model is
// one class implementing ContactModel (contact/contact_model.hpp), one
// ModelKind value (contact/params.hpp) and one row here. The first row of a
// grid is its first model, made with the solver (which so checks the grid).
struct Registration {
    bool gap_grid; // a gap grid (GridKind::gap), or the ellipse's grids
    ModelKind kind;
    std::unique_ptr<ContactModel> (*make)(const Grid&);
    const char* name; // in messages
};
constexpr Registration kModels[] = {
    {false, ModelKind::fastsim, &on_shared_grid<FastsimModel>, "FASTSIM"},
    {false, ModelKind::exact, &on_spec<ExactModel>, "the exact model"},
    {false, ModelKind::calibrated, &on_shared_grid<CalibratedModel>, "the calibrated model"},
    {true, ModelKind::exact, &on_spec<GapExactModel>, "the exact model on a gap grid"},
    {true, ModelKind::fastsim, &on_spec<GapFastsimModel>, "FASTSIM on a gap grid"},
    // FASTSIM under a law of the slip speed (route() picks them).
    {false, ModelKind::fastsim_law, &on_shared_grid<FastsimLawModel>,
     "FASTSIM with the law at every element"},
    {false, ModelKind::fastsim_global_slip, &on_shared_grid<FastsimGlobalSlipModel>,
     "FASTSIM at the global slip speed"},
};

// The model that solves the input: the one it names, or for FASTSIM on
// the ellipse's grids beyond Coulomb's law the march under the law at each
// element's slip speed or at the contact's global slip speed.
ModelKind route(const ContactInput& in, bool gap_grid)
{
    if (gap_grid || in.model != ModelKind::fastsim || !beyond_coulomb(in)) return in.model;
    return in.friction_speed == FrictionSpeed::global ? ModelKind::fastsim_global_slip
                                                      : ModelKind::fastsim_law;
}

std::string model_name(ModelKind kind)
{
    return kind == ModelKind::calibrated ? "calibrated" : std::to_string(static_cast<int>(kind));
}

std::unique_ptr<ContactModel> make_model(ModelKind kind, const Grid& grid)
{
    const bool gap_grid = grid->spec().kind == GridKind::gap;
    for (const Registration& r : kModels)
        if (r.gap_grid == gap_grid && r.kind == kind) {
            std::unique_ptr<ContactModel> made = r.make(grid);
            made->set_name(r.name);
            return made;
        }
    if (gap_grid)
        throw Error(ErrorKind::invalid_input,
                    "model = " + model_name(kind) +
                        " is invalid on a gap grid: a contact of any shape is solved by the "
                        "exact model (model = exact) or FASTSIM (model = fastsim)");
    throw Error(ErrorKind::invalid_input,
                "model = " + std::to_string(static_cast<int>(kind)) + " is unknown");
}

// The grid's first model: its first row in kModels.
ModelKind first_model(const GridSpec& grid)
{
    for (const Registration& r : kModels)
        if (r.gap_grid == (grid.kind == GridKind::gap)) return r.kind;
    return ModelKind::fastsim;
}

} // namespace

Solver::Solver(const GridSpec& grid) : Solver(grid, first_model(grid)) {}

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
    made->set_kernel_isa(isa_);
    models_.emplace_back(kind, std::move(made));
    return *models_.back().second;
}

Solver::Solver(const GridSpec& grid, ModelKind first)
    : grid_(std::make_shared<const ContactGrid>(grid)), isa_(best_kernel_isa())
{
    last_ = &model(first);
    one_patch_.reserve(1);
}

void Solver::prepare(ModelKind kind)
{
    view_made_ = false;
    model(kind).prepare();
}

const ExactModel* Solver::exact_model() const
{
    return dynamic_cast<const ExactModel*>(find(ModelKind::exact));
}

const GapExactModel* Solver::gap_model() const
{
    return dynamic_cast<const GapExactModel*>(find(ModelKind::exact));
}

double Solver::normal_force_by_approach()
{
    view_made_ = false;
    return solved_ ? last_->normal_force_by_approach() : 0.0;
}

CalibratedModel& Solver::calibrated_model()
{
    view_made_ = false; // the caller may solve it
    return static_cast<CalibratedModel&>(model(ModelKind::calibrated));
}

void Solver::set_kernel_isa(KernelIsa isa)
{
    if (!kernel_isa_supported(isa))
        throw Error(ErrorKind::invalid_input,
                    std::string("kernel ") + kernel_isa_name(isa) + " is not supported by this CPU");
    isa_ = isa;
    view_made_ = false;
    for (const auto& m : models_) m.second->set_kernel_isa(isa);
}

void Solver::set_friction_factors(const double* factor)
{
    has_factors_ = factor != nullptr;
    if (!factor) return;
    const size_t n = static_cast<size_t>(grid_->nx()) * static_cast<size_t>(grid_->ny());
    factors_.assign(factor, factor + n);
    factor_state_.resize(n);
}

// Coulomb's law with element-wise factors: the range of mu_static times the
// factor over the slipping elements (none slipping: mu_static).
void Solver::factor_range(const SolvedContact& view, SolveTotals& t)
{
    export_state(view, factor_state_.data());
    bool any = false;
    for (size_t e = 0; e < factor_state_.size(); ++e) {
        if (factor_state_[e] != 2) continue;
        const double mu = t.mu_static * factors_[e];
        t.mu_min = any ? std::min(t.mu_min, mu) : mu;
        t.mu_max = any ? std::max(t.mu_max, mu) : mu;
        any = true;
    }
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
    view_made_ = false; // the next read makes the view of this solve
    mode_ = mode;
    validate_grid_input(grid_->spec(), input);
    validate_friction_input(input);
    validate_layer_input(input);
    const bool gap_grid = grid_->spec().kind == GridKind::gap;
    ContactModel& m = model(route(input, gap_grid));
    if (const char* layer = layer_input_name(input))
        if (!m.takes_interface_layer())
            throw Error(ErrorKind::invalid_input,
                        std::string(layer) + ": " + m.name() +
                            " has no interface layer (the exact model has)");
    if (beyond_coulomb(input)) {
        if (input.friction_speed == FrictionSpeed::global && input.model != ModelKind::fastsim)
            throw Error(ErrorKind::invalid_input,
                        "friction_speed: the global slip speed is FASTSIM's (model = fastsim), "
                        "not " + m.name() + "'s");
        m.set_law(slip_speed_law(input), input.V);
    } else {
        m.clear_law();
    }
    m.set_friction_factors(has_factors_ ? factors_.data() : nullptr);
    auto* law_model = dynamic_cast<FastsimLawModel*>(&m);
    const bool has_memory =
        law_model || m.set_friction_memory(input.memory_distance, input.memory_s0);
    if (input.memory_distance > 0.0 && input.friction_law != FrictionLaw::coulomb && !has_memory)
        throw Error(ErrorKind::invalid_input,
                    "memory_distance: " + m.name() + " has no friction memory (the exact model "
                    "and FASTSIM on the ellipse's grids with friction_speed = local have)");
    if (law_model) law_model->set_memory(friction_memory(input));
    SolveTotals t = jacobian ? m.solve_jacobian(input, mode, *jacobian) : m.solve(input, mode);
    last_ = &m;
    t.mu_static = input.mu;
    if (input.friction_law != FrictionLaw::coulomb) t.mu_static += input.mu_e1 + input.mu_e2;
    if (!m.friction_range(t.mu_min, t.mu_max)) {
        t.mu_min = t.mu_max = t.mu_static;
        if (has_factors_) factor_range(m.solved(), t);
    }

    const double checks[] = {t.Fx, t.Fy, t.Mz, t.W_macro, t.W_micro_paper, t.K, t.W_consistent,
                             t.balance_factor, t.profile_max_diff, t.profile_rms_diff};
    for (double v : checks)
        if (!std::isfinite(v))
            throw Error(ErrorKind::numeric_failure,
                        "a result overflowed: the inputs are too extreme for double precision");
    // A model that does not find separate patches (the ellipse's) reports the
    // contact as one patch: its totals.
    if (!m.patches()) {
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
    if (last_->copy_strips(y, width)) return;
    // The strip grids are normalised by the semi-axis b of the last solve.
    const ContactGrid& g = grid();
    for (int j = 0; j < g.ny(); ++j) {
        y[j] = totals_.b * g.y_centre()[j];
        width[j] = totals_.b * g.y_width()[j];
    }
}

} // namespace creepwork
