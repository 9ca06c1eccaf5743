// Fitting the calibrated model's table on the training set.
#pragma once

#include <array>
#include <vector>

#include "calibrated/calibration_table.hpp"
#include "calibration_cases.hpp"
#include "calibration_reference.hpp"
#include "solver.hpp"

namespace cwcal {

// A solve of in on solver (full mode) as the metrics want it.
ModelResult solved_result(creepwork::Solver& solver, const creepwork::ContactInput& in);

// A solve of the calibrated model with the given parameters.
ModelResult calibrated_result(creepwork::CalibratedModel& model, const creepwork::ContactInput& in,
                              const creepwork::CalibrationParams& params);

// The weights of the fit's objective (calibration_fit.cpp, case_cost). The
// defaults are the ones `select-weights` chose by cross-validation on the
// training set (calibration_select.cpp; doc/dev/calibration.md).
struct FitWeights {
    double force_limit = 3.0; // % of mu N where the extra force penalty starts
    double penalty = 40.0;    // its weight
    double map_weight = 1.5;  // weight of the map and profile terms
};
// The defaults, each replaced by CW_FIT_FORCE_LIMIT, CW_FIT_PENALTY or
// CW_FIT_MAPW when set.
FitWeights fit_weights_from_env();

// The calibrated model as the fit sees it, against the exact model's
// continuum estimate (CaseReference::limit), on the map grid kMapN and on
// kFineN (its map summed onto the kMapN cells): a table fitted on one grid
// alone absorbs that grid's discretisation error and is worse on others.
class FitModel {
public:
    FitModel();
    CaseErrors errors(const CalibrationCase& c, const CaseReference& ref,
                      const creepwork::CalibrationParams& params, bool fine_grid);
    // case_cost on both grids, averaged.
    double cost(const CalibrationCase& c, const CaseReference& ref,
                const creepwork::CalibrationParams& params, const FitWeights& w);

private:
    creepwork::CalibratedModel map_grid_, fine_grid_;
};

// One case's share of the objective: each of the targeted errors in units of
// its bound, squared, plus the force penalty and the map weight of w.
double case_cost(const CaseErrors& e, const FitWeights& w);

using CalibrationTable = std::array<creepwork::CalibrationNode, creepwork::kCalibrationNodes>;

struct FitResult {
    CalibrationTable table;
    // Per node: cases used and weighted cost before -> after.
    std::array<size_t, creepwork::kCalibrationNodes> cases{};
    std::array<double, creepwork::kCalibrationNodes> cost_start{}, cost_fitted{};
};

// Fits the table on the cases whose indices are in use (into cases/refs).
FitResult fit_nodes(const std::vector<CalibrationCase>& cases, const std::vector<CaseReference>& refs,
                    const std::vector<size_t>& use, const FitWeights& w);

// Fits on the whole training set and prints the table (C++ source for
// core/calibrated/); returns 0.
int fit_table(const std::vector<CalibrationCase>& cases, const std::vector<CaseReference>& refs);

} // namespace cwcal
