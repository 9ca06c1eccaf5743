// Batches: many contacts on one grid in parallel (OpenMP), bitwise equal to one by one.
#include "capi_internal.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

extern "C" {

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

int cw_batch_prepare(cw_batch* batch, int model)
{
    if (!batch) return CW_ERR_NULL_POINTER;
    return guarded(&batch->last_error, [&] {
        const cw::ModelKind kind = to_model(model);
        for (cw::Solver& s : batch->solvers) s.prepare(kind);
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
        if (!valid_struct_size(pstride))
            fail(CW_ERR_STRUCT_SIZE, "params[0].struct_size is invalid");
        if (!valid_struct_size(rstride))
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
                // Exact contacts start cold: results must not depend on which
                // thread solved which contact before.
                cw::ContactInput in = to_input(p);
                in.warm_start = false;
                const cw::SolveTotals& tot = batch->solvers[t].solve(in, m);
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
            // Dynamic: contacts of one batch can differ 10x in cost (the
            // exact model, partial against full slip); a free thread takes
            // the next. Which thread solves a contact cannot change it.
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
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

} // extern "C"
