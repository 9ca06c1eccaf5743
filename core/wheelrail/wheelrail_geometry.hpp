// The geometry of one wheel on one rail: made once for a pair of profiles, a
// track, a wheelset and a side; evaluated for any wheelset position and
// velocity. It finds the contact patches and gives, per patch, the contact
// reference point and angle, the undeformed distance on a grid in the
// patch's tangent plane, the creepages and the rolling radius -- CONTACT's
// module 1 up to the contact solution (doc/wheelrail.md).
//
// Outputs follow CONTACT's module-1 conventions in SI units: track
// coordinates x forward, y to the right, z down; the patch frame is the
// track frame rolled about x by the contact angle delta (axes x, s, n: n
// into the rail); profile coordinates as the profiles are given (on the left
// side y_r points to the track centre); creepages are those of the rail
// relative to the wheel (CONTACT's CKSI, CETA, CPHI). doc/wheelrail.md maps
// them onto creepwork's convention (forces on the wheel, body 1).
#pragma once

#include <vector>

#include "wheelrail/contact_search.hpp"
#include "wheelrail/creepages.hpp"
#include "wheelrail/patch_grid.hpp"
#include "wheelrail/profile.hpp"
#include "wheelrail/profile_table.hpp"
#include "wheelrail/wheelrail_types.hpp"

namespace creepwork::wheelrail {

struct ContactPatch {
    // the contact reference point (on the rail's surface) and angle
    double x_tr = 0, y_tr = 0, z_tr = 0; // track coordinates [m]
    double delta = 0;                    // rotation about x from track z to n [rad]
    double y_r = 0, z_r = 0, s_r = 0;    // rail profile coordinates, arc length [m]
    double x_w = 0, y_w = 0, z_w = 0, s_w = 0; // wheel profile coordinates [m]
    double x_ws = 0, y_ws = 0, z_ws = 0; // wheelset coordinates [m]
    // the reference point on each profile as its points are given (y towards
    // the field side on both sides, unlike y_r, y_w), and how that y changes
    // along the patch's s axis (d y / d s): where wear lands on the profiles
    double rail_profile_y = 0, rail_s_cos = 1;   // [m], [-]
    double wheel_profile_y = 0, wheel_s_cos = 1; // [m], [-]
    double rolling_radius = 0;           // depth of the wheel's contact point below the axle [m]
    double wheel_radius = 0;             // the wheel's radius at y_w: nominal + profile height [m]
    // creepages at the reference point, rail relative to wheel
    double veloc = 0;                    // [m/s]
    double cksi = 0, ceta = 0;           // [-]
    double cphi = 0;                     // [1/m]
    bool forward = true;                 // rolling towards +x
    // the undeformed distance on the grid of the tangent plane: element
    // (i, j) is centred at x = x0 + i dx, s = s0 + j ds from the reference
    // point, h at [i + j nx] [m] (> 0 apart; datum: the given position, so
    // the approach of that position is 0)
    int nx = 0, ny = 0;
    double dx = 0, ds = 0, x0 = 0, s0 = 0;
    std::vector<double> h;
    double approach = 0;                 // -min h: the rigid overlap [m]
    double gap_min = 0;                  // least vertical gap of the region [m]
    // sub-patches (x_lo, x_hi, y_lo, y_hi, z_lo, z_hi in track coordinates)
    // and their mutual influence factors (n_sub x n_sub)
    std::vector<double> sub_extent, sub_factor;
};

struct WheelRailState {
    WheelsetPosition position;
    double gap_min = 0; // least vertical gap between wheel and rail [m] (> 0: no contact)
    std::vector<ContactPatch> patches; // from the field side to the track centre
};

class WheelRailGeometry {
public:
    // Throws creepwork::Error naming the input when one is out of range.
    WheelRailGeometry(const Profile& rail, const Profile& wheel, const Track& track,
                      const Wheelset& wheelset, Side side, const SearchOptions& options = {});

    // The patches at a prescribed wheelset position. height_only: the
    // position may differ from the last evaluated one in z alone; the
    // contact search then shifts that position's samples of the wheel
    // instead of sampling it anew (ContactSearch::find), and the wheel's
    // surface on a patch grid laid out as at the last height is solved from
    // the points found there (undeformed_distance).
    const WheelRailState& evaluate(const WheelsetPosition& position, const WheelsetVelocity& velocity,
                                   bool height_only = false);
    const WheelRailState& state() const { return state_; }
    // The rail's or the wheel's profile knots in track coordinates at the
    // last evaluated position (y un-mirrored on the left side, z down): the
    // rail as placed, the wheel in the wheelset's plane through the axle.
    void profile_in_track(bool rail, std::vector<double>& y, std::vector<double>& z) const;

    Side side() const { return side_; }
    const Track& track() const { return track_; }
    const Wheelset& wheelset() const { return wheelset_; }
    const SearchOptions& options() const { return opt_; }
    // The rail's frame in track coordinates (right-side frame, CONTACT's
    // rail marker before mirroring).
    const Frame& rail_frame() const { return rail_frame_; }
    // The profiles in canonical form (profile.hpp), as given after the unit.
    const Profile& rail_profile() const { return rail_; }
    const Profile& wheel_profile() const { return wheel_; }
    const ContactSearch& search() const { return search_; }

private:
    Profile rail_, wheel_, rail_track_;
    ProfileTable wheel_table_;
    Track track_;
    Wheelset wheelset_;
    Side side_;
    SearchOptions opt_;
    Frame rail_frame_, wheel_ws_;
    ContactSearch search_;
    std::vector<Region> regions_;
    PatchGrid grid_;
    std::vector<WheelNodes> wheel_nodes_; // per patch: the wheel's points at the last height
    WheelRailState state_;
};

} // namespace creepwork::wheelrail
