// Choosing the fit's objective weights (FitWeights) by k-fold
// cross-validation inside the training set, so that the evaluation set is
// used for no choice at all (doc/dev/calibration.md).
#pragma once

#include <vector>

#include "calibration_cases.hpp"
#include "calibration_reference.hpp"

namespace cwcal {

constexpr int kSelectFolds = 3;

// Fold (0 .. kSelectFolds-1) of each case: within each combination of
// creepages, the cases sorted by a/b are dealt to the folds in turn, so
// every fold spans the a/b range and holds every combination.
std::vector<int> fold_of_cases(const std::vector<CalibrationCase>& cases);

// For each candidate of a 3 x 3 x 3 grid (force limit 2, 2.5, 3 % of mu N;
// penalty 10, 20, 40; map weight 1, 1.5, 2): fits on two folds, counts the
// held-out fold's cases beyond the accuracy targets' bounds, sums over the three folds
// and prints one row; the best score last. cases must be the training set.
// Returns 0.
int select_weights(const std::vector<CalibrationCase>& cases, const std::vector<CaseReference>& refs);

} // namespace cwcal
