// Kalker's exact half-space theory of steady rolling on a contact of any
// shape: the caller gives the undeformed distance (the gap) on a regular
// grid, which is the potential contact area (CONTACT's module 3 with
// IBASE = 9). Made once per grid -- every workspace, FFT plan and
// coefficient table -- then solve() many times without allocating.
//
// One solve:
//  1. the normal problem on the gap by the method the input names
//     (normal/gap_normal.hpp), with the normal force or the approach
//     prescribed; warm solves start it from the last solution;
//  2. the tangential problem of steady rolling (exact/steady_rolling.hpp) with the
//     rigid slip w = (xi - phi y, eta + phi (x + spin_offset dx)) at the
//     element centres, x and y from the grid's origin; every patch of the
//     grid at once, on the smallest box of the grid that holds the contact
//     (tractions vanish outside it, and the influence coefficients depend
//     only on the offset: the same discrete problem on fewer elements, with
//     FFTs of the box's size);
//  3. the separate patches (normal/patches.hpp) and their totals, and in
//     full mode the work maps (exact/exact_work.hpp).
// The tangential problem starts from the last solution (warm) or from a
// hierarchy of coarser grids over the contact's box, each solved from the one
// below it, the coarsest from a march of Kalker's simplified theory with the
// flexibilities of the patches' equivalent ellipses; the coarse grids take
// the fine pressure interpolated at their centres. When the gap, the load
// and the material are those of the last solve, its normal solution is kept
// (a creepage sweep solves only the tangential problem).
//
// Units and frames as ExactModel's: the rolling frame (leading edge at +x;
// rolling_direction = -1 mirrors x), tractions in units of mu p_max with
// p_max the largest element pressure. Fields, totals and patches are
// reported in the caller's frame; Mz about the grid's origin.
#pragma once

#include <memory>
#include <vector>

#include "contact/contact_model.hpp"
#include "contact/fields.hpp"
#include "contact/friction_law.hpp"
#include "contact/params.hpp"
#include "exact/creepage_history.hpp"
#include "exact/exact_law.hpp"
#include "exact/exact_model.hpp"
#include "exact/steady_rolling.hpp"
#include "exact/tangential_solve.hpp"
#include "halfspace/grid_convolution.hpp"
#include "normal/gap_grid.hpp"
#include "normal/gap_normal.hpp"
#include "normal/patches.hpp"

namespace creepwork {

// Diagnostics of the last solve: the tangential solve's and the normal
// problem's (normal/gap_normal.hpp).
struct GapExactSolveInfo : TangentialInfo {
    int normal_iterations = 0;     // conjugate-gradient iterations of the normal problem
    int normal_products = 0;       // its FFT products (on its contact set's box or the grid)
    int semi_hertz_iterations = 0; // force evaluations of the semi-Hertzian method
    bool normal_reused = false;    // the last normal solution was kept (same gap and load)
};

class GapExactModel : public ContactModel {
public:
    // Throws Error(invalid_input) unless grid.kind is gap with finite origin
    // and positive spacing, Error(grid_out_of_range) outside 3 ...
    // kMaxExactCells cells per direction.
    explicit GapExactModel(const GridSpec& grid);
    ~GapExactModel() override;

    // Throws Error naming a bad input, or Error(not_converged).
    SolveTotals solve(const ContactInput& input, SolveMode mode) override;
    // The solve and its Jacobian (gap_exact_jacobian.cpp): derivatives of the
    // converged discrete system. Throws as solve(), and Error(invalid_input)
    // for normal_force = 0 (or an approach without contact) when mu > 0.
    SolveTotals solve_jacobian(const ContactInput& input, SolveMode mode,
                               Jacobian& jacobian) override;

    // The law of the slip speed and the rolling speed V [m/s] > 0 of the
    // next solves, as ExactModel's (exact/exact_law.hpp): the traction unit
    // is mu(0) p_max and input.mu is not read. Throws Error(invalid_input)
    // naming the input. The Jacobian takes the law.
    void set_law(const SlipSpeedLaw& law, double V) override;
    // Back to Coulomb's law with input.mu (the next solve is cold after a
    // law's).
    bool set_friction_memory(double distance, double s0) override
    {
        if (law_.set_memory(FrictionMemory{distance, s0})) has_previous_ = false;
        return true;
    }
    void clear_law() override
    {
        if (law_.clear()) has_previous_ = false;
    }
    // Under a law: the range of mu over the last solve's slipping elements
    // (mu(0) when none slips); false under Coulomb's law.
    bool friction_range(double& mu_min, double& mu_max) const override
    {
        return law_.friction_range(info_, mu_min, mu_max);
    }
    // Element-wise factors on mu (contact/friction_law.hpp, the caller's
    // layout, kept by the caller): the fine bound is each element's factor
    // times mu p (the coarse levels sample it); the Jacobian holds them.
    void set_friction_factors(const double* factor) override { factor_ = factor; }
    // The interface layer's elastic compliance layer_h / layer_G in every
    // level's operator (its yield, tau_c0, is refused by name).
    bool takes_interface_layer() const override { return true; }

    const GapExactSolveInfo& info() const { return info_; }
    // dN/d(approach) [N/m] at the last solve, its normal method's own
    // (GapNormal::force_by_approach; throws as that).
    double normal_force_by_approach() override { return normal_.force_by_approach(); }

    // The last successful solve (gap_exact_fields.cpp); the profile's
    // parabola spans the contact's lateral extent (centred on it),
    // positions are the grid's.
    SolvedContact solved() const override;
    // Per row j < ny: centre y [m] and width dy [m] (the wear's strips).
    bool copy_strips(double* y, double* width) const override;
    // The separate patches of the last solve (4-connected), caller's frame.
    const std::vector<PatchTotals>* patches() const override { return &patches_; }
    // The kernels of the semi-Hertzian start and the FFTs (every ISA gives
    // the same bits).
    void set_kernel_isa(KernelIsa isa) override;

private:
    // One grid of the hierarchy over the contact's box, with its geometry.
    struct Level : TangentialLevel {
        Level(int nx, int ny);
        double dx = 0, dy = 0; // [m]
        double x0 = 0, y0 = 0; // centre of element (0, 0), rolling frame [m]
    };
    struct Steps; // of the tangential solve
    void validate(const ContactInput& in) const;
    void set_normalised_creepages(const ContactInput& in);
    void predict_start(double nu); // level 0's warm start
    void remember(double nu);      // the solution, for the next warm start
    void set_totals(const ContactInput& in, SolveTotals& t); // and the patches'
    void add_work(SolveTotals& t);
    void set_rigid_slip(Level& L) const;
    // The tangential problem's box and levels from the pressure; coefficients:
    // the half-space's for this solve's nu.
    void set_box(const GridConvolution& coefficients);
    void scatter_box(); // level 0's solution onto the whole grid
    void sample_bound(Level& fine, Level& coarse) const; // fine is only read
    void interpolate(const Level& coarse, Level& fine) const;
    void march_start(Level& L, double nu, double G);
    void label_patches(SolveTotals& t);
    int caller_index(int i) const { return setup_.direction > 0 ? i : nx_ - 1 - i; }

    GridSpec grid_;
    int nx_, ny_;
    std::vector<std::unique_ptr<Level>> levels_; // [0]: the contact's box on the caller's grid
    int n_levels_ = 1;                            // those of the contact's box
    int box_i0_ = 0, box_j0_ = 0;                 // its first element (rolling frame)
    GapNormal normal_;                            // the normal problem (rolling frame)
    PatchLabels labels_;
    GapExactSolveInfo info_;
    bool has_previous_ = false;
    ExactLaw law_;
    const double* factor_ = nullptr; // element-wise friction factors, the caller's
    // The factors on the box's elements (rolling frame).
    ElementFriction box_friction() const
    {
        return ElementFriction{factor_, nx_, setup_.direction < 0, box_i0_, box_j0_};
    }

    // The last solve (rolling frame).
    struct Setup {
        int direction = 1;
        double p_ref = 0;          // largest element pressure [Pa]
        double traction_scale = 0; // mu p_ref [Pa]
        double slip_scale = 0;     // unit of the normalised slip [-]
        double xi = 0, eta = 0, phi = 0;        // rolling frame, physical
        double spin_offset = 0;
        double G = 0;
        double layer = 0; // the interface layer's compliance h / G3 [m/Pa]
        double y_mid = 0, half_width = 0;       // lateral centre and half extent of the contact [m]
        bool full = false, loaded = false;
    } setup_;
    // The tangential solution on the whole grid (rolling frame): traction,
    // slip, rigid slip and element states (zero outside the box).
    std::vector<SteadyRolling::Complex> traction_, slip_, rigid_;
    std::vector<signed char> state_;
    std::vector<signed char> in_contact_;
    std::vector<PatchTotals> patches_;
    std::vector<double> paper_, consistent_, profile_, row_d_, row_pool_;
    std::vector<double> x_column_, y_row_; // the grid's element centres [m]
    // The warm start: the last solutions as physical tractions (key: nu,
    // spin offset, rolling direction), and the last traction scale.
    CreepageHistory history_;
    double previous_traction_scale_ = 0;
    // solve_jacobian's: the rigid slip's derivative (box), the pressure's
    // by N [1/m^2] (whole grid, rolling frame) and the bound's (box).
    std::vector<SteadyRolling::Complex> tangent_w_;
    std::vector<double> dp_dN_, dg_;
};

} // namespace creepwork
