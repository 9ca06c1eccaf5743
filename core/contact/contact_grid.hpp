// Geometry of the discretised contact ellipse, in normalised coordinates
// X = x/a, Y = y/b of the rolling frame (leading edge at X = +1), so one grid
// serves every a, b, load and creepage. No physics here.
//
// Layout ("march order"): element (m, j) is stored at [m * ny + j], where m
// counts steps from the leading edge of the box (m = 0 first) and j the
// strips across y (j = 0 at the most negative y). Strips are the fastest
// index so the solver can advance all strips of one step together (SIMD).
#pragma once

#include <Eigen/Core>

#include "contact/params.hpp"

namespace creepwork {

class ContactGrid {
public:
    // Throws Error(grid_out_of_range) outside 1..kMaxGridCells or box scale
    // outside [1, kMaxBoxScale]. A gap grid (GridKind::gap) has no ellipse:
    // its grid holds the size alone (its per-element and per-strip arrays
    // are empty; the models on it read the caller's gap).
    explicit ContactGrid(const GridSpec& spec);

    // Kalker strip grid with explicit strip boundaries Y (ascending, from -1
    // to +1, ny + 1 values): the 1982 program may split a strip where the
    // longitudinal rigid slip changes sign.
    ContactGrid(int nx, const Eigen::ArrayXd& strip_bounds);

    const GridSpec& spec() const { return spec_; }
    int nx() const { return spec_.nx; }
    int ny() const { return ny_; }
    int size() const { return spec_.nx * ny_; }

    // Per element, march order.
    const Eigen::ArrayXd& x_centre() const { return x_centre_; }  // X of the element centre
    const Eigen::ArrayXd& x_slip() const { return x_slip_; }      // X where the rigid slip is taken
    const Eigen::ArrayXd& step() const { return step_; }          // step length from previous point, /a
    const Eigen::ArrayXd& in_contact() const { return in_contact_; } // 1 inside, 0 exterior
    const Eigen::ArrayXd& pressure_shape(PressureKind kind) const
    {
        return kind == PressureKind::parabolic ? shape_parabolic_ : shape_elliptic_;
    }

    // Per strip.
    const Eigen::ArrayXd& y_centre() const { return y_centre_; }  // Y of the strip centre
    const Eigen::ArrayXd& y_width() const { return y_width_; }    // strip width, /b
    const Eigen::ArrayXd& x_length() const { return x_length_; }  // element length, /a
    const Eigen::ArrayXi& contact_count() const { return contact_count_; }

    int n_contact() const { return n_contact_; }

private:
    void allocate();
    void build_strips(const Eigen::ArrayXd& strip_bounds);
    void build_uniform();
    void finish();

    GridSpec spec_;
    int ny_ = 0;
    int n_contact_ = 0;
    Eigen::ArrayXd x_centre_, x_slip_, step_, in_contact_;
    Eigen::ArrayXd shape_parabolic_, shape_elliptic_;
    Eigen::ArrayXd y_centre_, y_width_, x_length_;
    Eigen::ArrayXi contact_count_;
};

} // namespace creepwork
