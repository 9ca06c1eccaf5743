// The normal problem of a contact of any shape, once for every tangential
// model on a gap grid (the exact model and FASTSIM): one solve with the
// normal force or the approach prescribed, by the method the input names --
//  - NormalMethod::exact: Kalker's half-space problem (normal_problem.hpp,
//    solve_gap), started from the semi-Hertzian pressure, or, warm, from the
//    last solution (mirrored when the rolling direction changed), predicted
//    along the gap's drift once two solutions of the same problem are known
//    (pressure_drift.hpp);
//  - NormalMethod::semi_hertz: the semi-Hertzian method alone
//    (semi_hertz.hpp; the fast path);
// N = 0 gives no pressure and the approach where the surfaces just touch.
// A warm solve of the problem solved last (the same gap, load, method,
// material and rolling direction) keeps its solution, unless it asks for a
// tighter tolerance (ContactInput::normal_tolerance) than that was solved
// to: it is then solved again from it. The pressure's
// derivative by the load (for the Jacobians) follows the method of the last
// solve. Made once per grid; solves allocate nothing.
//
// The pressure is kept in the rolling frame [i + nx j] (the caller's rows
// reversed when rolling towards -x), where the tangential models work.
// Adding a method: its NormalMethod value, its class beside these, and here
// normal_method_known(), a member and a case in solve(), row_extent() and
// load_derivative() (CONTRIBUTING.md, "Adding a normal method").
#pragma once

#include <memory>
#include <vector>

#include "contact/params.hpp"
#include "halfspace/grid_convolution.hpp"
#include "normal/normal_problem.hpp"
#include "normal/pressure_drift.hpp"
#include "normal/semi_hertz.hpp"
#include "simd/kernel_isa.hpp"

namespace creepwork {

// The methods GapNormal solves by (validate_gap_input rejects the others).
inline bool normal_method_known(NormalMethod method)
{
    return method == NormalMethod::exact || method == NormalMethod::semi_hertz;
}

// How a tangential model uses the normal problem.
struct GapNormalOptions {
    // Warm solves may start from, or keep, the last solution (the exact
    // model's warm start); without it every solve starts afresh.
    bool warm = false;
    // The half-space problem's conjugate gradients run their products on the
    // contact set's box (NormalProblem::set_box_convolution), else on the
    // whole grid. The two differ in the last bits: each model keeps the one
    // its results were pinned with (the exact model: the box).
    bool box_products = false;
    // The half-space problem's memory (its FFTs' and conjugate gradients')
    // is made on the first solve by the exact method, or by
    // prepare_half_space(), instead of here: a model that solves by the
    // semi-Hertzian method alone is made in a fraction of the time (a
    // wheel/rail patch's grid changes with every trial height).
    bool half_space_on_first_use = false;
};

// What the last solve did.
struct GapNormalInfo {
    int normal_iterations = 0;     // conjugate-gradient iterations of the half-space problem
    int semi_hertz_iterations = 0; // force evaluations of the semi-Hertzian method
    int normal_products = 0;       // FFT products of the half-space problem
    bool reused = false;           // a warm solve kept the last solution
};

class GapNormal {
public:
    // grid: a checked gap grid (gap_grid.hpp). All workspace.
    GapNormal(const GridSpec& grid, GapNormalOptions options);
    ~GapNormal();

    // The normal problem of in (its gap, load, method and material, read
    // in the caller's layout); warm: a warm solve (options.warm only).
    // Throws Error(not_converged) when the half-space problem or the
    // semi-Hertzian method fails.
    const GapNormalInfo& solve(const ContactInput& in, bool warm);

    // Of the last solve: the pressure [Pa] per element, rolling frame; the
    // approach [m] from the gap's datum.
    const std::vector<double>& pressure() const { return pressure_; }
    double approach() const { return approach_; }
    // The elements lo .. hi of row j (rolling frame) outside which the
    // pressure is zero (hi < lo: the whole row is).
    void row_extent(int j, int& lo, int& hi) const
    {
        if (method_ == NormalMethod::semi_hertz) {
            semi_hertz_.row_extent(j, lo, hi);
        } else {
            lo = 0;
            hi = nx_ - 1;
        }
    }
    // The normal force [N]: the pressure summed row by row over its extents,
    // in four partial sums.
    double force() const;
    // dp/dN [1/m^2] per element (rolling frame) at the last solution, d/dN
    // along it whether the force or the approach was prescribed: of the
    // half-space problem linearised at its contact set, or the
    // semi-Hertzian method's closed form. Throws Error(not_converged) if the
    // half-space problem's linear solve fails.
    void load_derivative(double* dp_dN);
    // dN/d(approach) [N/m] at the last solution, the normal method's own:
    // the semi-Hertzian method's closed form, or the half-space problem
    // linearised at its contact set (one linear solve, as load_derivative);
    // 0 without contact. Throws Error(not_converged) if that solve fails.
    double force_by_approach();

    // The half-space coefficients of this grid's cells for nu (computed when
    // nu changes): the tangential problem copies them.
    const GridConvolution& half_space(double nu);
    // The convolution of the last solve's products on the contact set's box
    // (box_products), or nullptr: the tangential problem on that box may
    // copy its spectra (GridConvolution::copy_pair_spectra).
    const GridConvolution* box_convolution() const { return box_.get(); }
    // Makes the half-space problem's memory now (if not yet made), so that
    // no solve allocates.
    void prepare_half_space();
    // The kernels' ISA: the semi-Hertzian method's, the FFTs', the gap
    // check's (every ISA gives the same bits).
    void set_kernel_isa(KernelIsa isa);
    KernelIsa kernel_isa() const { return isa_; }

private:
    bool holds(const ContactInput& in) const; // the held solution is in's
    const double* rolling_gap(const ContactInput& in); // in's gap, rolling frame
    // start_ from pressure_, or predicted along the gap's drift (gap: in's,
    // rolling frame).
    void start_from_last(const ContactInput& in, const double* gap);
    // The half-space problem from start_ (warm: a warm start's); returns
    // the approach [m].
    double solve_half_space(const ContactInput& in, const double* gap, bool warm);
    void hold(const ContactInput& in);
    GridConvolution& conv()
    {
        if (!conv_) prepare_half_space();
        return *conv_;
    }
    NormalProblem& half_space_problem()
    {
        if (!half_space_) prepare_half_space();
        return *half_space_;
    }

    GapNormalOptions options_;
    int nx_, ny_;
    double dx_, dy_;
    KernelIsa isa_ = best_kernel_isa();
    SemiHertz semi_hertz_;
    // The half-space problem (made by prepare_half_space).
    std::unique_ptr<GridConvolution> conv_; // its products on the whole grid
    std::unique_ptr<GridConvolution> box_;  // its products on the contact set's box
    std::unique_ptr<NormalProblem> half_space_;
    // Per element, rolling frame [i + nx j].
    std::vector<double> gap_, gap_in_dx_, start_, pressure_;
    double approach_ = 0;
    double G_ = 0; // [Pa] of the last solve
    NormalMethod method_ = NormalMethod::exact; // of the last solve
    // pressure_ is zero outside the semi-Hertzian method's last extents (it
    // holds that method's pressure, or zeros), so it clears only those.
    bool zero_outside_extents_ = false;
    GapNormalInfo info_;
    // The problem held (options.warm): its gap (the caller's layout), load
    // and material, and whether its pressure has contact.
    struct Held {
        bool valid = false, loaded = false;
        NormalLoad load = NormalLoad::force;
        NormalMethod method = NormalMethod::exact;
        double value = 0, nu = 0, G = 0;
        int direction = 1;
        double tolerance = 0; // the half-space problem's, of the solution held
    } held_;
    std::vector<double> held_gap_;
    // The last exact solutions of the held problem (options.warm), and the
    // product A start_ predicted with start_ (when start_product_valid_).
    PressureDrift drift_;
    std::vector<double> start_product_;
    bool start_product_valid_ = false;
};

} // namespace creepwork
