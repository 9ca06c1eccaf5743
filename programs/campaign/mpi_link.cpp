#include "mpi_link.hpp"

#include <chrono>
#include <climits>
#include <cstdlib>
#include <iterator>
#include <stdexcept>
#include <thread>

namespace cwcampaign::mpi {

void init(int* argc, char*** argv)
{
    int provided = 0;
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    if (provided < MPI_THREAD_FUNNELED)
        throw std::runtime_error("the MPI library does not provide MPI_THREAD_FUNNELED");
}

void finalize() { MPI_Finalize(); }

int rank()
{
    int r = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
}

int size()
{
    int s = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &s);
    return s;
}

int ranks_on_node()
{
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    int n = 1;
    MPI_Comm_size(node, &n);
    MPI_Comm_free(&node);
    return n;
}

void abort_all(int code)
{
    MPI_Abort(MPI_COMM_WORLD, code);
    std::_Exit(code); // not reached: MPI_Abort does not return
}

namespace {

int checked_count(size_t n)
{
    if (n > static_cast<size_t>(INT_MAX))
        throw std::runtime_error("an MPI message would exceed 2 GiB; use a smaller --chunk");
    return static_cast<int>(n);
}

} // namespace

void send(int dest, int tag, const Bytes& bytes)
{
    MPI_Send(bytes.data(), checked_count(bytes.size()), MPI_BYTE, dest, tag, MPI_COMM_WORLD);
}

bool try_receive(int tag, Bytes& bytes, int& source)
{
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &flag, &status);
    if (!flag) return false;
    int count = 0;
    MPI_Get_count(&status, MPI_BYTE, &count);
    bytes.resize(static_cast<size_t>(count));
    source = status.MPI_SOURCE;
    MPI_Recv(bytes.data(), count, MPI_BYTE, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return true;
}

PendingSends::~PendingSends() { wait_all(); }

void PendingSends::start(int dest, int tag, Bytes bytes)
{
    sends_.push_back(Send{std::move(bytes), MPI_REQUEST_NULL});
    Send& s = sends_.back();
    MPI_Isend(s.bytes.data(), checked_count(s.bytes.size()), MPI_BYTE, dest, tag, MPI_COMM_WORLD,
              &s.request);
}

bool PendingSends::progress()
{
    for (auto it = sends_.begin(); it != sends_.end();) {
        int done = 0;
        MPI_Test(&it->request, &done, MPI_STATUS_IGNORE);
        it = done ? sends_.erase(it) : std::next(it);
    }
    return sends_.empty();
}

void PendingSends::wait_all()
{
    Backoff backoff;
    while (!progress()) backoff.idle();
}

void Backoff::idle()
{
    std::this_thread::sleep_for(std::chrono::microseconds(micros_));
    if (micros_ < 2000) micros_ *= 2;
}

int broadcast_int(int value)
{
    MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return value;
}

std::string broadcast_string(const std::string& value)
{
    int n = broadcast_int(static_cast<int>(value.size()));
    std::string s = value;
    s.resize(static_cast<size_t>(n));
    if (n > 0) MPI_Bcast(s.data(), n, MPI_CHAR, 0, MPI_COMM_WORLD);
    return s;
}

int sum_over_ranks(int value)
{
    int sum = 0;
    MPI_Allreduce(&value, &sum, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    return sum;
}

bool same_on_all_ranks(long long value)
{
    long long lo = 0, hi = 0;
    MPI_Allreduce(&value, &lo, 1, MPI_LONG_LONG, MPI_MIN, MPI_COMM_WORLD);
    MPI_Allreduce(&value, &hi, 1, MPI_LONG_LONG, MPI_MAX, MPI_COMM_WORLD);
    return lo == hi;
}

} // namespace cwcampaign::mpi
