#include "wheelrail/profile_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "contact/error.hpp"

namespace creepwork::wheelrail {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMinLength = 5e-3;   // [m], CONTACT's min_prf_length
constexpr double kMaxLength = 0.5;    // [m], CONTACT's max_prf_length
constexpr double kFeatureDepth = 5e-3; // [m]: a flange or a rail head stands out this much

std::string where(const std::string& source, const ProfilePoint& p, size_t index)
{
    char buf[64];
    if (p.line > 0)
        std::snprintf(buf, sizeof buf, " line %d", p.line);
    else
        std::snprintf(buf, sizeof buf, " point %zu", index + 1);
    return source + buf;
}

[[noreturn]] void fail(const std::string& message)
{
    throw Error(ErrorKind::invalid_input, message);
}

std::string degrees(double a)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f deg", a * 180.0 / kPi);
    return buf;
}

// Signed turn from segment (a, b) to segment (b, c), in (-pi, pi].
double turn(const ProfilePoint& a, const ProfilePoint& b, const ProfilePoint& c)
{
    const double a1 = std::atan2(b.z - a.z, b.y - a.y), a2 = std::atan2(c.z - b.z, c.y - b.y);
    double d = a2 - a1;
    if (d > kPi) d -= 2.0 * kPi;
    if (d <= -kPi) d += 2.0 * kPi;
    return d;
}

bool segments_cross(const ProfilePoint& p1, const ProfilePoint& p2, const ProfilePoint& q1,
                    const ProfilePoint& q2)
{
    auto side = [](const ProfilePoint& a, const ProfilePoint& b, const ProfilePoint& c) {
        return (b.y - a.y) * (c.z - a.z) - (b.z - a.z) * (c.y - a.y);
    };
    const double d1 = side(q1, q2, p1), d2 = side(q1, q2, p2);
    const double d3 = side(p1, p2, q1), d4 = side(p1, p2, q2);
    return ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) &&
           ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0));
}

void check_crossings(const std::vector<ProfilePoint>& p, const std::string& source)
{
    const size_t n = p.size();
    for (size_t i = 0; i + 1 < n; ++i) {
        const double ylo = std::min(p[i].y, p[i + 1].y), yhi = std::max(p[i].y, p[i + 1].y);
        const double zlo = std::min(p[i].z, p[i + 1].z), zhi = std::max(p[i].z, p[i + 1].z);
        for (size_t j = i + 2; j + 1 < n; ++j) {
            if (std::max(p[j].y, p[j + 1].y) < ylo || std::min(p[j].y, p[j + 1].y) > yhi ||
                std::max(p[j].z, p[j + 1].z) < zlo || std::min(p[j].z, p[j + 1].z) > zhi)
                continue;
            if (segments_cross(p[i], p[i + 1], p[j], p[j + 1]))
                fail(where(source, p[j], j) + ": the profile crosses itself (the segment to the next "
                     "point intersects the segment that starts at" + where("", p[i], i) +
                     "); the points form a loop");
        }
    }
}

// z downwards and, for a wheel, the flange on the track-centre side.
void check_direction(ProfileKind kind, const std::vector<ProfilePoint>& p, const std::string& source)
{
    size_t imin = 0, imax = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        if (p[i].z < p[imin].z) imin = i;
        if (p[i].z > p[imax].z) imax = i;
    }
    const double z_ends_lo = std::min(p.front().z, p.back().z);
    const double z_ends_hi = std::max(p.front().z, p.back().z);
    const bool valley = p[imax].z > z_ends_hi + kFeatureDepth; // a deep interior point
    const bool crest = p[imin].z < z_ends_lo - kFeatureDepth;  // a high interior point
    if (kind == ProfileKind::rail && valley && !crest)
        fail(source + ": the rail profile is upside down: its head must have the least z (z "
             "points downwards); mirror z");
    if (kind == ProfileKind::wheel && crest && !valley)
        fail(source + ": the wheel profile is upside down: its flange must point to larger z (z "
             "points downwards); mirror z");
    if (kind == ProfileKind::wheel && valley && p[imax].y > 0.5 * (p.front().y + p.back().y))
        fail(where(source, p[imax], imax) + ": the wheel's flange lies on the field side: y must "
             "point towards the field side (away from the flange); mirror y");
}

} // namespace

void orient_profile_points(ProfileKind kind, std::vector<ProfilePoint>& points)
{
    if (points.size() < 2) return;
    const double dy = points.back().y - points.front().y;
    if ((kind == ProfileKind::rail && dy < 0.0) || (kind == ProfileKind::wheel && dy > 0.0))
        std::reverse(points.begin(), points.end());
}

std::vector<int> check_profile_points(ProfileKind kind, const std::vector<ProfilePoint>& p,
                                      const std::string& source, const ProfileChecks& checks)
{
    const char* what = kind == ProfileKind::rail ? "rail" : "wheel";
    if (!(checks.kink_angle > 0.0 && checks.kink_angle <= kPi / 2))
        fail(source + ": the kink threshold must lie in (0, 90] deg, got " + degrees(checks.kink_angle));
    if (!(checks.min_spacing >= 0.0 && std::isfinite(checks.min_spacing)))
        fail(source + ": the duplicate-point spacing must be finite and >= 0");
    if (p.size() < 4)
        fail(source + ": a " + what + " profile needs at least 4 points, got " + std::to_string(p.size()));
    for (size_t i = 0; i < p.size(); ++i)
        if (!std::isfinite(p[i].y) || !std::isfinite(p[i].z))
            fail(where(source, p[i], i) + ": the point is not finite");
    const double dy = p.back().y - p.front().y;
    if ((kind == ProfileKind::rail && !(dy > 0.0)) || (kind == ProfileKind::wheel && !(dy < 0.0)))
        fail(source + ": the " + what + " profile's points must run " +
             (kind == ProfileKind::rail ? "with y increasing (track centre to field side)"
                                        : "with y decreasing (field side to flange back)"));
    // The length first: a profile in the wrong unit also has points too
    // close together, and its unit is what the message must name.
    double length = 0.0;
    for (size_t i = 1; i < p.size(); ++i) length += std::hypot(p[i].y - p[i - 1].y, p[i].z - p[i - 1].z);
    if (length < kMinLength || length > kMaxLength) {
        char buf[256];
        std::snprintf(buf, sizeof buf,
                      ": the %s profile is %.4g m long; a profile is 5 mm to 500 mm long: %s", what,
                      length,
                      length < kMinLength
                          ? "a profile in metres read as millimetres is 1000 times too short "
                            "(tables and MiniProf files are read in mm unless the length unit, "
                            "profile_unit, says otherwise)"
                          : "a profile in millimetres read as metres is 1000 times too long (set "
                            "the length unit, profile_unit, or SIMPACK's units.len.f)");
        fail(source + buf);
    }
    for (size_t i = 1; i < p.size(); ++i) {
        const double d = std::hypot(p[i].y - p[i - 1].y, p[i].z - p[i - 1].z);
        if (!(d > checks.min_spacing)) {
            char buf[96];
            std::snprintf(buf, sizeof buf, ": duplicate point (%.3g m from the previous one)", d);
            fail(where(source, p[i], i) + buf);
        }
    }
    std::vector<int> breaks{0};
    for (size_t i = 1; i + 1 < p.size(); ++i) {
        const double t = std::abs(turn(p[i - 1], p[i], p[i + 1]));
        if (t > kPi / 2)
            fail(where(source, p[i], i) + ": the profile turns back by " + degrees(t) +
                 " (points out of order, or a zig-zag where measured sections were joined)");
        if (t > checks.kink_angle) {
            if (!checks.accept_kinks)
                fail(where(source, p[i], i) + ": kink: the profile turns by " + degrees(t) +
                     " at this point, more than " + degrees(checks.kink_angle) +
                     ": a measurement spike, or a step where measured sections were joined; "
                     "remove or smooth the point");
            breaks.push_back(static_cast<int>(i));
        }
    }
    breaks.push_back(static_cast<int>(p.size()) - 1);
    check_crossings(p, source);
    check_direction(kind, p, source);
    return breaks;
}

} // namespace creepwork::wheelrail
