// Fitting the calibrated model's table on the training set.
#pragma once

#include <vector>

#include "calibration_cases.hpp"
#include "calibration_reference.hpp"
#include "solver.hpp"

namespace cwcal {

// A solve of in on solver (full mode) as the metrics want it.
ModelResult solved_result(creepwork::Solver& solver, const creepwork::ContactInput& in);

// A solve of the calibrated model with the given parameters.
ModelResult calibrated_result(creepwork::CalibratedModel& model, const creepwork::ContactInput& in,
                              const creepwork::CalibrationParams& params);

// Fits and prints the table (C++ source for core/calibrated/); returns 0.
int fit_table(const std::vector<CalibrationCase>& cases, const std::vector<CaseReference>& refs);

} // namespace cwcal
