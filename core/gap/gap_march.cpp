#include "gap/gap_march.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace creepwork {
namespace {

// A segment's sums, kept in registers along it (the output arrays could
// alias a patch's totals) and added to its patch's at its trailing edge.
// Per element only what varies along the row: sum qx, sum qy, sum x qy,
// sum pz; the row's y, the element area and the count come in at the
// trailing edge (Mz = area (sum x qy - y sum qx)).
struct SegmentSums {
    double qx = 0, qy = 0, xqy = 0, pz = 0, p_max = 0;
    int first = 0, n_slip = 0; // the segment's first element (its leading edge)

    void add_to(GapMarchTotals& t, double y, double area, int last) const
    {
        t.Fx += qx * area;
        t.Fy += qy * area;
        t.Mz += (xqy - y * qx) * area;
        t.Fn += pz * area;
        t.p_max = p_max > t.p_max ? p_max : t.p_max;
        t.n_contact += first - last + 1;
        t.n_slip += n_slip;
    }
};

// One row being marched: the traction of the element ahead (0 at a leading
// edge), and the segment's rigid slip over flexibility (omega_x constant
// along the row, omega_y = oy0 + oyx x; set at each leading edge, with the
// segment's patch: a segment lies in one patch).
struct RowMarch {
    size_t row = 0;
    double y = 0;
    double px = 0, py = 0, ox = 0, oy0 = 0, oyx = 0, L1 = 0, L2 = 0;
    int patch = -1; // of the segment being marched, -1 between segments
    SegmentSums sums;
    double mu_prev = 0; // under a law: the segment's last slipping element's mu
    GapLawRange range;  // under a law: the row's

    void start(const GapMarchInput& in, int j)
    {
        row = static_cast<size_t>(in.nx) * j;
        y = in.y0 + j * in.dy;
        px = py = 0.0;
        patch = -1;
    }
};

// The march's input and output held by value, with the constants of every
// step: the outputs could alias the input for all the compiler knows, and a
// copy it can see whole is not reloaded after every store.
struct MarchFrame {
    GapMarchInput in;
    GapMarchOutput out;
    double inv_dx, area;

    MarchFrame(const GapMarchInput& i, const GapMarchOutput& o)
        : in(i), out(o), inv_dx(1.0 / i.dx), area(i.dx * i.dy)
    {
    }
};

// Element i of row r (i = -1: past the trailing end, closing a segment).
// Law: under in.speed_law (gap_law_element), else Coulomb's projection.
template <bool Full, bool Law>
inline void step(const MarchFrame& frame, RowMarch& r, int i)
{
    using Complex = std::complex<double>;
    const GapMarchInput& in = frame.in;
    const GapMarchOutput& out = frame.out;
    const double dx = in.dx, inv_dx = frame.inv_dx, area = frame.area;
    const size_t k = r.row + i;
    const double pz = i >= 0 ? in.pressure[k] : 0.0;
    if (!(pz > 0.0)) {
        if (r.patch >= 0) { // a trailing edge: element i + 1 was the last
            r.sums.add_to(out.patch_totals[r.patch], r.y, area, i + 1);
            r.sums = SegmentSums{};
            r.patch = -1;
        }
        if (i < 0) return;
        out.p[k] = Complex(0.0, 0.0);
        if (Full) out.slip[k] = out.rigid[k] = Complex(0.0, 0.0);
        out.state[k] = 0;
        r.px = r.py = 0.0;
        return;
    }
    if (r.patch < 0) {
        r.patch = in.patch[k];
        r.sums.first = i;
        const GapMarchPatch& M = in.patches[r.patch];
        r.L1 = M.L1;
        r.L2 = M.L2;
        r.ox = (in.xi - in.phi * M.yc) / M.L1 - in.phi * (r.y - M.yc) / M.L3;
        r.oy0 = (in.eta + in.phi * M.xc) / M.L2 + in.phi * (in.spin_offset * dx - M.xc) / M.L3;
        r.oyx = in.phi / M.L3;
        if constexpr (Law) r.mu_prev = static_friction(*in.speed_law);
    }
    const double x = in.x0 + i * dx;
    const double ox = r.ox, oy = r.oy0 + r.oyx * x;
    double qx = r.px - dx * ox, qy = r.py - dx * oy;
    bool slips;
    if constexpr (Law) {
        const GapLawElement e = gap_law_element(in, bound_pressure(in, k, pz), qx, qy, r.L1, r.L2,
                                                r.mu_prev);
        slips = e.slips;
        if (slips) {
            qx *= e.f;
            qy *= e.f;
            r.mu_prev = e.r.mu;
            r.range.mu_min = std::min(r.range.mu_min, e.r.mu);
            r.range.mu_max = std::max(r.range.mu_max, e.r.mu);
            r.range.iterations += e.r.iterations;
        }
    } else {
        slips = project_traction(qx, qy, traction_bound(in.law, bound_pressure(in, k, pz))).slips;
    }
    out.p[k] = Complex(qx, qy);
    if (Full) {
        out.rigid[k] = Complex(r.L1 * ox, r.L2 * oy);
        out.slip[k] = slips ? Complex(r.L1 * (ox + (qx - r.px) * inv_dx),
                                      r.L2 * (oy + (qy - r.py) * inv_dx))
                            : Complex(0.0, 0.0);
    }
    out.state[k] = slips ? 2 : 1;
    SegmentSums& s = r.sums;
    s.qx += qx;
    s.qy += qy;
    s.xqy += x * qy;
    s.pz += pz;
    s.p_max = pz > s.p_max ? pz : s.p_max;
    s.n_slip += slips;
    r.px = qx;
    r.py = qy;
}

// Zeros in the outputs of row j's elements i0 .. i1.
template <bool Full>
void zero_elements(const MarchFrame& frame, int j, int i0, int i1)
{
    if (i1 < i0) return;
    const size_t k0 = static_cast<size_t>(frame.in.nx) * j + i0, n = i1 - i0 + 1;
    const GapMarchOutput& out = frame.out;
    std::fill_n(out.p + k0, n, std::complex<double>(0.0, 0.0));
    if (Full) {
        std::fill_n(out.slip + k0, n, std::complex<double>(0.0, 0.0));
        std::fill_n(out.rigid + k0, n, std::complex<double>(0.0, 0.0));
    }
    std::fill_n(out.state + k0, n, static_cast<signed char>(0));
}

// A row's law range into the march's (under a law).
inline void merge_range(const MarchFrame& frame, const RowMarch& r)
{
    GapLawRange* out = frame.out.law_range;
    if (!out) return;
    out->mu_min = std::min(out->mu_min, r.range.mu_min);
    out->mu_max = std::max(out->mu_max, r.range.mu_max);
    out->iterations += r.range.iterations;
}

// The march; Full: also the slip and the rigid slip of every element. Four
// rows at a time, element by element: each element's traction depends on the
// one ahead (in slip through a root and a division), independent rows keep
// the processor busy while one waits. With the rows' contact extents given,
// the steps go over the four rows' common extent (and the element behind
// it, which closes the segments), the rest is filled with zeros.
template <bool Full, bool Law>
void march(const GapMarchInput& input, const GapMarchOutput& output)
{
    const MarchFrame f(input, output);
    const GapMarchInput& in = f.in;
    const int nx = in.nx;
    constexpr int kRows = 4;
    for (int j = 0; j < in.ny; j += kRows) {
        const int rows = std::min(kRows, in.ny - j);
        int first = 0, last = nx - 1; // the steps: last .. first - 1
        if (in.row_first) {
            first = nx, last = -1;
            for (int r = 0; r < rows; ++r) {
                first = std::min(first, in.row_first[j + r]);
                last = std::max(last, in.row_last[j + r]);
            }
            if (last < first) first = nx; // no contact: zeros only
            for (int r = 0; r < rows; ++r) {
                zero_elements<Full>(f, j + r, 0, first - 2);
                zero_elements<Full>(f, j + r, std::max(last + 1, first - 1), nx - 1);
            }
            if (last < 0) continue;
        }
        if (rows == kRows) {
            RowMarch a, b, c, e;
            a.start(in, j);
            b.start(in, j + 1);
            c.start(in, j + 2);
            e.start(in, j + 3);
            for (int i = last; i >= first - 1; --i) {
                step<Full, Law>(f, a, i);
                step<Full, Law>(f, b, i);
                step<Full, Law>(f, c, i);
                step<Full, Law>(f, e, i);
            }
            if (Law)
                for (const RowMarch* r : {&a, &b, &c, &e}) merge_range(f, *r);
        } else
            for (int r = 0; r < rows; ++r) {
                RowMarch a;
                a.start(in, j + r);
                for (int i = last; i >= first - 1; --i) step<Full, Law>(f, a, i);
                if (Law) merge_range(f, a);
            }
    }
}

} // namespace

void gap_march(const GapMarchInput& in, const GapMarchOutput& out)
{
    if (out.law_range) *out.law_range = GapLawRange{};
    const bool full = out.slip && out.rigid;
    if (in.speed_law)
        full ? march<true, true>(in, out) : march<false, true>(in, out);
    else
        full ? march<true, false>(in, out) : march<false, false>(in, out);
}

} // namespace creepwork
