// Kalker's exact half-space theory of steady rolling on CONTACT's uniform
// grid, as one model of the contact (doc/theory/exact-discretisation.md
// lists the discretisation; CONTACT's method a).
// Made once per grid -- it owns every workspace, FFT plan and coefficient
// table -- then solve() many times without allocating.
//
// One solve: the half-space coefficients of the grid (halfspace/influence.hpp,
// halfspace/grid_convolution.hpp; recomputed only when a/b or nu change), the normal
// problem with the force prescribed (normal_problem.hpp; its normalised
// pressure depends only on the grid and a/b, so it is kept and reused), then
// the tangential problem (steady_rolling.hpp) and, in full mode, the work
// maps (exact_work.hpp). The tangential problem (tangential_solve.hpp) starts from
//  - the last solution on this model (tractions in units of mu p0) when
//    warm_start is set and the last exact solve succeeded, else
//  - a hierarchy of coarser grids over the same box (about half the
//    elements per direction each, down to ~10), each solved from the one
//    below it, the coarsest from Kalker's simplified theory.
// A warm start that does not converge is retried cold. Every solve ends
// with a result whose residual is within the tolerance, or with
// Error(not_converged).
//
// Units and frames: the model works in the rolling frame (leading edge at
// +x; rolling_direction = -1 mirrors x) in the normalised units of
// steady_rolling.hpp; fields are exported in the caller's layout and units.
#pragma once

#include <memory>
#include <vector>

#include "contact/contact_model.hpp"
#include "contact/fields.hpp"
#include "contact/jacobian.hpp"
#include "contact/params.hpp"
#include "exact/creepage_history.hpp"
#include "exact/exact_law.hpp"
#include "exact/tangential_solve.hpp"
#include "exact/steady_rolling.hpp"
#include "halfspace/exact_geometry.hpp"
#include "halfspace/grid_convolution.hpp"
#include "normal/normal_problem.hpp"

namespace creepwork {

// Defaults of ContactInput::tolerance and max_iterations for this model.
constexpr double kExactDefaultTolerance = 1e-8;
constexpr int kExactDefaultMaxIterations = 50;
constexpr double kExactDefaultSpinOffset = 1.0 / 6.0; // CONTACT's facphi

// Diagnostics of the last solve: the tangential solve's (with the law's),
// and the normal problem's conjugate-gradient iterations.
struct ExactSolveInfo : TangentialInfo {
    int normal_iterations = 0;
};

class ExactModel : public ContactModel {
public:
    // Throws Error(invalid_input) unless grid.kind is uniform, and
    // Error(grid_out_of_range) beyond kMaxExactCells.
    explicit ExactModel(const GridSpec& grid);
    ~ExactModel() override;

    // Throws Error naming a bad input, or Error(not_converged).
    SolveTotals solve(const ContactInput& input, SolveMode mode) override;
    // solve(), then rows Fx, Fy, Mz of the Jacobian (exact_jacobian.cpp).
    SolveTotals solve_jacobian(const ContactInput& input, SolveMode mode,
                               Jacobian& jacobian) override;

    // The law of the slip speed and the rolling speed V [m/s] > 0 of the
    // next solves (exact_law.hpp): mu(s) at each element's own slip speed
    // s = |micro-slip| V; input.mu is then not read (the traction unit is
    // mu(0) p0). Throws Error(invalid_input) naming the input (the law's
    // parameters, V). The Jacobian takes the law (exact_jacobian.cpp).
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
    // Element-wise factors on the coefficient (contact/friction_law.hpp),
    // applied to the finest level's bound; the coarse levels that give the
    // cold start's first guess take the law alone.
    void set_friction_factors(const double* factor) override { factor_ = factor; }
    // Under a law: the range of mu over the last solve's slipping elements
    // (mu(0) when none slips); false under Coulomb's law.
    bool friction_range(double& mu_min, double& mu_max) const override
    {
        return law_.friction_range(info_, mu_min, mu_max);
    }

    // The interface layer (ContactInput::layer_h, layer_G, tau_c0, k_tau):
    // the elastic compliance in every solve's operator; the yield stress a
    // cap on every element's bound (k_tau = 0), or hardening / softening
    // with the plastic flow carried along each row (SteadyRolling::set_yield),
    // under Coulomb's law only.
    bool takes_interface_layer() const override { return true; }

    const ExactSolveInfo& info() const { return info_; }
    int nx() const { return nx_; }
    int ny() const { return ny_; }

    // The last successful solve, per element (exact_fields.cpp).
    SolvedContact solved() const override;
    // The FFTs' kernel (every ISA gives the same bits).
    void set_kernel_isa(KernelIsa isa) override;

private:
    // One grid of the hierarchy with its geometry and normal problem.
    struct Level : TangentialLevel {
        Level(int nx, int ny);
        ExactGeometry geom;
        NormalProblem normal;
        // The normal solution held: for which a/b and nu, and whether it was
        // computed from scratch (a cold solve reuses only such a one, so that
        // results never depend on what was solved before).
        bool normal_valid = false, normal_cold = false;
        double normal_ratio = 0, normal_nu = 0;
    };
    struct Steps; // of the tangential solve
    void validate(const ContactInput& in) const;
    void set_up(const ContactInput& in, SolveMode mode); // setup_, the levels' geometry
    void set_normalised_creepages(double G);
    SolveTotals totals(const ContactInput& in, const SteadyRollingInfo& ti) const;
    void add_work(SolveTotals& t);
    void solve_normal(Level& level, double ratio, bool warm, const char* which);
    void interpolate(const Level& coarse, Level& fine) const;
    void fastsim_start(Level& level, double ratio, double nu, double G, double a, double b) const;
    void set_rigid_slip(Level& level) const;
    // Level's bound: the normalised pressure, capped by the yield stress.
    void set_bound(TangentialLevel& level, const std::vector<double>& pressure) const;
    void set_layer(const ContactInput& in);
    void predict_start(double ratio, double nu);
    void remember(double ratio, double nu);

    int nx_, ny_;
    double box_scale_;
    std::vector<std::unique_ptr<Level>> levels_; // [0] is the caller's grid
    ExactSolveInfo info_;
    bool has_previous_ = false;
    ExactLaw law_;
    const double* factor_ = nullptr; // element-wise friction factors, the caller's

    // The last solve (rolling frame), for the exports.
    struct Setup {
        int direction = 1;
        double a = 0, b = 0, dx = 0, dy = 0;
        double p0 = 0, traction_scale = 0, slip_scale = 0;
        double xi = 0, eta = 0, phi = 0;          // rolling frame, physical
        double c_xi = 0, c_eta = 0, c_phi = 0;     // normalised (per dx for phi)
        double spin_offset = 0;
        // The layer: compliance (h / G3) G / dx on the finest grid, the
        // yield stress over the traction unit (0: no yield) and its
        // hardening k_tau dx / G on the finest grid (0: perfectly plastic).
        double layer = 0, yield = 0, yield_k = 0;
        bool full = false;
    } setup_;
    std::vector<double> paper_, consistent_, profile_, row_d_, row_pool_;
    std::vector<double> x_column_, y_row_; // element centres of the caller's grid [m]
    std::vector<SteadyRolling::Complex> tangent_w_; // solve_jacobian's rigid-slip derivative
    std::vector<double> tangent_yield_;              // and the yield-capped bound's
    // The last solutions and their creepages, for the warm start's
    // prediction (key: a/b, nu, spin offset).
    CreepageHistory history_;
};

} // namespace creepwork
