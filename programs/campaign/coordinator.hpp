// Rank 0's scheduling loop: hands out chunks of the rows still to solve
// (ChunkPlanner) to every rank's worker -- its own LocalWorker included --
// keeping two chunks queued per worker, appends each returned chunk to the
// checkpoint, and reports progress on stderr. Dynamic: a worker that
// finishes sooner is given more; nothing about a result depends on who
// solved it or when.
#pragma once

#include <cstdint>
#include <vector>

#include "campaign_types.hpp"
#include "journal.hpp"
#include "worker.hpp"

namespace cwcampaign {

struct CoordinatorConfig {
    int mode = CW_SOLVE_FULL;
    uint64_t fixed_chunk = 0;    // rows per chunk; 0 = sized by measured speed
    double target_seconds = 0.25; // chunk duration aimed at when sized by speed
    WorkerConfig local;          // rank 0's own solver thread
    bool progress = true;        // progress lines on stderr:
    double first_report = 5.0;   //   the first after this many seconds,
    double report_every = 30.0;  //   then one every this many
};

struct RunStats {
    uint64_t rows = 0;    // solved in this run
    uint64_t chunks = 0;  // returned in this run
    double seconds = 0.0; // wall time of the loop
};

// Solves every row not marked done, appending results to journal. Returns
// when all are in the checkpoint and every worker has been told to stop.
RunStats coordinate(const std::vector<ContactCase>& cases, const std::vector<bool>& done,
                    Journal& journal, const CoordinatorConfig& config);

} // namespace cwcampaign
