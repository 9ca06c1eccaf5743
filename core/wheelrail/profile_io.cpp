#include "wheelrail/profile_io.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

#include "contact/error.hpp"
#include "wheelrail/profile_checks.hpp"

namespace creepwork::wheelrail {
namespace {

[[noreturn]] void fail(const std::string& source, int line, const std::string& message)
{
    throw Error(ErrorKind::invalid_input,
                source + (line > 0 ? " line " + std::to_string(line) : std::string()) + ": " + message);
}

std::string trim(const std::string& s)
{
    size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return s.substr(a, b - a);
}

// Numbers of a line split at spaces, tabs, commas and semicolons; false if
// any field is not a number (locale-independent).
bool parse_numbers(const std::string& text, std::vector<double>& out)
{
    out.clear();
    const char* p = text.data();
    const char* end = p + text.size();
    while (p < end) {
        while (p < end && (std::isspace(static_cast<unsigned char>(*p)) || *p == ',' || *p == ';')) ++p;
        if (p == end) break;
        if (*p == '+') ++p; // from_chars takes no leading plus
        double v = 0.0;
        const auto r = std::from_chars(p, end, v);
        if (r.ec != std::errc() ||
            (r.ptr < end && !std::isspace(static_cast<unsigned char>(*r.ptr)) && *r.ptr != ',' &&
             *r.ptr != ';'))
            return false;
        out.push_back(v);
        p = r.ptr;
    }
    return true;
}

// A line of a binary file: its bytes would be echoed into the messages.
void require_text(const std::string& source, int line, const std::string& text)
{
    for (size_t k = 0; k < text.size(); ++k) {
        const unsigned char c = static_cast<unsigned char>(text[k]);
        if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) {
            char buf[160];
            std::snprintf(buf, sizeof buf,
                          "byte 0x%02x at column %zu is not text: a profile is a text file "
                          "(SIMPACK .prr/.prw, MiniProf .ban/.whl, or a table of y z lines)",
                          c, k + 1);
            fail(source, line, buf);
        }
    }
}

struct RawPoint {
    double y, z;
    int line;
};

// The common tail of all formats: unit, mirrors, canonical order, checks.
Profile finish(std::vector<RawPoint>& raw, ProfileKind kind, const std::string& source,
               double unit, const ProfileReadOptions& opt)
{
    if (!(unit > 0.0 && std::isfinite(unit)))
        fail(source, 0, "the length unit must be finite and > 0 [m per file unit]");
    std::vector<ProfilePoint> pts;
    pts.reserve(raw.size());
    for (const RawPoint& r : raw)
        pts.push_back({(opt.mirror_y ? -r.y : r.y) * unit + opt.y_offset,
                       (opt.mirror_z ? -r.z : r.z) * unit, r.line});
    orient_profile_points(kind, pts);
    return Profile(kind, std::move(pts), source, opt.checks);
}

// --- SIMPACK .prr / .prw -------------------------------------------------

struct SimpackOptions {
    double dist_min = 1e-4, shift_y = 0.0, shift_z = 0.0, rotate = 0.0;
    double bound_y_min = -1e9, bound_y_max = 1e9, bound_z_min = -1e9, bound_z_max = 1e9;
    int mirror_y = 0, mirror_z = 0, inversion = -1;
    double units_len = 1.0;
    int type = -1;
};

Profile read_simpack(std::istream& in, ProfileKind kind, const std::string& source,
                     const ProfileReadOptions& opt)
{
    enum Section { none, header, spline, point };
    Section sec = none;
    SimpackOptions o;
    std::vector<RawPoint> raw;
    std::vector<double> nums;
    std::string text;
    int line = 0, open_line = 0;
    bool had_points = false;
    while (std::getline(in, text)) {
        ++line;
        require_text(source, line, text);
        const size_t bang = text.find_first_of("!%");
        std::string s = trim(bang == std::string::npos ? text : text.substr(0, bang));
        if (s.empty()) continue;
        const size_t eq = s.find('=');
        if (eq == std::string::npos && !parse_numbers(s, nums)) {
            // a section keyword
            auto expect = [&](bool ok) {
                if (!ok) fail(source, line, "section \"" + s + "\" is not allowed here");
            };
            if (s == "header.begin") { expect(sec == none); sec = header; open_line = line; }
            else if (s == "header.end") { expect(sec == header); sec = none; }
            else if (s == "spline.begin") { expect(sec == none); sec = spline; open_line = line; }
            else if (s == "spline.end") { expect(sec == spline); sec = none; }
            else if (s == "point.begin") { expect(sec == spline); sec = point; open_line = line; had_points = true; }
            else if (s == "point.end") { expect(sec == point); sec = spline; }
            else fail(source, line, "unknown keyword \"" + s + "\"");
            continue;
        }
        if (eq == std::string::npos) { // numbers
            if (sec != point) fail(source, line, "numbers outside a point section");
            if (nums.size() < 2 || nums.size() > 3)
                fail(source, line, "a point needs \"y z [weight]\", got " + std::to_string(nums.size()) + " values");
            raw.push_back({nums[0], nums[1], line});
            continue;
        }
        const std::string key = trim(s.substr(0, eq));
        const std::string val = trim(s.substr(eq + 1));
        if (sec == point) fail(source, line, "keyword \"" + key + "\" inside the point section");
        if (sec == none) fail(source, line, "keyword \"" + key + "\" outside any section");
        if (key == "file" || key == "comment" || key == "units.len" || key == "units.ang") continue;
        if (!parse_numbers(val, nums) || nums.size() != 1)
            fail(source, line, "keyword \"" + key + "\" needs one number, got \"" + val + "\"");
        const double v = nums[0];
        if (sec == header) {
            if (key == "type") o.type = static_cast<int>(v);
            continue; // version and other header keys carry no geometry
        }
        if (key == "point.dist.min") o.dist_min = std::max(1e-6, v);
        else if (key == "shift.y") o.shift_y = v;
        else if (key == "shift.z") o.shift_z = v;
        else if (key == "rotate") o.rotate = v;
        else if (key == "bound.y.min") o.bound_y_min = v;
        else if (key == "bound.y.max") o.bound_y_max = v;
        else if (key == "bound.z.min") o.bound_z_min = v;
        else if (key == "bound.z.max") o.bound_z_max = v;
        else if (key == "mirror.y") o.mirror_y = static_cast<int>(v);
        else if (key == "mirror.z") o.mirror_z = static_cast<int>(v);
        else if (key == "inversion") o.inversion = static_cast<int>(v);
        else if (key == "units.len.f") o.units_len = v;
        // approx.smooth, type, file.mtime, units.ang.f: no effect on the points
    }
    if (sec != none)
        fail(source, open_line, "section opened here is not closed before the end of the file");
    if (!had_points) fail(source, 0, "no point section (point.begin ... point.end)");
    const int want = kind == ProfileKind::rail ? 0 : 1;
    if (o.type != want)
        fail(source, 0, std::string("header type must be ") + (want == 0 ? "0 (rail profile)" : "1 (wheel profile)") +
                            ", got " + std::to_string(o.type));
    if (std::abs(o.rotate) > 1e-12) fail(source, 0, "a rotated profile (rotate != 0) is not supported");
    if (!(o.units_len > 0.0)) fail(source, 0, "units.len.f must be > 0");
    // point.dist.min: drop points closer than that to the previous kept one
    std::vector<RawPoint> kept;
    for (const RawPoint& r : raw)
        if (kept.empty() || std::hypot(r.y - kept.back().y, r.z - kept.back().z) >= o.dist_min) kept.push_back(r);
    raw.swap(kept);
    for (RawPoint& r : raw) {
        r.y += o.shift_y;
        r.z += o.shift_z;
    }
    if (o.bound_y_min < o.bound_y_max)
        raw.erase(std::remove_if(raw.begin(), raw.end(),
                                 [&](const RawPoint& r) { return r.y < o.bound_y_min || r.y > o.bound_y_max; }),
                  raw.end());
    if (o.bound_z_min < o.bound_z_max)
        for (RawPoint& r : raw) r.z = std::clamp(r.z, o.bound_z_min, o.bound_z_max);
    for (RawPoint& r : raw) {
        if (o.mirror_y == 1) r.y = -r.y;
        if (o.mirror_z == 1) r.z = -r.z;
    }
    if (o.inversion == 1) std::reverse(raw.begin(), raw.end());
    const double unit = opt.length_unit > 0.0 ? opt.length_unit : 1.0 / o.units_len;
    return finish(raw, kind, source, unit, opt);
}

// --- MiniProf .ban / .whl ------------------------------------------------

Profile read_miniprof(std::istream& in, ProfileKind kind, const std::string& source,
                      const ProfileReadOptions& opt)
{
    std::vector<RawPoint> raw;
    std::vector<double> nums;
    std::string text;
    int line = 0, icol_y = 0, icol_z = 1, ncol = 2;
    double xoff = 0.0, yoff = 0.0;
    bool in_header = true;
    while (std::getline(in, text)) {
        ++line;
        require_text(source, line, text);
        const std::string s = trim(text);
        if (s.empty()) {
            in_header = false; // the points follow the first blank line
            continue;
        }
        if (s[0] == '!' || s[0] == '"' || s[0] == '%' || s[0] == '#') continue;
        const size_t eq = s.find('=');
        if (eq != std::string::npos) {
            if (!in_header) fail(source, line, "header line \"" + s + "\" after the points");
            const std::string key = trim(s.substr(0, eq)), val = trim(s.substr(eq + 1));
            if (key == "ColumnDef") {
                ncol = 0;
                icol_y = icol_z = -1;
                for (size_t i = 0; i < val.size(); ++i) {
                    if (val[i] == ',' || std::isspace(static_cast<unsigned char>(val[i]))) continue;
                    if (val[i] == 'X') icol_y = ncol;
                    if (val[i] == 'Y') icol_z = ncol;
                    ++ncol;
                }
                if (icol_y < 0 || icol_z < 0)
                    fail(source, line, "ColumnDef \"" + val + "\" must name the columns X and Y");
            } else if (key == "XOffset" || key == "Xoffset" || key == "YOffset" || key == "Yoffset") {
                if (!parse_numbers(val, nums) || nums.size() != 1)
                    fail(source, line, key + " needs one number, got \"" + val + "\"");
                (key[0] == 'X' ? xoff : yoff) = nums[0];
            }
            continue; // all other MiniProf keys describe the measurement, not the shape
        }
        if (!parse_numbers(s, nums)) {
            if (in_header) continue; // old-style header text without '='
            fail(source, line, "expected numbers, got \"" + s + "\"");
        }
        in_header = false;
        if (static_cast<int>(nums.size()) < std::max(ncol, 2))
            fail(source, line, "a point needs " + std::to_string(std::max(ncol, 2)) + " values, got " +
                                   std::to_string(nums.size()));
        raw.push_back({nums[icol_y] + xoff, nums[icol_z] + yoff, line});
    }
    // CONTACT drops MiniProf points closer than 1e-4 file units (0.1 um) to
    // the previous one: repeated points where measured sections were joined
    std::vector<RawPoint> kept;
    for (const RawPoint& r : raw)
        if (kept.empty() || std::hypot(r.y - kept.back().y, r.z - kept.back().z) >= 1e-4) kept.push_back(r);
    raw.swap(kept);
    const double unit = opt.length_unit > 0.0 ? opt.length_unit : 1e-3;
    return finish(raw, kind, source, unit, opt);
}

// --- plain table ------------------------------------------------------------

Profile read_table(std::istream& in, ProfileKind kind, const std::string& source,
                   const ProfileReadOptions& opt)
{
    std::vector<RawPoint> raw;
    std::vector<double> nums;
    std::string text;
    int line = 0;
    bool first = true;
    while (std::getline(in, text)) {
        ++line;
        require_text(source, line, text);
        const std::string s = trim(text);
        if (s.empty() || s[0] == '#' || s[0] == '%' || s[0] == '!') continue;
        const bool numeric = parse_numbers(s, nums);
        if (!numeric && first) { // column names
            first = false;
            continue;
        }
        first = false;
        if (!numeric || nums.size() != 2)
            fail(source, line, "expected two numbers \"y z\", got \"" + s + "\"");
        raw.push_back({nums[0], nums[1], line});
    }
    const double unit = opt.length_unit > 0.0 ? opt.length_unit : 1e-3;
    return finish(raw, kind, source, unit, opt);
}

} // namespace

Profile read_profile(std::istream& in, ProfileKind kind, ProfileFormat format,
                     const std::string& source, const ProfileReadOptions& options)
{
    if (!(options.length_unit >= 0.0 && std::isfinite(options.length_unit)))
        fail(source, 0, "the length unit must be finite and >= 0 (0: the format's own)");
    if (!(std::fabs(options.y_offset) <= 1.0))
        fail(source, 0, "the lateral offset must lie within +-1 m");
    switch (format) {
    case ProfileFormat::simpack: return read_simpack(in, kind, source, options);
    case ProfileFormat::miniprof: return read_miniprof(in, kind, source, options);
    case ProfileFormat::table: break;
    }
    return read_table(in, kind, source, options);
}

ProfileFormat profile_format_of(const std::string& path)
{
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of("/\\");
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return ProfileFormat::table;
    std::string ext = path.substr(dot + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == "prr" || ext == "prw") return ProfileFormat::simpack;
    if (ext == "ban" || ext == "whl") return ProfileFormat::miniprof;
    return ProfileFormat::table;
}

} // namespace creepwork::wheelrail
