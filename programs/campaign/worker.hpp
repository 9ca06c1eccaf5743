// The workers: they take chunks, solve them (ChunkSolver) and hand back
// the results. Ranks 1.. run RemoteWorker's loop over MPI; rank 0 also
// solves, on a thread of its own (LocalWorker), while its main thread
// schedules, so a one-rank-per-node job loses no node to bookkeeping.
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>

#include "campaign_types.hpp"
#include "surface_setup.hpp"
#include "wear_setup.hpp"

namespace cwcampaign {

struct WorkerConfig {
    int threads = 1;        // OpenMP threads of each cw_batch
    size_t max_batches = 8; // grid shapes kept ready at once
    // Test hook (CREEPWORK_CAMPAIGN_TEST_CHUNK_DELAY_MS): sleep after each
    // chunk, so that a test can kill a run while it is certainly midway.
    int test_delay_ms = 0;
    // --wear, and --temperature or --k-yield: rows are solved one by one
    // with their wear, temperature and damage (RowChunkSolver); the setups
    // outlive the workers. Both nullptr: the batch API (ChunkSolver).
    const WearSetup* wear = nullptr;
    const SurfaceSetup* surface = nullptr;
};

// Ranks other than 0: until rank 0 says stop, solve the chunks it sends, in
// the order sent, and send each result back.
void run_remote_worker(const WorkerConfig& config);

// Rank 0's solver thread. give() and stop() queue work; take() returns a
// finished result if there is one. A failure inside the thread (out of
// memory) is rethrown by take().
class LocalWorker {
public:
    explicit LocalWorker(const WorkerConfig& config);
    ~LocalWorker(); // stops and joins
    LocalWorker(const LocalWorker&) = delete;
    LocalWorker& operator=(const LocalWorker&) = delete;

    void give(Chunk chunk);
    void stop();
    bool take(ChunkResult& result);

private:
    void run();

    WorkerConfig config_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<Chunk> inbox_;
    std::deque<ChunkResult> outbox_;
    bool stopping_ = false;
    std::exception_ptr failure_;
    std::thread thread_;
};

} // namespace cwcampaign
