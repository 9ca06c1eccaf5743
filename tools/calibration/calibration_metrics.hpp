// The error measures of the accuracy targets, of one model's solve against the exact
// reference of the same contact.
#pragma once

#include <vector>

#include "contact/params.hpp"

namespace cwcal {

// What a model gives for one case: totals and, on the 40 x 40 uniform grid,
// the energy-consistent work map in the caller layout [i + j*nx].
struct ModelResult {
    double Fx = 0, Fy = 0, Mz = 0, W = 0;
    double adhesion_fraction = 0;
    std::vector<double> work_map; // empty when not on the map grid
};

struct CaseErrors {
    double dFx = 0, dFy = 0;      // |dF| in % of mu N
    bool mz_relative = true;      // |Mz_ref| >= 0.01 mu N c
    double dMz = 0;               // % of |Mz_ref|, or % of mu N c when not relative
    bool has_spin = false;
    double dW = 0;                // % of W_ref (spin cases)
    bool partial_slip = false;    // exact 40 x 40: 5 % .. 95 % of the patch adheres
    bool has_map = false;         // the model gave a map on the map grid
    double map_L1 = 0, profile_L1 = 0;
};

// ref: the yardstick totals; exact40: the exact model on the map grid (its
// map and adhesion fraction); nx, ny: the map grid.
CaseErrors case_errors(const creepwork::ContactInput& in, const ModelResult& model,
                       const ModelResult& ref, const ModelResult& exact40, int nx, int ny);

// An n_fine x n_fine map [i + j*n_fine] summed over the blocks of each cell
// of the n_coarse x n_coarse grid whose cells it nests in (n_fine a
// multiple of n_coarse).
std::vector<double> summed_onto_coarse_grid(const std::vector<double>& fine, int n_fine,
                                            int n_coarse);

// L1 distance of two maps each scaled to unit total (0 .. 2).
double unit_l1(const std::vector<double>& a, const std::vector<double>& b);
// The same for their lateral profiles (sums over i per row j).
double profile_l1(const std::vector<double>& a, const std::vector<double>& b, int nx, int ny);

} // namespace cwcal

namespace cwcal {

// The median of v (NaN when empty).
double median_of(std::vector<double> v);

} // namespace cwcal
