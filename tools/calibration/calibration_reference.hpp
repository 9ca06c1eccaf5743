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
constexpr int kFineN = 160; // finest grid: its map summed onto kMapN cells

struct CaseReference {
    ModelResult exact20, exact40, ref;
    // exact kFineN x kFineN, its work map summed over the 4 x 4 blocks of
    // each kMapN cell (the continuum map on the comparison grid, as well as
    // the exact model can give it); the continuum estimate of each total
    // from 40, 80 and 160 (continuum_limit: Richardson with the observed
    // order when clean, else the 160 value), with the summed map and the 160
    // adhesion fraction. Filled by continuum_references.
    ModelResult fine, limit;
};

// Reads the cache when it holds every case of the set, else solves and
// writes it. Progress goes to stderr.
std::vector<CaseReference> exact_references(const std::vector<CalibrationCase>& cases,
                                            const std::string& cache_path);

// The uniform grid of the references and of the simplified models: n x n
// elements over the ellipse's bounding box (box scale 1).
creepwork::GridSpec uniform_grid(int n);

// A kFineN x kFineN map summed onto the kMapN x kMapN grid (its cells nest).
std::vector<double> summed_onto_map_grid(const std::vector<double>& fine);

// Adds fine and limit to refs (the exact model at kFineN, ~0.3-1 s per
// case), cached in cache_path as exact_references does.
void continuum_references(const std::vector<CalibrationCase>& cases,
                          std::vector<CaseReference>& refs, const std::string& cache_path);

} // namespace cwcal
