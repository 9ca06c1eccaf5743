#include "nonhertz/gap_march.hpp"

#include <cmath>

namespace creepwork {

GapMarchTotals gap_march(const GapMarchInput& in, const GapMarchOutput& out)
{
    using Complex = std::complex<double>;
    const int nx = in.nx;
    const double dx = in.dx, area = in.dx * in.dy;
    GapMarchTotals t;
    for (int j = 0; j < in.ny; ++j) {
        const double y = in.y0 + j * in.dy;
        const size_t row = static_cast<size_t>(nx) * j;
        double px = 0.0, py = 0.0; // the traction of the element ahead (0 at a leading edge)
        // The segment's rigid slip over flexibility: omega_x constant along
        // the row, omega_y = oy0 + oyx x; set at each leading edge.
        double ox = 0.0, oy0 = 0.0, oyx = 0.0, L1 = 0.0, L2 = 0.0;
        bool in_segment = false;
        for (int i = nx - 1; i >= 0; --i) {
            const size_t k = row + i;
            const double pz = in.pressure[k];
            if (!(pz > 0.0)) {
                out.p[k] = out.slip[k] = out.rigid[k] = Complex(0.0, 0.0);
                out.state[k] = 0;
                px = py = 0.0;
                in_segment = false;
                continue;
            }
            if (!in_segment) {
                const GapMarchPatch& P = in.patches[in.patch[k]];
                L1 = P.L1;
                L2 = P.L2;
                ox = (in.xi - in.phi * P.yc) / P.L1 - in.phi * (y - P.yc) / P.L3;
                oy0 = (in.eta + in.phi * P.xc) / P.L2 +
                      in.phi * (in.spin_offset * dx - P.xc) / P.L3;
                oyx = in.phi / P.L3;
                in_segment = true;
            }
            const double x = in.x0 + i * dx;
            const double oy = oy0 + oyx * x;
            double qx = px - dx * ox, qy = py - dx * oy;
            // |q| > bound compared squared: the root only in slip (tractions
            // in Pa square far below overflow; the C ABI bounds the inputs).
            const double bound = in.mu * pz, n2 = qx * qx + qy * qy;
            const bool slips = n2 > bound * bound;
            if (slips) {
                const double f = bound / std::sqrt(n2); // |q| > bound >= 0
                qx *= f;
                qy *= f;
            }
            out.p[k] = Complex(qx, qy);
            out.rigid[k] = Complex(L1 * ox, L2 * oy);
            out.slip[k] = slips ? Complex(L1 * (ox + (qx - px) / dx), L2 * (oy + (qy - py) / dx))
                                : Complex(0.0, 0.0);
            out.state[k] = slips ? 2 : 1;
            t.Fx += qx * area;
            t.Fy += qy * area;
            t.Mz += (x * qy - y * qx) * area;
            ++t.n_contact;
            t.n_slip += slips;
            px = qx;
            py = qy;
        }
    }
    return t;
}

} // namespace creepwork
