// The campaign's only contact with MPI: start-up, byte messages, and
// waiting without spinning. Waiting is by polling (MPI_Iprobe / MPI_Test)
// with short sleeps that grow while nothing arrives: a blocking MPI call
// would spin a core that the OpenMP threads of a rank on the same node need.
// Only the thread that initialised MPI calls these (MPI_THREAD_FUNNELED).
#pragma once

#include <list>
#include <string>

#include <mpi.h>

#include "wire.hpp"

namespace cwcampaign::mpi {

// Message tags.
constexpr int kTagWork = 1;   // rank 0 -> worker: a chunk, or stop
constexpr int kTagResult = 2; // worker -> rank 0: a chunk's results

// MPI_Init_thread with MPI_THREAD_FUNNELED (rank 0 runs a solver thread
// beside the one that talks MPI). Throws std::runtime_error when the MPI
// library cannot provide it.
void init(int* argc, char*** argv);
void finalize();
int rank();
int size();
// Number of ranks on this rank's node (MPI_COMM_TYPE_SHARED).
int ranks_on_node();
[[noreturn]] void abort_all(int code);

// Blocking send: for results, which rank 0 collects promptly.
void send(int dest, int tag, const Bytes& bytes);
// A message from any source with this tag, if one is waiting.
bool try_receive(int tag, Bytes& bytes, int& source);

// Sends that complete in the background while the caller polls: rank 0's
// chunk assignments, so that a worker busy solving never blocks rank 0.
class PendingSends {
public:
    ~PendingSends();
    void start(int dest, int tag, Bytes bytes);
    // Completes what can be completed; true when nothing is pending.
    bool progress();
    void wait_all();

private:
    struct Send {
        Bytes bytes;
        MPI_Request request;
    };
    std::list<Send> sends_;
};

// Sleeps a little longer each time nothing happened (20 us up to 2 ms).
class Backoff {
public:
    void idle();
    void reset() { micros_ = 20; }

private:
    long micros_ = 20;
};

// Collective: the same int on every rank, from rank 0.
int broadcast_int(int value);
// Collective: the same string on every rank, from rank 0.
std::string broadcast_string(const std::string& value);
// Collective: the sum of value over the ranks, on every rank.
int sum_over_ranks(int value);
// Collective: true when value is equal on every rank.
bool same_on_all_ranks(long long value);

} // namespace cwcampaign::mpi
