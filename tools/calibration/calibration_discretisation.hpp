// Elements needed for 1 % discretisation error: each
// model is solved on uniform n x n grids for a small subset of the
// evaluation set, its own continuum limit is estimated from its finest
// grids, and the smallest n whose totals stay within 1 % of that limit is
// reported with the observed order of convergence (doc/validation/calibrated.md).
#pragma once

#include <string>

namespace cwcal {

// Prints the subset, the per-model table and the observed orders; the exact
// references in cache_dir (exact_evaluation.txt) pick the partial-slip cases.
int discretisation_study(const std::string& cache_dir);

} // namespace cwcal
