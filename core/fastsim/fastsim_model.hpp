// Kalker's simplified theory as one model of the contact: the FASTSIM march
// (march/march.hpp), its work bookkeeping (march/march_work.hpp) and the export of its
// fields. Made once per grid (it owns the grid geometry in the kernels'
// layout and every workspace, and picks the kernel for this CPU), then
// solve() many times without allocating.
//
// The fields are not stored in the caller's layout: the march keeps the trial
// traction q' and the factor f (p' = f q') in march order, and each field is
// computed from them while it is copied out (march/march_fields.cpp).
#pragma once

#include "contact/contact_grid.hpp"
#include "contact/fields.hpp"
#include "contact/jacobian.hpp"
#include "contact/params.hpp"
#include "march/march_setup.hpp"
#include "march/march_work.hpp"
#include "march/march.hpp"
#include "calibrated/march_directional.hpp"
#include "fastsim/march_tangent.hpp"

namespace creepwork {

class FastsimModel {
public:
    explicit FastsimModel(const GridSpec& grid);

    // Throws Error(invalid_input) naming a bad input. With jacobian, the
    // march also carries its tangents (march_tangent.hpp) and *jacobian
    // receives rows Fx, Fy, Mz (fastsim_jacobian.hpp; the W_macro row is the
    // solver's); the totals are bitwise those of a solve without it.
    SolveTotals solve(const ContactInput& input, SolveMode mode, Jacobian* jacobian = nullptr);
    // The same march for a setup made (and possibly adjusted) by the caller:
    // models built on FASTSIM's march (calibrated/) change the kinematics
    // and the traction bound and keep everything else. setup comes from
    // make_model_setup(input); solve(input, mode) is
    // solve_setup(make_model_setup(input), input, mode). FASTSIM's own
    // Jacobian (fastsim_jacobian differentiates make_model_setup) is
    // solve()'s; an adjusted setup is differentiated by
    // solve_setup_directional() along the caller's directions.
    SolveTotals solve_setup(const ModelSetup& setup, const ContactInput& input, SolveMode mode);
    // The same march differentiated along directions of the setup that the
    // caller gives (march_directional.hpp: the derivatives of each strip's
    // rigid slip, cy and the bound blend by each creepage); *jacobian
    // receives rows Fx, Fy, Mz with one column per direction. The totals are
    // bitwise those of solve_setup().
    SolveTotals solve_setup_directional(const ModelSetup& setup, const ContactInput& input,
                                        SolveMode mode, MarchDirections& directions,
                                        Jacobian& jacobian);

    const ContactGrid& grid() const { return grid_; }
    // The load the grid carries per unit pressure scale (exact_load).
    const DiscreteLoad& discrete_load() const { return load_; }
    // Allocates the workspace of a blended traction bound
    // (NormalisedKinematics::bound_blend), for models that use one.
    void reserve_blended_bound() { geometry_.reserve_blend(); }
    // The march's steps from the leading edge (MarchGeometry::
    // march_from_leading_edge), for models that use them.
    void march_from_leading_edge() { geometry_.march_from_leading_edge(grid_); }
    KernelIsa kernel_isa() const { return isa_; }
    void set_kernel_isa(KernelIsa isa); // throws when the CPU cannot run it

    // Of the last solve (the caller checks that there is one).
    void copy_field(Field f, double* out) const;
    void add_field(Field f, double scale, double* out) const; // out += scale * field
    void copy_state(int* out) const;
    // Per strip j < ny: strip centre y [m], energy-consistent work per unit
    // width [J/m per m], and the equal-area parabola of total W at y.
    void copy_profile(double W, double* y, double* work, double* parabola) const;

private:
    // The march from setup, its totals and (jacobian != nullptr) its tangents.
    SolveTotals march_and_total(const ModelSetup& setup, const ContactInput& input,
                                SolveMode mode, Jacobian* jacobian,
                                MarchDirections* directions = nullptr);
    template <class Op>
    void export_field(Field f, const Op& op, double* out) const;

    ContactGrid grid_;
    MarchGeometry geometry_; // the grid in the kernels' layout
    MarchState march_;
    TangentState tangent_;
    WorkState work_;
    ModelSetup setup_;
    KernelIsa isa_ = KernelIsa::baseline;
    double max_shape_parabolic_ = 0, max_shape_elliptic_ = 0; // largest pz / p0 on the grid
    DiscreteLoad load_;
};

} // namespace creepwork
