// What the legacy layer (creepwork_legacy*.f90) keeps per calling thread:
// the detailed message of its last call (CWLAST), so that a FORTRAN 77
// caller learns which of many arguments was wrong.
//
// Fortran has no thread-local storage, and a SAVE or module variable is one
// per program; OpenMP's threadprivate is per OpenMP thread only (a host's
// pthreads, or a second OpenMP runtime, would share it) and would make the
// library depend on OpenMP. C++ thread_local is one per thread whatever made
// the thread. Internal: the cwl_ functions are hidden (not exported by
// libcreepwork_fortran.so, not declared in creepwork.h); only the legacy
// routines call them.
#include <cstddef>
#include <cstring>

#define CWL_INTERNAL extern "C" __attribute__((visibility("hidden")))

namespace {

constexpr std::size_t kMessageCapacity = 2048;

struct ThreadState {
    char message[kMessageCapacity] = {};
    std::size_t message_length = 0;

    void set_message(const char* text, std::size_t length)
    {
        message_length = length < kMessageCapacity ? length : kMessageCapacity;
        if (message_length > 0) std::memcpy(message, text, message_length);
    }
};

thread_local ThreadState state;

} // namespace

// The calling thread's last message := text[0..length) (cut at the capacity).
CWL_INTERNAL void cwl_set_message(const char* text, std::size_t length)
{
    state.set_message(text, length);
}

// Copies the calling thread's last message into out (at most capacity
// bytes, no NUL) and returns the number of bytes copied.
CWL_INTERNAL std::size_t cwl_copy_message(char* out, std::size_t capacity)
{
    const std::size_t n = state.message_length < capacity ? state.message_length : capacity;
    if (n > 0) std::memcpy(out, state.message, n);
    return n;
}
