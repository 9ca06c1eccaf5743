// The exact gap model's solved contact (gap_exact_model.hpp): tractions and
// slips in units of mu p_max and mu p_max / G on the whole grid (rolling
// frame), positions the grid's own (x0 + i dx, y0 + j dy), the moment
// about the grid's origin (contact/solved_contact.hpp exports it).
#include "gap/gap_exact_model.hpp"

namespace creepwork {

SolvedContact GapExactModel::solved() const
{
    const Setup& s = setup_;
    SolvedContact c;
    c.nx = nx_;
    c.ny = ny_;
    c.mirrored = s.direction < 0;
    c.direction = s.direction;
    c.x_column = x_column_.data();
    c.y_row = y_row_.data();
    c.element_area = grid_.dx * grid_.dy;
    c.pressure = normal_.pressure().data();
    c.traction = traction_.data();
    c.traction_scale = s.traction_scale;
    c.state = state_.data();
    c.slip = slip_.data();
    c.slip_scale = s.slip_scale;
    c.slip_masked = true;
    c.work_paper = paper_.data();
    c.work_consistent = consistent_.data();
    c.profile = profile_.data();
    c.profile_b = s.half_width > 0.0 ? s.half_width : grid_.dy;
    c.profile_y_mid = s.y_mid;
    return c;
}

bool GapExactModel::copy_strips(double* y, double* width) const
{
    copy_gap_rows(grid_, y, width);
    return true;
}

} // namespace creepwork
