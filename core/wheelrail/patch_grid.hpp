// One contact patch's frame and grid (CONTACT's set_cpatch_reference,
// set_planar_potcon and wr_ud_planar, planar contact approach).
//
// The contact reference point lies on the rail's top at the region's
// weighted lateral position and at its weighted x; the patch frame is the
// track frame rolled about x by the contact angle delta (the weighted rail
// inclination): axes x, s (lateral, in the tangent plane), n (normal, into
// the rail). The potential contact area covers the region with one element
// to spare on every side; element centres sit at whole multiples of dx, ds
// from the reference point. The undeformed distance of an element is the
// distance along n from the wheel's surface to the rail's surface through
// its centre: h = n_rail - n_wheel, > 0 where they are apart, < 0 where the
// rigid surfaces overlap at the given wheelset position.
//
// All in the right-side frame (the left side is mirrored).
#pragma once

#include <vector>

#include "wheelrail/contact_search.hpp"
#include "wheelrail/frame.hpp"
#include "wheelrail/profile.hpp"
#include "wheelrail/profile_table.hpp"
#include "wheelrail/wheelrail_types.hpp"

namespace creepwork::wheelrail {

struct PatchGrid {
    int nx = 0, ny = 0;       // elements along x and s
    int ix_lo = 0, iy_lo = 0; // element (i, j) has its centre at ((ix_lo + i) dx, (iy_lo + j) ds)
    double dx = 0.0, ds = 0.0; // [m], CONTACT's dx, ds doubled until nx ny < max_elements
    std::vector<double> h;    // [m] undeformed distance, element (i, j) at [i + j nx]
    double h_min = 0.0;       // least h [m]
};

// The reference frame of a region: origin on the rail's top, rolled by the
// contact angle. `s_rail` receives the rail profile's s there.
Frame contact_reference(const Region& region, const Profile& rail_in_track, double& s_rail);

// The potential contact grid (sizes and position; h not filled).
void potential_contact(const Region& region, const Profile& rail_in_track, double s_rail,
                       const Frame& reference, const SearchOptions& opt, PatchGrid& grid);

// The wheel's surface points found at the exact nodes of a grid's rows
// (wheel profile coordinates: points of the wheel's body), kept to start
// the wheel's Newton solves of the same grid at the next height.
struct WheelNodes {
    static constexpr int kPerRow = 5;  // exact wheel heights per row (fewer on narrow grids)
    int nx = 0, ny = 0, ix_lo = 0, iy_lo = 0; // the grid they belong to
    double dx = 0.0, ds = 0.0;
    Frame wheel;             // the wheel's frame they were found in
    std::vector<Vec3> p;     // row j, node k at [j kPerRow + k]
    std::vector<char> found; // per row: its nodes were found
};

// Fills grid.h and grid.h_min. wheel_table: the wheel's bottom in wheel
// profile coordinates; wheel: the wheel profile's frame in track coordinates.
// nodes (optional) receives the wheel's points at the rows' nodes; with
// warm, when it holds those of a grid of the same layout and the wheel has
// moved along track z only since (the same rotation, x and y), each node's
// Newton solve starts from the line's point nearest its old point and stops
// at a step below 1e-8 m, instead of from the last row's solution with a
// step below 1e-14 m. Newton converges quadratically: after a step d the
// error is about c d^2, c = g''/(2 g') of the wheel's equation along the
// line: 1/(2 R) on a flat tread, plus half the profile's curvature times
// sin^2 of the contact angle; for c < 40 /m (profile radii above 12 mm)
// the error left is below 4e-15 m.
void undeformed_distance(const Frame& reference, const Profile& rail_in_track, double s_rail,
                         const ProfileTable& wheel_table, const Frame& wheel, double nominal_radius,
                         PatchGrid& grid, WheelNodes* nodes = nullptr, bool warm = false);

// The wheel's n coordinate in the patch frame at (x, s), exactly (Newton
// along n, starting from the value n holds on entry); false if the line
// misses the wheel.
bool wheel_surface_n(const Frame& reference, const ProfileTable& wheel_table, const Frame& wheel,
                     double nominal_radius, double x, double s, double& n);

} // namespace creepwork::wheelrail
