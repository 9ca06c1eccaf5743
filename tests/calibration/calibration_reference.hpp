// The yardstick: this library's exact model (CW_MODEL_EXACT) on the uniform
// grid (box scale 1, spin offset 1/6 as CONTACT) for each case, at N = 20,
// 40 and kRefN elements per direction; the kRefN solve is the reference, the
// 40 x 40 one also gives the reference work map. Computed once and kept in a
// cache file (plain text) so that fitting and evaluation rerun quickly.
#pragma once

#include <string>
#include <vector>

#include "calibration_cases.hpp"
#include "calibration_metrics.hpp"

namespace cwcal {

constexpr int kMapN = 40;  // grid of the work-map comparison
constexpr int kRefN = 80;  // grid of the reference totals

struct CaseReference {
    ModelResult exact20, exact40, ref;
};

// Reads the cache when it holds every case of the set, else solves and
// writes it. Progress goes to stderr.
std::vector<CaseReference> exact_references(const std::vector<CalibrationCase>& cases,
                                            const std::string& cache_path);

} // namespace cwcal
