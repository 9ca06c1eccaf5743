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
    if (r.has(Input::approach)) {
        p.normal_load = CW_NORMAL_APPROACH;
        p.approach = r.number(Input::approach);
    }
    if (r.has(Input::normal_method) &&
        r.choice(Input::normal_method, {"exact", "semi_hertz"}) == "semi_hertz")
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
    p.gap = f.h->data(); // the row's checks read the heights
    p.gap_len = f.h->size();
    for (std::string& w : cwcli::plausibility_warnings(f.grid, p, r, path))
        warnings.push_back(std::move(w));
    p.gap = nullptr;
    c.params = p;
    c.gap_values = f.h;
}

} // namespace cwcampaign
