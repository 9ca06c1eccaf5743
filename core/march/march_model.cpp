#include "march/march_model.hpp"

#include <string>
#include <utility>

#include "contact/error.hpp"
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
    bound_ = geometry_.shape(PressureKind::parabolic).data();
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
    bound_ = bound;
    bound_max_ = bound_max;
    set_rigid_slip(*grid_, setup_.kin, state_, 0, grid_->ny());
}

void MarchModel::march() { creepwork::march(view(), isa_); }

void MarchModel::march_with_work()
{
    creepwork::march_with_work(geometry_, bound_, *grid_, setup_, state_, work_, isa_);
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

void MarchModel::copy_profile(double W, double* y, double* work, double* parabola) const
{
    for (int j = 0; j < grid_->ny(); ++j) {
        const double yj = setup_.b * grid_->y_centre()[j];
        if (y) y[j] = yj;
        if (work) work[j] = work_.profile[j];
        if (parabola) parabola[j] = equal_area_parabola(W, setup_.b, yj);
    }
}

} // namespace creepwork
