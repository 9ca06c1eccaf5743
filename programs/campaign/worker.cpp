#include "worker.hpp"

#include <chrono>

#include <memory>

#include "chunk_solver.hpp"
#include "mpi_link.hpp"
#include "row_solver.hpp"
#include "wire.hpp"

namespace cwcampaign {

namespace {

// A worker's solvers: the batches, or, when rows need their fields, the
// row-by-row solver.
struct Solvers {
    explicit Solvers(const WorkerConfig& c) : plain(c.threads, c.max_batches)
    {
        if (c.wear || (c.surface && c.surface->any()))
            rows = std::make_unique<RowChunkSolver>(c.threads, c.max_batches, c.wear, c.surface);
    }
    ChunkSolver plain;
    std::unique_ptr<RowChunkSolver> rows;
};

ChunkResult solve_chunk(Solvers& solvers, const Chunk& chunk, int test_delay_ms)
{
    const auto start = std::chrono::steady_clock::now();
    ChunkResult r;
    if (solvers.rows) {
        r = solvers.rows->solve(chunk);
    } else {
        r.id = chunk.id;
        r.first_row = chunk.first_row;
        r.outcomes = solvers.plain.solve(chunk);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (test_delay_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(test_delay_ms));
    return r;
}

} // namespace

void run_remote_worker(const WorkerConfig& config)
{
    Solvers solver(config);
    std::deque<Chunk> queue;
    bool stopping = false;
    mpi::Backoff backoff;
    Bytes message;
    int source = 0;
    for (;;) {
        // Rank 0 keeps up to two chunks queued here, so the next one is
        // usually waiting when a chunk is done. A stop comes after the
        // chunks sent before it (MPI keeps the order of one sender's
        // messages), so queued chunks are still solved.
        while (mpi::try_receive(mpi::kTagWork, message, source)) {
            if (is_stop(message))
                stopping = true;
            else
                queue.push_back(decode_chunk(message));
        }
        if (!queue.empty()) {
            const ChunkResult r = solve_chunk(solver, queue.front(), config.test_delay_ms);
            queue.pop_front();
            mpi::send(0, mpi::kTagResult, encode_result(r));
            backoff.reset();
            continue;
        }
        if (stopping) return;
        backoff.idle();
    }
}

LocalWorker::LocalWorker(const WorkerConfig& config) : config_(config)
{
    thread_ = std::thread([this] { run(); });
}

LocalWorker::~LocalWorker()
{
    {
        // Normally nothing is queued any more; after a failure elsewhere,
        // queued chunks are dropped (the checkpoint has what was finished).
        std::lock_guard<std::mutex> lock(mutex_);
        inbox_.clear();
        stopping_ = true;
    }
    wake_.notify_one();
    if (thread_.joinable()) thread_.join();
}

void LocalWorker::give(Chunk chunk)
{
    {
        std::lock_guard<std::mutex> lock(mutex_);
        inbox_.push_back(std::move(chunk));
    }
    wake_.notify_one();
}

void LocalWorker::stop()
{
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_one();
}

bool LocalWorker::take(ChunkResult& result)
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (failure_) std::rethrow_exception(failure_);
    if (outbox_.empty()) return false;
    result = std::move(outbox_.front());
    outbox_.pop_front();
    return true;
}

void LocalWorker::run()
{
    try {
        Solvers solver(config_);
        for (;;) {
            Chunk chunk;
            {
                std::unique_lock<std::mutex> lock(mutex_);
                wake_.wait(lock, [this] { return !inbox_.empty() || stopping_; });
                if (inbox_.empty()) return; // stopping, nothing left
                chunk = std::move(inbox_.front());
                inbox_.pop_front();
            }
            ChunkResult r = solve_chunk(solver, chunk, config_.test_delay_ms);
            std::lock_guard<std::mutex> lock(mutex_);
            outbox_.push_back(std::move(r));
        }
    } catch (...) {
        std::lock_guard<std::mutex> lock(mutex_);
        failure_ = std::current_exception();
    }
}

} // namespace cwcampaign
