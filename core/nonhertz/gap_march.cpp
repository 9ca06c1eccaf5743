#include "nonhertz/gap_march.hpp"

#include <cmath>

namespace creepwork {
namespace {

// The march; Full: also the slip and the rigid slip of every element.
// A segment's sums, kept in registers along it (the output arrays could
// alias a patch's totals) and added to its patch's at its trailing edge.
struct SegmentSums {
    double Fx = 0, Fy = 0, Mz = 0, Fn = 0, p_max = 0;
    int n_contact = 0, n_slip = 0;

    void add_to(GapMarchTotals& t) const
    {
        t.Fx += Fx;
        t.Fy += Fy;
        t.Mz += Mz;
        t.Fn += Fn;
        t.p_max = p_max > t.p_max ? p_max : t.p_max;
        t.n_contact += n_contact;
        t.n_slip += n_slip;
    }
};

// The march; Full: also the slip and the rigid slip of every element.
template <bool Full>
void march(const GapMarchInput& in, const GapMarchOutput& out)
{
    using Complex = std::complex<double>;
    const int nx = in.nx;
    const double dx = in.dx, inv_dx = 1.0 / in.dx, area = in.dx * in.dy;
    for (int j = 0; j < in.ny; ++j) {
        const double y = in.y0 + j * in.dy;
        const size_t row = static_cast<size_t>(nx) * j;
        double px = 0.0, py = 0.0; // the traction of the element ahead (0 at a leading edge)
        // The segment's rigid slip over flexibility: omega_x constant along
        // the row, omega_y = oy0 + oyx x; set at each leading edge, with the
        // segment's patch (a segment lies in one patch).
        double ox = 0.0, oy0 = 0.0, oyx = 0.0, L1 = 0.0, L2 = 0.0;
        int patch = -1; // of the segment being marched, -1 between segments
        SegmentSums sums;
        for (int i = nx - 1; i >= -1; --i) {
            const size_t k = row + i;
            const double pz = i >= 0 ? in.pressure[k] : 0.0;
            if (!(pz > 0.0)) {
                if (patch >= 0) { // a trailing edge
                    sums.add_to(out.patch_totals[patch]);
                    sums = SegmentSums{};
                    patch = -1;
                }
                if (i < 0) break;
                out.p[k] = Complex(0.0, 0.0);
                if (Full) out.slip[k] = out.rigid[k] = Complex(0.0, 0.0);
                out.state[k] = 0;
                px = py = 0.0;
                continue;
            }
            if (patch < 0) {
                patch = in.patch[k];
                const GapMarchPatch& M = in.patches[patch];
                L1 = M.L1;
                L2 = M.L2;
                ox = (in.xi - in.phi * M.yc) / M.L1 - in.phi * (y - M.yc) / M.L3;
                oy0 = (in.eta + in.phi * M.xc) / M.L2 +
                      in.phi * (in.spin_offset * dx - M.xc) / M.L3;
                oyx = in.phi / M.L3;
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
            sums.Fx += qx * area;
            sums.Fy += qy * area;
            sums.Mz += (x * qy - y * qx) * area;
            sums.Fn += pz * area;
            sums.p_max = pz > sums.p_max ? pz : sums.p_max;
            ++sums.n_contact;
            sums.n_slip += slips;
            px = qx;
            py = qy;
        }
    }
}

} // namespace

void gap_march(const GapMarchInput& in, const GapMarchOutput& out)
{
    if (out.slip && out.rigid)
        march<true>(in, out);
    else
        march<false>(in, out);
}

} // namespace creepwork
