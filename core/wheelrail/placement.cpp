#include "wheelrail/placement.hpp"

#include <cmath>

#include "contact/fp_safe.hpp"

namespace creepwork::wheelrail {
namespace {

// s of a local minimum of y (coord 0) or z (coord 1) near knot k: Newton on
// the derivative, kept inside the neighbouring segments.
double refine_min(const Profile& p, int k, int coord)
{
    const int n = p.size();
    const double lo = p.knots_s()[k > 0 ? k - 1 : 0], hi = p.knots_s()[k + 1 < n ? k + 1 : n - 1];
    double s = p.knots_s()[k];
    for (int it = 0; it < 50; ++it) {
        const Profile::Point q = p.at(s);
        const double d1 = coord == 0 ? q.dy : q.dz, d2 = coord == 0 ? q.d2y : q.d2z;
        if (!(d2 > 0.0)) break;
        const double next = std::min(hi, std::max(lo, s - quotient_if_positive(d1, d2)));
        if (std::abs(next - s) < 1e-15) return next;
        s = next;
    }
    return s;
}

// s in [s_a, s_b] where z(s) = z_target, found from the end s_b backwards
// (the gauge face below the top); bisection polished by Newton.
double solve_z_backwards(const Profile& p, int ka, int kb, double z_target)
{
    const auto& zs = p.knots_z();
    int k = kb;
    while (k > ka && (zs[k - 1] - z_target) * (zs[k] - z_target) > 0.0) --k;
    double lo = p.knots_s()[k > ka ? k - 1 : ka], hi = p.knots_s()[k];
    double flo = p.at(lo).z - z_target;
    for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
        const double mid = 0.5 * (lo + hi), f = p.at(mid).z - z_target;
        if ((f > 0.0) == (flo > 0.0)) {
            lo = mid;
            flo = f;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

} // namespace

Frame place_rail(const Profile& rail, const Track& track, Side side)
{
    const double sgn = side == Side::right ? 1.0 : -1.0;
    Frame f;
    f.r = rotation_x(-track.cant + sgn * track.rail_roll);
    if (track.gauge_height <= 0.0) {
        f.o = Vec3(0.0, sgn * (track.rail_y0 + track.rail_dy), track.rail_z0 + track.rail_dz);
        return f;
    }
    // CONTACT's find_gauge_meas_pt on the canted profile
    Frame cant;
    cant.r = rotation_x(-track.cant);
    const Profile c = rail.placed(cant);
    const auto& s = c.knots_s();
    const auto& y = c.knots_y();
    const auto& z = c.knots_z();
    int ktop = 0;
    for (int k = 1; k < c.size(); ++k)
        if (z[k] < z[ktop]) ktop = k;
    const double s_top = refine_min(c, ktop, 1);
    const double z_top = c.at(s_top).z;
    int k = 0, first = -1, left = 0;
    double y_gauge = 1e9;
    while (s[k] < s_top && k < c.size() - 1) {
        if (z[k] - z_top <= track.gauge_height) {
            if (first < 0) first = k;
            if (y[k] < y_gauge) {
                y_gauge = y[k];
                left = k;
            }
        }
        ++k;
    }
    const int last = k;
    if (left == 0) {
        y_gauge = y[0]; // no gauge face found: CONTACT falls back to the first point
    } else if (left == first) {
        y_gauge = c.at(solve_z_backwards(c, 0, last, z_top + track.gauge_height)).y;
    } else {
        y_gauge = c.at(refine_min(c, left, 0)).y; // the face bulges out above gauge height
    }
    f.o = Vec3(0.0, 0.5 * track.gauge_width - y_gauge + sgn * track.rail_dy, -z_top + track.rail_dz);
    return f;
}

Frame wheel_in_wheelset(const Wheelset& ws)
{
    Frame f;
    f.o = Vec3(0.0, 0.5 * ws.flange_back_distance - ws.flange_back_position, ws.nominal_radius);
    return f;
}

Frame wheelset_in_track(const WheelsetPosition& pos, const Wheelset& ws, Side side)
{
    const double sgn = side == Side::right ? 1.0 : -1.0;
    Frame f;
    f.r = rotation_x(sgn * pos.roll) * rotation_z(sgn * pos.yaw);
    f.o = Vec3(0.0, sgn * pos.y, pos.z - ws.nominal_radius);
    return f;
}

} // namespace creepwork::wheelrail
