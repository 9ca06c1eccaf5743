// The exact model's solved contact (exact_model.hpp): the fine level's
// tractions, slips and states, normalised by mu p0 and mu p0 / G, on the
// caller's uniform grid (contact/solved_contact.hpp exports it).
#include "exact/exact_model.hpp"

namespace creepwork {

SolvedContact ExactModel::solved() const
{
    const Level& L = *levels_[0];
    const Setup& s = setup_;
    SolvedContact c;
    c.nx = nx_;
    c.ny = ny_;
    c.mirrored = s.direction < 0;
    c.direction = s.direction;
    c.x_column = x_column_.data();
    c.y_row = y_row_.data();
    c.element_area = s.dx * s.dy;
    if (s.p0 > 0.0) c.pressure = L.normal.pressure().data();
    c.pressure_scale = s.p0;
    c.traction = L.tangential.traction().data();
    c.traction_scale = s.traction_scale;
    c.state = L.tangential.state().data();
    c.slip = L.tangential.slip().data();
    c.slip_scale = s.slip_scale;
    c.slip_masked = true;
    c.work_paper = paper_.data();
    c.work_consistent = consistent_.data();
    c.profile = profile_.data();
    c.profile_b = s.b;
    return c;
}

} // namespace creepwork
