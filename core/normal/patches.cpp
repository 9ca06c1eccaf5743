#include "normal/patches.hpp"

#include <algorithm>
#include <cstddef>

namespace creepwork {

void add_patch_totals(const std::vector<PatchTotals>& patches, const ContactInput& in,
                      SolveTotals& t)
{
    for (const PatchTotals& P : patches) {
        t.Fx += P.Fx;
        t.Fy += P.Fy;
        t.Mz += P.Mz;
        t.n_contact += P.n_contact;
        t.n_slip += P.n_slip;
    }
    t.W_macro = -(t.Fx * in.xi_x + t.Fy * in.xi_y + t.Mz * in.phi);
    t.n_adhesion = t.n_contact - t.n_slip;
    t.adhesion_fraction = t.n_contact > 0 ? double(t.n_adhesion) / t.n_contact : 0.0;
}

PatchLabels::PatchLabels(int nx, int ny)
    : nx_(nx), ny_(ny), label_(static_cast<std::size_t>(nx) * ny, -1),
      row_start_(static_cast<std::size_t>(ny) + 1, 0)
{
    // At most (nx + 1) / 2 runs in a row (a gap between any two).
    const std::size_t most = static_cast<std::size_t>((nx + 1) / 2) * ny;
    for (auto* v : {&run_lo_, &run_hi_, &run_patch_, &parent_}) v->assign(most, 0);
}

int PatchLabels::label(const signed char* in_contact)
{
    clear_runs();
    for (int j = 0; j < ny_; ++j) {
        const signed char* row = in_contact + static_cast<std::size_t>(nx_) * j;
        for (int i = 0; i < nx_; ++i) {
            if (!row[i]) continue;
            const int lo = i;
            while (i + 1 < nx_ && row[i + 1]) ++i;
            add_run(lo, i);
        }
        end_row();
    }
    label_runs();
    std::fill(label_.begin(), label_.end(), -1);
    for (int j = 0; j < ny_; ++j)
        for (int r = row_start_[j]; r < row_start_[j + 1]; ++r)
            std::fill(label_.begin() + static_cast<std::ptrdiff_t>(nx_) * j + run_lo_[r],
                      label_.begin() + static_cast<std::ptrdiff_t>(nx_) * j + run_hi_[r] + 1,
                      run_patch_[r]);
    return count_;
}

int PatchLabels::label_runs()
{
    // Union-find over the runs, each root the lowest run of its set.
    auto find = [this](int r) {
        while (parent_[r] != r) r = parent_[r] = parent_[parent_[r]];
        return r;
    };
    for (int r = 0; r < n_runs_; ++r) parent_[r] = r;
    for (int j = 1; j < rows_; ++j) {
        // Runs of rows j - 1 and j that share a column, by a merge of the
        // two rows' runs (both in increasing i).
        int a = row_start_[j - 1], b = row_start_[j];
        const int a_end = row_start_[j], b_end = row_start_[j + 1];
        while (a < a_end && b < b_end) {
            if (run_lo_[a] <= run_hi_[b] && run_lo_[b] <= run_hi_[a]) {
                const int ra = find(a), rb = find(b);
                if (ra != rb) parent_[std::max(ra, rb)] = std::min(ra, rb);
            }
            // Advance the run that ends first (it meets no later run).
            if (run_hi_[a] < run_hi_[b])
                ++a;
            else
                ++b;
        }
    }
    // Number the sets in the order of their first run: the first run in
    // layout order holds the set's first element.
    count_ = 0;
    for (int r = 0; r < n_runs_; ++r) {
        const int root = find(r);
        run_patch_[r] = root == r ? count_++ : run_patch_[root];
    }
    return count_;
}

} // namespace creepwork
