// The separate contact patches of a solution on a grid: the 4-connected
// components of its contact elements (elements sharing an edge belong to one
// patch; touching corners do not join), as CONTACT counts them. Patches are
// numbered in the order of their first element in the layout [i + nx j]
// (lowest row first, then lowest x).
//
// The labelling works on runs (the contact elements of one row with no gap
// between them): runs of neighbouring rows that share a column join
// (union-find), so the cost follows the runs, not the elements.
#pragma once

#include <vector>

#include "contact/params.hpp"

namespace creepwork {

// The contact's totals from its patches' (each complete): Fx, Fy, Mz and the
// element counts summed in the patches' order, then W_macro, n_adhesion and
// the adhesion fraction.
void add_patch_totals(const std::vector<PatchTotals>& patches, const ContactInput& in,
                      SolveTotals& t);

class PatchLabels {
public:
    PatchLabels(int nx, int ny); // all workspace

    // Labels the elements with in_contact[k] != 0; returns the number of
    // patches. Allocates nothing.
    int label(const signed char* in_contact);
    // Patch of element k (0-based), or -1 outside the contact (after label()).
    int of(int k) const { return label_[k]; }
    int count() const { return count_; }

    // The runs directly, row by row from j = 0 and in increasing i within a
    // row: clear_runs(), then per row add_run(lo, hi) for each run of
    // elements lo .. hi and end_row(); label_runs() numbers them (of() is
    // not set: run_patch() is). Allocates nothing.
    void clear_runs()
    {
        n_runs_ = 0;
        rows_ = 0;
        row_start_[0] = 0;
    }
    void add_run(int lo, int hi)
    {
        run_lo_[n_runs_] = lo;
        run_hi_[n_runs_++] = hi;
    }
    void end_row() { row_start_[++rows_] = n_runs_; }
    int label_runs();
    int runs() const { return n_runs_; }
    // Runs row_start(j) .. row_start(j + 1) - 1 lie in row j.
    int row_start(int j) const { return row_start_[j]; }
    int run_lo(int r) const { return run_lo_[r]; }
    int run_hi(int r) const { return run_hi_[r]; }
    int run_patch(int r) const { return run_patch_[r]; }

private:
    int nx_, ny_, count_ = 0, n_runs_ = 0, rows_ = 0;
    std::vector<int> label_;
    std::vector<int> row_start_, run_lo_, run_hi_, run_patch_, parent_;
};

} // namespace creepwork
