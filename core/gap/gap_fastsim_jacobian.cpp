// FASTSIM's Jacobian on a gap grid: the march of the solve again in forward
// mode (gap_march_tangent.hpp) with the solve's pressure, patches,
// flexibilities and spin centres, and the normal method's dp/dN
// (normal/gap_normal.hpp) in the N column: d/dN along the solution, whether
// the force or the approach is prescribed. Held fixed: the contact set, the
// patches and so their flexibilities and spin centres (they change only
// where an element enters or leaves contact). Under a law of the slip speed
// the march's tangent takes each slipping element's law (gap_march_tangent.hpp).

#include "contact/jacobian_load.hpp"
#include "gap/gap_fastsim_model.hpp"
#include "gap/gap_march_tangent.hpp"

namespace creepwork {

SolveTotals GapFastsimModel::solve_jacobian(const ContactInput& in, SolveMode mode, Jacobian& J)
{
    const SolveTotals t = solve(in, mode);
    ContactInput effective = in; // under a law, its static coefficient bounds the tractions
    if (has_law_) effective.mu = static_friction(law_);
    if (gap_jacobian_is_zero(effective, t.n_contact, J)) return t;
    Jacobian out;
    normal_.load_derivative(dp_dN_.data());

    // The march's input as solve() gives it (rolling frame).
    const double d = direction_;
    // With factors the bound's pressure and its derivative both carry them.
    GapMarchInput m = march_input(in);
    m.bound_pressure = factored(m.pressure, bound_p_);
    const double* dbound = factor_ ? factored(dp_dN_.data(), bound_dp_) : dp_dN_.data();
    double dF[3][4];
    gap_march_tangent(m, dbound, dF);

    // Caller's frame: Fx = d Fx', Mz = d Mz' (x = d x'), xi = d xi_x, phi = d phi.
    const double frame[3] = {d, 1.0, d}, dc[4] = {d, 1.0, d, 1.0};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) out.d[r][c] = frame[r] * dF[r][c] * dc[c];
    J = out;
    return t;
}

} // namespace creepwork
