// Choosing the fit's objective weights (FitWeights) by k-fold
// cross-validation inside the training set, so that the evaluation set is
// used for no choice at all (README "How the table was generated").
#pragma once

#include <vector>

#include "calibration_cases.hpp"
#include "calibration_reference.hpp"

namespace cwcal {

// For each candidate of a 3 x 3 x 3 grid (force limit 2, 2.5, 3 % of mu N;
// penalty 10, 20, 40; map weight 1, 1.5, 2): fits on two folds, counts the
// held-out fold's cases beyond issue 10's bounds, sums over the three folds
// and prints one row; the best score last. cases must be the training set.
// Returns 0, or 1 when the table interpolation disagrees with core's.
int select_weights(const std::vector<CalibrationCase>& cases, const std::vector<CaseReference>& refs);

} // namespace cwcal
