// The gap grid: the regular grid of cells on which the caller gives a
// contact of any shape by its undeformed distance (the gap), and what every
// model on it needs of its input. Checked here once for the normal problem
// and both tangential models.
#pragma once

#include <cstddef>
#include <vector>

#include "contact/params.hpp"
#include "simd/kernel_isa.hpp"

namespace creepwork {

// Smallest gap grid per direction (the semi-Hertzian method fits curvatures
// over three cells).
constexpr int kMinGapCells = 3;

// The grid of a model on a gap grid, checked before anything is allocated
// for it: throws Error(invalid_input) unless grid.kind is gap with finite
// origin and positive spacing, Error(grid_out_of_range) outside
// kMinGapCells ... kMaxExactCells cells per direction.
const GridSpec& checked_gap_grid(const GridSpec& grid);
// Per row j < ny of a gap grid: centre y [m] and width dy [m].
void copy_gap_rows(const GridSpec& grid, double* y, double* width);
// The element centres of a gap grid [m]: x0 + i dx (i < nx), y0 + j dy (j < ny).
void gap_centres(const GridSpec& grid, std::vector<double>& x, std::vector<double>& y);
// What every model on a gap grid needs of its input (n elements): the gap,
// the load, the normal method, mu, G, nu, the creepages, the rolling
// direction and the spin offset. Throws Error(invalid_input) naming the
// input. isa: the gap check's kernel (one branch-free pass; every ISA gives
// the same answer).
void validate_gap_input(const ContactInput& in, size_t n, KernelIsa isa);

} // namespace creepwork
