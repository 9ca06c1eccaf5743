// Rank 0's end of a wear campaign: the chunks' profile states (read from
// the checkpoint in input order) added into one exact accumulator per body,
// and the accumulated depths written as DIR/wear_profile_rail.csv and
// DIR/wear_profile_wheel.csv (each only when some row wore that body). The
// sums are exact, so the files are bitwise the same for any ranks, threads,
// chunking, and for a run resumed after a kill.
#pragma once

#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "campaign_types.hpp"
#include "wear_setup.hpp"

namespace cwcampaign {

class WearProfiles {
public:
    explicit WearProfiles(const WearSetup& setup); // throws std::runtime_error
    ~WearProfiles();
    WearProfiles(const WearProfiles&) = delete;
    WearProfiles& operator=(const WearProfiles&) = delete;

    // Adds a chunk's states (throws JournalError for a state of other nodes).
    void add_chunk(const ChunkResult& chunk);
    // Writes the profile files into dir; returns their names.
    std::vector<std::string> write(const std::string& dir) const;
    // Totals of body's accumulator (adds == 0: no row wore it).
    cw_wear_profile_totals totals(int body) const;

private:
    const WearSetup& setup_;
    cw_wear_profile* profile_[kWearBodies] = {nullptr, nullptr};
};

} // namespace cwcampaign
