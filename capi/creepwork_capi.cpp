// The C boundary: every extern "C" body runs inside guarded(), which turns
// C++ exceptions into status codes; then plain translation to the core.
#include "creepwork/creepwork.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "contact/error.hpp"
#include "contact/hertz.hpp"
#include "contact/kalker_coefficients.hpp"
#include "fastsim/kalker_normalised.hpp"
#include "solver.hpp"

namespace cw = creepwork;

struct cw_solver {
    explicit cw_solver(const cw::GridSpec& g) : solver(g) {}
    cw::Solver solver;
    std::string last_error;
};

struct cw_accumulator {
    cw::GridSpec grid;
    int nx = 0, ny = 0;
    std::vector<double> paper, consistent, strips;
    std::vector<double> next_paper, next_consistent; // a step is checked here first
    cw_accumulation totals{};
    std::string last_error;
};

struct cw_batch {
    cw::GridSpec grid;
    int threads = 1;
    std::vector<cw::Solver> solvers;           // one per thread
    // Per thread: first failing index, its status and message, and scratch.
    std::vector<size_t> thread_error_index;
    std::vector<int> thread_error_status;
    std::vector<std::string> thread_errors, thread_scratch;
    std::string last_error;
};

namespace {

constexpr size_t kMaxStructSize = 1 << 16; // larger is certainly garbage

// Status with a message for the handle.
struct Failure {
    int status;
    std::string message;
};

int map_kind(cw::ErrorKind kind)
{
    switch (kind) {
    case cw::ErrorKind::invalid_input: return CW_ERR_INVALID_INPUT;
    case cw::ErrorKind::grid_out_of_range: return CW_ERR_GRID_OUT_OF_RANGE;
    case cw::ErrorKind::numeric_failure: return CW_ERR_NUMERIC;
    case cw::ErrorKind::not_converged: return CW_ERR_NOT_CONVERGED;
    }
    return CW_ERR_INTERNAL;
}

// Runs body (which returns a status) and converts every exception. The
// message goes to *message when given (handle functions) -- no exception
// ever leaves this function.
template <class Body>
int guarded(std::string* message, Body&& body) noexcept
{
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
void copy_message(const std::string& text, char* out, size_t len) noexcept
{
    if (!out || len == 0) return;
    const size_t n = std::min(text.size(), len - 1);
    std::memcpy(out, text.data(), n);
    out[n] = '\0';
}

template <class Body>
int guarded_free(char* out, size_t len, Body&& body) noexcept
{
    std::string message;
    const int status = guarded(&message, body);
    if (status != CW_OK && message.empty()) message = cw_status_string(status);
    copy_message(status == CW_OK ? std::string() : message, out, len);
    return status;
}

[[noreturn]] void fail(int status, const std::string& message)
{
    throw Failure{status, message};
}

void require(const void* p, const char* name)
{
    if (!p) fail(CW_ERR_NULL_POINTER, std::string(name) + " is NULL");
}

// Reads a versioned struct: defaults for fields beyond the caller's size.
template <class T>
T read_struct(const T* caller, const T& defaults, const char* name)
{
    const size_t size = caller->struct_size;
    if (size < sizeof(size_t) || size > kMaxStructSize)
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
    if (size < sizeof(size_t) || size > kMaxStructSize)
        fail(CW_ERR_STRUCT_SIZE, "result struct_size = " + std::to_string(size) +
                                     " is invalid (call the _init function first)");
    T copy = value;
    copy.struct_size = size;
    std::memcpy(caller, &copy, std::min(size, sizeof(T)));
}

cw_grid default_grid()
{
    cw_grid g;
    std::memset(&g, 0, sizeof g);
    g.struct_size = sizeof g;
    g.kind = CW_GRID_KALKER_STRIPS;
    g.nx = 20;
    g.ny = 20;
    g.box_scale = 1.0;
    return g;
}

cw_params default_params()
{
    cw_params p;
    std::memset(&p, 0, sizeof p);
    p.struct_size = sizeof p;
    p.a = 6e-3;
    p.b = 6e-3;
    p.normal_force = 80e3;
    p.mu = 0.3;
    p.flexibility = CW_FLEX_FROM_MATERIAL;
    p.pressure = CW_PRESSURE_PARABOLIC;
    p.G = 82e9;
    p.nu = 0.28;
    p.rolling_direction = 1;
    p.model = CW_MODEL_FASTSIM;
    p.warm_start = 1;
    p.spin_offset = CW_SPIN_OFFSET_DEFAULT;
    return p;
}

cw::GridSpec to_grid(const cw_grid* grid)
{
    require(grid, "grid");
    const cw_grid g = read_struct(grid, default_grid(), "grid");
    cw::GridSpec spec;
    if (g.kind == CW_GRID_KALKER_STRIPS)
        spec.kind = cw::GridKind::kalker_strips;
    else if (g.kind == CW_GRID_UNIFORM)
        spec.kind = cw::GridKind::uniform;
    else
        fail(CW_ERR_UNKNOWN_OPTION, "grid->kind = " + std::to_string(g.kind) +
                                        " is not CW_GRID_KALKER_STRIPS (0) or CW_GRID_UNIFORM (1)");
    spec.nx = g.nx;
    spec.ny = g.ny;
    // The strip grid has no box: whatever the caller left there (even NaN)
    // must not make two equal strip grids compare unequal.
    spec.box_scale = spec.kind == cw::GridKind::uniform ? g.box_scale : 1.0;
    return spec;
}

cw::ContactInput to_input(const cw_params* params)
{
    const cw_params p = read_struct(params, default_params(), "params");
    cw::ContactInput in;
    in.a = p.a;
    in.b = p.b;
    in.normal_force = p.normal_force;
    in.mu = p.mu;
    if (p.flexibility == CW_FLEX_FROM_MATERIAL)
        in.flexibility = cw::FlexibilitySource::kalker_from_material;
    else if (p.flexibility == CW_FLEX_GIVEN)
        in.flexibility = cw::FlexibilitySource::given;
    else
        fail(CW_ERR_UNKNOWN_OPTION, "params->flexibility = " +
                                        std::to_string(p.flexibility) +
                                        " is not CW_FLEX_FROM_MATERIAL (0) or CW_FLEX_GIVEN (1)");
    if (p.pressure == CW_PRESSURE_PARABOLIC)
        in.pressure = cw::PressureKind::parabolic;
    else if (p.pressure == CW_PRESSURE_ELLIPTIC)
        in.pressure = cw::PressureKind::elliptic;
    else
        fail(CW_ERR_UNKNOWN_OPTION,
             "params->pressure = " + std::to_string(p.pressure) +
                 " is not CW_PRESSURE_PARABOLIC (0) or CW_PRESSURE_ELLIPTIC (1)");
    in.G = p.G;
    in.nu = p.nu;
    in.L1 = p.L1;
    in.L2 = p.L2;
    in.L3 = p.L3;
    in.xi_x = p.xi_x;
    in.xi_y = p.xi_y;
    in.phi = p.phi;
    in.rolling_direction = p.rolling_direction;
    if (p.model == CW_MODEL_FASTSIM)
        in.model = cw::ModelKind::fastsim;
    else if (p.model == CW_MODEL_EXACT)
        in.model = cw::ModelKind::exact;
    else if (p.model == CW_MODEL_CALIBRATED)
        in.model = cw::ModelKind::calibrated;
    else
        fail(CW_ERR_UNKNOWN_OPTION, "params->model = " + std::to_string(p.model) +
                                        " is not CW_MODEL_FASTSIM (0), CW_MODEL_EXACT (1) or "
                                        "CW_MODEL_CALIBRATED (2)");
    in.tolerance = p.tolerance;
    in.max_iterations = p.max_iterations;
    if (p.warm_start != 0 && p.warm_start != 1)
        fail(CW_ERR_INVALID_INPUT,
             "params->warm_start = " + std::to_string(p.warm_start) + " must be 0 or 1");
    in.warm_start = p.warm_start == 1;
    in.spin_offset = p.spin_offset;
    if (p.flexibility_blending != 0 && p.flexibility_blending != 1)
        fail(CW_ERR_INVALID_INPUT, "params->flexibility_blending = " +
                                       std::to_string(p.flexibility_blending) +
                                       " must be 0 or 1");
    in.flexibility_blending = p.flexibility_blending == 1;
    return in;
}

cw::SolveMode to_mode(int mode)
{
    if (mode == CW_SOLVE_FORCES) return cw::SolveMode::forces_only;
    if (mode == CW_SOLVE_FULL) return cw::SolveMode::full;
    fail(CW_ERR_UNKNOWN_OPTION, "mode = " + std::to_string(mode) +
                                    " is not CW_SOLVE_FORCES (0) or CW_SOLVE_FULL (1)");
}

cw_result to_result(const cw::SolveTotals& t)
{
    cw_result r;
    std::memset(&r, 0, sizeof r);
    r.struct_size = sizeof r;
    r.Fx = t.Fx;
    r.Fy = t.Fy;
    r.Mz = t.Mz;
    r.W_macro = t.W_macro;
    r.W_micro_paper = t.W_micro_paper;
    r.K = t.K;
    r.W_consistent = t.W_consistent;
    r.balance_factor = t.balance_factor;
    r.adhesion_fraction = t.adhesion_fraction;
    r.n_contact = t.n_contact;
    r.n_adhesion = t.n_adhesion;
    r.n_slip = t.n_slip;
    r.work_flags = t.work_flags;
    r.a = t.a;
    r.b = t.b;
    r.L1 = t.L1;
    r.L2 = t.L2;
    r.L3 = t.L3;
    r.C11 = t.C11;
    r.C22 = t.C22;
    r.C23 = t.C23;
    r.C33 = t.C33;
    r.profile_max_diff = t.profile_max_diff;
    r.profile_rms_diff = t.profile_rms_diff;
    r.model = static_cast<int>(t.model);
    r.p_max = t.p_max;
    r.approach = t.approach;
    r.iterations = t.iterations;
    r.residual = t.residual;
    return r;
}

cw::Field to_field(int field)
{
    if (field < CW_FIELD_X || field > CW_FIELD_WORK_CONSISTENT)
        fail(CW_ERR_UNKNOWN_OPTION, "field = " + std::to_string(field) +
                                        " is not one of CW_FIELD_X (0) .. "
                                        "CW_FIELD_WORK_CONSISTENT (10)");
    return static_cast<cw::Field>(field);
}

void require_length(size_t have, size_t need, const char* name)
{
    if (have < need)
        fail(CW_ERR_BUFFER_TOO_SMALL, std::string(name) + " holds " + std::to_string(have) +
                                          " values but " + std::to_string(need) +
                                          " are needed");
}

size_t element_count(const cw::Solver& s)
{
    return static_cast<size_t>(s.grid().nx()) * static_cast<size_t>(s.grid().ny());
}

void require_solution(const cw::Solver& s, bool needs_work)
{
    if (!s.has_solution())
        fail(CW_ERR_NO_SOLUTION, "no successful solve on this solver yet (or the last failed)");
    if (needs_work && !s.has_work())
        fail(CW_ERR_NO_WORK, "this output needs the last solve to use CW_SOLVE_FULL");
}

void require_finite(const char* name, double v)
{
    if (!std::isfinite(v)) fail(CW_ERR_INVALID_INPUT, std::string(name) + " must be finite");
}

int hardware_threads()
{
#ifdef _OPENMP
    return std::max(1, omp_get_num_procs());
#else
    return 1;
#endif
}

} // namespace

extern "C" {

int cw_version_number(void) { return CW_VERSION_NUMBER; }
int cw_abi_version(void) { return CW_ABI_VERSION; }
const char* cw_version_string(void) { return "1.0.0"; }

const char* cw_status_string(int status)
{
    switch (status) {
#define CW_STATUS_MESSAGE_(name, value, message) \
    case value: return message;
        CW_STATUS_LIST(CW_STATUS_MESSAGE_)
#undef CW_STATUS_MESSAGE_
    default: return "unknown status code";
    }
}

int cw_grid_init(cw_grid* grid)
{
    if (!grid) return CW_ERR_NULL_POINTER;
    *grid = default_grid();
    return CW_OK;
}

int cw_params_init(cw_params* params)
{
    if (!params) return CW_ERR_NULL_POINTER;
    *params = default_params();
    return CW_OK;
}

int cw_result_init(cw_result* result)
{
    if (!result) return CW_ERR_NULL_POINTER;
    std::memset(result, 0, sizeof *result);
    result->struct_size = sizeof *result;
    return CW_OK;
}

int cw_solver_create(const cw_grid* grid, cw_solver** solver, char* message, size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(solver, "solver");
        *solver = nullptr;
        const cw::GridSpec spec = to_grid(grid);
        *solver = new cw_solver(spec);
        return CW_OK;
    });
}

int cw_solver_destroy(cw_solver* solver)
{
    delete solver;
    return CW_OK;
}

int cw_solver_grid_size(const cw_solver* solver, int* nx, int* ny)
{
    if (!solver || !nx || !ny) return CW_ERR_NULL_POINTER;
    *nx = solver->solver.grid().nx();
    *ny = solver->solver.grid().ny();
    return CW_OK;
}

int cw_solver_solve(cw_solver* solver, const cw_params* params, int mode, cw_result* result)
{
    if (!solver) return CW_ERR_NULL_POINTER;
    const int status = guarded(&solver->last_error, [&] {
        require(params, "params");
        if (result && (result->struct_size < sizeof(size_t) || result->struct_size > kMaxStructSize))
            fail(CW_ERR_STRUCT_SIZE, "result->struct_size = " +
                                         std::to_string(result->struct_size) +
                                         " is invalid (call cw_result_init first)");
        const cw::ContactInput in = to_input(params);
        const cw::SolveMode m = to_mode(mode);
        const cw::SolveTotals& t = solver->solver.solve(in, m);
        if (result) write_struct(result, to_result(t));
        return CW_OK;
    });
    // The header's promise: after any failed solve the handle holds no solution.
    if (status != CW_OK) solver->solver.discard();
    return status;
}

int cw_solver_get_result(const cw_solver* solver, cw_result* result)
{
    if (!solver) return CW_ERR_NULL_POINTER;
    auto* self = const_cast<cw_solver*>(solver);
    return guarded(&self->last_error, [&] {
        require(result, "result");
        require_solution(solver->solver, false);
        write_struct(result, to_result(solver->solver.totals()));
        return CW_OK;
    });
}

int cw_solver_get_field(const cw_solver* solver, int field, double* out, size_t out_len)
{
    if (!solver) return CW_ERR_NULL_POINTER;
    auto* self = const_cast<cw_solver*>(solver);
    return guarded(&self->last_error, [&] {
        const cw::Field f = to_field(field);
        require(out, "out");
        require_solution(solver->solver, cw::Solver::needs_work(f));
        require_length(out_len, element_count(solver->solver), "out");
        solver->solver.copy_field(f, out);
        return CW_OK;
    });
}

int cw_solver_get_state(const cw_solver* solver, int* out, size_t out_len)
{
    if (!solver) return CW_ERR_NULL_POINTER;
    auto* self = const_cast<cw_solver*>(solver);
    return guarded(&self->last_error, [&] {
        require(out, "out");
        require_solution(solver->solver, false);
        require_length(out_len, element_count(solver->solver), "out");
        solver->solver.copy_state(out);
        return CW_OK;
    });
}

int cw_solver_get_profile(const cw_solver* solver, double* y, double* w, double* parabola,
                          size_t len)
{
    if (!solver) return CW_ERR_NULL_POINTER;
    auto* self = const_cast<cw_solver*>(solver);
    return guarded(&self->last_error, [&] {
        require_solution(solver->solver, true);
        require_length(len, static_cast<size_t>(solver->solver.grid().ny()), "profile buffers");
        solver->solver.copy_profile(y, w, parabola);
        return CW_OK;
    });
}

const char* cw_solver_last_error(const cw_solver* solver)
{
    return solver ? solver->last_error.c_str() : "solver is NULL";
}

int cw_accumulation_init(cw_accumulation* totals)
{
    if (!totals) return CW_ERR_NULL_POINTER;
    std::memset(totals, 0, sizeof *totals);
    totals->struct_size = sizeof *totals;
    return CW_OK;
}

int cw_accumulator_create(const cw_solver* solver, cw_accumulator** accumulator)
{
    if (!accumulator) return CW_ERR_NULL_POINTER;
    *accumulator = nullptr;
    if (!solver) return CW_ERR_NULL_POINTER;
    return guarded(nullptr, [&] {
        auto acc = new cw_accumulator;
        acc->grid = solver->solver.grid().spec();
        acc->nx = solver->solver.grid().nx();
        acc->ny = solver->solver.grid().ny();
        try {
            acc->paper.assign(element_count(solver->solver), 0.0);
            acc->consistent.assign(element_count(solver->solver), 0.0);
            acc->next_paper.assign(element_count(solver->solver), 0.0);
            acc->next_consistent.assign(element_count(solver->solver), 0.0);
            acc->strips.assign(static_cast<size_t>(acc->ny), 0.0);
        } catch (...) {
            delete acc;
            throw;
        }
        cw_accumulation_init(&acc->totals);
        *accumulator = acc;
        return CW_OK;
    });
}

int cw_accumulator_destroy(cw_accumulator* accumulator)
{
    delete accumulator;
    return CW_OK;
}

int cw_accumulator_reset(cw_accumulator* accumulator)
{
    if (!accumulator) return CW_ERR_NULL_POINTER;
    std::fill(accumulator->paper.begin(), accumulator->paper.end(), 0.0);
    std::fill(accumulator->consistent.begin(), accumulator->consistent.end(), 0.0);
    std::fill(accumulator->strips.begin(), accumulator->strips.end(), 0.0);
    cw_accumulation_init(&accumulator->totals);
    accumulator->last_error.clear();
    return CW_OK;
}

int cw_accumulator_add(cw_accumulator* accumulator, const cw_solver* solver, double distance)
{
    if (!accumulator) return CW_ERR_NULL_POINTER;
    return guarded(&accumulator->last_error, [&] {
        require(solver, "solver");
        const cw::Solver& s = solver->solver;
        const cw::GridSpec& g = s.grid().spec();
        if (g.kind != accumulator->grid.kind || g.nx != accumulator->nx ||
            g.ny != accumulator->ny || g.box_scale != accumulator->grid.box_scale)
            fail(CW_ERR_GRID_MISMATCH, "the solver's grid differs from the accumulator's");
        require_solution(s, true);
        if (!(std::isfinite(distance) && distance >= 0.0))
            fail(CW_ERR_INVALID_INPUT, "distance = " + std::to_string(distance) +
                                           " must be finite and >= 0 (V*dt)");
        const cw::SolveTotals& t = s.totals();
        // The step goes into copies first (same size: no allocation), so a
        // step that would overflow leaves the accumulator as it was.
        accumulator->next_paper = accumulator->paper;
        accumulator->next_consistent = accumulator->consistent;
        s.add_field(cw::Field::work_paper, distance, accumulator->next_paper.data());
        s.add_field(cw::Field::work_consistent, distance, accumulator->next_consistent.data());
        cw_accumulation a = accumulator->totals;
        a.distance += distance;
        a.W_macro += t.W_macro * distance;
        a.W_micro_paper += t.W_micro_paper * distance;
        a.W_consistent += t.W_consistent * distance;
        a.K = a.W_micro_paper != 0.0 ? a.W_macro / a.W_micro_paper : 0.0;
        bool finite = std::isfinite(a.distance) && std::isfinite(a.W_macro) &&
                      std::isfinite(a.W_micro_paper) && std::isfinite(a.W_consistent) &&
                      std::isfinite(a.K);
        for (size_t k = 0; finite && k < accumulator->next_paper.size(); ++k)
            finite = std::isfinite(accumulator->next_paper[k]) &&
                     std::isfinite(accumulator->next_consistent[k]);
        if (!finite)
            fail(CW_ERR_NUMERIC, "distance = " + std::to_string(distance) +
                                     " makes the accumulated work overflow");
        accumulator->paper.swap(accumulator->next_paper);
        accumulator->consistent.swap(accumulator->next_consistent);
        const size_t nx = static_cast<size_t>(accumulator->nx);
        for (size_t j = 0; j < accumulator->strips.size(); ++j) {
            double sum = 0.0;
            for (size_t i = 0; i < nx; ++i) sum += accumulator->consistent[i + j * nx];
            accumulator->strips[j] = sum;
        }
        a.steps += 1;
        accumulator->totals = a;
        return CW_OK;
    });
}

int cw_accumulator_get_totals(const cw_accumulator* accumulator, cw_accumulation* totals)
{
    if (!accumulator) return CW_ERR_NULL_POINTER;
    auto* self = const_cast<cw_accumulator*>(accumulator);
    return guarded(&self->last_error, [&] {
        require(totals, "totals");
        write_struct(totals, accumulator->totals);
        return CW_OK;
    });
}

int cw_accumulator_get_field(const cw_accumulator* accumulator, int field, double* out,
                             size_t out_len)
{
    if (!accumulator) return CW_ERR_NULL_POINTER;
    auto* self = const_cast<cw_accumulator*>(accumulator);
    return guarded(&self->last_error, [&] {
        if (field != CW_FIELD_WORK_PAPER && field != CW_FIELD_WORK_CONSISTENT)
            fail(CW_ERR_UNKNOWN_OPTION, "field = " + std::to_string(field) +
                                            " is not CW_FIELD_WORK_PAPER (9) or "
                                            "CW_FIELD_WORK_CONSISTENT (10)");
        require(out, "out");
        const std::vector<double>& src =
            field == CW_FIELD_WORK_PAPER ? accumulator->paper : accumulator->consistent;
        require_length(out_len, src.size(), "out");
        std::copy(src.begin(), src.end(), out);
        return CW_OK;
    });
}

int cw_accumulator_get_strip_work(const cw_accumulator* accumulator, double* out, size_t len)
{
    if (!accumulator) return CW_ERR_NULL_POINTER;
    auto* self = const_cast<cw_accumulator*>(accumulator);
    return guarded(&self->last_error, [&] {
        require(out, "out");
        require_length(len, accumulator->strips.size(), "out");
        std::copy(accumulator->strips.begin(), accumulator->strips.end(), out);
        return CW_OK;
    });
}

const char* cw_accumulator_last_error(const cw_accumulator* accumulator)
{
    return accumulator ? accumulator->last_error.c_str() : "accumulator is NULL";
}

int cw_batch_create(const cw_grid* grid, int threads, cw_batch** batch, char* message,
                    size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(batch, "batch");
        *batch = nullptr;
        const cw::GridSpec spec = to_grid(grid);
        if (threads > CW_MAX_BATCH_THREADS)
            fail(CW_ERR_INVALID_INPUT, "threads = " + std::to_string(threads) +
                                           " exceeds CW_MAX_BATCH_THREADS (256)");
        auto b = new cw_batch;
        try {
            b->grid = spec;
            b->threads = threads > 0 ? threads : hardware_threads();
            b->solvers.reserve(static_cast<size_t>(b->threads));
            for (int t = 0; t < b->threads; ++t) b->solvers.emplace_back(spec);
            const size_t nt = static_cast<size_t>(b->threads);
            b->thread_error_index.resize(nt);
            b->thread_error_status.resize(nt);
            b->thread_errors.resize(nt);
            b->thread_scratch.resize(nt);
        } catch (...) {
            delete b;
            throw;
        }
        *batch = b;
        return CW_OK;
    });
}

int cw_batch_destroy(cw_batch* batch)
{
    delete batch;
    return CW_OK;
}

int cw_batch_solve(cw_batch* batch, size_t count, const cw_params* params, int mode,
                   cw_result* results, int* statuses)
{
    if (!batch) return CW_ERR_NULL_POINTER;
    return guarded(&batch->last_error, [&] {
        if (count == 0) return CW_OK;
        require(params, "params");
        require(results, "results");
        const cw::SolveMode m = to_mode(mode);
        const size_t pstride = params[0].struct_size;
        const size_t rstride = results[0].struct_size;
        if (pstride < sizeof(size_t) || pstride > kMaxStructSize)
            fail(CW_ERR_STRUCT_SIZE, "params[0].struct_size is invalid");
        if (rstride < sizeof(size_t) || rstride > kMaxStructSize)
            fail(CW_ERR_STRUCT_SIZE, "results[0].struct_size is invalid");
        const auto* pbytes = reinterpret_cast<const unsigned char*>(params);
        auto* rbytes = reinterpret_cast<unsigned char*>(results);
        for (size_t i = 0; i < count; ++i) {
            const auto* p = reinterpret_cast<const cw_params*>(pbytes + i * pstride);
            const auto* r = reinterpret_cast<const cw_result*>(rbytes + i * rstride);
            if (p->struct_size != pstride || r->struct_size != rstride)
                fail(CW_ERR_STRUCT_SIZE, "params[" + std::to_string(i) + "] or results[" +
                                             std::to_string(i) +
                                             "] has a different struct_size than element 0");
        }

        const int threads = batch->threads;
        for (int t = 0; t < threads; ++t) batch->thread_error_index[t] = count;
        const long n = static_cast<long>(count);
        auto solve_one = [&](long i, int t) {
            const auto* p = reinterpret_cast<const cw_params*>(pbytes + i * pstride);
            auto* r = reinterpret_cast<cw_result*>(rbytes + i * rstride);
            std::string& scratch = batch->thread_scratch[t];
            const int status = guarded(&scratch, [&] {
                const cw::SolveTotals& tot = batch->solvers[t].solve(to_input(p), m);
                write_struct(r, to_result(tot));
                return CW_OK;
            });
            if (statuses) statuses[i] = status;
            if (status != CW_OK && static_cast<size_t>(i) < batch->thread_error_index[t]) {
                batch->thread_error_index[t] = static_cast<size_t>(i);
                batch->thread_error_status[t] = status;
                try {
                    batch->thread_errors[t] = "params[" + std::to_string(i) + "]: " + scratch;
                } catch (...) {
                }
            }
        };
        if (threads == 1 || n == 1) {
            // No parallel region: libgomp allocates a new team for every
            // one-thread region, and solving allocates nothing.
            for (long i = 0; i < n; ++i) solve_one(i, 0);
        } else {
#pragma omp parallel for schedule(static) num_threads(threads)
            for (long i = 0; i < n; ++i) {
#ifdef _OPENMP
                solve_one(i, omp_get_thread_num());
#else
                solve_one(i, 0);
#endif
            }
        }

        size_t first = count;
        int owner = -1;
        for (int t = 0; t < threads; ++t)
            if (batch->thread_error_index[t] < first) {
                first = batch->thread_error_index[t];
                owner = t;
            }
        if (owner < 0) return CW_OK;
        fail(batch->thread_error_status[owner], batch->thread_errors[owner]);
    });
}

const char* cw_batch_last_error(const cw_batch* batch)
{
    return batch ? batch->last_error.c_str() : "batch is NULL";
}

int cw_kalker_coefficients(double a_over_b, double nu, double coefficients[4], char* message,
                           size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(coefficients, "coefficients");
        require_finite("a_over_b", a_over_b);
        require_finite("nu", nu);
        if (!(a_over_b >= CW_MIN_ASPECT && a_over_b <= CW_MAX_ASPECT))
            fail(CW_ERR_INVALID_INPUT, "a_over_b = " + std::to_string(a_over_b) +
                                           " must lie in [1e-3, 1e3]");
        if (!(nu >= 0.0 && nu <= 0.5))
            fail(CW_ERR_INVALID_INPUT, "nu = " + std::to_string(nu) + " must lie in [0, 0.5]");
        const cw::CreepCoefficients c = cw::kalker_coefficients(a_over_b, nu);
        coefficients[0] = c.C11;
        coefficients[1] = c.C22;
        coefficients[2] = c.C23;
        coefficients[3] = c.C33;
        return CW_OK;
    });
}

int cw_kalker_flexibilities(double a, double b, double G, double nu, double flexibilities[3],
                            char* message, size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(flexibilities, "flexibilities");
        cw::ContactInput in;
        in.a = a;
        in.b = b;
        in.G = G;
        in.nu = nu;
        const cw::ModelSetup s = cw::make_model_setup(in); // validates a, b, G, nu
        flexibilities[0] = s.L1;
        flexibilities[1] = s.L2;
        flexibilities[2] = s.L3;
        return CW_OK;
    });
}

int cw_hertz_solve(double A, double B, double normal_force, double E_star, double hertz[4],
                   char* message, size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(hertz, "hertz");
        const double values[4] = {A, B, normal_force, E_star};
        const char* names[4] = {"A", "B", "normal_force", "E_star"};
        for (int k = 0; k < 4; ++k) {
            require_finite(names[k], values[k]);
            const bool ok = k == 2 ? values[k] >= 0.0 : values[k] > 0.0;
            if (!ok)
                fail(CW_ERR_INVALID_INPUT, std::string(names[k]) + " = " +
                                               std::to_string(values[k]) +
                                               (k == 2 ? " must be >= 0" : " must be > 0"));
        }
        const double ratio = std::max(A, B) / std::min(A, B);
        if (!std::isfinite(ratio) || ratio > 1e12)
            fail(CW_ERR_INVALID_INPUT, "A/B = " + std::to_string(A / B) +
                                           " is too extreme (ratio of curvatures above 1e12)");
        const cw::HertzContact h = cw::hertz_from_curvatures(A, B, normal_force, E_star);
        const double out[4] = {h.a, h.b, h.p0, h.approach};
        for (double v : out)
            if (!std::isfinite(v))
                fail(CW_ERR_NUMERIC, "the Hertz solution overflowed for these inputs");
        std::copy(out, out + 4, hertz);
        return CW_OK;
    });
}

int cw_fastsim_normalised(double ux, double uy, double fx, double fy, int mx, int my, double tol,
                          double* tx, double* ty, char* message, size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(tx, "tx");
        require(ty, "ty");
        // Named here: the core's grid speaks of nx, ny.
        if (mx < 1 || mx > CW_MAX_GRID_CELLS)
            fail(CW_ERR_GRID_OUT_OF_RANGE, "mx = " + std::to_string(mx) + " is outside 1..1000");
        if (my < 1 || my > CW_MAX_GRID_CELLS)
            fail(CW_ERR_GRID_OUT_OF_RANGE, "my = " + std::to_string(my) + " is outside 1..1000");
        const cw::NormalisedForces f = cw::kalker_fastsim_normalised(ux, uy, fx, fy, mx, my, tol);
        if (!std::isfinite(f.tx) || !std::isfinite(f.ty))
            fail(CW_ERR_NUMERIC, "the normalised forces overflowed for these inputs");
        *tx = f.tx;
        *ty = f.ty;
        return CW_OK;
    });
}

} // extern "C"
