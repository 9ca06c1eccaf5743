// The Jacobian of a solve's totals: J[r][c] = d(total r)/d(input c), rows
// Fx, Fy, Mz, W_macro and columns xi_x, xi_y, phi, N, in the caller's frame
// and units (N, N m, J/m per unit creepage, per 1/m of spin, per N). The
// same 4 x 4 row-major layout goes through the C ABI: J[r][c] at [4 r + c].
// Every model differentiates Fx, Fy, Mz; the W_macro row follows from them
// for all (jacobian_work_row).
#pragma once

namespace creepwork {

enum JacobianRow { jac_Fx = 0, jac_Fy = 1, jac_Mz = 2, jac_W = 3 };
enum JacobianColumn { jac_xi_x = 0, jac_xi_y = 1, jac_phi = 2, jac_N = 3 };

struct Jacobian {
    double d[4][4] = {};
};

// W_macro = -(Fx xi_x + Fy xi_y + Mz phi) (paper eq. 34), so
// dW/dc = -(Fx dxi_x/dc + Fy dxi_y/dc + Mz dphi/dc + xi_x dFx/dc + ...).
inline void jacobian_work_row(Jacobian& J, double Fx, double Fy, double Mz, double xi_x,
                              double xi_y, double phi)
{
    const double own[4] = {Fx, Fy, Mz, 0.0};
    for (int c = 0; c < 4; ++c)
        J.d[jac_W][c] = -(own[c] + xi_x * J.d[jac_Fx][c] + xi_y * J.d[jac_Fy][c] +
                          phi * J.d[jac_Mz][c]);
}

} // namespace creepwork
