// Frictional work bookkeeping of one solve (per unit rolling distance, J/m,
// positive for dissipation):
//  - the paper's local work as eq. 36 prints it (element force x translational
//    micro-slip + element moment about its own position x spin) and K (eq. 39);
//  - the energy-consistent distribution, which sums to W_macro exactly.
//
// The energy-consistent map. Along a strip the march satisfies exactly
//   -sum_k h_k p_k.w_k dy = sum_k D_k + sum_k 1/2 dp_k L dp_k dy + 1/2 p_e L p_e dy
// where D_k = -p_k.(u_k - u*_k) dy >= 0 is the friction dissipation of
// element k (zero in adhesion), dp_k = p_k - p_(k-1) the traction jump of a
// step (numerical dissipation) and p_e the traction carried out of the
// trailing edge (stored elastic energy). The last two are energy released in
// slip zones the grid cannot resolve, so each strip's losses go to its slip
// elements in proportion to D_k; a strip without slip hands them to the
// nearest strip(s) with slip. Finally everything is scaled by
//   balance = W_macro / (sum of all the above),
// which is 1 on the uniform grid without spin or with L1 = L2 = L3, and
// otherwise absorbs the simplified theory's own energy defect with three
// flexibilities (scaled spin in the rigid slip) and the strip grid's offset
// between slip points and element centres. The result is non-negative, zero
// in adhesion, sums to W_macro to rounding, and converges to the model's
// dissipation density times a grid-independent factor.
//
// Computation (march_with_work, then distribute_work once W_macro is known):
// block by block of kStripBlock strips, the march, then a work pass over the
// block's (q', f) while they are in cache (micro-slip, paper's work, D_k and
// the strip losses; it carries nothing from element to element but p', so
// unlike the march it is not a chain of dependent steps); then one pass
// scales D_k into the map. Sums run strip by strip along the march, then
// over the strips in order, so they do not depend on the kernel's vector
// width. Totals are therefore summed in another order than element by
// element: they differ from such a sum by rounding only.
#pragma once

#include <Eigen/Core>

#include "contact/contact_grid.hpp"
#include "march/march.hpp"
#include "march/march_geometry.hpp"
#include "march/march_setup.hpp"

namespace creepwork {

struct WorkState {
    // Per element, the kernels' layout [m * stride + j] (MarchGeometry),
    // rolling frame; per strip, j < stride.
    Eigen::ArrayXd slip_x, slip_y;  // model micro-slip s = W/V [-], zero in adhesion
    Eigen::ArrayXd paper;           // paper's local work [J/m]
    Eigen::ArrayXd consistent;      // energy-consistent local work [J/m] (D_k until distributed)
    // Per strip.
    Eigen::ArrayXd strip_dissipation, strip_loss, strip_pool, strip_paper, strip_work;
    Eigen::ArrayXd profile;         // consistent work per unit width [J/m / m]
    // Per strip, constants of one solve (scratch).
    Eigen::ArrayXd width, rigid_slip_x, rigid_slip_y, paper_spin_x, neg_area_T, ratio;

    void resize(int n_elements, int ny);
};

struct WorkTotals {
    double W_micro_paper = 0;
    double W_consistent = 0;
    double balance = 1;
    int flags = 0;
    double profile_max_diff = 0, profile_rms_diff = 0;
};

// The march of every strip (as march(), the same results) with the traction
// bound (per element, the kernels' layout) and the rigid slip already in
// march, and the work of every element. Allocates nothing.
void march_with_work(const MarchGeometry& geometry, const double* bound, const ContactGrid& grid,
                     const ModelSetup& setup, MarchState& march, WorkState& work, KernelIsa isa);
// The same work for a march already done by a model's own kernel (march
// holds every element's q' and f and the exit tractions): the work depends
// on (q', f) alone, not on the law that found f. Allocates nothing.
void work_of_march(const MarchGeometry& geometry, const double* bound, const ContactGrid& grid,
                   const ModelSetup& setup, MarchState& march, WorkState& work, KernelIsa isa);

// The paper's total and the energy-consistent map, given W_macro of the
// march just done by march_with_work.
WorkTotals distribute_work(const MarchGeometry& geometry, const ContactGrid& grid,
                           const ModelSetup& setup, double W_macro, WorkState& work,
                           KernelIsa isa);

} // namespace creepwork
