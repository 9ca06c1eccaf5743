#include "input_csv.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <unordered_map>

#include "../options.hpp" // parse_finite_double, parse_int, nearest: the CLI's strict rules
#include "csv_text.hpp"

namespace cwcampaign {

const std::vector<std::string>& required_columns()
{
    static const std::vector<std::string> c = {"id", "model", "grid", "nx",   "ny",
                                               "a",  "b",     "N",    "mu",   "G",
                                               "nu", "xi_x",  "xi_y", "phi"};
    return c;
}

const std::vector<std::string>& optional_columns()
{
    static const std::vector<std::string> c = {
        "box_scale", "pressure",  "rolling_direction", "spin_offset", "flexibility_blending",
        "L1",        "L2",        "L3",                "tolerance",   "max_iterations",
        "s0",        "distance"};
    return c;
}

const std::vector<std::string>& wear_columns()
{
    static const std::vector<std::string> c = {"body", "contact_angle", "passes", "speed"};
    return c;
}

namespace {

constexpr double kPi = 3.14159265358979323846;

// A row the reader rejects: the message names the line and the column.
struct RowError {
    std::string message;
};

std::string lower(std::string s)
{
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

class RowReader {
public:
    RowReader(const std::map<std::string, size_t>& index, const std::vector<std::string>& fields,
              long line)
        : index_(index), fields_(fields), line_(line)
    {
    }

    bool has(const std::string& column) const
    {
        const auto it = index_.find(column);
        return it != index_.end() && !fields_[it->second].empty();
    }
    const std::string& text(const std::string& column) const
    {
        static const std::string empty;
        const auto it = index_.find(column);
        return it == index_.end() ? empty : fields_[it->second];
    }
    [[noreturn]] void fail(const std::string& column, const std::string& problem) const
    {
        throw RowError{"line " + std::to_string(line_) + ", column " + column + ": " + problem};
    }
    void require(const std::string& column) const
    {
        if (!has(column)) fail(column, "empty (a value is required)");
    }
    double number(const std::string& column) const
    {
        require(column);
        double v = 0.0;
        if (!cwcli::parse_finite_double(text(column), v))
            fail(column, "'" + text(column) + "' is not a finite number");
        return v;
    }
    int integer(const std::string& column) const
    {
        require(column);
        int v = 0;
        if (!cwcli::parse_int(text(column), v))
            fail(column, "'" + text(column) + "' is not an integer");
        return v;
    }
    // Index of the value among choices (not case sensitive, as the CLI).
    size_t choice(const std::string& column, const std::vector<std::string>& choices) const
    {
        require(column);
        const std::string v = lower(text(column));
        for (size_t k = 0; k < choices.size(); ++k)
            if (v == choices[k]) return k;
        std::string list;
        for (const std::string& c : choices) list += (list.empty() ? "" : "|") + c;
        const std::string hint = cwcli::nearest(text(column), choices);
        fail(column, "'" + text(column) + "' is not one of " + list +
                         (hint.empty() ? std::string() : "; did you mean " + hint + "?"));
    }

private:
    const std::map<std::string, size_t>& index_;
    const std::vector<std::string>& fields_;
    long line_;
};

ContactCase read_row(const RowReader& r)
{
    ContactCase c{};
    cw_grid_init(&c.grid);
    cw_params_init(&c.params);
    cw_params& p = c.params;

    static const int models[] = {CW_MODEL_FASTSIM, CW_MODEL_EXACT, CW_MODEL_CALIBRATED};
    p.model = models[r.choice("model", {"fastsim", "exact", "calibrated"})];
    c.grid.kind = r.choice("grid", {"strips", "uniform"}) == 1 ? CW_GRID_UNIFORM
                                                               : CW_GRID_KALKER_STRIPS;
    c.grid.nx = r.integer("nx");
    c.grid.ny = r.integer("ny");
    if (r.has("box_scale")) {
        if (c.grid.kind != CW_GRID_UNIFORM) r.fail("box_scale", "only used with grid = uniform");
        c.grid.box_scale = r.number("box_scale");
    }

    p.a = r.number("a");
    p.b = r.number("b");
    p.normal_force = r.number("N");
    p.mu = r.number("mu");
    p.xi_x = r.number("xi_x");
    p.xi_y = r.number("xi_y");
    p.phi = r.number("phi");

    // Flexibilities: G and nu, or all three of L1, L2, L3 (as the CLI's
    // --L1 --L2 --L3), never both.
    const int given = r.has("L1") + r.has("L2") + r.has("L3");
    if (given == 0) {
        p.G = r.number("G");
        p.nu = r.number("nu");
    } else {
        if (given != 3)
            r.fail(!r.has("L1") ? "L1" : !r.has("L2") ? "L2" : "L3",
                   "empty: L1, L2 and L3 must be given together");
        if (r.has("G") || r.has("nu"))
            r.fail(r.has("G") ? "G" : "nu", "must be empty when L1, L2, L3 give the flexibilities");
        p.flexibility = CW_FLEX_GIVEN;
        p.L1 = r.number("L1");
        p.L2 = r.number("L2");
        p.L3 = r.number("L3");
    }

    if (r.has("pressure"))
        p.pressure = r.choice("pressure", {"parabolic", "elliptic"}) == 1 ? CW_PRESSURE_ELLIPTIC
                                                                          : CW_PRESSURE_PARABOLIC;
    if (r.has("rolling_direction"))
        p.rolling_direction = r.choice("rolling_direction", {"+1", "1", "-1"}) == 2 ? -1 : 1;
    if (r.has("spin_offset")) p.spin_offset = r.number("spin_offset");
    if (r.has("flexibility_blending"))
        p.flexibility_blending = static_cast<int>(r.choice("flexibility_blending", {"0", "1"}));
    if (r.has("tolerance")) p.tolerance = r.number("tolerance");
    if (r.has("max_iterations")) p.max_iterations = r.integer("max_iterations");
    return c;
}

// The wear columns of a row (--wear), as `creepwork wear` reads them: s0;
// passes, or (a wheel) distance / (2 pi R); the contact angle, body, speed.
RowWear read_row_wear(const RowReader& r, const WearRules& rules, double s0, double distance)
{
    RowWear w;
    r.require("s0");
    if (!(std::fabs(s0) <= 1e6)) r.fail("s0", "must lie within +-1e6 m");
    w.s0 = s0;
    w.body = rules.default_body;
    if (r.has("body")) w.body = r.choice("body", {"rail", "wheel"}) == 1 ? kWheel : kRail;
    if (r.has("contact_angle")) {
        w.angle = r.number("contact_angle");
        if (!(std::fabs(w.angle) <= CW_WEAR_MAX_CONTACT_ANGLE))
            r.fail("contact_angle", "must lie within +-85 degrees (+-1.4835 rad)");
    }
    if (r.has("passes") && r.has("distance"))
        r.fail("passes", "give passes or distance, not both");
    if (r.has("passes")) {
        w.passes = r.number("passes");
        if (!(w.passes >= 0 && w.passes <= CW_WEAR_MAX_PASSES))
            r.fail("passes", "must lie in [0, 1e15]");
    } else if (r.has("distance")) {
        if (w.body != kWheel)
            r.fail("distance", "is for a wheel (passes = distance / (2 pi R)); a rail row needs "
                               "passes (axle passages)");
        if (!(rules.wheel_radius > 0))
            r.fail("distance", "needs --wheel-radius (passes = distance / (2 pi R))");
        w.passes = distance / (2.0 * kPi * rules.wheel_radius);
        if (!(w.passes <= CW_WEAR_MAX_PASSES)) r.fail("distance", "makes more than 1e15 passes");
    } else {
        r.fail("passes", w.body == kWheel ? "empty: a wheel row needs passes (revolutions) or "
                                            "distance (rolled, with --wheel-radius)"
                                          : "empty: a rail row needs passes (axle passages)");
    }
    if (r.has("speed")) {
        w.speed = r.number("speed");
        if (!(w.speed > 0 && w.speed <= 1e3)) r.fail("speed", "must lie in (0, 1000] m/s");
    } else if (rules.archard && !rules.speed_given) {
        r.fail("speed", "empty: Archard's KTH map needs the rolling speed (a speed column or "
                        "--speed)");
    }
    return w;
}

// The file-level checks: every column known, none twice, the required there.
std::map<std::string, size_t> column_index(const std::vector<std::string>& header,
                                           const std::string& path, bool wear)
{
    std::vector<std::string> known = required_columns();
    known.insert(known.end(), optional_columns().begin(), optional_columns().end());
    for (size_t k = 0; k < header.size(); ++k)
        if (!wear && std::find(wear_columns().begin(), wear_columns().end(), header[k]) !=
                         wear_columns().end())
            throw InputError(path + ": column '" + header[k] + "' is a wear column: add --wear "
                                                               "(or drop the column)");
    if (wear) known.insert(known.end(), wear_columns().begin(), wear_columns().end());
    std::map<std::string, size_t> index;
    for (size_t k = 0; k < header.size(); ++k) {
        const std::string& name = header[k];
        if (std::find(known.begin(), known.end(), name) == known.end()) {
            const std::string hint = cwcli::nearest(name, known);
            throw InputError(path + ": column '" + name + "' (header field " +
                             std::to_string(k + 1) + ") is unknown" +
                             (hint.empty() ? std::string("")
                                           : "; did you mean " + hint + "?") +
                             " (doc/campaigns.md lists the columns)");
        }
        if (!index.emplace(name, k).second)
            throw InputError(path + ": column '" + name + "' appears twice in the header");
    }
    std::string missing;
    for (const std::string& name : required_columns())
        if (!index.count(name)) missing += (missing.empty() ? "" : ",") + name;
    if (!missing.empty())
        throw InputError(path + ": the header lacks the required column(s) " + missing +
                         " (required: id,model,grid,nx,ny,a,b,N,mu,G,nu,xi_x,xi_y,phi)");
    return index;
}

bool blank_record(const std::vector<std::string>& fields)
{
    return fields.size() == 1 && fields[0].empty();
}

} // namespace

CampaignInput read_campaign_csv(const std::string& path, const WearRules* wear)
{
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path + ": cannot open the input file");
    // Spreadsheets export CSV with a UTF-8 byte-order mark; it is not part of
    // the first column's name.
    char bom[3] = {0, 0, 0};
    file.read(bom, 3);
    if (!(file.gcount() == 3 && bom[0] == '\xEF' && bom[1] == '\xBB' && bom[2] == '\xBF')) {
        file.clear();
        file.seekg(0);
    }
    CsvRecordReader csv(file);
    std::vector<std::string> header;
    std::string error;
    while (csv.next(header, error) && blank_record(header)) {
    }
    if (header.empty() || blank_record(header))
        throw InputError(path + ": the file is empty (expected a header line, then one row per "
                                "contact)");
    if (!error.empty())
        throw InputError(path + ": header (line " + std::to_string(csv.line()) + "): " + error);
    const std::map<std::string, size_t> index = column_index(header, path, wear != nullptr);
    if (wear && !index.count("s0"))
        throw InputError(path + ": --wear needs the column s0 (the profile coordinate of each "
                                "patch centre, m)");

    CampaignInput in;
    in.has_s0 = index.count("s0") != 0;
    in.has_distance = index.count("distance") != 0;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::unordered_map<std::string, long> id_line;
    std::vector<std::string> fields;
    const size_t id_column = index.at("id");
    while (csv.next(fields, error)) {
        if (blank_record(fields) && error.empty()) continue;
        const long line = csv.line();
        ContactCase c{};
        std::string id = id_column < fields.size() ? fields[id_column] : std::string();
        double s0 = nan, distance = nan;
        try {
            if (!error.empty()) throw RowError{"line " + std::to_string(line) + ": " + error};
            if (fields.size() != header.size())
                throw RowError{"line " + std::to_string(line) + " has " +
                               std::to_string(fields.size()) + " fields, the header " +
                               std::to_string(header.size())};
            const RowReader r(index, fields, line);
            r.require("id");
            const auto [seen, fresh] = id_line.emplace(id, line);
            if (!fresh)
                r.fail("id", "'" + id + "' repeats the id of line " + std::to_string(seen->second));
            c = read_row(r);
            if (r.has("s0")) s0 = r.number("s0");
            if (r.has("distance")) {
                distance = r.number("distance");
                if (distance < 0.0) r.fail("distance", "must be >= 0 (a rolled distance in m)");
            }
            if (wear) c.wear = read_row_wear(r, *wear, s0, distance);
        } catch (const RowError& e) {
            c = ContactCase{};
            c.unreadable = e.message;
        }
        in.cases.push_back(std::move(c));
        in.ids.push_back(std::move(id));
        in.lines.push_back(line);
        if (in.has_s0) in.s0.push_back(s0);
        if (in.has_distance) in.distance.push_back(distance);
    }
    if (csv.bad()) throw InputError(path + ": read error");
    if (in.cases.empty()) throw InputError(path + ": the file has a header but no rows");
    in.hash = csv.hash();
    return in;
}

} // namespace cwcampaign
