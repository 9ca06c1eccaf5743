// Checks of the points of a wheel or rail profile before the spline is made.
// Every failure throws creepwork::Error naming the source and the input line.
//
//   order      rail points run with y increasing, wheel points with y
//              decreasing (orient_profile_points reverses a profile given the
//              other way round, as SIMPACK's "inversion" and CONTACT do);
//              a point where the curve turns back by more than 90 degrees is
//              out of order (or a stitching zig-zag) and is an error.
//   duplicates successive points closer than ProfileChecks::min_spacing.
//   kinks      a turn between successive segments above
//              ProfileChecks::kink_angle: an error unless kinks are accepted,
//              then a corner of the spline.
//   crossing   two segments of the curve that intersect (a loop).
//   size       at least 4 points; total length between 5 mm and 500 mm
//              (CONTACT's limits: anything else means a unit error, e.g. a
//              profile in mm read as metres).
//   direction  z downwards: a rail whose head is a valley in z, or a wheel
//              whose flange points upwards, is upside down; a wheel's flange
//              lies on the track-centre side (negative y).
#pragma once

#include <string>
#include <vector>

#include "wheelrail/profile.hpp"

namespace creepwork::wheelrail {

// Reverses the points when they run the other way round (rail: last y below
// first y; wheel: last y above first y).
void orient_profile_points(ProfileKind kind, std::vector<ProfilePoint>& points);

// Checks the points (in canonical form and order); returns the indices that
// break the spline into sections: 0, the accepted kinks, size - 1.
std::vector<int> check_profile_points(ProfileKind kind, const std::vector<ProfilePoint>& points,
                                      const std::string& source, const ProfileChecks& checks);

} // namespace creepwork::wheelrail
