// The march's data in the kernels' layout: per element [m * stride + j],
// m the step from the leading edge and j the strip, stride the strip count
// padded to whole vectors of the widest kernel; per strip [j]. The grid's
// geometry (MarchGeometry, made once per solver) and the state of one solve
// (MarchState).
#pragma once

#include <Eigen/Core>

#include "contact/contact_grid.hpp"
#include "contact/params.hpp"

namespace creepwork {

// Strips are padded to a multiple of this (the widest vector), so that every
// kernel runs whole vectors. Padding strips are exterior: they stay zero.
constexpr int kStripPad = 8;
constexpr int padded_strips(int ny) { return (ny + kStripPad - 1) / kStripPad * kStripPad; }

// The grid's per-element arrays in the kernels' layout. Made once per solver.
struct MarchGeometry {
    int nx = 0, ny = 0, stride = 0;
    Eigen::ArrayXd x_centre, x_slip, step, inside;
    // The pressure laws' shapes (pz / p0, 0 outside the contact), the traction
    // bounds of FASTSIM, and their largest values.
    Eigen::ArrayXd shape_parabolic, shape_elliptic;
    double max_parabolic = 0.0, max_elliptic = 0.0;

    MarchGeometry() = default;
    explicit MarchGeometry(const ContactGrid& grid);
    const Eigen::ArrayXd& shape(PressureKind kind) const
    {
        return kind == PressureKind::parabolic ? shape_parabolic : shape_elliptic;
    }
    double max_shape(PressureKind kind) const
    {
        return kind == PressureKind::parabolic ? max_parabolic : max_elliptic;
    }
    // On the uniform grid, each strip's first step from where the strip
    // enters the ellipse (X = sqrt(1 - Y^2)), not a full element, and the
    // rigid slip at each step's midpoint, as Kalker's strip grid does: both
    // of CONTACT's choices (a full first step, the slip at the element
    // centre) are first-order errors. Used by the calibrated model; plain
    // FASTSIM keeps CONTACT's. Nothing to do on the strip grid.
    void march_from_leading_edge(const ContactGrid& grid);
};

// Per-element state of one solve, [m * stride + j] (see MarchGeometry): the
// trial traction q' (elastic predictor) and the factor f that scales it onto
// the traction bound: p' = f q', f = 1 in adhesion, f < 1 in slip. Slip,
// dissipation and every other field follow from (q', f).
struct MarchState {
    int nx = 0, ny = 0, stride = 0;
    Eigen::ArrayXd qx, qy, factor;
    // Per strip: sums over the strip of p'_x, p'_y and X p'_y, and the
    // number of slip elements (a double so the kernels stay all-double).
    Eigen::ArrayXd sum_px, sum_py, sum_x_py, slip_count;
    // Per strip: the traction leaving the trailing edge.
    Eigen::ArrayXd px, py;
    // Per strip: rigid slip over flexibility along x, ux - cx Y, and the
    // part of the one along y that does not vary along the strip, uy (plus
    // cy times the spin offset); scratch, set by set_rigid_slip().
    Eigen::ArrayXd wx, wy;

    void resize(int n_elements, int ny);
};

} // namespace creepwork
