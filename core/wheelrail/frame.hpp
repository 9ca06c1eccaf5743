// Rigid frames for the wheel/rail geometry: an origin and a rotation,
// mapping local coordinates into the parent frame (p_parent = o + R p_local).
// Rotations follow CONTACT's roll-yaw-pitch convention (Vollebregt, CONTACT
// user guide, "Wheelset degrees of freedom"): roll about x, then yaw about
// the new z, then pitch about the new y; R = Rx(roll) Rz(yaw) Ry(pitch).
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace creepwork::wheelrail {

// π, one definition for the geometry's angles (the sources share a
// translation unit in the unity build).
inline constexpr double kPi = 3.14159265358979323846;

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

inline Mat3 rotation_x(double a)
{
    const double c = std::cos(a), s = std::sin(a);
    Mat3 r;
    r << 1, 0, 0, 0, c, -s, 0, s, c;
    return r;
}

inline Mat3 rotation_y(double a)
{
    const double c = std::cos(a), s = std::sin(a);
    Mat3 r;
    r << c, 0, s, 0, 1, 0, -s, 0, c;
    return r;
}

inline Mat3 rotation_z(double a)
{
    const double c = std::cos(a), s = std::sin(a);
    Mat3 r;
    r << c, -s, 0, s, c, 0, 0, 0, 1;
    return r;
}

// A frame given in its parent: origin o and axes R (columns).
struct Frame {
    Vec3 o = Vec3::Zero();
    Mat3 r = Mat3::Identity();

    Vec3 to_parent(const Vec3& p) const { return o + r * p; }
    Vec3 to_local(const Vec3& p) const { return r.transpose() * (p - o); }
    // This frame's child `f` expressed in this frame's parent.
    Frame compose(const Frame& f) const { return {o + r * f.o, r * f.r}; }
    // Frame `f` (given in the same parent) expressed in this frame.
    Frame local_of(const Frame& f) const
    {
        return {r.transpose() * (f.o - o), r.transpose() * f.r};
    }
    // Roll angle of the axes, for a rotation about x only (contact frames).
    double roll() const { return std::atan2(r(2, 1), r(1, 1)); }
};

} // namespace creepwork::wheelrail
