#include "input_csv.hpp"

#include <filesystem>
#include <limits>
#include <unordered_map>

#include "gap_rows.hpp"

namespace cwcampaign {

namespace {

using cwcli::ContactSource;
using cwcli::Input;
using cwcli::RowError;
using cwcli::RowSource;

int status_of(ContactSource::Refusal why)
{
    switch (why) {
    case ContactSource::Refusal::invalid_input: return CW_ERR_INVALID_INPUT;
    case ContactSource::Refusal::grid_out_of_range: return CW_ERR_GRID_OUT_OF_RANGE;
    case ContactSource::Refusal::unreadable: break;
    }
    return kStatusRowUnreadable;
}

std::string joined(const std::vector<std::string>& parts)
{
    std::string out;
    for (const std::string& p : parts) out += (out.empty() ? "" : "; ") + p;
    return out;
}

} // namespace

CampaignInput read_campaign_csv(const std::string& path, const WearRules* wear, bool strict)
{
    using cwcli::RowFile;
    const cw_params defaults = cwcli::library_default_params();
    const cw_grid default_grid = cwcli::library_default_grid();
    CampaignInput in;
    try {
        cwcli::RowFileReader file(path, wear ? RowFile::campaign_wear : RowFile::campaign);
        const cwcli::RowHeader& header = file.header();
        in.notes = header.notes();
        const std::string note = cwcli::defaults_note(header, defaults, path);
        if (!note.empty()) in.notes.push_back(note);
        in.has_s0 = header.has(Input::s0);
        in.has_distance = header.has(Input::distance);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        std::unordered_map<std::string, long> id_line;
        GapFiles gaps;
        const std::string dir = std::filesystem::path(path).parent_path().string();
        std::vector<std::string> cells;
        std::string error;
        long line = 0;
        while (file.next(cells, line, error)) {
            ContactCase c{};
            std::string id = header.field(Input::id) < cells.size()
                                 ? cells[header.field(Input::id)]
                                 : std::string();
            double s0 = nan, distance = nan;
            std::vector<std::string> warnings;
            try {
                if (!error.empty()) throw RowError{error, ContactSource::Refusal::unreadable};
                const RowSource r(header, cells, line);
                r.require_values();
                const auto [seen, fresh] = id_line.emplace(id, line);
                if (!fresh)
                    r.fail(r.name(Input::id),
                           "'" + id + "' repeats the id of line " + std::to_string(seen->second),
                           ContactSource::Refusal::unreadable);
                if (r.has(Input::gap_file)) {
                    read_gap_row(r, dir, gaps, c, warnings);
                } else {
                    refuse_gap_columns(r);
                    const cwcli::ContactInputs contact =
                        cwcli::read_contact_inputs(r, defaults, default_grid);
                    c.params = contact.params;
                    c.grid = contact.grid;
                    warnings = cwcli::plausibility_warnings(c.grid, c.params, r);
                }
                if (r.has(Input::s0)) s0 = r.number(Input::s0);
                if (r.has(Input::distance)) {
                    distance = r.number(Input::distance);
                    if (!(distance >= 0.0))
                        r.fail(r.name(Input::distance),
                               "must be >= 0 (a rolled distance; got " +
                                   cwcli::value_text(r, Input::distance, distance) + ")",
                               ContactSource::Refusal::invalid_input);
                }
                if (wear) {
                    const cwcli::WearPlacement w = cwcli::read_wear_columns(r, *wear);
                    c.wear.body = w.body;
                    c.wear.s0 = w.s0;
                    c.wear.angle = w.angle;
                    c.wear.passes = w.passes;
                    c.wear.speed = w.speed;
                    for (std::string& text : cwcli::wear_row_warnings(w.s0, w.angle, w.passes, r))
                        warnings.push_back(std::move(text));
                }
                if (strict && !warnings.empty()) {
                    c.rejected = "line " + std::to_string(line) + ": " + joined(warnings);
                    c.rejected_status = kStatusRowImplausible;
                    warnings.clear();
                }
            } catch (const RowError& e) {
                c = ContactCase{};
                c.rejected = e.message;
                c.rejected_status = status_of(e.why);
                warnings.clear();
            }
            in.cases.push_back(std::move(c));
            in.ids.push_back(std::move(id));
            in.lines.push_back(line);
            in.warnings.push_back(warnings.empty() ? std::string()
                                                   : "warning: " + joined(warnings));
            if (in.has_s0) in.s0.push_back(s0);
            if (in.has_distance) in.distance.push_back(distance);
        }
        if (file.bad()) throw InputError(path + ": read error");
        in.hash = file.hash();
        in.gap_hash = gaps.hash();
    } catch (const cwcli::RowFileError& e) {
        throw InputError(e.what());
    }
    if (in.cases.empty()) throw InputError(path + ": the file has a header but no rows");
    return in;
}

} // namespace cwcampaign
