#include "coordinator.hpp"

#include <chrono>
#include <memory>

#include "../cli/progress.hpp"
#include "chunk_planner.hpp"
#include "mpi_link.hpp"
#include "wire.hpp"

namespace cwcampaign {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Chunks queued per worker: one being solved, one waiting, so a worker
// never idles while rank 0 answers.
constexpr int kQueueDepth = 2;

struct WorkerState {
    int outstanding = 0;
    double rate = 0.0; // rows per second, smoothed
    bool stopped = false;
};

class Coordinator {
public:
    Coordinator(const std::vector<ContactCase>& cases, const std::vector<bool>& done,
                Journal& journal, const CoordinatorConfig& config)
        : cases_(cases), journal_(journal), config_(config), workers_(mpi::size()),
          planner_(pending_ranges(done), config.fixed_chunk, mpi::size(), config.target_seconds),
          total_(cases.size()), already_(cases.size() - planner_.remaining())
    {
    }

    RunStats run()
    {
        const Clock::time_point start = Clock::now();
        local_ = std::make_unique<LocalWorker>(config_.local);
        for (int w = 0; w < static_cast<int>(workers_.size()); ++w) top_up(w);
        mpi::Backoff backoff;
        Clock::time_point last_sync = Clock::now();
        cwcli::Progress progress("campaign", "rows", total_,
                                 {config_.progress, config_.first_report, config_.report_every},
                                 already_);
        Bytes bytes;
        int source = 0;
        while (!finished()) {
            bool progressed = false;
            sends_.progress();
            while (mpi::try_receive(mpi::kTagResult, bytes, source)) {
                const ChunkResult r = decode_result(bytes);
                accept(source, r, bytes);
                progressed = true;
            }
            ChunkResult local;
            while (local_->take(local)) {
                accept(0, local, encode_result(local));
                progressed = true;
            }
            if (since(last_sync) >= 1.0) {
                journal_.sync();
                last_sync = Clock::now();
            }
            progress.update(already_ + stats_.rows);
            if (progressed)
                backoff.reset();
            else
                backoff.idle();
        }
        journal_.sync();
        for (int w = 0; w < static_cast<int>(workers_.size()); ++w) stop(w);
        sends_.wait_all();
        local_.reset(); // joins the solver thread
        stats_.seconds = since(start);
        return stats_;
    }

private:
    bool finished() const
    {
        if (!planner_.empty()) return false;
        for (const WorkerState& w : workers_)
            if (w.outstanding > 0) return false;
        return true;
    }

    // Queues chunks for worker w until it holds kQueueDepth; a stop once
    // there is nothing left to give.
    void top_up(int w)
    {
        WorkerState& s = workers_[static_cast<size_t>(w)];
        while (s.outstanding < kQueueDepth && !planner_.empty()) {
            const auto [first, count] = planner_.next(s.rate);
            Chunk chunk;
            chunk.id = next_id_++;
            chunk.first_row = first;
            chunk.mode = config_.mode;
            chunk.cases.assign(cases_.begin() + static_cast<std::ptrdiff_t>(first),
                               cases_.begin() + static_cast<std::ptrdiff_t>(first + count));
            if (w == 0)
                local_->give(std::move(chunk));
            else
                sends_.start(w, mpi::kTagWork, encode_chunk(chunk));
            ++s.outstanding;
        }
        if (planner_.empty()) stop(w);
    }

    void stop(int w)
    {
        WorkerState& s = workers_[static_cast<size_t>(w)];
        if (s.stopped) return;
        s.stopped = true;
        if (w == 0)
            local_->stop();
        else
            sends_.start(w, mpi::kTagWork, encode_stop());
    }

    void accept(int w, const ChunkResult& r, const Bytes& encoded)
    {
        WorkerState& s = workers_[static_cast<size_t>(w)];
        journal_.append(r.first_row, r.outcomes.size(), encoded);
        --s.outstanding;
        stats_.rows += r.outcomes.size();
        ++stats_.chunks;
        if (r.seconds > 0.0) {
            const double rate = static_cast<double>(r.outcomes.size()) / r.seconds;
            s.rate = s.rate > 0.0 ? 0.5 * (s.rate + rate) : rate;
        }
        top_up(w);
    }

    const std::vector<ContactCase>& cases_;
    Journal& journal_;
    CoordinatorConfig config_;
    std::vector<WorkerState> workers_;
    ChunkPlanner planner_;
    uint64_t total_, already_;
    std::unique_ptr<LocalWorker> local_;
    mpi::PendingSends sends_;
    uint64_t next_id_ = 0;
    RunStats stats_;
};

} // namespace

RunStats coordinate(const std::vector<ContactCase>& cases, const std::vector<bool>& done,
                    Journal& journal, const CoordinatorConfig& config)
{
    Coordinator c(cases, done, journal, config);
    return c.run();
}

} // namespace cwcampaign
