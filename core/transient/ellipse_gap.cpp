#include "transient/ellipse_gap.hpp"

#include "contact/contact_input.hpp"
#include "contact/hertz.hpp"
#include "normal/gap_grid.hpp"

namespace creepwork {

EllipseGap ellipse_gap(const GridSpec& uniform, const ContactInput& in)
{
    ContactInput check = in;
    check.xi_x = check.xi_y = check.phi = 0.0; // a step's, not the contact's
    validate_contact_input(check);
    validate_grid_input(uniform, check);
    require_positive("normal_force", in.normal_force);
    EllipseGap e;
    e.grid = uniform;
    e.grid.kind = GridKind::gap;
    const double S = uniform.box_scale;
    e.grid.dx = 2.0 * S * in.a / uniform.nx;
    e.grid.dy = 2.0 * S * in.b / uniform.ny;
    e.grid.x0 = -S * in.a + 0.5 * e.grid.dx;
    e.grid.y0 = -S * in.b + 0.5 * e.grid.dy;
    checked_gap_grid(e.grid);
    const HertzCurvatures hz = hertz_from_semi_axes(in.a, in.b, in.normal_force, in.G / (1.0 - in.nu));
    e.h.resize(static_cast<std::size_t>(uniform.nx) * uniform.ny);
    for (int j = 0; j < uniform.ny; ++j)
        for (int i = 0; i < uniform.nx; ++i) {
            const double x = e.grid.x0 + i * e.grid.dx, y = e.grid.y0 + j * e.grid.dy;
            e.h[i + static_cast<std::size_t>(uniform.nx) * j] = hz.A * x * x + hz.B * y * y;
        }
    return e;
}

} // namespace creepwork
