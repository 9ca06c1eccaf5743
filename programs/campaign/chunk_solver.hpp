// Solves the contacts of a chunk through the library's batch API: one
// cw_batch per grid shape (kind, nx, ny, box scale), each running `threads`
// OpenMP threads, kept in a small least-recently-used cache so that a
// campaign mixing shapes does not rebuild a batch (and, for the exact
// model, its influence tables) for every chunk. Each contact's result is
// the library's own, bitwise equal to a one-by-one cw_solver_solve (the
// batch's guarantee), so it cannot depend on which rank or thread ran it.
// A gap grid's shape includes its origin and spacing: one batch per
// distinct gap grid, each row's gap the values its chunk carries.
#pragma once

#include <cstddef>
#include <list>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "campaign_types.hpp"

namespace cwcampaign {

class ChunkSolver {
public:
    ChunkSolver(int threads, size_t max_batches);
    ~ChunkSolver();
    ChunkSolver(const ChunkSolver&) = delete;
    ChunkSolver& operator=(const ChunkSolver&) = delete;

    // One outcome per case, in the chunk's order. Never throws for a bad
    // contact: its status and the library's message go into its outcome.
    std::vector<Outcome> solve(const Chunk& chunk);

private:
    struct Entry {
        cw_grid grid;
        cw_batch* batch = nullptr;
    };
    // The batch for grid (created on first use), or nullptr with the
    // library's status and message when the grid is rejected.
    cw_batch* batch_for(const cw_grid& grid, int& status, std::string& message);
    // The chunk's cases at rows (one grid) solved in mode into out.
    void solve_rows(cw_batch* batch, const Chunk& chunk, const std::vector<size_t>& rows,
                    int mode, std::vector<Outcome>& out);

    int threads_;
    size_t max_batches_;
    std::list<Entry> batches_; // most recently used first
    std::vector<cw_params> params_;
    std::vector<cw_result> results_;
    std::vector<int> statuses_;
};

} // namespace cwcampaign
