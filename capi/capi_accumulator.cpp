// The work accumulator: running totals and maps over a simulation run.
#include "capi_internal.hpp"

#include <cmath>

extern "C" {

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
        const cw::SolvedContact& view = s.solved();
        cw::add_field(view, cw::Field::work_paper, distance, accumulator->next_paper.data());
        cw::add_field(view, cw::Field::work_consistent, distance,
                      accumulator->next_consistent.data());
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
    return guarded(&accumulator->last_error, [&] {
        require(totals, "totals");
        write_struct(totals, accumulator->totals);
        return CW_OK;
    });
}

int cw_accumulator_get_field(const cw_accumulator* accumulator, int field, double* out,
                             size_t out_len)
{
    if (!accumulator) return CW_ERR_NULL_POINTER;
    return guarded(&accumulator->last_error, [&] {
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
    return guarded(&accumulator->last_error, [&] {
        require(out, "out");
        require_length(len, accumulator->strips.size(), "out");
        std::copy(accumulator->strips.begin(), accumulator->strips.end(), out);
        return CW_OK;
    });
}

} // extern "C"
