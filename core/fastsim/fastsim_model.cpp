#include "fastsim/fastsim_model.hpp"

#include <string>

#include "contact/error.hpp"
#include "contact/fp_safe.hpp"
#include "contact/hertz.hpp"
#include "fastsim/fastsim_jacobian.hpp"

namespace creepwork {

FastsimModel::FastsimModel(const GridSpec& grid)
    : grid_(grid), geometry_(grid_), isa_(best_kernel_isa()), load_(creepwork::discrete_load(grid_))
{
    march_.resize(grid_.size(), grid_.ny());
    work_.resize(grid_.size(), grid_.ny());
    tangent_.resize(geometry_);
    max_shape_parabolic_ = grid_.pressure_shape(PressureKind::parabolic).maxCoeff();
    max_shape_elliptic_ = grid_.pressure_shape(PressureKind::elliptic).maxCoeff();
}

void FastsimModel::set_kernel_isa(KernelIsa isa)
{
    if (!kernel_isa_supported(isa))
        throw Error(ErrorKind::invalid_input,
                    std::string("kernel ") + kernel_isa_name(isa) + " is not supported by this CPU");
    isa_ = isa;
}

SolveTotals FastsimModel::solve(const ContactInput& input, SolveMode mode, Jacobian* jacobian)
{
    return march_and_total(make_model_setup(input, discrete_load_of(load_, input.pressure)), input,
                           mode, jacobian);
}

SolveTotals FastsimModel::solve_setup(const ModelSetup& setup, const ContactInput& input,
                                      SolveMode mode)
{
    return march_and_total(setup, input, mode, nullptr);
}

SolveTotals FastsimModel::solve_setup_directional(const ModelSetup& setup,
                                                  const ContactInput& input, SolveMode mode,
                                                  MarchDirections& directions, Jacobian& jacobian)
{
    if (directions.stride != geometry_.stride)
        throw Error(ErrorKind::invalid_input, "directions: sized for another grid");
    return march_and_total(setup, input, mode, &jacobian, &directions);
}

SolveTotals FastsimModel::march_and_total(const ModelSetup& setup, const ContactInput& input,
                                          SolveMode mode, Jacobian* jacobian,
                                          MarchDirections* directions)
{
    setup_ = setup;
    // The calibrated model's blended bound (parabolic units), made before the
    // march reads it.
    if (setup_.kin.bound_blend != 0.0) {
        if (setup_.pressure != PressureKind::parabolic || (jacobian && !directions))
            throw Error(ErrorKind::invalid_input,
                        "a blended traction bound needs the parabolic pressure scale and has no "
                        "Jacobian");
        geometry_.set_blend(setup_.kin.bound_blend);
    }
    if (mode == SolveMode::full)
        march_with_work(geometry_, grid_, setup_, march_, work_, isa_); // work accounted
    // With work, the tangent march repeats the march: the same state, bitwise.
    if (directions) {
        march_directional(geometry_, grid_, setup_, march_, *directions, isa_);
        *jacobian = directional_jacobian(setup_, grid_, march_, *directions);
    } else if (jacobian) {
        march_tangent(geometry_, grid_, setup_, march_, tangent_, isa_);
        *jacobian = fastsim_jacobian(input, setup_, grid_, march_, tangent_);
    } else if (mode != SolveMode::full) {
        march(geometry_, grid_, setup_.kin, setup_.pressure, march_, isa_);
    }

    // Totals in the rolling frame: F = T a b sum(p' A'), A' per strip.
    const double T = setup_.traction_scale, a = setup_.a, b = setup_.b;
    double fx = 0.0, fy = 0.0, mz = 0.0;
    int n_slip = 0;
    for (int j = 0; j < grid_.ny(); ++j) {
        const double area = a * b * grid_.x_length()[j] * grid_.y_width()[j];
        const double y = b * grid_.y_centre()[j];
        fx += area * march_.sum_px[j];
        fy += area * march_.sum_py[j];
        mz += area * (a * march_.sum_x_py[j] - y * march_.sum_px[j]);
        n_slip += static_cast<int>(march_.slip_count[j]);
    }
    fx *= T;
    fy *= T;
    mz *= T;

    SolveTotals t;
    const double d = setup_.direction;
    t.Fx = d * fx;
    t.Fy = fy;
    t.Mz = d * mz;
    // Paper eq. 34 per unit rolling distance, positive when dissipating.
    t.W_macro = -(setup_.xi * fx + setup_.eta * fy + setup_.phi * mz);
    t.n_contact = grid_.n_contact();
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
    t.model = ModelKind::fastsim;
    t.p_max = setup_.pressure_scale * (setup_.kin.bound_blend != 0.0 ? geometry_.blend_max
                                       : setup_.pressure == PressureKind::parabolic
                                           ? max_shape_parabolic_
                                           : max_shape_elliptic_);
    if (input.flexibility == FlexibilitySource::kalker_from_material)
        t.approach =
            hertz_from_semi_axes(a, b, input.normal_force, input.G / (1.0 - input.nu)).approach;

    if (mode == SolveMode::full) {
        const WorkTotals w = distribute_work(geometry_, grid_, setup_, t.W_macro, work_, isa_);
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

} // namespace creepwork
