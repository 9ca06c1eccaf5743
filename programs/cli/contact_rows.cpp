#include "contact_rows.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "options.hpp"

namespace cwcli {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Another name for a column: (alias, input).
const std::pair<const char*, Input> kAliases[] = {{"spin", Input::phi}};

bool is_wear_column(Input in)
{
    return in == Input::body || in == Input::contact_angle || in == Input::passes ||
           in == Input::speed;
}

bool is_gap_column(Input in)
{
    return in == Input::gap_file || in == Input::approach || in == Input::normal_method;
}

// Whether the command reads the column (else it is ignored with a note).
bool reads(RowFile kind, Input in)
{
    if (in == Input::id) return kind != RowFile::wear;
    if (is_wear_column(in)) return kind != RowFile::campaign;
    if (is_gap_column(in)) return kind != RowFile::wear;
    return true;
}

// The columns a row needs; a row with a gap_file takes its contact from the
// file, so it needs no semi-axes (and N or approach, checked by the campaign).
std::vector<Input> required(RowFile kind, bool gap_row = false)
{
    std::vector<Input> r;
    if (!gap_row) r = {Input::a, Input::b, Input::N};
    if (kind != RowFile::campaign) r.insert(r.begin(), Input::s0);
    if (kind != RowFile::wear) r.insert(r.begin(), Input::id);
    return r;
}

std::string joined(const std::vector<std::string>& names, const char* separator = ", ")
{
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : separator) + n;
    return out;
}

const char* command_name(RowFile kind)
{
    return kind == RowFile::wear            ? "creepwork wear"
           : kind == RowFile::campaign_wear ? "creepwork campaign --wear"
                                            : "creepwork campaign";
}

bool blank_record(const std::vector<std::string>& fields)
{
    return fields.size() == 1 && fields[0].empty();
}

bool comment_record(const std::vector<std::string>& fields)
{
    return !fields.empty() && !fields[0].empty() && fields[0][0] == '#';
}

} // namespace

RowHeader::RowHeader(const std::vector<std::string>& fields, RowFile kind, const std::string& path)
    : columns_(fields.size()), kind_(kind)
{
    std::vector<std::string> known;
    for (const InputInfo& i : all_inputs()) known.emplace_back(i.column);
    for (const auto& [alias, in] : kAliases) known.emplace_back(alias);
    std::vector<std::string> ignored;
    for (size_t k = 0; k < fields.size(); ++k) {
        const std::string& name = fields[k];
        const InputInfo* found = nullptr;
        for (const InputInfo& i : all_inputs())
            if (name == i.column) found = &i;
        for (const auto& [alias, in] : kAliases)
            if (name == alias) found = &info(in);
        if (!found) {
            const std::string hint = nearest(name, known);
            throw RowFileError(path + ": column '" + name + "' (header field " +
                               std::to_string(k + 1) + ") is unknown" +
                               (hint.empty() ? std::string() : "; did you mean " + hint + "?") +
                               " (doc/input-schema.md lists the columns)");
        }
        const Input in = found->input;
        if (spelling_.count(in))
            throw RowFileError(
                path + ": column '" + name + "' appears twice in the header" +
                (spelling_[in] != name ? " (as '" + spelling_[in] + "': " + name +
                                             " is another name for " + found->column + ")"
                                       : std::string()));
        spelling_[in] = name;
        if (reads(kind, in))
            field_[in] = k;
        else
            ignored.push_back(name);
    }
    if (kind == RowFile::campaign_wear && has(Input::gap_file))
        throw RowFileError(path + ": column gap_file: creepwork campaign --wear takes elliptic "
                                  "rows only (a, b); solve contacts of any shape without --wear");
    // With a gap_file column, rows may take their contact from gap files: a,
    // b are then optional columns, and the load is N or approach.
    const bool gap = has(Input::gap_file);
    if (gap && !has(Input::N) && !has(Input::approach))
        throw RowFileError(path + ": the header lacks N and approach (a row with a gap_file "
                                  "needs the normal force N or the approach)");
    std::vector<std::string> missing;
    for (Input in : required(kind, gap))
        if (!has(in)) missing.emplace_back(info(in).column);
    if (!missing.empty()) {
        std::vector<std::string> need;
        for (Input in : required(kind)) need.emplace_back(info(in).column);
        throw RowFileError(path + ": the header lacks the required column(s) " +
                           joined(missing, ",") + " (" + command_name(kind) + " requires " +
                           joined(need, ",") + "; the others are optional)");
    }
    if (!ignored.empty())
        notes_.push_back(
            "note: " + path + ": " + (ignored.size() == 1 ? "column " : "columns ") +
            joined(ignored) + (kind == RowFile::campaign ? " (read with --wear only)" : "") +
            " not read by " + command_name(kind) + ": ignored");
}

std::string RowHeader::spelling(Input in) const
{
    const auto it = spelling_.find(in);
    return it == spelling_.end() ? info(in).column : it->second;
}

RowFileReader::RowFileReader(const std::string& path, RowFile kind)
    : file_(path, std::ios::binary)
{
    if (!file_) throw RowFileError(path + ": cannot open the input file");
    // Spreadsheets export CSV with a UTF-8 byte-order mark; it is not part of
    // the first column's name.
    char bom[3] = {0, 0, 0};
    file_.read(bom, 3);
    if (!(file_.gcount() == 3 && bom[0] == '\xEF' && bom[1] == '\xBB' && bom[2] == '\xBF')) {
        file_.clear();
        file_.seekg(0);
    }
    csv_ = std::make_unique<CsvRecordReader>(file_);
    std::vector<std::string> fields;
    std::string error;
    bool found = false;
    while (!found && csv_->next(fields, error))
        found = !blank_record(fields) && !comment_record(fields);
    if (!found)
        throw RowFileError(path + ": the file is empty: no header line (expected a header "
                                  "line, then one row per contact)");
    if (!error.empty())
        throw RowFileError(path + ": header (line " + std::to_string(csv_->line()) + "): " +
                           error);
    header_ = RowHeader(fields, kind, path);
}

bool RowFileReader::next(std::vector<std::string>& cells, long& line, std::string& error)
{
    while (csv_->next(cells, error)) {
        if ((blank_record(cells) || comment_record(cells)) && error.empty()) continue;
        line = csv_->line();
        if (!error.empty())
            error = "line " + std::to_string(line) + ": " + error;
        else if (cells.size() != header_.columns())
            error = "line " + std::to_string(line) + " has " + std::to_string(cells.size()) +
                    " fields, the header " + std::to_string(header_.columns());
        return true;
    }
    return false;
}

const Units& RowSource::units() const
{
    static const Units si = Units::si();
    return si;
}

const std::string& RowSource::text(Input in) const
{
    static const std::string empty;
    return header_.has(in) ? cells_[header_.field(in)] : empty;
}

void RowSource::raise(const std::string& names, const std::string& problem, Refusal why) const
{
    throw RowError{"line " + std::to_string(line_) + ", column " + names + ": " + problem, why};
}

void RowSource::require(Input in) const
{
    if (!has(in)) fail(name(in), "empty (a value is required)", Refusal::unreadable);
}

void RowSource::require_values() const
{
    for (Input in : required(header_.kind(), has(Input::gap_file))) require(in);
}

double RowSource::number(Input in) const
{
    require(in);
    double v = 0.0;
    if (!parse_finite_double(text(in), v))
        fail(name(in), "'" + text(in) + "' is not a finite number", Refusal::unreadable);
    return v;
}

int RowSource::integer(Input in) const
{
    require(in);
    int v = 0;
    if (!parse_int(text(in), v))
        fail(name(in), "'" + text(in) + "' is not an integer", Refusal::unreadable);
    return v;
}

std::string RowSource::choice(Input in, const std::vector<std::string>& choices) const
{
    require(in);
    const std::string match = match_choice(text(in), choices);
    if (!match.empty()) return match;
    const std::string hint = nearest(text(in), choices);
    fail(name(in), "'" + text(in) + "' is not one of " + joined(choices, "|") +
                       (hint.empty() ? std::string() : "; did you mean " + hint + "?"),
         Refusal::unreadable);
}

bool RowSource::flag(Input in) const { return choice(in, {"0", "1"}) == "1"; }

WearPlacement read_wear_columns(const RowSource& r, const WearRules& rules)
{
    using R = ContactSource::Refusal;
    const auto out_of_range = [&r](Input in, const std::string& rule, const std::string& value) {
        r.fail(r.name(in), rule + " (got " + value + ")", R::invalid_input);
    };
    WearPlacement w;
    w.s0 = r.number(Input::s0);
    if (!(std::fabs(w.s0) <= 1e6)) out_of_range(Input::s0, "must lie within +-1e6 m", round_trip_text(w.s0) + " m");
    w.body = rules.default_body;
    if (r.has(Input::body)) w.body = r.choice(Input::body, {"rail", "wheel"}) == "wheel" ? 1 : 0;
    if (r.has(Input::contact_angle)) {
        w.angle = r.number(Input::contact_angle);
        if (!(std::fabs(w.angle) <= CW_WEAR_MAX_CONTACT_ANGLE))
            out_of_range(Input::contact_angle, "must lie within +-85 degrees (+-1.4835 rad)",
                         round_trip_text(w.angle) + " rad");
    }
    if (r.has(Input::passes) && r.has(Input::distance))
        r.fail(r.name(Input::passes), "give passes or distance, not both", R::unreadable);
    if (r.has(Input::passes)) {
        w.passes = r.number(Input::passes);
        if (!(w.passes >= 0 && w.passes <= CW_WEAR_MAX_PASSES))
            out_of_range(Input::passes, "must lie in [0, 1e15]", round_trip_text(w.passes));
    } else if (r.has(Input::distance)) {
        const double distance = r.number(Input::distance);
        if (w.body != 1)
            r.fail(r.name(Input::distance),
                   "is for a wheel (passes = distance / (2 pi R)); a rail row needs passes "
                   "(axle passages)",
                   R::unreadable);
        if (!(distance >= 0))
            out_of_range(Input::distance, "must be >= 0 (a rolled distance)",
                         round_trip_text(distance) + " m");
        if (!(rules.wheel_radius > 0))
            r.fail(r.name(Input::distance), "needs --wheel-radius (passes = distance / (2 pi R))",
                   R::unreadable);
        w.passes = distance / (2.0 * kPi * rules.wheel_radius);
        if (!(w.passes <= CW_WEAR_MAX_PASSES))
            out_of_range(Input::distance, "makes more than 1e15 passes",
                         round_trip_text(distance) + " m");
    } else {
        const bool columns = r.header().has(Input::passes) || r.header().has(Input::distance);
        const std::string need = w.body == 1 ? "a wheel row needs passes (revolutions) or "
                                               "distance (rolled, with --wheel-radius)"
                                             : "a rail row needs passes (axle passages)";
        r.fail(r.name(Input::passes),
               columns ? "empty: " + need : need + "; the file has no column passes",
               R::unreadable);
    }
    if (r.has(Input::speed)) {
        w.speed = r.number(Input::speed);
        if (!(w.speed > 0 && w.speed <= 1e3))
            out_of_range(Input::speed, "must lie in (0, 1000] m/s", round_trip_text(w.speed) + " m/s");
        if (r.has(Input::V) && std::fabs(w.speed - r.number(Input::V)) > 1e-9 * w.speed)
            r.fail(r.name(Input::speed),
                   round_trip_text(w.speed) + " m/s differs from the row's V " +
                       round_trip_text(r.number(Input::V)) +
                       " m/s: give the rolling speed once, or the same in both",
                   R::unreadable);
    } else if (rules.archard && !rules.speed_given && !r.has(Input::V)) {
        r.fail(r.name(Input::speed),
               "empty: Archard's KTH map needs the rolling speed (a speed or V column, or "
               "--speed)",
               R::unreadable);
    }
    return w;
}

std::string defaults_note(const RowHeader& header, const cw_params& defaults,
                          const std::string& path, const std::vector<Input>& given_elsewhere)
{
    const auto absent = [&](Input in) {
        return !header.has(in) &&
               std::find(given_elsewhere.begin(), given_elsewhere.end(), in) ==
                   given_elsewhere.end();
    };
    std::vector<std::string> columns, values;
    const auto add = [&](Input in, const std::string& value) {
        if (!absent(in)) return;
        columns.emplace_back(info(in).column);
        values.push_back(std::string(info(in).column) + " = " + value);
    };
    add(Input::mu, round_trip_text(defaults.mu));
    if (!header.has(Input::L1)) {
        add(Input::G, round_trip_text(defaults.G) + " Pa");
        add(Input::nu, round_trip_text(defaults.nu));
    }
    if (columns.empty()) return "";
    return "note: " + path + ": no column " + joined(columns, ", ") +
           ": every row takes the library's defaults (steel on steel), as creepwork solve: " +
           joined(values);
}

} // namespace cwcli
