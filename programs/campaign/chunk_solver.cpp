#include "chunk_solver.hpp"

#include <map>

namespace cwcampaign {

namespace {

struct GridOrder {
    bool operator()(const cw_grid& a, const cw_grid& b) const { return grid_shape_less(a, b); }
};

// cw_batch_last_error names the contact as "params[i]: "; a row's message
// is about the row itself.
std::string without_index(const std::string& message)
{
    const std::string prefix = "params[0]: ";
    return message.compare(0, prefix.size(), prefix) == 0 ? message.substr(prefix.size())
                                                           : message;
}

} // namespace

ChunkSolver::ChunkSolver(int threads, size_t max_batches)
    : threads_(threads), max_batches_(max_batches < 1 ? 1 : max_batches)
{
}

ChunkSolver::~ChunkSolver()
{
    for (Entry& e : batches_) cw_batch_destroy(e.batch);
}

cw_batch* ChunkSolver::batch_for(const cw_grid& grid, int& status, std::string& message)
{
    for (auto it = batches_.begin(); it != batches_.end(); ++it)
        if (same_grid_shape(it->grid, grid)) {
            batches_.splice(batches_.begin(), batches_, it);
            return batches_.front().batch;
        }
    if (batches_.size() >= max_batches_) {
        cw_batch_destroy(batches_.back().batch);
        batches_.pop_back();
    }
    char text[512] = "";
    cw_batch* batch = nullptr;
    status = cw_batch_create(&grid, threads_, &batch, text, sizeof text);
    if (status != CW_OK) {
        message = text[0] ? text : cw_status_string(status);
        return nullptr;
    }
    batches_.push_front(Entry{grid, batch});
    return batch;
}

void ChunkSolver::solve_rows(cw_batch* batch, const Chunk& chunk, const std::vector<size_t>& rows,
                             int mode, std::vector<Outcome>& out)
{
    const size_t m = rows.size();
    if (m == 0) return;
    params_.resize(m);
    results_.resize(m);
    statuses_.assign(m, CW_OK);
    for (size_t k = 0; k < m; ++k) {
        const ContactCase& c = chunk.cases[rows[k]];
        params_[k] = c.params;
        // A gap row's values travel with the chunk, which outlives the solve.
        if (c.gap_values) {
            params_[k].gap = c.gap_values->data();
            params_[k].gap_len = c.gap_values->size();
        }
        cw_result_init(&results_[k]);
    }
    cw_batch_solve(batch, m, params_.data(), mode, results_.data(), statuses_.data());
    for (size_t k = 0; k < m; ++k) {
        Outcome& o = out[rows[k]];
        o.status = statuses_[k];
        o.result = results_[k];
        if (o.status == CW_OK) continue;
        // The batch keeps only the first failure's message: solve the
        // row alone to get its own (same status; the library is
        // deterministic, and a failing row is usually rejected at once).
        cw_result scratch;
        cw_result_init(&scratch);
        const int again = cw_batch_solve(batch, 1, &params_[k], mode, &scratch, nullptr);
        o.message = again == o.status ? without_index(cw_batch_last_error(batch))
                                      : cw_status_string(o.status);
        cw_result_init(&o.result);
    }
}

std::vector<Outcome> ChunkSolver::solve(const Chunk& chunk)
{
    const size_t n = chunk.cases.size();
    std::vector<Outcome> out(n);
    // Rows grouped by grid shape, each group in chunk order; the order of
    // the groups does not matter (each contact's result is its own).
    std::map<cw_grid, std::vector<size_t>, GridOrder> groups;
    for (size_t i = 0; i < n; ++i) {
        const ContactCase& c = chunk.cases[i];
        if (!c.rejected.empty()) {
            out[i].status = c.rejected_status;
            out[i].message = c.rejected;
            cw_result_init(&out[i].result);
            continue;
        }
        groups[c.grid].push_back(i);
    }
    for (const auto& [grid, rows] : groups) {
        int status = CW_OK;
        std::string message;
        cw_batch* batch = batch_for(grid, status, message);
        if (!batch) {
            for (size_t i : rows) {
                out[i].status = status;
                out[i].message = message;
                cw_result_init(&out[i].result);
            }
            continue;
        }
        solve_rows(batch, chunk, rows, chunk.mode, out);
    }
    return out;
}

} // namespace cwcampaign
