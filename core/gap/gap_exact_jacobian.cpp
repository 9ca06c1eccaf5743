// The exact model's Jacobian on a gap grid: derivatives of the converged
// discrete system by the implicit function theorem, as ExactModel's
// (exact_jacobian.cpp), on the box the solve ran on, with its frame and
// normalisation (tractions per T = mu p_ref, rigid slip per T / G).
//
// Creepages: the rigid slip w = (xi - phi y, eta + phi (x + spin_offset dx))
// is linear in them; with the element states held as the solve found them,
// dq/dc solves (I - G'(q)) dq = G_w dw (SteadyRolling::tangent).
//
// N: the column is d/dN along the solution, whether the force or the
// approach is prescribed. The normal method gives dp/dN per element
// (normal/gap_normal.hpp: the exact normal problem linearised at its
// contact set, or the semi-Hertzian closed form). The normalisation T is
// held fixed (any constant scale describes the same discrete problem; p_ref,
// the largest pressure, moves with N but only rescales the unknowns), so the
// rigid slip stays and the bound changes by dg = (dp/dN) / p_ref: dq/dN
// solves (I - G'(q)) dq = G_g dg (SteadyRolling::tangent_bound). The
// contact set and the box are those of the solution: the derivative at a
// load where no element enters or leaves contact. Under a law of the slip
// speed the slip speed's unit V T / G stays with T, and the local
// derivative by the bound is the law's (SteadyRolling::tangent_bound).

#include "contact/jacobian_load.hpp"
#include "gap/gap_exact_model.hpp"

namespace creepwork {
SolveTotals GapExactModel::solve_jacobian(const ContactInput& in, SolveMode mode, Jacobian& J)
{
    const SolveTotals t = solve(in, mode);
    ContactInput effective = in; // under a law, its mu(0) scales the tractions
    effective.mu = law_.coefficient(in);
    if (gap_jacobian_is_zero(effective, setup_.loaded ? t.n_contact : 0, J)) return t;
    Jacobian out;

    Level& fine = *levels_[0];
    const Setup& s = setup_;
    const double tolerance = in.tolerance > 0.0 ? in.tolerance : kExactDefaultTolerance;
    const size_t nb = static_cast<size_t>(fine.nx) * fine.ny;
    normal_.load_derivative(dp_dN_.data());
    tangent_w_.resize(nb);
    dg_.resize(nb);
    for (int j = 0; j < fine.ny; ++j)
        for (int i = 0; i < fine.nx; ++i)
            dg_[i + static_cast<size_t>(fine.nx) * j] =
                dp_dN_[box_i0_ + i + static_cast<size_t>(nx_) * (box_j0_ + j)] / s.p_ref;
    scale_bounds(box_friction(), dg_.data(), fine.nx, fine.ny); // the factors held

    // d(rolling-frame sums of q: x, y, x qy - y qx [m])/d(s.xi, s.eta, s.phi, N)
    auto x = [&](int i) { return fine.x0 + i * fine.dx; };
    auto y = [&](int j) { return fine.y0 + j * fine.dy; };
    double dS[3][4] = {};
    for (int k = 0; k < 4; ++k) {
        if (k < 3) creepage_tangent(tangent_w_, fine.nx, fine.ny, k, x, y, s.spin_offset * fine.dx);
        const std::vector<SteadyRolling::Complex>& dq =
            k < 3 ? fine.tangential.tangent(fine.conv, tangent_w_, tolerance,
                                            kMaxJacobianIterations)
                  : fine.tangential.tangent_bound(fine.conv, dg_, tolerance,
                                                  kMaxJacobianIterations);
        const TractionMoments m = traction_moments(dq, fine.nx, fine.ny, x, y);
        dS[0][k] = m.x;
        dS[1][k] = m.y;
        dS[2][k] = m.z;
    }

    // s.xi = d xi_x / slip_scale, s.eta = xi_y / slip_scale, s.phi = d phi /
    // slip_scale; the caller's Fx = d T area S_x, Fy = T area S_y, Mz = d T
    // area S_mz (Mz about the grid's origin: x_caller = d x).
    const double d = s.direction, area = grid_.dx * grid_.dy, T = s.traction_scale;
    const double dc[4] = {d / s.slip_scale, 1.0 / s.slip_scale, d / s.slip_scale, 1.0};
    const double frame[3] = {d, 1.0, d};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) out.d[r][c] = frame[r] * T * area * dS[r][c] * dc[c];
    J = out;
    return t;
}

} // namespace creepwork
