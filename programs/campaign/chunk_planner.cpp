#include "chunk_planner.hpp"

#include <algorithm>
#include <cmath>

namespace cwcampaign {

ChunkPlanner::ChunkPlanner(std::vector<std::pair<uint64_t, uint64_t>> pending,
                           uint64_t fixed_chunk, int workers, double target_seconds)
    : pending_(std::move(pending)), fixed_(fixed_chunk), workers_(std::max(1, workers)),
      target_seconds_(target_seconds)
{
    pending_.erase(std::remove_if(pending_.begin(), pending_.end(),
                                  [](const auto& r) { return r.second <= r.first; }),
                   pending_.end());
    for (const auto& r : pending_) remaining_ += r.second - r.first;
    if (!pending_.empty()) cursor_ = pending_[0].first;
}

std::pair<uint64_t, uint64_t> ChunkPlanner::next(double rate)
{
    uint64_t count = 0;
    if (fixed_ > 0) {
        count = fixed_;
    } else {
        const double by_time = rate > 0.0 ? std::floor(rate * target_seconds_) : kFirstChunk;
        count = static_cast<uint64_t>(std::clamp(by_time, 1.0, double(kMaxChunk)));
        const uint64_t tail = remaining_ / (2 * static_cast<uint64_t>(workers_));
        count = std::max<uint64_t>(1, std::min(count, tail));
    }
    const uint64_t end = pending_[range_].second;
    count = std::min(count, end - cursor_);
    const std::pair<uint64_t, uint64_t> chunk{cursor_, count};
    cursor_ += count;
    remaining_ -= count;
    if (cursor_ == end && ++range_ < pending_.size()) cursor_ = pending_[range_].first;
    return chunk;
}

std::vector<std::pair<uint64_t, uint64_t>> pending_ranges(const std::vector<bool>& done)
{
    std::vector<std::pair<uint64_t, uint64_t>> ranges;
    const uint64_t n = done.size();
    for (uint64_t i = 0; i < n;) {
        if (done[i]) {
            ++i;
            continue;
        }
        uint64_t j = i;
        while (j < n && !done[j]) ++j;
        ranges.emplace_back(i, j);
        i = j;
    }
    return ranges;
}

} // namespace cwcampaign
