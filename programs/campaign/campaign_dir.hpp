// The output directory of a campaign and its rules. Unlike `creepwork solve
// --out` (all or nothing), a campaign writes as it goes -- its checkpoint
// is what makes it resumable -- so the rules are about what an existing
// directory may hold:
//   - missing or empty: a new campaign starts there;
//   - written by a campaign (it holds .creepwork-campaign):
//       unfinished (a checkpoint): --resume continues it, after checking
//         the checkpoint belongs to this input; --force starts over;
//       finished (no checkpoint): --force starts over; --resume has
//         nothing to do;
//       without either flag: an error saying which flag to add;
//   - anything else: never touched.
// --resume on a missing or empty directory starts a new campaign, so a
// batch job that may be requeued can always pass it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "journal.hpp"

namespace cwcampaign {

extern const char* const kCampaignMarker; // ".creepwork-campaign"
extern const char* const kCheckpointFile; // "checkpoint.cwj"

struct PreparedOutput {
    enum class State { fresh, resumed, complete } state = State::fresh;
    std::unique_ptr<Journal> journal; // null when complete
    uint64_t done_rows = 0;           // rows already in the checkpoint
    bool dropped_torn_tail = false;
};

// Applies the rules above. Throws cwcli::CliError: kExitUsage for a
// directory the rules refuse (naming --out and the flag to use),
// kExitFailure when the file system refuses (naming the path).
PreparedOutput prepare_output(const std::string& dir, bool resume, bool force,
                              const JournalIdentity& identity);

// The end of a campaign: the checkpoint is no longer needed once the
// results are written (it would also make the directory look unfinished).
void remove_checkpoint(const std::string& dir);

} // namespace cwcampaign
