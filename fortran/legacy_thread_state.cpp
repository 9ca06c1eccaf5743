// What the legacy layer (creepwork_legacy*.f90) keeps per calling thread:
//   - the detailed message of its last call (CWLAST), so that a FORTRAN 77
//     caller learns which of many arguments was wrong;
//   - the solvers of CWFORC, one per grid shape, reused from call to call.
//
// Fortran has no thread-local storage, and a SAVE or module variable is one
// per program; OpenMP's threadprivate is per OpenMP thread only (a host's
// pthreads, or a second OpenMP runtime, would share it) and would make the
// library depend on OpenMP. C++ thread_local is one per thread whatever made
// the thread, and its destructor frees the solvers when the thread ends
// (for the main thread: at exit). Internal: the cwl_ functions are hidden
// (not exported by libcreepwork_fortran.so, not declared in creepwork.h);
// only the legacy routines call them. They call nothing but the C ABI.
#include <cstddef>
#include <cstring>

#include "creepwork/creepwork.h"

#define CWL_INTERNAL extern "C" __attribute__((visibility("hidden")))

namespace {

// Grid shapes kept per thread: a vehicle loop alternates between few (one
// per wheel type, say); a host that changes shape on every call gets a
// create and a destroy per call and never more than this many solvers.
constexpr int kCachedSolvers = 4;
constexpr std::size_t kMessageCapacity = 2048;

struct CachedSolver {
    cw_grid grid;
    cw_solver* solver = nullptr;
    unsigned long last_use = 0;
};

bool same_grid(const cw_grid& a, const cw_grid& b)
{
    return a.kind == b.kind && a.nx == b.nx && a.ny == b.ny &&
           (a.kind != CW_GRID_UNIFORM || a.box_scale == b.box_scale);
}

struct ThreadState {
    char message[kMessageCapacity] = {};
    std::size_t message_length = 0;
    CachedSolver cache[kCachedSolvers];
    unsigned long clock = 0;

    ThreadState() = default;
    ThreadState(const ThreadState&) = delete;
    ThreadState& operator=(const ThreadState&) = delete;
    ~ThreadState() { free_solvers(); }

    void free_solvers()
    {
        for (CachedSolver& c : cache) {
            cw_solver_destroy(c.solver);
            c.solver = nullptr;
        }
    }

    void set_message(const char* text, std::size_t length)
    {
        message_length = length < kMessageCapacity ? length : kMessageCapacity;
        if (message_length > 0) std::memcpy(message, text, message_length);
    }

    // "<static message>: <detail>", as module creepwork's errmsg.
    void set_error(int status, const char* detail)
    {
        const char* head = cw_status_string(status);
        std::size_t n = 0;
        auto append = [&](const char* s) {
            const std::size_t k = std::strlen(s);
            const std::size_t room = kMessageCapacity - n;
            const std::size_t m = k < room ? k : room;
            std::memcpy(message + n, s, m);
            n += m;
        };
        append(head);
        if (detail && detail[0] != '\0') {
            append(": ");
            append(detail);
        }
        message_length = n;
    }

    // The solver of this grid shape: the cached one, or a new one in the
    // least recently used slot (whose solver is freed first, so that at most
    // kCachedSolvers exist per thread). NULL with the message set on error.
    cw_solver* solver_for(const cw_grid& grid, int* status)
    {
        CachedSolver* slot = &cache[0];
        for (CachedSolver& c : cache) {
            if (c.solver && same_grid(c.grid, grid)) {
                c.last_use = ++clock;
                *status = CW_OK;
                return c.solver;
            }
            if (!c.solver || (slot->solver && c.last_use < slot->last_use)) slot = &c;
        }
        cw_solver_destroy(slot->solver);
        slot->solver = nullptr;
        char detail[kMessageCapacity] = {};
        *status = cw_solver_create(&grid, &slot->solver, detail, sizeof detail);
        if (*status != CW_OK) {
            set_error(*status, detail);
            return nullptr;
        }
        slot->grid = grid;
        slot->last_use = ++clock;
        return slot->solver;
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

// cw_solver_solve on the calling thread's solver for grid (made on first
// use); the thread's message becomes "" on success, else the detailed one.
CWL_INTERNAL int cwl_solve_cached(const cw_grid* grid, const cw_params* params, int mode,
                                  cw_result* result)
{
    int status = CW_OK;
    cw_solver* solver = state.solver_for(*grid, &status);
    if (!solver) return status;
    status = cw_solver_solve(solver, params, mode, result);
    if (status == CW_OK) {
        state.message_length = 0;
    } else {
        state.set_error(status, cw_solver_last_error(solver));
    }
    return status;
}

// Frees the calling thread's cached solvers (CWFREE).
CWL_INTERNAL void cwl_free_solvers(void) { state.free_solvers(); }

// Number of solvers the calling thread holds (for the tests).
CWL_INTERNAL int cwl_cached_solvers(void)
{
    int n = 0;
    for (const CachedSolver& c : state.cache) n += c.solver != nullptr;
    return n;
}
