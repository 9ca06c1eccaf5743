// Which rows go into the next chunk: rank 0's load balancing. Rows are
// handed out in input order, in chunks sized to take about target_seconds
// on the worker that asks (from its measured rate), so a rank with slow
// contacts simply asks less often; near the end chunks shrink (at most the
// remaining rows / (2 x workers)) so that no worker finishes long after the
// others. A fixed --chunk size replaces the estimate. None of this can
// change a result: each contact is solved on its own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace cwcampaign {

class ChunkPlanner {
public:
    // pending: the row ranges [first, end) still to solve, ascending.
    ChunkPlanner(std::vector<std::pair<uint64_t, uint64_t>> pending, uint64_t fixed_chunk,
                 int workers, double target_seconds);

    bool empty() const { return range_ == pending_.size(); }
    uint64_t remaining() const { return remaining_; }
    // The next chunk [first, first + count) for a worker solving `rate` rows
    // per second (0 = not measured yet). Requires !empty().
    std::pair<uint64_t, uint64_t> next(double rate);

    static constexpr uint64_t kFirstChunk = 8;      // before any rate is known
    static constexpr uint64_t kMaxChunk = 1u << 16; // bounds a message and a lost chunk

private:
    std::vector<std::pair<uint64_t, uint64_t>> pending_;
    size_t range_ = 0;      // current range
    uint64_t cursor_ = 0;   // next row within it
    uint64_t remaining_ = 0;
    uint64_t fixed_;
    int workers_;
    double target_seconds_;
};

// The ranges of rows not yet done, from a done-flag per row.
std::vector<std::pair<uint64_t, uint64_t>> pending_ranges(const std::vector<bool>& done);

} // namespace cwcampaign
