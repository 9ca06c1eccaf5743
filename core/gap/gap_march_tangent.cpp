#include "gap/gap_march_tangent.hpp"

#include <cmath>
#include <cstddef>

namespace creepwork {

void gap_march_tangent(const GapMarchInput& in, const double* dpressure, double dF[3][4])
{
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) dF[r][c] = 0.0;
    const int nx = in.nx;
    const double dx = in.dx, area = in.dx * in.dy;
    for (int j = 0; j < in.ny; ++j) {
        const double y = in.y0 + j * in.dy;
        const std::size_t row = static_cast<size_t>(nx) * j;
        // The element ahead's traction and its derivatives (0 at a leading edge).
        double px = 0.0, py = 0.0, dpx[4] = {}, dpy[4] = {};
        double ox = 0.0, oy0 = 0.0, oyx = 0.0;
        // d(omega)/d(xi, eta, phi): omega_x's, and omega_y's = b0 + b1 x.
        double dox[3] = {}, doy0[3] = {}, doy1[3] = {};
        bool in_segment = false;
        for (int i = nx - 1; i >= 0; --i) {
            const std::size_t k = row + i;
            const double pz = in.pressure[k];
            if (!(pz > 0.0)) {
                in_segment = false;
                px = py = 0.0;
                for (int c = 0; c < 4; ++c) dpx[c] = dpy[c] = 0.0;
                continue;
            }
            if (!in_segment) { // a leading edge: the segment's patch (as gap_march)
                in_segment = true;
                const GapMarchPatch& M = in.patches[in.patch[k]];
                ox = (in.xi - in.phi * M.yc) / M.L1 - in.phi * (y - M.yc) / M.L3;
                oy0 = (in.eta + in.phi * M.xc) / M.L2 +
                      in.phi * (in.spin_offset * dx - M.xc) / M.L3;
                oyx = in.phi / M.L3;
                dox[0] = 1.0 / M.L1, doy0[0] = 0.0, doy1[0] = 0.0;
                dox[1] = 0.0, doy0[1] = 1.0 / M.L2, doy1[1] = 0.0;
                dox[2] = -M.yc / M.L1 - (y - M.yc) / M.L3;
                doy0[2] = M.xc / M.L2 + (in.spin_offset * dx - M.xc) / M.L3;
                doy1[2] = 1.0 / M.L3;
            }
            const double x = in.x0 + i * dx;
            double qx = px - dx * ox, qy = py - dx * (oy0 + oyx * x);
            double dqx[4], dqy[4];
            for (int c = 0; c < 3; ++c) {
                dqx[c] = dpx[c] - dx * dox[c];
                dqy[c] = dpy[c] - dx * (doy0[c] + doy1[c] * x);
            }
            dqx[3] = dpx[3];
            dqy[3] = dpy[3];
            const double tx = qx, ty = qy;
            const ScalarProjection s = project_traction(qx, qy, traction_bound(in.law, pz));
            if (s.slips) { // as gap_march decides it
                const double ex = tx / s.norm, ey = ty / s.norm;
                const double dbound = dpressure ? traction_bound(in.law, dpressure[k]) : 0.0;
                for (int c = 0; c < 4; ++c) projection_derivative(s, ex, ey, dqx[c], dqy[c]);
                dqx[3] += ex * dbound;
                dqy[3] += ey * dbound;
            }
            for (int c = 0; c < 4; ++c) {
                dF[0][c] += dqx[c] * area;
                dF[1][c] += dqy[c] * area;
                dF[2][c] += (x * dqy[c] - y * dqx[c]) * area;
                dpx[c] = dqx[c];
                dpy[c] = dqy[c];
            }
            px = qx;
            py = qy;
        }
    }
}

} // namespace creepwork
