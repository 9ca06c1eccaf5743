// Kalker's simplified theory (FASTSIM) on a contact of any shape: model =
// fastsim on a gap grid. Made once per grid, then solve() many times without
// allocating.
//
// One solve:
//  1. the normal problem on the gap, with the normal force or the approach
//     prescribed, by the method normal_method names (normal/gap_normal.hpp):
//     the semi-Hertzian method (the fast path, its cost measured in
//     doc/validation/non-hertzian.md), or the exact half-space problem (as
//     the exact model's, so that FASTSIM's tangential part can be judged on
//     the exact pressure). normal_method's default is exact, as for the
//     exact model: the same input describes the same contact whichever model
//     solves it. Each solve starts afresh (no warm start);
//  2. the separate patches (4-connected, normal/patches.hpp), and per
//     patch Kalker's flexibilities L1, L2, L3 of its "patch ellipse": a =
//     half the patch's largest row length along x, b = its area / (pi a),
//     from G and nu (kalker_flexibilities). Measured against the exact model
//     on 26 shapes (bench/fastsim_flexibility_study.cpp) this rule
//     beats flexibilities per row (each segment's own half length) and one
//     ellipse for the whole contact: a patch deforms as one elastic body, so
//     its flexibility follows its own size, and two patches far apart do not
//     share one;
//  3. the march of every contact segment of every row from its own leading
//     edge (gap/gap_march.hpp), traction bound mu pz, with the rigid
//     slip split per patch into the patch's creepage (over L1, L2) and a
//     spin about the patch's centroid (over L3): Kalker's L3 is the
//     flexibility of a rotation about the ellipse's centre, and the spin
//     about the grid's origin would scale the translation phi (-yc, xc) it
//     gives a patch away from the origin by L3 instead of L1, L2 (measured
//     by the study: several times the error);
//  4. totals and per-patch totals in the caller's frame (Mz about the
//     grid's origin, as the exact model's), and in full mode the work maps
//     (exact/exact_work.hpp, the same energy-consistent distribution as
//     FASTSIM's: sums to W_macro, >= 0, zero in adhesion).
// Under a law of the slip speed (set_law) each slipping element's bound is
// mu(s) pz at its own slip speed (gap/gap_march.hpp), in the march, the work
// maps and the Jacobian; the global slip speed and friction memory are the
// ellipse's FASTSIM's (refused by name here). Element-wise friction factors
// (set_friction_factors: mu(T)) scale each element's bound, under Coulomb's
// law and under a law; the fields report the pressure itself.
// The calibrated model is not available on a gap grid.
//
// Units and frames: the march runs in the rolling frame (leading edge at
// +x; rolling_direction = -1 mirrors x); fields, totals and patches are
// reported in the caller's frame and layout [i + nx j]. spin_offset: as
// FASTSIM's (default 0, no offset).
#pragma once

#include <complex>
#include <memory>
#include <vector>

#include "contact/contact_model.hpp"
#include "contact/fields.hpp"
#include "contact/params.hpp"
#include "gap/gap_march.hpp"
#include "normal/gap_grid.hpp"
#include "normal/gap_normal.hpp"
#include "normal/patches.hpp"

namespace creepwork {

class GapFastsimModel : public ContactModel {
public:
    // Throws as GapExactModel's constructor (the same grid checks).
    explicit GapFastsimModel(const GridSpec& grid);

    // Throws Error naming a bad input, or Error(not_converged) from the
    // exact normal problem.
    SolveTotals solve(const ContactInput& input, SolveMode mode) override;
    // The solve and its Jacobian (gap_fastsim_jacobian.cpp): forward-mode
    // derivatives of the march, the normal method's dp/dN in the N column.
    // Throws as solve(), and Error(invalid_input) for normal_force = 0 (or
    // an approach without contact) when mu > 0.
    SolveTotals solve_jacobian(const ContactInput& input, SolveMode mode,
                               Jacobian& jacobian) override;

    // The law of the slip speed and the rolling speed V [m/s] > 0 of the next
    // solves (input.mu, its mu_kin, is then not read; the law's static
    // coefficient bounds the tractions). Throws Error(invalid_input) naming
    // the law's parameter or V.
    void set_law(const SlipSpeedLaw& law, double V) override;
    void clear_law() override { has_law_ = false; }
    // Element-wise factors on mu (contact/friction_law.hpp, the caller's
    // layout, kept by the caller; null: none): each element's bound is its
    // factor times mu pz, in the march and its Jacobian (the factors held).
    void set_friction_factors(const double* factor) override { factor_ = factor; }
    // Under a law: the range of mu over the last solve's slipping elements
    // (the static coefficient when none slips); false under Coulomb's law.
    bool friction_range(double& mu_min, double& mu_max) const override;
    // Under a law: local_slip's steps in the last solve (0 under Coulomb's).
    long friction_iterations() const { return law_range_.iterations; }

    // The last successful solve (gap_fastsim_fields.cpp), as the exact gap
    // model's.
    SolvedContact solved() const override;
    const std::vector<PatchTotals>* patches() const override { return &patches_; }
    // Per row j < ny: centre y [m] and width dy [m] (the wear's strips).
    bool copy_strips(double* y, double* width) const override
    {
        copy_gap_rows(grid_, y, width);
        return true;
    }
    // The kernels' ISA (every ISA gives the same bits).
    void set_kernel_isa(KernelIsa isa) override { normal_.set_kernel_isa(isa); }
    // The flexibilities and spin centres (rolling frame) of the last solve's
    // patches, in the order of patches().
    const std::vector<GapMarchPatch>& march_patches() const { return march_patches_; }
    // dN/d(approach) [N/m] at the last solve, its normal method's own
    // (GapNormal::force_by_approach; throws as that).
    double normal_force_by_approach() override { return normal_.force_by_approach(); }
    // The exact normal problem's memory is made on its first solve by the
    // exact method, or by this (Solver::prepare), so that no solve allocates.
    void prepare() override { normal_.prepare_half_space(); }

private:
    void validate(const ContactInput& in) const;
    double label_contact(); // the contact's patches; returns the largest pressure
    void check_rigid_slip(const ContactInput& in) const;
    void set_totals(const ContactInput& in, SolveTotals& t); // and the patches'
    void add_work(SolveTotals& t);
    void set_patches(const ContactInput& in);
    // The march's input for the last solve's pressure and patches (rolling frame).
    GapMarchInput march_input(const ContactInput& in) const;
    int caller_index(int i) const { return direction_ > 0 ? i : nx_ - 1 - i; }
    // values times the factors (rolling frame) into out; returns out's
    // data, or null without factors.
    const double* factored(const double* values, std::vector<double>& out) const;

    GridSpec grid_;
    int nx_, ny_;
    GapNormal normal_; // the normal problem (rolling frame)
    PatchLabels labels_;

    // The last solve: rolling direction, spin offset, mode, extent.
    int direction_ = 1;
    bool full_ = false;
    double y_mid_ = 0, half_width_ = 0, extent_x_ = 0, extent_y_ = 0;
    // Per element, rolling frame [i + nx j].
    std::vector<double> paper_, consistent_;
    std::vector<double> x_column_, y_row_; // the grid's element centres [m]
    std::vector<std::complex<double>> p_, slip_, rigid_;
    std::vector<signed char> state_;
    std::vector<int> patch_of_; // on the contact's elements alone
    // Per patch (reserved for the most patches a grid can hold).
    std::vector<GapMarchPatch> march_patches_;
    std::vector<GapMarchTotals> march_totals_;
    std::vector<double> longest_, elements_; // longest row [m], element count
    std::vector<PatchTotals> patches_;
    std::vector<double> profile_, row_d_, row_pool_; // per row
    std::vector<int> row_first_, row_last_; // per row: the contact's extent, rolling frame
    std::vector<double> dp_dN_; // solve_jacobian's dpz/dN [1/m^2], rolling frame
    const double* factor_ = nullptr; // element-wise friction factors, the caller's
    std::vector<double> bound_p_, bound_dp_; // the factored pressure and dpz/dN, rolling frame
    // A law of the slip speed (has_law_), the rolling speed, the last range.
    SlipSpeedLaw law_;
    double V_ = 0;
    bool has_law_ = false;
    GapLawRange law_range_;
};

} // namespace creepwork
