#include "wheelrail/patch_grid.hpp"

#include <algorithm>
#include <cmath>

#include "contact/fp_safe.hpp"
#include "simd/simd.hpp"

namespace creepwork::wheelrail {
namespace {

constexpr double kApart = 1.0; // [m] h where a surface is missing: far apart
constexpr int kNodes = WheelNodes::kPerRow; // exact wheel heights per row, quartic in between
constexpr double kColdStep = 1e-14; // [m] Newton's last step from a far start
constexpr double kWarmStep = 1e-8;  // [m] ... from the last height's point (below)

// The wheel surface point on the line p(t) = b + a_x x + a_s s + a_n t in
// wheel profile coordinates: (p_z + R)^2 + p_x^2 = (R + z(p_y))^2, the root
// near t (Newton; the far root lies a wheel diameter away), done at a step
// below last_step.
bool solve_wheel(const ProfileTable& tab, double R, const Vec3& q, const Vec3& an, double& t,
                 double last_step = kColdStep)
{
    for (int it = 0; it < 30; ++it) {
        const Vec3 p = q + t * an;
        double z = 0.0, dz = 0.0;
        if (!tab.at(p(1), z, dz)) return false;
        const double pz = p(2) + R, r = R + z;
        const double g = pz * pz + p(0) * p(0) - r * r;
        const double dg = 2.0 * (pz * an(2) + p(0) * an(0) - r * dz * an(1));
        if (dg == 0.0) return false;
        const double step = quotient_or_zero(g, dg);
        t -= step;
        if (std::abs(step) < last_step) return std::isfinite(t);
    }
    return false;
}

// The least of lowest and row[0..n): two elements per vector, two vectors
// at a time (min is exact: the same value as a scalar loop, which
// compilers do not vectorize for doubles).
double row_lowest(const double* row, int n, double lowest)
{
    using V = simd::Vec<2>;
    V m0 = simd::broadcast<2>(lowest), m1 = m0;
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const V a = simd::load<2>(row + i), b = simd::load<2>(row + i + 2);
        m0 = a < m0 ? a : m0;
        m1 = b < m1 ? b : m1;
    }
    double best = simd::min_lane(m0 < m1 ? m0 : m1);
    for (; i < n; ++i) best = std::min(best, row[i]);
    return best;
}

// The rail's n coordinate at lateral coordinate s of the patch frame: the
// point of the rail curve with (P - o) . e_s = s (Newton in the profile's s
// from the guess sigma).
bool rail_n(const Profile& rail, const Frame& ref, double s, double& sigma, double& n)
{
    const Vec3 es = ref.r.col(1), en = ref.r.col(2);
    int seg = -1;
    for (int it = 0; it < 50; ++it) {
        const Profile::Point p = rail.at(sigma, &seg);
        const double f = es(1) * (p.y - ref.o(1)) + es(2) * (p.z - ref.o(2)) - s;
        const double df = es(1) * p.dy + es(2) * p.dz;
        if (df <= 1e-6) return false; // the rail turns away from the tangent plane
        const double next = std::clamp(sigma - quotient_if_positive(f, df), rail.s_first(), rail.s_last());
        const bool done = std::abs(next - sigma) < 1e-14;
        sigma = next;
        if (done) {
            const Profile::Point q = rail.at(sigma, &seg);
            if (std::abs(es(1) * (q.y - ref.o(1)) + es(2) * (q.z - ref.o(2)) - s) > 1e-12) return false;
            n = en(1) * (q.y - ref.o(1)) + en(2) * (q.z - ref.o(2));
            return true;
        }
    }
    return false;
}

} // namespace

Frame contact_reference(const Region& region, const Profile& rail, double& s_rail)
{
    if (!rail.visible_s_at_y(region.wgt_y, s_rail))
        s_rail = region.wgt_y < rail.y_min() ? rail.s_first() : rail.s_last();
    const Profile::Point p = rail.at(s_rail);
    // contact angles of exactly +-90 deg move 1 mrad away (CONTACT)
    double delta = region.wgt_angle;
    if (delta > 0.0 && std::abs(delta - 0.5 * kPi) < 1e-3)
        delta = 0.5 * kPi + 1e-3 * (delta - 0.5 * kPi >= 0.0 ? 1.0 : -1.0);
    else if (delta < 0.0 && std::abs(delta + 0.5 * kPi) < 1e-3)
        delta = -0.5 * kPi + 1e-3 * (delta + 0.5 * kPi >= 0.0 ? 1.0 : -1.0);
    Frame f;
    f.o = Vec3(region.wgt_x, p.y, p.z);
    f.r = rotation_x(delta);
    return f;
}

void potential_contact(const Region& region, const Profile& rail, double s_rail, const Frame& ref,
                       const SearchOptions& opt, PatchGrid& g)
{
    double s_lo = 0.0, s_hi = 0.0;
    if (!rail.visible_s_at_y(region.y_lo, s_lo)) s_lo = region.y_lo < rail.y_min() ? rail.s_first() : rail.s_last();
    if (!rail.visible_s_at_y(region.y_hi, s_hi)) s_hi = region.y_hi < rail.y_min() ? rail.s_first() : rail.s_last();
    double sp_lo = s_lo - s_rail, sp_hi = s_hi - s_rail;
    double xp_lo = region.x_lo - ref.o(0), xp_hi = region.x_hi - ref.o(0);
    if (xp_lo > xp_hi) std::swap(xp_lo, xp_hi);
    if (sp_lo > sp_hi) std::swap(sp_lo, sp_hi);
    g.dx = opt.dx;
    g.ds = opt.ds;
    auto size = [&](double lo, double hi, double step, int& first) {
        first = static_cast<int>(std::floor(lo / step)) - 1;
        return static_cast<int>(std::ceil(hi / step)) + 1 - first + 1;
    };
    g.nx = size(xp_lo, xp_hi, g.dx, g.ix_lo);
    g.ny = size(sp_lo, sp_hi, g.ds, g.iy_lo);
    while (static_cast<long>(g.nx) * g.ny >= opt.max_elements && (g.nx > 10 || g.ny > 10)) {
        if (g.nx > 10) {
            g.dx *= 2.0;
            g.nx = size(xp_lo, xp_hi, g.dx, g.ix_lo);
        }
        if (g.ny > 10) {
            g.ds *= 2.0;
            g.ny = size(sp_lo, sp_hi, g.ds, g.iy_lo);
        }
    }
    g.h.resize(static_cast<size_t>(g.nx) * g.ny); // every element written by undeformed_distance
}

bool wheel_surface_n(const Frame& ref, const ProfileTable& tab, const Frame& wheel, double R, double x,
                     double s, double& n)
{
    const Mat3 a = wheel.r.transpose() * ref.r;
    const Vec3 b = wheel.r.transpose() * (ref.o - wheel.o);
    const Vec3 q = b + a.col(0) * x + a.col(1) * s;
    return solve_wheel(tab, R, q, a.col(2), n);
}

void undeformed_distance(const Frame& ref, const Profile& rail, double s_rail, const ProfileTable& tab,
                         const Frame& wheel, double R, PatchGrid& g, WheelNodes* kept, bool warm)
{
    const Mat3 a = wheel.r.transpose() * ref.r;
    const Vec3 b = wheel.r.transpose() * (ref.o - wheel.o);
    const Vec3 an = a.col(2);
    // Row by row: the wheel exactly at the Chebyshev-Lobatto points of the
    // row's x range, the quartic through them at the element centres: the
    // surface is smooth along x, up to the jumps of the profile's third
    // derivative at its knots (test: within 7 nm inside the benchmark's
    // deepest flange contact)
    const double x_first = g.ix_lo * g.dx, x_last = (g.ix_lo + g.nx - 1) * g.dx;
    const double xc = 0.5 * (x_first + x_last), xh = 0.5 * (x_last - x_first);
    const bool exact_rows = g.nx <= kNodes;
    const int nodes = exact_rows ? g.nx : kNodes;
    double xn[kNodes] = {}, vinv[kNodes][kNodes] = {};
    if (exact_rows) {
        for (int k = 0; k < nodes; ++k) xn[k] = (g.ix_lo + k) * g.dx;
    } else {
        // monomial coefficients in u = (x - xc) / xh from the node values:
        // the inverse of the Vandermonde matrix of the nodes u_k
        double un[kNodes];
        for (int k = 0; k < nodes; ++k) {
            un[k] = -std::cos(kPi * k / (nodes - 1));
            xn[k] = xc + xh * un[k];
        }
        for (int k = 0; k < nodes; ++k) { // coefficients of the Lagrange polynomial of node k
            double c[kNodes] = {1.0};
            int deg = 0;
            double den = 1.0;
            for (int m = 0; m < nodes; ++m) {
                if (m == k) continue;
                for (int d = deg + 1; d > 0; --d) c[d] = c[d - 1] - un[m] * c[d];
                c[0] = -un[m] * c[0];
                ++deg;
                den *= un[k] - un[m];
            }
            for (int d = 0; d < nodes; ++d) vinv[d][k] = c[d] / den;
        }
    }
    double sigma = s_rail, tn[kNodes];
    bool have_guess = false;
    double h_min = kApart; // a local: row's stores cannot alias it
    // the last height's points: the same grid, the wheel moved along z only
    warm = warm && kept && kept->nx == g.nx && kept->ny == g.ny && kept->ix_lo == g.ix_lo &&
           kept->iy_lo == g.iy_lo && kept->dx == g.dx && kept->ds == g.ds && kept->wheel.r == wheel.r &&
           kept->wheel.o(0) == wheel.o(0) && kept->wheel.o(1) == wheel.o(1);
    if (kept) kept->wheel = wheel;
    if (kept && !warm) {
        kept->nx = g.nx;
        kept->ny = g.ny;
        kept->ix_lo = g.ix_lo;
        kept->iy_lo = g.iy_lo;
        kept->dx = g.dx;
        kept->ds = g.ds;
        kept->p.assign(static_cast<size_t>(g.ny) * kNodes, Vec3::Zero());
        kept->found.assign(static_cast<size_t>(g.ny), 0);
    }
    for (int j = 0; j < g.ny; ++j) {
        const double s = (g.iy_lo + j) * g.ds;
        double* row = &g.h[static_cast<size_t>(j) * g.nx];
        double nr = 0.0;
        double sig = j == 0 ? s_rail + s : sigma;
        if (!rail_n(rail, ref, s, sig, nr)) {
            std::fill(row, row + g.nx, kApart);
            if (kept) kept->found[static_cast<size_t>(j)] = 0;
            continue;
        }
        sigma = sig + g.ds;
        bool ok = true;
        const bool from_kept = warm && kept->found[static_cast<size_t>(j)];
        Vec3* old = kept ? &kept->p[static_cast<size_t>(j) * kNodes] : nullptr;
        for (int k = 0; k < nodes && ok; ++k) {
            const Vec3 q = b + a.col(0) * xn[k] + a.col(1) * s;
            if (from_kept)
                tn[k] = an.dot(old[k] - q);
            else if (!have_guess)
                tn[k] = nr;
            ok = solve_wheel(tab, R, q, an, tn[k], from_kept ? kWarmStep : kColdStep);
            if (ok && kept) old[k] = q + tn[k] * an;
        }
        if (kept) kept->found[static_cast<size_t>(j)] = ok;
        if (!ok) {
            std::fill(row, row + g.nx, kApart);
            have_guess = false;
            continue;
        }
        have_guess = true;
        if (exact_rows) {
            for (int i = 0; i < g.nx; ++i) row[i] = nr - tn[i];
        } else {
            double c[kNodes] = {};
            for (int d = 0; d < nodes; ++d)
                for (int k = 0; k < nodes; ++k) c[d] += vinv[d][k] * tn[k];
            const double du = g.dx / xh, c0 = c[0], c1 = c[1], c2 = c[2], c3 = c[3], c4 = c[4];
            for (int i = 0; i < g.nx; ++i) {
                const double u = -1.0 + i * du;
                row[i] = nr - (c0 + u * (c1 + u * (c2 + u * (c3 + u * c4))));
            }
        }
        // apart from the loop above, which vectorizes without the minimum
        h_min = row_lowest(row, g.nx, h_min);
    }
    g.h_min = h_min;
}

} // namespace creepwork::wheelrail
