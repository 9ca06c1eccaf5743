// The command line of `creepwork campaign` (creepwork-campaign), read with
// the CLI's strict parser: every rank parses the same argv to the same
// result, so a bad option stops every rank before any work.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "creep_table.hpp"
#include "surface_setup.hpp"
#include "wear_setup.hpp"

namespace cwcampaign {

struct CampaignOptions {
    bool help = false;
    bool table = false;   // --table: the rows are a creep-force table's points
    std::string in;       // --in FILE.csv (campaign)
    TableSpec spec;       // --table's axes and solver options
    std::string out;      // --out DIR
    bool resume = false, force = false;
    int threads = 0;          // --threads per rank; 0 = from the rank's CPUs
    uint64_t chunk = 0;       // --chunk rows; 0 = sized by measured speed
    int max_grids = 8;        // --max-grids: batches (grid shapes) kept per rank
    bool quiet = false;       // --quiet: no progress lines
    double progress = 0;      // --progress S: a line every S seconds; 0: 5 s, then 30 s
    bool strict = false;      // --strict: a row with a plausibility warning is rejected
    bool wear = false;        // --wear: each row's wear, accumulated on profiles
    WearSetup wear_setup;     // --wear's options (nodes made later, on rank 0)
    SurfaceSetup surface;     // --temperature, --mu-T, --k-yield
    std::vector<std::string> notes; // warnings about implausible options, for stderr
};

// Throws cwcli::CliError(kExitUsage) naming the option.
CampaignOptions read_campaign_options(int argc, char** argv, int first);

const char* usage_campaign();

} // namespace cwcampaign
