// Solves the rows of a chunk one by one when a row needs more than the
// batch API returns -- its fields, for its wear (--wear) or its surface
// temperature and damage indices (--temperature, --k-yield) -- each on a
// cw_solver of its grid (CW_SOLVE_FULL, cold: warm_start = 0, so a row's
// result is what cw_batch_solve gives, bitwise, whoever solves it). A row
// with friction mu(T) (--mu-T) runs cw_temperature_solve's loop on a new
// solver, as `creepwork solve --mu-T` does. The rows are spread over
// `threads` threads, each with its own handles (one set per grid shape,
// least recently used dropped) and wear accumulators; the threads'
// accumulators are merged at the end of the chunk. They sum exactly
// (cw_wear_profile_*), so the chunk's profile states do not depend on which
// thread added which row.
#pragma once

#include <list>
#include <memory>
#include <vector>

#include <creepwork/creepwork.h>

#include "campaign_types.hpp"
#include "surface_setup.hpp"
#include "wear_setup.hpp"

namespace cwcampaign {

class RowChunkSolver {
public:
    // wear, surface: nullptr when not asked for; both outlive the solver.
    RowChunkSolver(int threads, size_t max_grids, const WearSetup* wear,
                   const SurfaceSetup* surface);
    ~RowChunkSolver();
    RowChunkSolver(const RowChunkSolver&) = delete;
    RowChunkSolver& operator=(const RowChunkSolver&) = delete;

    // One outcome per case (with its wear and surface values), and with
    // --wear the chunk's profile states per body (empty for a body no row
    // wore). Never throws for a bad row: its status and message go into its
    // outcome, and it adds nothing to a profile.
    ChunkResult solve(const Chunk& chunk);

private:
    // A grid's handles; the post-processors' only when asked for.
    struct Handles {
        cw_grid grid;
        cw_solver* solver = nullptr;
        cw_wear* wear = nullptr;
        cw_temperature* temperature = nullptr;
        cw_damage* damage = nullptr;
        void release(); // destroys every handle
    };
    // One thread's handles and accumulators.
    struct Lane {
        std::list<Handles> grids; // most recently used first
        cw_wear_profile* profile[kWearBodies] = {nullptr, nullptr};
        ~Lane();
    };

    Handles* handles_for(Lane& lane, const cw_grid& grid, int& status, std::string& message);
    void solve_row(Lane& lane, const ContactCase& c, Outcome& out);
    // The row's wear, added to the lane's profile; its status (out: failed).
    int add_wear(Lane& lane, Handles& h, const ContactCase& c, Outcome& out);
    // The row's temperature (unless --mu-T computed it) and damage indices.
    int add_surface(Handles& h, const cw_solver* solver, const ContactCase& c,
                    const cw_temperature_result* solved, Outcome& out);

    int threads_;
    size_t max_grids_;
    const WearSetup* wear_;
    const SurfaceSetup* surface_;
    std::vector<std::unique_ptr<Lane>> lanes_;
};

} // namespace cwcampaign
