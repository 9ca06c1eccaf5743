#include "wheelrail/creepages.hpp"

#include <cmath>

#include "contact/fp_safe.hpp"

namespace creepwork::wheelrail {

Creepages creepages_at(const Frame& ref, double approach, const Frame& ws, const WheelsetVelocity& v,
                       const Track& track, Side side)
{
    const double sgn = side == Side::right ? 1.0 : -1.0;
    Creepages c;
    // the rail: at rest, or turning about the track origin in a curve
    const double yaw_rate_rail = -sgn * v.vs * track.curvature;
    const Vec3 p = ref.o;
    const Vec3 v_p(-yaw_rate_rail * p(1), yaw_rate_rail * p(0), 0.0);
    const Vec3 w_p(0.0, 0.0, yaw_rate_rail);
    // the wheel at Q
    const Vec3 q = ref.o + approach * ref.r.col(2);
    const Vec3 arm = q - ws.o; // = R_ws q_ws
    c.q_wheelset = ws.r.transpose() * arm;
    c.rolling_radius = c.q_wheelset(2);
    const Vec3 w_q = ws.r * Vec3(sgn * v.vroll, v.vpitch, sgn * v.vyaw);
    const Vec3 v_q = Vec3(v.vs, sgn * v.vy, v.vz) + w_q.cross(arm);
    const Vec3 v_pitch = (ws.r * Vec3(0.0, v.vpitch, 0.0)).cross(arm);
    const double vs_est = v_q(0) - v_p(0) - v_pitch(0);
    c.veloc = 0.5 * (std::abs(vs_est) + std::abs(v_pitch(0)));
    c.forward = (std::abs(vs_est) >= std::abs(v_pitch(0)) && vs_est >= 0.0) ||
                (std::abs(v_pitch(0)) > std::abs(vs_est) && v_pitch(0) <= 0.0);
    if (c.veloc < 1e-9) return c; // at rest: no creepage
    const Vec3 dv = ref.r.transpose() * (v_p - v_q);
    const Vec3 dw = ref.r.transpose() * (w_p - w_q);
    c.cksi = quotient_if_positive(dv(0), c.veloc);
    c.ceta = quotient_if_positive(dv(1), c.veloc);
    c.cphi = quotient_if_positive(dw(2), c.veloc);
    return c;
}

} // namespace creepwork::wheelrail
