#include "results_writer.hpp"

#include <algorithm>
#include <cmath>

#include "atomic_file.hpp"
#include "../cli/csv_text.hpp"
#include "number_text.hpp" // the digits `creepwork solve --format json` prints

namespace cwcampaign {

using cwcli::csv_quote;

namespace {

// The numbers of one result, in the order of `creepwork solve`'s JSON keys,
// then the fields appended to cw_result in 1.1 and 1.2.
struct Column {
    const char* name;
    double (*real)(const cw_result&);
    long (*integer)(const cw_result&);
};

#define CW_REAL(field) {#field, [](const cw_result& r) { return r.field; }, nullptr}
#define CW_INT(field) {#field, nullptr, [](const cw_result& r) { return long(r.field); }}
const Column kColumns[] = {
    CW_REAL(Fx),        CW_REAL(Fy),           CW_REAL(Mz),
    CW_REAL(W_macro),   CW_REAL(W_micro_paper), CW_REAL(K),
    CW_REAL(W_consistent), CW_REAL(balance_factor), CW_INT(work_flags),
    CW_REAL(adhesion_fraction), CW_INT(n_contact), CW_INT(n_adhesion),
    CW_INT(n_slip),     CW_REAL(a),            CW_REAL(b),
    CW_REAL(L1),        CW_REAL(L2),           CW_REAL(L3),
    CW_REAL(C11),       CW_REAL(C22),          CW_REAL(C23),
    CW_REAL(C33),       CW_REAL(profile_max_diff), CW_REAL(profile_rms_diff),
    CW_REAL(p_max),     CW_REAL(approach),     CW_INT(iterations),
    CW_REAL(residual),
    // Appended in 1.2: the normal force a gap row finds from its approach
    // (else the row's N) and the separate patches of a gap row.
    {"Fn", [](const cw_result& r) { return r.normal_force; }, nullptr},
    CW_INT(n_patches),
    // Appended in 1.3: the friction coefficient at rest and over the slip area.
    CW_REAL(mu_static), CW_REAL(mu_min), CW_REAL(mu_max)};
#undef CW_REAL
#undef CW_INT

// results.csv's wear columns, in WearValue order.
const char* const kWearColumns[kWearValues] = {
    "passes",          "wear_work",         "wear_mass_per_distance", "wear_mass_per_pass",
    "wear_max_depth",  "wear_mass",         "wear_area_regime1",      "wear_area_regime2",
    "wear_area_regime3", "wear_area_regime4"};

// results.csv's temperature and damage columns: `creepwork solve`'s JSON
// keys, each with its value in Outcome::surface and its group.
struct SurfaceColumn {
    const char* name;
    SurfaceValue value;
    bool ResultColumns::*group;
};
const SurfaceColumn kSurfaceColumns[] = {
    {"T_max_1", kSurfaceTMax1, &ResultColumns::temperature},
    {"T_max_2", kSurfaceTMax2, &ResultColumns::temperature},
    {"T_max_x", kSurfaceTMaxX, &ResultColumns::temperature},
    {"T_max_y", kSurfaceTMaxY, &ResultColumns::temperature},
    {"temperature_iterations", kSurfaceIterations, &ResultColumns::iterations},
    {"rcf_index_max", kSurfaceRcfIndexMax, &ResultColumns::damage},
    {"FI_surf", kSurfaceFISurf, &ResultColumns::damage},
    {"T_gamma", kSurfaceTGamma, &ResultColumns::damage},
    {"wlrm_damage", kSurfaceWlrmDamage, &ResultColumns::damage}};

std::string optional_number(const std::vector<double>& values, uint64_t row)
{
    const double v = values[row];
    return std::isnan(v) ? std::string() : number_text(v);
}

} // namespace

void for_each_row_in_order(const Journal& journal, uint64_t rows,
                           const std::function<void(uint64_t, const Outcome&)>& visit,
                           const std::function<void(const ChunkResult&)>& chunk_visit)
{
    std::vector<Journal::Record> order = journal.records();
    std::sort(order.begin(), order.end(),
              [](const Journal::Record& x, const Journal::Record& y) {
                  return x.first_row < y.first_row;
              });
    uint64_t next = 0;
    for (const Journal::Record& rec : order) {
        if (rec.first_row != next || rec.count == 0 || rec.first_row + rec.count > rows)
            throw JournalError("the checkpoint does not cover rows " + std::to_string(next) +
                               " onwards exactly once (chunk at row " +
                               std::to_string(rec.first_row) + ")");
        const ChunkResult chunk = journal.read(rec);
        if (chunk.first_row != rec.first_row || chunk.outcomes.size() != rec.count)
            throw JournalError("a checkpoint record does not match its index");
        if (chunk_visit) chunk_visit(chunk);
        for (uint64_t k = 0; k < rec.count; ++k) visit(rec.first_row + k, chunk.outcomes[k]);
        next = rec.first_row + rec.count;
    }
    if (next != rows)
        throw JournalError("the checkpoint holds " + std::to_string(next) + " of " +
                           std::to_string(rows) + " rows");
}

std::vector<std::string> results_columns(const CampaignInput& in, const ResultColumns& extra)
{
    std::vector<std::string> names = {"id", "status"};
    for (const Column& c : kColumns) names.emplace_back(c.name);
    if (in.has_s0) names.emplace_back("s0");
    if (in.has_distance) names.emplace_back("distance");
    if (extra.wear) {
        names.emplace_back("body");
        for (const char* name : kWearColumns) names.emplace_back(name);
    }
    for (const SurfaceColumn& c : kSurfaceColumns)
        if (extra.*c.group) names.emplace_back(c.name);
    names.emplace_back("message");
    return names;
}

MergeSummary write_results_csv(const Journal& journal, const CampaignInput& in,
                               const std::string& path, WearProfiles* wear,
                               ResultColumns extra)
{
    extra.wear = wear != nullptr;
    AtomicFile out(path);
    std::string line;
    for (const std::string& name : results_columns(in, extra))
        line += (line.empty() ? "" : ",") + name;
    out.write(line + "\n");

    MergeSummary summary;
    summary.rows = in.cases.size();
    for_each_row_in_order(journal, summary.rows, [&](uint64_t row, const Outcome& o) {
        line = csv_quote(in.ids[row]) + "," + status_name(o.status);
        for (const Column& c : kColumns) {
            line += ',';
            if (o.status != CW_OK) continue;
            if (c.real)
                append_number(line, c.real(o.result));
            else
                line += std::to_string(c.integer(o.result));
        }
        if (in.has_s0) line += "," + optional_number(in.s0, row);
        if (in.has_distance) line += "," + optional_number(in.distance, row);
        if (wear) {
            const ContactCase& c = in.cases[row];
            line += ',';
            if (c.rejected.empty()) line += body_name(c.wear.body);
            for (int k = 0; k < kWearValues; ++k) {
                line += ',';
                if (o.status == CW_OK && o.wear.size() == kWearValues)
                    append_number(line, o.wear[k]);
            }
        }
        for (const SurfaceColumn& c : kSurfaceColumns) {
            if (!(extra.*c.group)) continue;
            line += ',';
            if (o.status == CW_OK && o.surface.size() == kSurfaceValues)
                append_number(line, o.surface[c.value]);
        }
        // A solved row's message holds its plausibility warnings.
        const std::string& message = o.status == CW_OK ? in.warnings[row] : o.message;
        line += "," + csv_quote(message) + "\n";
        out.write(line);
        // Messages of rejected rows already name their line.
        const std::string where =
            "id " + in.ids[row] + ": " +
            (message.compare(0, 5, "line ") == 0 ? ""
                                                 : "line " + std::to_string(in.lines[row]) + ": ");
        if (o.status == CW_OK) {
            ++summary.ok;
            if (!message.empty() && ++summary.warned <= 3)
                summary.first_warnings.push_back(where + message);
        } else {
            ++summary.failed;
            if (summary.first_failures.size() < 3) summary.first_failures.push_back(where + message);
        }
    }, wear ? std::function<void(const ChunkResult&)>(
                  [wear](const ChunkResult& chunk) { wear->add_chunk(chunk); })
            : nullptr);
    out.commit();
    return summary;
}

} // namespace cwcampaign
