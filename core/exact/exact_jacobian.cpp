// The Jacobian of the exact model: derivatives of the converged discrete
// system by the implicit function theorem (SteadyRolling::tangent), not by
// re-solving. The solution q solves q = G(q; w) with w the rigid slip, linear
// in the normalised creepages c = (c_xi, c_eta, c_phi); with the element
// states (adhesion, slip and the slip directions) held as the solve found
// them, dq/dc_k solves (I - G'(q)) dq = G_w dw_k: one GMRES solve per
// creepage with the Newton steps' operator and preconditioner.
//
// N: the normal problem's pressure is p0 times a shape that does not depend
// on N (a, b fixed), tractions scale with mu p0 and the rigid slip with
// mu p0 / G, so the forces are homogeneous of degree 1 in (N, xi_x, xi_y,
// phi) and dF/dN = (F - xi_x dF/dxi_x - xi_y dF/dxi_y - phi dF/dphi) / N
// (Euler), exactly for the discrete system. Under a law of the slip speed
// the law's argument kappa sigma (kappa = V mu(0) p0 / G, proportional to
// N) adds the derivative by ln kappa (SteadyRolling::tangent_speed) over N.
// A layer's yield stress tau_c does not grow with N: the bound it caps,
// tau_c / (mu p0), falls as 1/N, which adds -tau_c dF/dtau_c / N
// (SteadyRolling::tangent_bound on the capped elements; with hardening or
// softening tangent_yield, tau_c0 and its floor scaled along every row;
// k_tau dx / G does not depend on N). The layer's
// compliance is in the operator and does not depend on N.

#include "contact/jacobian_load.hpp"
#include "exact/exact_model.hpp"

namespace creepwork {
SolveTotals ExactModel::solve_jacobian(const ContactInput& in, SolveMode mode, Jacobian& J)
{
    const SolveTotals t = solve(in, mode);
    Jacobian out;
    if (law_.coefficient(in) == 0.0) { // no traction whatever the inputs
        J = out;
        return t;
    }
    if (in.normal_force == 0.0)
        throw zero_load_jacobian_error();

    Level& fine = *levels_[0];
    const Setup& s = setup_;
    const double tolerance = in.tolerance > 0.0 ? in.tolerance : kExactDefaultTolerance;
    // d(rolling-frame sums of q: x, y, x qy - y qx)/d(c_xi, c_eta, c_phi)
    double dS[3][3] = {};
    for (int k = 0; k < 3; ++k) {
        creepage_tangent(
            tangent_w_, nx_, ny_, k, [&](int i) { return fine.geom.X(i); },
            [&](int j) { return fine.geom.Y(j); }, s.spin_offset);
        const std::vector<SteadyRolling::Complex>& dq =
            fine.tangential.tangent(fine.conv, tangent_w_, tolerance, kMaxJacobianIterations);
        const TractionMoments m = traction_moments(
            dq, nx_, ny_, [&](int i) { return fine.geom.X(i) * s.dx; },
            [&](int j) { return fine.geom.Y(j) * s.dx; });
        dS[0][k] = m.x;
        dS[1][k] = m.y;
        dS[2][k] = m.z;
    }

    // c = rolling-frame creepage / slip_scale (phi per element length dx);
    // the caller's Fx = d T area S_x, Fy = T area S_y, Mz = d T area S_mz.
    const double d = s.direction, area = s.dx * s.dy, T = s.traction_scale;
    const double dc[3] = {d / s.slip_scale, 1.0 / s.slip_scale, d * s.dx / s.slip_scale};
    const double frame[3] = {d, 1.0, d};
    const double F[3] = {t.Fx, t.Fy, t.Mz};
    const double inputs[3] = {in.xi_x, in.xi_y, in.phi};
    // Under a law the slip speed per unit of normalised slip, kappa =
    // V mu(0) p0 / G, grows with N as well: dF/dN gains T area dS/dln kappa / N.
    double dS_speed[3] = {};
    if (law_.active()) {
        const TractionMoments m = traction_moments(
            fine.tangential.tangent_speed(fine.conv, tolerance, kMaxJacobianIterations), nx_, ny_,
            [&](int i) { return fine.geom.X(i) * s.dx; },
            [&](int j) { return fine.geom.Y(j) * s.dx; });
        dS_speed[0] = m.x;
        dS_speed[1] = m.y;
        dS_speed[2] = m.z;
    }
    // tau_c dS/dtau_c: the capped elements' bound scaled by 1 + epsilon.
    double dS_yield[3] = {};
    if (s.yield > 0.0) {
        const std::vector<double>& g = fine.tangential.bound();
        const std::vector<double>& pn = fine.normal.pressure();
        if (s.yield_k == 0.0)
            for (size_t k = 0; k < g.size(); ++k) tangent_yield_[k] = pn[k] > s.yield ? g[k] : 0.0;
        const TractionMoments m = traction_moments(
            s.yield_k != 0.0 ? fine.tangential.tangent_yield(fine.conv, tolerance,
                                                             kMaxJacobianIterations)
                             : fine.tangential.tangent_bound(fine.conv, tangent_yield_, tolerance,
                                                             kMaxJacobianIterations),
            nx_, ny_, [&](int i) { return fine.geom.X(i) * s.dx; },
            [&](int j) { return fine.geom.Y(j) * s.dx; });
        dS_yield[0] = m.x;
        dS_yield[1] = m.y;
        dS_yield[2] = m.z;
    }
    for (int r = 0; r < 3; ++r) {
        double euler = F[r];
        for (int c = 0; c < 3; ++c) {
            out.d[r][c] = frame[r] * T * area * dS[r][c] * dc[c];
            euler -= inputs[c] * out.d[r][c];
        }
        if (law_.active()) euler += frame[r] * T * area * dS_speed[r];
        if (s.yield > 0.0) euler -= frame[r] * T * area * dS_yield[r];
        out.d[r][3] = euler / in.normal_force;
    }
    J = out;
    return t;
}

} // namespace creepwork
