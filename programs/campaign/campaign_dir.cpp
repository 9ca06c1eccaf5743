#include "campaign_dir.hpp"

#include <filesystem>
#include <fstream>
#include <system_error>

#include "../cli/cli_error.hpp"

namespace fs = std::filesystem;

namespace cwcampaign {

const char* const kCampaignMarker = ".creepwork-campaign";
const char* const kCheckpointFile = "checkpoint.cwj";

namespace {

using cwcli::CliError;
using cwcli::kExitFailure;
using cwcli::kExitUsage;

// Files a campaign writes; --force removes these and nothing else.
const char* const kOwnFiles[] = {"checkpoint.cwj", "results.csv", "campaign.json",
                                 "table.csv",      "table.json"};

CliError refuse(const std::string& dir, const std::string& why)
{
    return cwcli::usage_error("--out", "'" + dir + "' " + why);
}

std::string identity_line(const JournalIdentity& id)
{
    return "identity " + std::to_string(id.kind) + " " + std::to_string(id.input_hash) + " " +
           std::to_string(id.rows);
}

// Whether the marker names this input (a finished campaign keeps no
// checkpoint, so the marker is what says what it was a campaign of).
bool marker_matches(const fs::path& d, const JournalIdentity& id)
{
    std::ifstream marker(d / kCampaignMarker);
    std::string line;
    while (std::getline(marker, line))
        if (line == identity_line(id)) return true;
    return false;
}

void start_fresh(const fs::path& d, const std::string& dir, const JournalIdentity& identity)
{
    std::error_code ec;
    fs::create_directories(d, ec);
    if (ec) throw CliError(kExitFailure, "--out: cannot create '" + dir + "': " + ec.message());
    for (const char* name : kOwnFiles) {
        fs::remove(d / name, ec);
        fs::remove(d / (std::string(name) + ".tmp"), ec);
    }
    std::ofstream marker(d / kCampaignMarker);
    marker << "Written by creepwork campaign; --force may replace its files.\n"
           << identity_line(identity) << "\n";
    marker.close();
    if (!marker)
        throw CliError(kExitFailure, "--out: cannot write into '" + dir + "' (" +
                                         (d / kCampaignMarker).string() + ")");
}

} // namespace

PreparedOutput prepare_output(const std::string& dir, bool resume, bool force,
                              const JournalIdentity& identity)
{
    if (dir.empty()) throw cwcli::usage_error("--out", "missing: the campaign's directory");
    const fs::path d(dir);
    std::error_code ec;
    PreparedOutput out;
    const bool exists = fs::exists(d, ec);
    if (exists && !fs::is_directory(d, ec)) throw refuse(dir, "exists and is not a directory");
    const bool fresh = !exists || fs::is_empty(d, ec);
    if (!fresh && !fs::exists(d / kCampaignMarker, ec))
        throw refuse(dir, std::string("exists and was not written by a campaign (no ") +
                              kCampaignMarker + "); refusing to write into it");
    const fs::path checkpoint = d / kCheckpointFile;
    const bool unfinished = !fresh && fs::exists(checkpoint, ec);
    if (unfinished && Journal::in_use(checkpoint.string()))
        throw refuse(dir, "is in use by a running campaign (its checkpoint is locked)");

    if (fresh || force) {
        start_fresh(d, dir, identity);
    } else if (unfinished && resume) {
        try {
            out.journal = std::make_unique<Journal>(
                Journal::open_existing(checkpoint.string(), identity));
        } catch (const JournalError& e) {
            throw refuse(dir, std::string("cannot be resumed: ") + e.what() +
                                  "; add --force to start over");
        }
        out.state = PreparedOutput::State::resumed;
        for (const Journal::Record& r : out.journal->records()) out.done_rows += r.count;
        out.dropped_torn_tail = out.journal->dropped_torn_tail();
        return out;
    } else if (unfinished) {
        throw refuse(dir, "holds an unfinished campaign; add --resume to continue it, or --force "
                          "to start over");
    } else if (resume) {
        if (!marker_matches(d, identity))
            throw refuse(dir, "holds a finished campaign of another input; add --force to "
                              "replace it, or choose another directory");
        out.state = PreparedOutput::State::complete;
        return out;
    } else {
        throw refuse(dir, "holds a finished campaign; add --force to replace it, or choose "
                          "another directory");
    }
    try {
        out.journal =
            std::make_unique<Journal>(Journal::create(checkpoint.string(), identity));
    } catch (const JournalError& e) {
        throw CliError(kExitFailure, std::string("--out: ") + e.what());
    }
    return out;
}

void remove_checkpoint(const std::string& dir)
{
    std::error_code ec;
    fs::remove(fs::path(dir) / kCheckpointFile, ec);
}

} // namespace cwcampaign
