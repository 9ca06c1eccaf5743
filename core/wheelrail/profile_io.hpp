// Readers for wheel and rail profile files: SIMPACK (.prr rail, .prw wheel),
// MiniProf (.ban rail, .whl wheel) and a plain table of (y, z) pairs. The
// parsers read text from a stream; profile_file.cpp opens files. Every error
// names the source and the line (creepwork::Error).
//
// SIMPACK: sections header / spline / point; header "type" must be 0 for a
// rail, 1 for a wheel; the spline section's point.dist.min, shift.y/z,
// bound.y/z.min/max, mirror.y/z, inversion and units.len.f are applied as
// SIMPACK and CONTACT do (rotate must be 0); points are "y z [weight]".
// MiniProf: "Key=Value" header lines up to the first blank line, then the
// points; ColumnDef (default X,Y) names the columns, XOffset/YOffset shift
// them; a point closer than 1e-4 file units to the previous one is dropped
// (as in CONTACT); lines starting with ! " % # are comments (MiniProf marks excluded
// points with a leading "). Table: one "y z" pair per line (separated by
// spaces, tabs, commas or semicolons), lines starting with # % ! are
// comments, an optional first line of column names.
//
// After the file's own options: the length unit, then the mirrors and the
// offset below, then the points are put in canonical order (profile.hpp)
// and checked.
#pragma once

#include <istream>
#include <string>

#include "wheelrail/profile.hpp"

namespace creepwork::wheelrail {

enum class ProfileFormat { simpack, miniprof, table };

struct ProfileReadOptions {
    // Metres per unit of length in the file; 0: the format's own (SIMPACK:
    // 1/units.len.f, i.e. metres unless the file says otherwise; MiniProf and
    // tables: millimetres).
    double length_unit = 0.0;
    bool mirror_y = false; // y := -y (profiles measured with y towards the track centre)
    bool mirror_z = false; // z := -z (profiles measured with z upwards)
    double y_offset = 0.0; // [m] added to y after the unit and the mirrors
    ProfileChecks checks;
};

Profile read_profile(std::istream& in, ProfileKind kind, ProfileFormat format,
                     const std::string& source, const ProfileReadOptions& options = {});

// The format from the file name: .prr/.prw SIMPACK, .ban/.whl MiniProf, any
// other name a table (case-insensitive).
ProfileFormat profile_format_of(const std::string& path);

// Opens `path` and reads it (profile_file.cpp).
Profile read_profile_file(const std::string& path, ProfileKind kind,
                          const ProfileReadOptions& options = {});

} // namespace creepwork::wheelrail
