// Internals of the C boundary, shared by its source files (one per area of
// the header): the handle structs, the exception guard, versioned-struct
// reading and writing, and the translation between C structs and the core.
// Every extern "C" body runs inside guarded(), which turns C++ exceptions
// into status codes and sets the floating-point mode of the call
// (capi_fp_mode.hpp).
#pragma once

#include "creepwork/creepwork.h"

#include <algorithm>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "capi_fp_mode.hpp"
#include "contact/error.hpp"
#include "solver.hpp"
#include "wear/wear_profile.hpp"

namespace cw = creepwork;

// A solver the caller made (owned), or a view of one a wheel/rail handle
// owns (cw_wheelrail_patch_solver), which the caller only reads.
struct cw_solver {
    explicit cw_solver(const cw::GridSpec& g) : owned(std::make_unique<cw::Solver>(g)), solver(*owned) {}
    explicit cw_solver(const cw::Solver& view) : solver(const_cast<cw::Solver&>(view)) {}
    std::unique_ptr<cw::Solver> owned;
    cw::Solver& solver;
    // The rolling speed and direction of the last successful solve
    // (cw_params.V, 0: not given; cw_params.rolling_direction, 0: no solve),
    // for the post-processors that need them (capi_surface.cpp, capi_wear.cpp).
    double V = 0.0;
    int rolling_direction = 0;
    mutable std::string last_error; // the last call's message, const getters' included
};

struct cw_wear_profile {
    explicit cw_wear_profile(const double* s, long n) : acc(s, n) {}
    creepwork::wear::ProfileAccumulator acc;
    mutable std::string last_error; // the last call's message, const getters' included
};

struct cw_accumulator {
    cw::GridSpec grid;
    int nx = 0, ny = 0;
    std::vector<double> paper, consistent, strips;
    std::vector<double> next_paper, next_consistent; // a step is checked here first
    cw_accumulation totals{};
    mutable std::string last_error; // the last call's message, const getters' included
};

struct cw_batch {
    cw::GridSpec grid;
    int threads = 1;
    std::vector<cw::Solver> solvers;           // one per thread
    // Per thread: first failing index, its status and message, and scratch.
    std::vector<size_t> thread_error_index;
    std::vector<int> thread_error_status;
    std::vector<std::string> thread_errors, thread_scratch;
    mutable std::string last_error; // the last call's message, const getters' included
};

namespace creepwork::capi {

constexpr size_t kMaxStructSize = 1 << 16; // larger is certainly garbage

// Status with a message for the handle.
struct Failure {
    int status;
    std::string message;
};

int map_kind(cw::ErrorKind kind);

// Runs body (which returns a status) and converts every exception. The
// message goes to *message when given (handle functions) -- no exception
// ever leaves this function.
template <class Body>
inline int guarded(std::string* message, Body&& body) noexcept
{
    const ScopedFpMode fp_mode; // masked, subnormals flushed; the caller's MXCSR back on return
    try {
        if (message) message->clear();
        return body();
    } catch (const Failure& f) {
        try {
            if (message) *message = f.message;
        } catch (...) {
        }
        return f.status;
    } catch (const cw::Error& e) {
        try {
            if (message) *message = e.what();
        } catch (...) {
        }
        return map_kind(e.kind());
    } catch (const std::bad_alloc&) {
        if (message) message->clear();
        return CW_ERR_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        try {
            if (message) *message = std::string("internal error: ") + e.what();
        } catch (...) {
        }
        return CW_ERR_INTERNAL;
    } catch (...) {
        return CW_ERR_INTERNAL;
    }
}

// Free functions report through a caller buffer instead of a handle.
void copy_message(const std::string& text, char* out, size_t len) noexcept;

template <class Body>
inline int guarded_free(char* out, size_t len, Body&& body) noexcept
{
    std::string message;
    const int status = guarded(&message, body);
    if (status != CW_OK && message.empty()) message = cw_status_string(status);
    copy_message(status == CW_OK ? std::string() : message, out, len);
    return status;
}

[[noreturn]] void fail(int status, const std::string& message);
void require(const void* p, const char* name);

// A versioned struct's struct_size: at least the size field itself, and
// not garbage.
inline bool valid_struct_size(size_t size)
{
    return size >= sizeof(size_t) && size <= kMaxStructSize;
}

// The caller's result struct (optional), checked before a solve, so that a
// bad struct_size fails before any work is done; init names its _init
// function.
template <class T>
void require_result_size(const T* result, const char* init)
{
    if (result && !valid_struct_size(result->struct_size))
        fail(CW_ERR_STRUCT_SIZE, "result->struct_size = " + std::to_string(result->struct_size) +
                                     " is invalid (call " + init + " first)");
}

// Reads a versioned struct: defaults for fields beyond the caller's size.
template <class T>
T read_struct(const T* caller, const T& defaults, const char* name)
{
    const size_t size = caller->struct_size;
    if (!valid_struct_size(size))
        fail(CW_ERR_STRUCT_SIZE, std::string(name) + "->struct_size = " + std::to_string(size) +
                                     " is invalid (call the _init function first)");
    T value = defaults;
    std::memcpy(&value, caller, std::min(size, sizeof(T)));
    value.struct_size = sizeof(T);
    return value;
}

template <class T>
void write_struct(T* caller, const T& value)
{
    const size_t size = caller->struct_size;
    if (!valid_struct_size(size))
        fail(CW_ERR_STRUCT_SIZE, "result struct_size = " + std::to_string(size) +
                                     " is invalid (call the _init function first)");
    T copy = value;
    copy.struct_size = size;
    std::memcpy(caller, &copy, std::min(size, sizeof(T)));
}

cw_grid default_grid();
cw_params default_params();
cw::GridSpec to_grid(const cw_grid* grid);
cw::ContactInput to_input(const cw_params* params);
cw::SolveMode to_mode(int mode);
cw::ModelKind to_model(int model, const char* name = "model");
cw_result to_result(const cw::SolveTotals& t);
cw::Field to_field(int field);
void require_length(size_t have, size_t need, const char* name);
size_t element_count(const cw::Solver& s);
void require_solution(const cw::Solver& s, bool needs_work);
void require_finite(const char* name, double v);
double rolling_speed_of(double own, const char* own_name, double solve_V);
int hardware_threads();

} // namespace creepwork::capi

using namespace creepwork::capi;
