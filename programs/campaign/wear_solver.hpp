// Solves the rows of a chunk with their wear (--wear): each row on a
// cw_solver of its grid (CW_SOLVE_FULL, cold: warm_start = 0, so a row's
// result is what cw_batch_solve gives, bitwise, whoever solves it), its
// wear by cw_wear_compute, and its lateral wear profile added, its passes
// times, to its body's profile accumulator. The batch API returns no
// fields, so the rows are spread over `threads` threads here, each with its
// own solvers (one per grid shape, least recently used dropped) and
// accumulators; the threads' accumulators are merged at the end of the
// chunk. The accumulators sum exactly (cw_wear_profile_*), so the chunk's
// profile states do not depend on which thread added which row.
#pragma once

#include <list>
#include <memory>
#include <vector>

#include <creepwork/creepwork.h>

#include "campaign_types.hpp"
#include "wear_setup.hpp"

namespace cwcampaign {

class WearChunkSolver {
public:
    WearChunkSolver(int threads, size_t max_grids, const WearSetup& setup);
    ~WearChunkSolver();
    WearChunkSolver(const WearChunkSolver&) = delete;
    WearChunkSolver& operator=(const WearChunkSolver&) = delete;

    // One outcome per case (with its wear values), and the chunk's profile
    // states per body (empty for a body no row wore). Never throws for a
    // bad row: its status and message go into its outcome, and it adds
    // nothing to a profile.
    ChunkResult solve(const Chunk& chunk);

private:
    struct Handles {
        cw_grid grid;
        cw_solver* solver = nullptr;
        cw_wear* wear = nullptr;
    };
    // One thread's solvers and accumulators.
    struct Lane {
        std::list<Handles> grids; // most recently used first
        cw_wear_profile* profile[kWearBodies] = {nullptr, nullptr};
        ~Lane();
    };

    Handles* handles_for(Lane& lane, const cw_grid& grid, int& status, std::string& message);
    void solve_row(Lane& lane, const ContactCase& c, Outcome& out);

    int threads_;
    size_t max_grids_;
    const WearSetup& setup_;
    std::vector<std::unique_ptr<Lane>> lanes_;
};

} // namespace cwcampaign
