#include "march/march_model.hpp"

#include <string>
#include <utility>

#include "contact/error.hpp"
#include "contact/friction_law.hpp"
#include "contact/fp_safe.hpp"
#include "contact/hertz.hpp"

namespace creepwork {

MarchModel::MarchModel(const GridSpec& grid) : MarchModel(std::make_shared<const ContactGrid>(grid))
{
}

MarchModel::MarchModel(std::shared_ptr<const ContactGrid> grid)
    : grid_(std::move(grid)), geometry_(*grid_), isa_(best_kernel_isa()),
      load_(creepwork::discrete_load(*grid_))
{
    state_.resize(grid_->size(), grid_->ny());
    work_.resize(grid_->size(), grid_->ny());
    bound_ = pressure_ = geometry_.shape(PressureKind::parabolic).data();
}

void MarchModel::set_kernel_isa(KernelIsa isa)
{
    if (!kernel_isa_supported(isa))
        throw Error(ErrorKind::invalid_input,
                    std::string("kernel ") + kernel_isa_name(isa) + " is not supported by this CPU");
    isa_ = isa;
}

void MarchModel::begin(const ModelSetup& setup, const double* bound, double bound_max)
{
    setup_ = setup;
    bound_ = pressure_ = bound;
    bound_max_ = bound_max;
    if (factor_) {
        // Element m of strip j is the caller's element (m, j) read mirrored
        // when the march starts at +x (solved(): mirrored = direction > 0).
        const ElementFriction f{factor_, geometry_.nx, setup_.direction > 0};
        factored_.assign(bound, bound + geometry_.inside.size());
        scale_bounds(f, factored_.data(), geometry_.nx, grid_->ny(),
                     static_cast<std::size_t>(geometry_.stride), 1);
        bound_ = factored_.data();
    }
    set_rigid_slip(*grid_, setup_.kin, state_, 0, grid_->ny());
}

void MarchModel::march() { creepwork::march(view(), isa_); }

void MarchModel::march_with_work()
{
    creepwork::march_with_work(geometry_, bound_, *grid_, setup_, state_, work_, isa_);
}

void MarchModel::work_of_march()
{
    creepwork::work_of_march(geometry_, bound_, *grid_, setup_, state_, work_, isa_);
}

SolveTotals MarchModel::totals(const ContactInput& input, SolveMode mode, ModelKind model)
{
    // Totals in the rolling frame: F = T a b sum(p' A'), A' per strip.
    const double T = setup_.traction_scale, a = setup_.a, b = setup_.b;
    double Phi[3];
    scaled_forces(*grid_, a, b, state_, Phi);
    const double fx = Phi[0] * T, fy = Phi[1] * T, mz = Phi[2] * T;
    int n_slip = 0;
    for (int j = 0; j < grid_->ny(); ++j) n_slip += static_cast<int>(state_.slip_count[j]);

    SolveTotals t;
    const double d = setup_.direction;
    t.Fx = d * fx;
    t.Fy = fy;
    t.Mz = d * mz;
    // Paper eq. 34 per unit rolling distance, positive when dissipating.
    t.W_macro = -(setup_.xi * fx + setup_.eta * fy + setup_.phi * mz);
    t.n_contact = geometry_.n_contact;
    t.n_slip = n_slip;
    t.n_adhesion = t.n_contact - n_slip;
    t.adhesion_fraction = quotient_or_zero(t.n_adhesion, t.n_contact);
    t.a = a;
    t.b = b;
    t.L1 = setup_.L1;
    t.L2 = setup_.L2;
    t.L3 = setup_.L3;
    t.C11 = setup_.C.C11;
    t.C22 = setup_.C.C22;
    t.C23 = setup_.C.C23;
    t.C33 = setup_.C.C33;
    t.model = model;
    t.p_max = setup_.pressure_scale * bound_max_;
    if (input.flexibility == FlexibilitySource::kalker_from_material)
        t.approach =
            hertz_from_semi_axes(a, b, input.normal_force, input.G / (1.0 - input.nu)).approach;

    if (mode == SolveMode::full) {
        const WorkTotals w = distribute_work(geometry_, *grid_, setup_, t.W_macro, work_, isa_);
        t.W_micro_paper = w.W_micro_paper;
        t.K = quotient_or_zero(t.W_macro, w.W_micro_paper);
        t.W_consistent = w.W_consistent;
        t.balance_factor = w.balance;
        t.work_flags = w.flags;
        t.profile_max_diff = w.profile_max_diff;
        t.profile_rms_diff = w.profile_rms_diff;
    }
    return t;
}

SolvedContact MarchModel::solved() const
{
    const ContactGrid& g = *grid_;
    SolvedContact c;
    c.nx = g.nx();
    c.ny = g.ny();
    c.layout = SolvedLayout::strips;
    c.mirrored = setup_.direction > 0; // the march starts at the leading edge
    c.direction = setup_.direction;
    c.pressure = pressure_;
    c.pressure_scale = setup_.pressure_scale;
    c.traction_scale = setup_.traction_scale;
    c.work_paper = work_.paper.data();
    c.work_consistent = work_.consistent.data();
    c.profile = work_.profile.data();
    c.profile_b = setup_.b;
    SolvedStrips& s = c.strips;
    s.stride = geometry_.stride;
    s.a = setup_.a;
    s.b = setup_.b;
    s.x_centre = geometry_.x_centre.data();
    s.inside = geometry_.inside.data();
    s.y_centre = g.y_centre().data();
    s.x_length = g.x_length().data();
    s.y_width = g.y_width().data();
    s.qx = state_.qx.data();
    s.qy = state_.qy.data();
    s.factor = state_.factor.data();
    s.slip_x = work_.slip_x.data();
    s.slip_y = work_.slip_y.data();
    s.isa = isa_;
    return c;
}

} // namespace creepwork
