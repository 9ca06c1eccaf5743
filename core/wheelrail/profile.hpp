// A wheel or rail profile: a smooth curve (y(s), z(s)) through the measured
// points, parametrised by the summed chord length s.
//
// Canonical form (CONTACT's, user guide "Inputs regarding wheel and rail
// profiles"): lengths in metres, y towards the field side, z downwards; rail
// points run from the track centre to the field side (y increasing at the
// top of the rail), wheel points from the field side to the flange back (y
// decreasing), so the material always lies to the right of the direction of
// travel. The same profile serves the left and the right side: the left side
// is solved mirrored.
//
// The curve is a natural cubic interpolating spline in s for y and z, as in
// CONTACT (m_spline_make, no smoothing); a point where the profile turns by
// more than the kink threshold is an error unless kinks are accepted, and then
// the spline is broken there (a corner). s = 0 lies at y = 0 when y is
// monotone along the profile, else at the point closest to the origin.
#pragma once

#include <string>
#include <vector>

#include "wheelrail/frame.hpp"

namespace creepwork::wheelrail {

enum class ProfileKind { rail, wheel };

// One input point, already in the canonical form, and the input line it
// came from (0 if none) for the error messages.
struct ProfilePoint {
    double y = 0.0; // [m]
    double z = 0.0; // [m]
    int line = 0;
};

struct ProfileChecks {
    // A turn of the curve between successive segments above this angle is a
    // kink: an error, or a corner of the spline when kinks are accepted.
    // CONTACT's KINKHIGH default (pi/6, user guide "Curation of anomalous
    // input data").
    double kink_angle = 0.5235987755982988; // [rad]
    bool accept_kinks = false;
    // Successive points closer than this are duplicates (an error).
    double min_spacing = 1e-9; // [m]
};

class Profile {
public:
    // Builds the spline after checking the points (profile_checks.hpp):
    // throws creepwork::Error naming `source` and the offending line.
    Profile(ProfileKind kind, std::vector<ProfilePoint> points, const std::string& source,
            const ProfileChecks& checks = {});
    Profile() = default;

    ProfileKind kind() const { return kind_; }
    const std::string& source() const { return source_; }
    int size() const { return static_cast<int>(s_.size()); }
    double s_first() const { return s_.front(); }
    double s_last() const { return s_.back(); }
    const std::vector<double>& knots_s() const { return s_; }
    const std::vector<double>& knots_y() const { return y_; }
    const std::vector<double>& knots_z() const { return z_; }

    struct Point {
        double y, z;     // position [m]
        double dy, dz;   // first derivatives in s
        double d2y, d2z; // second derivatives in s
    };
    // The curve at s (clamped to [s_first, s_last]); `segment` is a search
    // hint, updated to the segment that holds s.
    Point at(double s, int* segment = nullptr) const;
    // Inclination atan2(dz/ds, dy/ds) at s [rad].
    double inclination(double s) const;

    // The visible surface at lateral position y: the top of a rail (least z)
    // or the bottom of a wheel (largest z) among the parts of the curve over
    // y. Returns false when no part covers y.
    bool visible_s_at_y(double y, double& s) const;
    // Lowest/highest y of the curve (the visible range in y).
    double y_min() const { return y_lo_; }
    double y_max() const { return y_hi_; }

    // The same curve placed in a parent frame (p_parent = o + R p, R a roll
    // about x: only its y-z block is used); s keeps its values.
    Profile placed(const Frame& f) const;

    // s where y(s) = y within [s_a, s_b] (y monotone there, y between the
    // ends); Newton safeguarded by bisection.
    double solve_y(double y, double s_a, double s_b) const;

private:
    struct Piece { // part of the curve with monotone y(s)
        double s_a, s_b, y_a, y_b;
    };
    void build_spline(const std::vector<int>& breaks);
    void build_pieces();
    int segment_of(double s, int hint) const;

    ProfileKind kind_ = ProfileKind::rail;
    std::string source_;
    std::vector<double> s_, y_, z_;             // knots
    std::vector<double> cy_, cz_;               // per segment: 3 coefficients each (t, t^2, t^3)
    std::vector<Piece> pieces_;
    double y_lo_ = 0.0, y_hi_ = 0.0;
};

} // namespace creepwork::wheelrail
