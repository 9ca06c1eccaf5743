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

// The grid's per-element arrays in the kernels' layout, and the contact the
// march runs on: the grid's ellipse (ContactGrid::in_contact and its
// pressure laws' shapes) unless set_contact() gives another, element by
// element. Made once per solver.
//
// A strip may hold several contact segments (runs of contact elements
// separated by exterior ones). The march needs nothing more for them: an
// exterior element has q' = bound = 0, so each segment starts again from
// zero displacement at its own leading edge (march_step.hpp). Only the first
// step of a segment depends on where it starts (march_from_leading_edges).
struct MarchGeometry {
    int nx = 0, ny = 0, stride = 0;
    Eigen::ArrayXd x_centre, x_slip, step;
    // The contact: 1 inside, 0 exterior; the number of contact elements per
    // strip (j < ny) and in all.
    Eigen::ArrayXd inside;
    Eigen::ArrayXi strip_contacts;
    int n_contact = 0;
    // The ellipse's pressure laws' shapes (pz / p0, 0 outside it), the
    // traction bounds of FASTSIM, and their largest values.
    Eigen::ArrayXd shape_parabolic, shape_elliptic;
    double max_parabolic = 0.0, max_elliptic = 0.0;
    // The traction bound's shape set_contact() gave (0 outside the contact)
    // and its largest value; empty until then.
    Eigen::ArrayXd shape_given;
    double max_given = 0.0;

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

    // A contact given by the caller, on the uniform grid: inside (1 or 0) and
    // the bound's shape (>= 0, 0 where inside is 0) per element in the grid's
    // march order [m * ny + j] (contact_grid.hpp), for models whose contact
    // is not an ellipse (a gap function's). Its segments are marched by the
    // step rule in force. Allocates shape_given on its first call only.
    // Throws Error(invalid_input) on the strip grid (its strips are cut to
    // the ellipse's chords).
    void set_contact(const ContactGrid& grid, const double* inside, const double* shape);
    // The step rule: on the uniform grid each contact segment's first step
    // from where the segment starts -- the ellipse's chord end
    // X = sqrt(1 - Y^2), or for a contact given by set_contact() the front
    // edge of its first element -- not a full element, and the rigid slip at
    // each step's midpoint, as Kalker's strip grid does: both of CONTACT's
    // choices (a full first step, the slip at the element centre) are
    // first-order errors. Used by the calibrated model; plain FASTSIM keeps
    // CONTACT's. Nothing to do on the strip grid.
    void march_from_leading_edges(const ContactGrid& grid);

private:
    void set_steps(const ContactGrid& grid); // the grid's steps, then the rule
    bool leading_edges_ = false, given_ = false;
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
