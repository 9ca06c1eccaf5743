#include "gap_rows.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "../cli/cli_error.hpp"
#include "../cli/gap_input.hpp"
#include "../cli/options.hpp"
#include "wire.hpp"

namespace cwcampaign {

namespace {

using cwcli::ContactSource;
using cwcli::Input;
using cwcli::RowSource;
using Refusal = ContactSource::Refusal;

// A gap file typed in millimetres reads as cells of 0.05-1 m and gaps of
// tenths of a metre: the same bounds as `solve --gap` on the spacing, and
// on the values' spread (a wheel-rail gap over its potential contact area
// spans a fraction of a millimetre; 10 mm is far beyond any).
std::vector<std::string> unit_warnings(const cw_grid& g, const std::vector<double>& h,
                                       const std::string& path)
{
    std::vector<std::string> w;
    const std::string head = "column gap_file: " + path + ": ";
    const std::string tail = " is implausible for a wheel-rail contact";
    const std::string mm = "the file is read in metres: millimetres typed as metres?)";
    for (const auto& [name, d] : {std::pair<const char*, double>{"dx", g.dx}, {"dy", g.dy}})
        if (d > 5e-3 || d < 1e-6)
            w.push_back(head + "cells of " + name + " = " + cwcli::round_trip_text(d) + " m" +
                        tail + " (0.05-1 mm; " + mm);
    const auto [lo, hi] = std::minmax_element(h.begin(), h.end());
    if (lo != h.end() && *hi - *lo > 1e-2)
        w.push_back(head + "gaps spanning " + cwcli::round_trip_text(*hi - *lo) + " m" + tail +
                    " (its gaps span a fraction of a millimetre over the potential contact "
                    "area; " + mm);
    return w;
}

// read_gap_file's message ("--gap: PATH:LINE: ...") for a row, which names
// its column itself.
std::string gap_file_message(const std::string& message)
{
    const std::string prefix = "--gap: ";
    return message.compare(0, prefix.size(), prefix) == 0 ? message.substr(prefix.size())
                                                          : message;
}

// FNV-1a of a gap grid's shape and geometry and of its values' bits: the
// gap file's part of the campaign's identity.
uint64_t gap_hash(const cw_grid& g, const std::vector<double>& h)
{
    uint64_t hash = fnv1a(&g.nx, sizeof g.nx);
    hash = fnv1a(&g.ny, sizeof g.ny, hash);
    for (const double* v : {&g.x0, &g.y0, &g.dx, &g.dy}) hash = fnv1a(v, sizeof *v, hash);
    return fnv1a(h.data(), h.size() * sizeof(double), hash);
}

} // namespace

const GapFiles::File& GapFiles::load(const std::string& path)
{
    const auto found = files_.find(path);
    if (found != files_.end()) return found->second;
    File f;
    cw_grid_init(&f.grid);
    try {
        cwcli::GapFile g = cwcli::read_gap_file(path);
        f.grid = g.grid;
        f.hash = gap_hash(g.grid, g.h);
        f.warnings = unit_warnings(g.grid, g.h, path);
        f.h = std::make_shared<const std::vector<double>>(std::move(g.h));
        hash_ = fnv1a(&f.hash, sizeof f.hash, hash_ ? hash_ : fnv1a("gap files", 9));
    } catch (const cwcli::CliError& e) {
        f.error = gap_file_message(e.what());
    }
    return files_.emplace(path, std::move(f)).first->second;
}

void refuse_gap_columns(const RowSource& r)
{
    for (Input in : {Input::approach, Input::normal_method})
        if (r.has(in))
            r.fail(r.name(in), "only used on a row with a " + r.name(Input::gap_file) +
                                   " (a contact of any shape)",
                   Refusal::unreadable);
}

void read_gap_row(const RowSource& r, const std::string& dir, GapFiles& files, ContactCase& c,
                  std::vector<std::string>& warnings)
{
    const std::string gap = r.name(Input::gap_file);
    const std::string shape = "must be empty on a row with a " + gap + ": ";
    const std::string flex = shape + "on a gap the flexibilities come from G and nu";
    const std::string grid = shape + "the gap file defines the grid";
    const struct {
        Input in;
        std::string why;
    } unused[] = {
        {Input::a, shape + "the gap file defines the contact (no semi-axes)"},
        {Input::b, shape + "the gap file defines the contact (no semi-axes)"},
        {Input::grid, grid},
        {Input::nx, grid},
        {Input::ny, grid},
        {Input::box_scale, grid},
        {Input::pressure, shape + "the normal problem is solved on the gap (" +
                              r.name(Input::normal_method) + ")"},
        {Input::L1, flex},
        {Input::L2, flex},
        {Input::L3, flex},
        {Input::flexibility_blending, shape + "a FASTSIM option for an ellipse"}};
    for (const auto& u : unused)
        if (r.has(u.in)) r.fail(r.name(u.in), u.why, Refusal::unreadable);
    if (r.has(Input::N) == r.has(Input::approach))
        r.fail(r.has(Input::N) ? r.name(Input::N) + "/" + r.name(Input::approach)
                               : r.name(Input::N),
               r.has(Input::N) ? "give the normal force or the approach, not both"
                               : "empty: a row with a " + gap +
                                     " needs the normal force N or the approach",
               Refusal::unreadable);
    if (r.has(Input::model) &&
        r.choice(Input::model, {"fastsim", "exact", "calibrated"}) == "calibrated")
        r.fail(r.name(Input::model),
               "calibrated is not available on a row with a " + gap +
                   ": a gap is solved by the exact model (the default there) or fastsim",
               Refusal::invalid_input);

    cw_params start = cwcli::library_default_params();
    start.model = CW_MODEL_EXACT; // as `creepwork solve --gap`
    const cwcli::ContactInputs in =
        cwcli::read_contact_inputs(r, start, cwcli::library_default_grid());
    cw_params p = in.params;
    for (std::string& w : cwcli::plausibility_warnings(p, r)) warnings.push_back(std::move(w));
    if (r.has(Input::approach)) {
        p.normal_load = CW_NORMAL_APPROACH;
        p.approach = r.number(Input::approach);
        if (std::fabs(p.approach) > 1e-3)
            warnings.push_back(r.label(Input::approach) + " = " +
                               cwcli::value_text(r, Input::approach, p.approach) +
                               " is implausible for a wheel-rail contact: approaches are 10-200 "
                               "um (millimetres typed as metres? " +
                               r.units_note() + ")");
    }
    if (r.has(Input::normal_method) &&
        r.choice(Input::normal_method, {"exact", "semi-hertz"}) == "semi-hertz")
        p.normal_method = CW_NORMAL_SEMI_HERTZ;

    namespace fs = std::filesystem;
    fs::path file(r.text(Input::gap_file));
    if (file.is_relative()) file = fs::path(dir) / file;
    std::error_code ignored;
    const fs::path absolute = fs::absolute(file, ignored);
    const std::string path = (absolute.empty() ? file : absolute).lexically_normal().string();
    const GapFiles::File& f = files.load(path);
    if (!f.error.empty()) r.fail(gap, f.error, Refusal::unreadable);
    c.grid = f.grid;
    p.gap = nullptr;
    p.gap_len = f.h->size();
    c.params = p;
    c.gap_values = f.h;
    warnings.insert(warnings.end(), f.warnings.begin(), f.warnings.end());
}

} // namespace cwcampaign
