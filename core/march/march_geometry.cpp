#include "march/march_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "contact/error.hpp"

namespace creepwork {

MarchGeometry::MarchGeometry(const ContactGrid& grid)
    : nx(grid.nx()), ny(grid.ny()), stride(padded_strips(grid.ny()))
{
    const Eigen::Index n = static_cast<Eigen::Index>(nx) * stride;
    x_centre.setZero(n);
    x_slip.setZero(n);
    step.setOnes(n); // padding strips: a harmless step, never used
    inside.setZero(n);
    shape_parabolic.setZero(n);
    shape_elliptic.setZero(n);
    strip_contacts = grid.contact_count();
    n_contact = grid.n_contact();
    for (int m = 0; m < nx; ++m)
        for (int j = 0; j < ny; ++j) {
            const Eigen::Index k = static_cast<Eigen::Index>(m) * ny + j;
            const Eigen::Index p = static_cast<Eigen::Index>(m) * stride + j;
            x_centre[p] = grid.x_centre()[k];
            x_slip[p] = grid.x_slip()[k];
            step[p] = grid.step()[k];
            inside[p] = grid.in_contact()[k];
            shape_parabolic[p] = grid.pressure_shape(PressureKind::parabolic)[k];
            shape_elliptic[p] = grid.pressure_shape(PressureKind::elliptic)[k];
        }
    max_parabolic = shape_parabolic.size() > 0 ? shape_parabolic.maxCoeff() : 0.0;
    max_elliptic = shape_elliptic.size() > 0 ? shape_elliptic.maxCoeff() : 0.0;
}

void MarchGeometry::set_contact(const ContactGrid& grid, const double* in, const double* shape)
{
    if (grid.spec().kind != GridKind::uniform)
        throw Error(ErrorKind::invalid_input,
                    "a contact given element by element needs the uniform grid (the strip "
                    "grid's strips are cut to the ellipse)");
    const Eigen::Index n = static_cast<Eigen::Index>(nx) * stride;
    if (shape_given.size() != n) shape_given.setZero(n);
    strip_contacts.setZero();
    n_contact = 0;
    max_given = 0.0;
    for (int m = 0; m < nx; ++m)
        for (int j = 0; j < ny; ++j) {
            const Eigen::Index k = static_cast<Eigen::Index>(m) * ny + j;
            const Eigen::Index p = static_cast<Eigen::Index>(m) * stride + j;
            const bool contact = in[k] != 0.0;
            inside[p] = contact ? 1.0 : 0.0;
            shape_given[p] = contact ? shape[k] : 0.0;
            max_given = shape_given[p] > max_given ? shape_given[p] : max_given;
            strip_contacts[j] += contact ? 1 : 0;
            n_contact += contact ? 1 : 0;
        }
    given_ = true;
    set_steps(grid);
}

void MarchGeometry::march_from_leading_edges(const ContactGrid& grid)
{
    leading_edges_ = true;
    set_steps(grid);
}

void MarchGeometry::set_steps(const ContactGrid& grid)
{
    for (int m = 0; m < nx; ++m)
        for (int j = 0; j < ny; ++j) {
            const Eigen::Index k = static_cast<Eigen::Index>(m) * ny + j;
            const Eigen::Index p = static_cast<Eigen::Index>(m) * stride + j;
            x_slip[p] = grid.x_slip()[k];
            step[p] = grid.step()[k];
        }
    if (!leading_edges_ || grid.spec().kind != GridKind::uniform) return;
    for (int j = 0; j < ny; ++j) {
        const double Y = grid.y_centre()[j];
        const double chord_end = std::sqrt(std::max(0.0, 1.0 - Y * Y)); // the ellipse's
        bool in_segment = false;
        double previous = 0.0; // where the step ends that reaches the element
        for (int m = 0; m < nx; ++m) {
            const Eigen::Index p = static_cast<Eigen::Index>(m) * stride + j;
            if (inside[p] == 0.0) { // between segments, or outside them
                in_segment = false;
                continue;
            }
            if (!in_segment) // the segment's leading edge
                previous = given_ ? x_centre[p] + 0.5 * grid.x_length()[j] : chord_end;
            in_segment = true;
            step[p] = previous - x_centre[p];
            x_slip[p] = 0.5 * (previous + x_centre[p]);
            previous = x_centre[p];
        }
    }
}

void MarchState::resize(int n_elements, int ny_)
{
    ny = ny_;
    nx = ny > 0 ? n_elements / ny : 0;
    stride = padded_strips(ny);
    const Eigen::Index n = static_cast<Eigen::Index>(nx) * stride;
    qx.setZero(n);
    qy.setZero(n);
    factor.setZero(n);
    sum_px.setZero(stride);
    sum_py.setZero(stride);
    sum_x_py.setZero(stride);
    slip_count.setZero(stride);
    px.setZero(stride);
    py.setZero(stride);
    wx.setZero(stride);
    wy.setZero(stride);
}

} // namespace creepwork
