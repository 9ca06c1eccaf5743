// The FASTSIM march (Kalker 1982) in normalised units: tractions p' in units
// of mu*p0, bound = pressure shape (1 at the centre). Strips are independent:
// the kernels advance a group of strips (several SIMD vectors of them) from
// the leading edge to the trailing edge together, with each strip's running
// traction and sums held in registers (march_step.hpp).
//
// Kernels (kernel_isa.hpp): compiled for the baseline ISA and, on x86-64,
// AVX2 and AVX-512. Results are bitwise identical whichever kernel runs:
// every operation is an IEEE add, subtract, multiply, divide or square root
// (correctly rounded on every ISA), no multiply-add is contracted
// (-ffp-contract=off, no -ffast-math), and every sum runs in a fixed order
// that does not depend on the vector width (each strip along the march, then
// the strips in order).
#pragma once

#include "contact/contact_grid.hpp"
#include "march/kernel_isa.hpp"
#include "march/march_geometry.hpp"
#include "march/march_setup.hpp"

namespace creepwork {

// The per-strip rigid slip of kin (state.wx, state.wy) for strips [first, last).
void set_rigid_slip(const ContactGrid& grid, const NormalisedKinematics& kin, MarchState& state,
                    int first, int last);
// The same into wx[j], wy[j] (callers that differentiate it).
void rigid_slip_of_strips(const ContactGrid& grid, const NormalisedKinematics& kin, double* wx,
                          double* wy, int first, int last);

// Advance every strip from the leading edge (m = 0) to the trailing edge.
// Writes state (sized by resize(nx * ny, ny)); allocates nothing.
void march(const MarchGeometry& geometry, const ContactGrid& grid,
           const NormalisedKinematics& kin, PressureKind pressure, MarchState& state,
           KernelIsa isa);
// Only the view's strips [first, last) (march_step.hpp; first a multiple of
// kStripBlock), the rigid slip of which is set: callers that follow each
// block with more work while its data are in cache.
constexpr int kStripBlock = 32;
struct MarchView;
void march(const MarchView& view, KernelIsa isa);
// The same for a one-off grid (allocates its MarchGeometry).
void march(const ContactGrid& grid, const NormalisedKinematics& kin, PressureKind pressure,
           MarchState& state, KernelIsa isa = best_kernel_isa());

} // namespace creepwork
