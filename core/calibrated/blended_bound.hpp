// The calibrated model's traction bound: one number, the blend, moves the
// bound from FASTSIM's parabolic law towards the elliptic (Hertz) law, with
// the normal force unchanged.
//
// In units of the parabolic law's p0 = 2N/(pi a b), with P = 1 - X^2 - Y^2
// the parabolic shape (X = x/a, Y = y/b):
//   parabolic  P                   (p0 = 2N/(pi a b))
//   elliptic   (3/4) sqrt(P)       (p0 = 3N/(2 pi a b), Hertz)
// Each integrates over the unit disc to pi/2 (int P = pi/2,
// int sqrt(P) = 2 pi/3), so each carries the force N, and so does the blend
//   (1 - blend) P + blend (3/4) sqrt(P),   blend in [0, 1],
// which lowers the bound in the middle and raises it near the edge (more
// adhesion at the trailing edge).
#pragma once

#include <Eigen/Core>

#include "march/march_geometry.hpp"

namespace creepwork {

// Largest blend accepted (the elliptic law); callers clamp to [0, it].
constexpr double kMaxBoundBlend = 1.0;

// The blended bound at one point from its parabolic shape P (>= 0) and
// sqrt(P), in units of the parabolic p0. 0 outside the contact (P = 0).
inline double blended_bound_shape(double parabolic, double sqrt_parabolic, double blend)
{
    return (1.0 - blend) * parabolic + blend * 0.75 * sqrt_parabolic;
}

// The blended bound of every element of a grid, in the kernels' layout
// (march_geometry.hpp).
class BlendedBound {
public:
    // Allocates the bound of geometry (blend 0), so that set() allocates
    // nothing.
    explicit BlendedBound(const MarchGeometry& geometry);
    // The bound for this blend in [0, kMaxBoundBlend] (nothing to do when
    // it is the last one).
    void set(const MarchGeometry& geometry, double blend);
    const double* data() const { return shape_.data(); }
    double max() const { return max_; } // the largest element

private:
    Eigen::ArrayXd shape_;
    double blend_ = 0.0, max_ = 0.0;
};

} // namespace creepwork
