// FASTSIM's solved contact on a gap grid (gap_fastsim_model.hpp): the
// march's tractions [Pa] and slips [-] on the whole grid (rolling frame),
// positions the grid's own, the moment about the grid's origin, as the
// exact gap model's (contact/solved_contact.hpp exports it).
#include "gap/gap_fastsim_model.hpp"

namespace creepwork {

SolvedContact GapFastsimModel::solved() const
{
    SolvedContact c;
    c.nx = nx_;
    c.ny = ny_;
    c.mirrored = direction_ < 0;
    c.direction = direction_;
    c.x_column = x_column_.data();
    c.y_row = y_row_.data();
    c.element_area = grid_.dx * grid_.dy;
    c.pressure = normal_.pressure().data();
    c.traction = p_.data();
    c.state = state_.data();
    c.slip = slip_.data(); // zero unless slipping
    c.work_paper = paper_.data();
    c.work_consistent = consistent_.data();
    c.profile = profile_.data();
    c.profile_b = half_width_ > 0.0 ? half_width_ : grid_.dy;
    c.profile_y_mid = y_mid_;
    return c;
}

} // namespace creepwork
