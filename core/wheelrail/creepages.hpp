// Creepages at a contact reference point from the wheelset's motion
// (CONTACT's wr_creep_cref, planar contact approach), in the right-side
// frame. P is the reference point on the rail; Q, the point of the wheel at
// the approach pen above it along the patch normal. With velocities taken
// in the track frame (fixed to the ground, moving along the curve), the
// creepages are those of the rail relative to the wheel (CONTACT module 1:
// the rail is body 1):
//     cksi = (v_P - v_Q) . e_x / V,  ceta = (v_P - v_Q) . e_s / V,
//     cphi = (w_P - w_Q) . e_n / V,
// V = (|v_Qx - v_Px - v_pitch,x| + |v_pitch,x|) / 2 the mean of the forward
// and the rolling speed, v_pitch = (R_ws (0, vpitch, 0)) x (Q - O_ws). The
// wheelset's angular velocity is R_ws (vroll, vpitch, vyaw) (the rates of
// its Euler angles); a curved track turns the rail at -V_s k about z.
#pragma once

#include "wheelrail/frame.hpp"
#include "wheelrail/wheelrail_types.hpp"

namespace creepwork::wheelrail {

struct Creepages {
    double veloc = 0.0; // V [m/s]
    double cksi = 0.0, ceta = 0.0; // [-]
    double cphi = 0.0;  // [1/m]
    bool forward = true; // the patch moves along +x (CONTACT's chi = 0)
    double rolling_radius = 0.0; // depth of Q below the axle in wheelset coordinates [m]
    Vec3 q_wheelset = Vec3::Zero(); // Q in wheelset coordinates [m]
};

Creepages creepages_at(const Frame& reference, double approach, const Frame& wheelset,
                       const WheelsetVelocity& vel, const Track& track, Side side);

} // namespace creepwork::wheelrail
