#include "calibrated/blended_bound.hpp"

#include <cmath>

namespace creepwork {

BlendedBound::BlendedBound(const MarchGeometry& geometry)
    : shape_(geometry.shape_parabolic), blend_(0.0), max_(geometry.max_parabolic)
{
}

void BlendedBound::set(const MarchGeometry& geometry, double blend)
{
    if (blend == blend_) return;
    // blended_bound_shape with its coefficients taken out of the loop, so
    // that it vectorises (a vehicle loop remakes it every solve).
    const Eigen::Index n = shape_.size();
    const double* P = geometry.shape_parabolic.data();
    const double* E = geometry.shape_elliptic.data(); // sqrt(P)
    double* out = shape_.data();
    const double cp = 1.0 - blend, ce = blend * 0.75;
    for (Eigen::Index k = 0; k < n; ++k) out[k] = cp * P[k] + ce * E[k];
    // The blend increases with P, so the largest is at the largest P.
    max_ = blended_bound_shape(geometry.max_parabolic, std::sqrt(geometry.max_parabolic), blend);
    blend_ = blend;
}

} // namespace creepwork
