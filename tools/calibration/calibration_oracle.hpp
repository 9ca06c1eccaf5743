// The floor of the calibrated model's form (doc/theory/calibrated.md, "What
// the form can reach"): for each partial-slip case, the knobs of
// CalibrationParams chosen for that case alone, by coordinate search against
// the continuum reference, to minimise one error. No table of the form --
// which gives every case of an a/b and creepage the same knobs -- can do
// better than these per-case optima, so where they miss one of the accuracy targets'
// bounds that bound is out of the form's reach. Fitted to the very cases it
// measures, on purpose: a bound, not a model.
#pragma once

#include <functional>
#include <string>

#include "calibrated/calibration_params.hpp"
#include "calibration_cases.hpp"

namespace cwcal {

// Coordinate search over the knobs of CalibrationParams (k_long, k_lat,
// k_spin_x, k_spin_y in [0.2, 5], equalise [0, 1], lateral_moment [0, 1.5],
// edge_gain [-0.9, 5], bound_blend [0, 1]) from start: each knob up or down
// by the step, clamped to its range, while that lowers f; the step halved
// from 0.2 down to 0.0125. Returns the lowest f found; its knobs go to
// *best when given.
double search_knobs(const std::function<double(const creepwork::CalibrationParams&)>& f,
                    creepwork::CalibrationParams start, creepwork::CalibrationParams* best = nullptr);

// Prints per case and in summary the best map L1 (model on 40 x 40 and on
// 160 x 160 summed onto 40 x 40), the best profile L1 (40 x 40), and the
// best map L1 (both grids) among knobs that keep the forces within 3 % of
// mu N and, with spin, W within 5 % (2, the largest distance, where the
// search found no such knobs). Returns 0.
int oracle_study(CaseSet set, const std::string& dir);

} // namespace cwcal
