// What a campaign carries from its input to a worker and back: one contact
// (the grid and parameters of one row, or why the row could not be read)
// and the outcome of its solve. Plain data, so the same structs travel in
// MPI messages and in the checkpoint journal (wire.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

namespace cwcampaign {

// Status of a row the input reader rejected (never sent to the library).
// Library statuses are the CW_STATUS_LIST codes, all >= 0.
constexpr int kStatusRowUnreadable = -1;

// One contact, in SI, as cw_batch_solve takes it. A row the reader rejected
// keeps its reason in `unreadable` and is passed through untouched.
struct ContactCase {
    cw_grid grid;
    cw_params params;
    std::string unreadable; // non-empty: the row could not be read (the message)
};

// The result of one row: the library's status and totals, or a message.
struct Outcome {
    int status = CW_OK; // CW_OK, a CW_ERR_* code, or kStatusRowUnreadable
    cw_result result;   // valid when status == CW_OK
    std::string message; // why the row failed ("" when it succeeded)
    // Seam for issue 11 (wear): a worker will put the row's wear-depth
    // profile on the host's profile grid here, computed from the row's own
    // solve; rank 0 adds the profiles in input order (results_writer.hpp),
    // so the sum does not depend on ranks or threads. Empty until then.
    std::vector<double> wear;
};

// A run of consecutive input rows: the unit of scheduling and checkpoints.
struct Chunk {
    uint64_t id = 0;        // assignment number (diagnostics only)
    uint64_t first_row = 0; // input row index (0-based) of cases[0]
    int mode = CW_SOLVE_FULL;
    std::vector<ContactCase> cases;
};

struct ChunkResult {
    uint64_t id = 0;
    uint64_t first_row = 0;
    double seconds = 0.0; // the worker's wall time for the chunk (load balancing)
    std::vector<Outcome> outcomes;
};

// Human name of a status for results.csv: "ok", "CW_ERR_INVALID_INPUT", ...,
// or "ROW_UNREADABLE".
const char* status_name(int status);

} // namespace cwcampaign
