#include "gap/gap_march_tangent.hpp"

#include <cmath>
#include <cstddef>

namespace creepwork {
namespace {

// dq -> dp of a slipping element under a law (gap_march_tangent.hpp), the
// four columns; dpz: the pressure's derivative by N (the fourth).
void law_derivative(const SlipSpeedLaw& law, const GapLawElement& e, double pz, double dpz, double qx, double qy,
                    double L1, double L2, double dqx[4], double dqy[4])
{
    const double P = e.P, t = e.r.t, c = e.c, f = e.f;
    const double dmu = friction_value(law, e.r.s).dmu_ds, denom = 1.0 + pz * c * dmu;
    const double inv = denom != 0.0 ? 1.0 / denom : 0.0;
    const double lx = L1 * qx, ly = L2 * qy;
    for (int k = 0; k < 4; ++k) {
        const double dP = (qx * dqx[k] + qy * dqy[k]) / P;
        const double dLq = (L1 * lx * dqx[k] + L2 * ly * dqy[k]) / e.Lq;
        const double dc = c * (dLq / e.Lq - dP / P);
        double dt = pz * dmu * (c * dP + (P - t) * dc);
        if (k == 3) dt += e.r.mu * dpz;
        dt *= inv;
        const double df = (dt - f * dP) / P;
        dqx[k] = df * qx + f * dqx[k];
        dqy[k] = df * qy + f * dqy[k];
    }
}

} // namespace

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
        double mu_prev = 0.0; // under a law: as gap_march's
        double L1 = 0.0, L2 = 0.0;
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
                L1 = M.L1;
                L2 = M.L2;
                if (in.speed_law) mu_prev = static_friction(*in.speed_law);
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
            if (in.speed_law) {
                const double pb = bound_pressure(in, k, pz);
                const GapLawElement e = gap_law_element(in, pb, qx, qy, L1, L2, mu_prev);
                if (e.slips) { // as gap_march decides it
                    law_derivative(*in.speed_law, e, pb, dpressure ? dpressure[k] : 0.0, qx, qy, L1,
                                   L2, dqx, dqy);
                    qx *= e.f;
                    qy *= e.f;
                    mu_prev = e.r.mu;
                }
            } else {
                const double tx = qx, ty = qy;
                const ScalarProjection s =
                    project_traction(qx, qy, traction_bound(in.law, bound_pressure(in, k, pz)));
                if (s.slips) { // as gap_march decides it
                    const double ex = tx / s.norm, ey = ty / s.norm;
                    const double dbound = dpressure ? traction_bound(in.law, dpressure[k]) : 0.0;
                    for (int c = 0; c < 4; ++c) projection_derivative(s, ex, ey, dqx[c], dqy[c]);
                    dqx[3] += ex * dbound;
                    dqy[3] += ey * dbound;
                }
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
