// Where the rail and the wheel profiles are in track coordinates: the rail
// by the gauge (or absolutely), the wheel by the flange-back distance and
// the wheelset's position (CONTACT's m_wr_profiles). All frames are those of
// the right side; the left side is solved mirrored (sign -1 on y, roll, yaw).
#pragma once

#include "wheelrail/frame.hpp"
#include "wheelrail/profile.hpp"
#include "wheelrail/wheelrail_types.hpp"

namespace creepwork::wheelrail {

// The rail profile's frame in track coordinates (a roll and a shift). By
// the gauge: rotated by -cant, lifted to touch z = 0, and moved so that its
// gauge point -- the leftmost point of the gauge face within gauge_height of
// the top -- lies at y = gauge_width / 2.
Frame place_rail(const Profile& rail, const Track& track, Side side);

// The wheel profile's frame in wheelset coordinates: its origin at
// y = flange_back_distance / 2 - flange_back_position, z = nominal_radius.
Frame wheel_in_wheelset(const Wheelset& ws);

// The wheelset's frame in track coordinates: roll, then yaw, at
// (0, y, z - nominal_radius); pitch does not move a round wheel.
Frame wheelset_in_track(const WheelsetPosition& pos, const Wheelset& ws, Side side);

} // namespace creepwork::wheelrail
