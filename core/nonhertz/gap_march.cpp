#include "nonhertz/gap_march.hpp"

#include <cmath>

namespace creepwork {
namespace {

// The march; Full: also the slip and the rigid slip of every element.
template <bool Full>
GapMarchTotals march(const GapMarchInput& in, const GapMarchOutput& out)
{
    using Complex = std::complex<double>;
    const int nx = in.nx;
    const double dx = in.dx, inv_dx = 1.0 / in.dx, area = in.dx * in.dy;
    GapMarchTotals t;
    GapMarchTotals scratch;
    for (int j = 0; j < in.ny; ++j) {
        const double y = in.y0 + j * in.dy;
        const size_t row = static_cast<size_t>(nx) * j;
        double px = 0.0, py = 0.0; // the traction of the element ahead (0 at a leading edge)
        // The segment's rigid slip over flexibility: omega_x constant along
        // the row, omega_y = oy0 + oyx x; set at each leading edge, with the
        // segment's patch (a segment lies in one patch).
        double ox = 0.0, oy0 = 0.0, oyx = 0.0, L1 = 0.0, L2 = 0.0;
        GapMarchTotals* P = &scratch;
        bool in_segment = false;
        for (int i = nx - 1; i >= 0; --i) {
            const size_t k = row + i;
            const double pz = in.pressure[k];
            if (!(pz > 0.0)) {
                out.p[k] = Complex(0.0, 0.0);
                if (Full) out.slip[k] = out.rigid[k] = Complex(0.0, 0.0);
                out.state[k] = 0;
                px = py = 0.0;
                in_segment = false;
                continue;
            }
            if (!in_segment) {
                const int p = in.patch[k];
                const GapMarchPatch& M = in.patches[p];
                L1 = M.L1;
                L2 = M.L2;
                ox = (in.xi - in.phi * M.yc) / M.L1 - in.phi * (y - M.yc) / M.L3;
                oy0 = (in.eta + in.phi * M.xc) / M.L2 +
                      in.phi * (in.spin_offset * dx - M.xc) / M.L3;
                oyx = in.phi / M.L3;
                P = out.patch_totals ? out.patch_totals + p : &scratch;
                in_segment = true;
            }
            const double x = in.x0 + i * dx;
            const double oy = oy0 + oyx * x;
            double qx = px - dx * ox, qy = py - dx * oy;
            // |q| > bound compared squared: the root only in slip (the model
            // keeps dx |omega| far below overflow).
            const double bound = in.mu * pz, n2 = qx * qx + qy * qy;
            const bool slips = n2 > bound * bound;
            if (slips) {
                const double f = bound / std::sqrt(n2); // |q| > bound >= 0
                qx *= f;
                qy *= f;
            }
            out.p[k] = Complex(qx, qy);
            if (Full) {
                out.rigid[k] = Complex(L1 * ox, L2 * oy);
                out.slip[k] = slips ? Complex(L1 * (ox + (qx - px) * inv_dx),
                                              L2 * (oy + (qy - py) * inv_dx))
                                    : Complex(0.0, 0.0);
            }
            out.state[k] = slips ? 2 : 1;
            const double fx = qx * area, fy = qy * area, mz = (x * qy - y * qx) * area;
            P->Fx += fx;
            P->Fy += fy;
            P->Mz += mz;
            P->Fn += pz * area;
            P->p_max = pz > P->p_max ? pz : P->p_max;
            ++P->n_contact;
            P->n_slip += slips;
            t.Fx += fx;
            t.Fy += fy;
            t.Mz += mz;
            t.Fn += pz * area;
            t.p_max = pz > t.p_max ? pz : t.p_max;
            ++t.n_contact;
            t.n_slip += slips;
            px = qx;
            py = qy;
        }
    }
    return t;
}

} // namespace

GapMarchTotals gap_march(const GapMarchInput& in, const GapMarchOutput& out)
{
    return out.slip && out.rigid ? march<true>(in, out) : march<false>(in, out);
}

} // namespace creepwork
