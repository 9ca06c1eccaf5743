// The contact search of one wheel on one rail (CONTACT's module 1, locating
// method D = 2: contact locus, weighted centre, weighted angle).
//
// A prismatic rail can touch the wheel only where the wheel's surface normal
// is perpendicular to the track: on every circle of the wheel that is one
// point, the contact locus (Vollebregt, Vehicle System Dynamics 60 (2022)
// 1253-1291, "Detailed wheel/rail geometry processing using the planar
// contact approach").
// The vertical gap between the rail's top and the locus, sampled laterally
// every lateral_step * ds, has its local minima where the surfaces come
// closest; each minimum with interpenetration (gap < 0) opens a region
// bounded by the nearest points with gap >= 0, whose weighted centre --
// weight the squared interpenetration integrated along the wheel's
// circumference, pen(x) = pen - x^2 / (2 R) -- and weighted rail
// inclination make the patch's reference point and contact angle. Regions
// closer than the combination distances are then joined (patch_combination).
//
// Everything here is in the right-side frame: the left side is mirrored.
#pragma once

#include <utility>
#include <vector>

#include "wheelrail/frame.hpp"
#include "wheelrail/profile.hpp"
#include "wheelrail/wheelrail_types.hpp"

namespace creepwork::wheelrail {

// An interpenetration region, or a near miss (gap_min >= 0), in track
// coordinates (right-side frame).
struct Region {
    double gap_min = 0.0; // least vertical gap [m] (< 0: interpenetration)
    Vec3 deepest = Vec3::Zero(); // where it is, on the rail
    double wgt_x = 0.0, wgt_y = 0.0, wgt_z = 0.0; // weighted centre [m]
    double wgt_angle = 0.0;    // weighted rail inclination [rad]
    double weight = 0.0;       // total weight [m^3]
    double x_lo = 0.0, x_hi = 0.0; // extent along the track [m]
    double y_lo = 0.0, y_hi = 0.0; // extent across, where the gap changes sign [m]
    double z_lo = 0.0, z_hi = 0.0; // rail heights at y_lo, y_hi [m]
    // Sub-patches joined into this one (x_lo, x_hi, y_lo, y_hi, z_lo, z_hi),
    // and the factors that reduce their mutual influence (sub x sub,
    // row-major; 1 on the diagonal), CONTACT's f_sep.
    std::vector<double> sub_extent, sub_factor;
    int n_sub() const { return static_cast<int>(sub_extent.size() / 6); }
};

// The rail's top sampled once per track, and the search per wheel position.
class ContactSearch {
public:
    ContactSearch() = default;
    // rail: the rail profile placed in track coordinates (right-side frame);
    // wheel: the wheel profile in its own coordinates.
    ContactSearch(const Profile& rail_in_track, const Profile& wheel, const SearchOptions& opt,
                  double nominal_radius);

    // Finds the regions of the wheel placed by `wheel_in_track` (the wheel
    // profile's frame in track coordinates), deepest first, at most two near
    // misses. Returns the least gap over the whole sampling (the vertical
    // distance to first contact when > 0). shift_height: the wheel may have
    // moved along track z only since the last sampling (the same rotation,
    // the same x and y of its origin): its samples are then those of that
    // sampling shifted by the height's change (a vertical translation moves
    // every sample of the locus by it), not sampled anew; any other move is
    // sampled anew.
    double find(const Frame& wheel_in_track, std::vector<Region>& regions, bool shift_height = false);

    // The sampled gap of the last call: lateral positions, rail and wheel
    // heights, locus x (invalid samples carry a wheel height of -1e3 m).
    int samples() const { return n_; }
    double y_at(int i) const { return y0_ + i * dy_; }
    const std::vector<double>& rail_z() const { return zr_; }
    const std::vector<double>& wheel_z() const { return zw_; }
    const std::vector<double>& locus_x() const { return xw_; }
    const std::vector<double>& gap() const { return gap_; }

private:
    void sample_wheel(const Frame& f);
    std::pair<int, int> add_region(int i_min, double gap_locmin, std::vector<Region>& regions);

    double y0_ = 0.0, dy_ = 0.0, radius_ = 0.0;
    int n_ = 0;
    std::vector<double> zr_, alpha_;        // rail: height and inclination per sample
    std::vector<double> zw_, xw_, gap_;     // wheel locus per sample, gap
    Frame sampled_;                         // the wheel's frame at the last sampling
    bool has_sampled_ = false;
    std::vector<double> zw_sampled_;        // zw_ of the last sampling
    std::vector<char> mask_;
    std::vector<int> minima_;
    // the wheel's knots: position and derivatives in s (fixed), and the
    // locus there (work arrays)
    std::vector<Profile::Point> knot_;
    std::vector<double> ky_, kx_, kz_, kdx_, kdz_;
};

} // namespace creepwork::wheelrail
