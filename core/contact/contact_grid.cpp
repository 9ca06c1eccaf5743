#include "contact/contact_grid.hpp"

#include <cmath>
#include <string>

#include "contact/error.hpp"

namespace creepwork {
namespace {

void check_cells(const char* name, int n)
{
    if (n < 1 || n > kMaxGridCells)
        throw Error(ErrorKind::grid_out_of_range,
                    std::string(name) + " = " + std::to_string(n) + " is outside 1.." +
                        std::to_string(kMaxGridCells));
}

} // namespace

ContactGrid::ContactGrid(const GridSpec& spec) : spec_(spec), ny_(spec.ny)
{
    check_cells("nx", spec.nx);
    check_cells("ny", spec.ny);
    if (spec.kind == GridKind::uniform &&
        !(spec.box_scale >= 1.0 && spec.box_scale <= kMaxBoxScale))
        throw Error(ErrorKind::grid_out_of_range,
                    "box_scale = " + std::to_string(spec.box_scale) +
                        " is outside [1, 100] (the box must hold the ellipse)");
    if (spec.kind == GridKind::gap) return; // the caller's gap gives the contact
    allocate();
    if (spec.kind == GridKind::uniform) {
        build_uniform();
    } else {
        Eigen::ArrayXd bounds = Eigen::ArrayXd::LinSpaced(ny_ + 1, -1.0, 1.0);
        build_strips(bounds);
    }
    finish();
}

ContactGrid::ContactGrid(int nx, const Eigen::ArrayXd& strip_bounds)
{
    spec_.kind = GridKind::kalker_strips;
    spec_.nx = nx;
    spec_.ny = static_cast<int>(strip_bounds.size()) - 1;
    ny_ = spec_.ny;
    check_cells("nx", spec_.nx);
    check_cells("ny", spec_.ny);
    allocate();
    build_strips(strip_bounds);
    finish();
}

void ContactGrid::allocate()
{
    const Eigen::Index n = static_cast<Eigen::Index>(spec_.nx) * ny_;
    x_centre_.setZero(n);
    x_slip_.setZero(n);
    step_.setZero(n);
    in_contact_.setZero(n);
    shape_parabolic_.setZero(n);
    shape_elliptic_.setZero(n);
    y_centre_.setZero(ny_);
    y_width_.setZero(ny_);
    x_length_.setZero(ny_);
    contact_count_.setZero(ny_);
}

// Kalker 1982: each strip is cut into nx equal elements over its own chord at
// the strip centre; the march starts at the leading edge with a half step to
// the first element centre and takes the rigid slip at each step's midpoint.
void ContactGrid::build_strips(const Eigen::ArrayXd& strip_bounds)
{
    const int nx = spec_.nx;
    for (int j = 0; j < ny_; ++j) {
        const double y = 0.5 * (strip_bounds[j] + strip_bounds[j + 1]);
        const double half_chord = std::sqrt(1.0 - y * y);
        const double dx = 2.0 * half_chord / nx;
        y_centre_[j] = y;
        y_width_[j] = strip_bounds[j + 1] - strip_bounds[j];
        x_length_[j] = dx;
        double previous = half_chord;
        for (int m = 0; m < nx; ++m) {
            const Eigen::Index k = static_cast<Eigen::Index>(m) * ny_ + j;
            const double x = half_chord - (m + 0.5) * dx;
            x_centre_[k] = x;
            x_slip_[k] = 0.5 * (x + previous);
            step_[k] = previous - x;
            in_contact_[k] = 1.0;
            previous = x;
        }
    }
}

// CONTACT: a box of equal elements; an element is in contact when its centre
// lies inside the ellipse. Each strip starts from zero displacement in its
// first contact element with a full step; rigid slip at element centres.
void ContactGrid::build_uniform()
{
    const int nx = spec_.nx;
    const double s = spec_.box_scale;
    const double dx = 2.0 * s / nx;
    const double dy = 2.0 * s / ny_;
    for (int j = 0; j < ny_; ++j) {
        const double y = -s + (j + 0.5) * dy;
        y_centre_[j] = y;
        y_width_[j] = dy;
        x_length_[j] = dx;
        for (int m = 0; m < nx; ++m) {
            const Eigen::Index k = static_cast<Eigen::Index>(m) * ny_ + j;
            const double x = s - (m + 0.5) * dx;
            x_centre_[k] = x;
            x_slip_[k] = x;
            step_[k] = dx;
            in_contact_[k] = (x * x + y * y < 1.0) ? 1.0 : 0.0;
        }
    }
}

void ContactGrid::finish()
{
    n_contact_ = 0;
    for (Eigen::Index k = 0; k < x_centre_.size(); ++k) {
        const int j = static_cast<int>(k % ny_);
        const double x = x_centre_[k];
        const double y = y_centre_[j];
        const double r = std::fmax(0.0, 1.0 - x * x - y * y);
        const bool inside = in_contact_[k] != 0.0;
        shape_parabolic_[k] = inside ? r : 0.0;
        shape_elliptic_[k] = inside ? std::sqrt(r) : 0.0;
        contact_count_[j] += inside ? 1 : 0;
        n_contact_ += inside ? 1 : 0;
    }
}

} // namespace creepwork
