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
#include "simd/kernel_isa.hpp"
#include "march/march_geometry.hpp"
#include "march/march_setup.hpp"

namespace creepwork {

struct MarchView; // march_step.hpp

// The per-strip rigid slip over flexibility of kin, wx[j] = ux - cx Y_j and
// the part of the lateral one constant along the strip, wy[j] (uy, plus
// cy times the spin offset), for strips [first, last).
void rigid_slip_of_strips(const ContactGrid& grid, const NormalisedKinematics& kin, double* wx,
                          double* wy, int first, int last);
// The same into state.wx, state.wy.
void set_rigid_slip(const ContactGrid& grid, const NormalisedKinematics& kin, MarchState& state,
                    int first, int last);

// Advance the view's strips [first, last) from the leading edge (m = 0) to
// the trailing edge, their rigid slip set: writes q', f and the strip sums
// (MarchState); allocates nothing. Callers that follow each block of
// kStripBlock strips with more work do so while its data are in cache.
constexpr int kStripBlock = 32;
void march(const MarchView& view, KernelIsa isa);
// Every strip of a one-off grid with FASTSIM's bound for pressure (allocates
// its MarchGeometry; Kalker's normalised interface).
void march(const ContactGrid& grid, const NormalisedKinematics& kin, PressureKind pressure,
           MarchState& state, KernelIsa isa = best_kernel_isa());

// Rolling-frame forces over the traction scale T, Phi = (fx, fy, mz) / T,
// from the march's strip sums, summed strip by strip in order.
void scaled_forces(const ContactGrid& grid, double a, double b, const MarchState& march,
                   double Phi[3]);

// Derivatives of the march's strip sums along kStripTangents tangents (or
// directions), [k * stride + j] for tangent k and strip j.
constexpr int kStripTangents = 3;
struct StripTangents {
    const double *sum_px = nullptr, *sum_py = nullptr, *sum_x_py = nullptr;
    int stride = 0;
};
// Phi as above (bitwise) and its derivatives dPhi[i][k] along each tangent.
void scaled_forces(const ContactGrid& grid, double a, double b, const MarchState& march,
                   const StripTangents& tangents, double Phi[3],
                   double dPhi[3][kStripTangents]);

} // namespace creepwork
