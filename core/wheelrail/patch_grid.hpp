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

// Fills grid.h and grid.h_min. wheel_table: the wheel's bottom in wheel
// profile coordinates; wheel: the wheel profile's frame in track coordinates.
void undeformed_distance(const Frame& reference, const Profile& rail_in_track, double s_rail,
                         const ProfileTable& wheel_table, const Frame& wheel, double nominal_radius,
                         PatchGrid& grid);

// The wheel's n coordinate in the patch frame at (x, s), exactly (Newton
// along n, starting from the value n holds on entry); false if the line
// misses the wheel.
bool wheel_surface_n(const Frame& reference, const ProfileTable& wheel_table, const Frame& wheel,
                     double nominal_radius, double x, double s, double& n);

} // namespace creepwork::wheelrail
