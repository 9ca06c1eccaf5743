#include "wheelrail/profile_table.hpp"

#include <algorithm>
#include <cmath>

namespace creepwork::wheelrail {

ProfileTable::ProfileTable(const Profile& p, double step)
{
    n_ = std::max(2, static_cast<int>(std::ceil((p.y_max() - p.y_min()) / step)) + 1);
    step_ = (p.y_max() - p.y_min()) / (n_ - 1);
    inv_step_ = 1.0 / step_;
    y0_ = p.y_min();
    last_ = n_ - 1;
    z_.resize(n_);
    d_.resize(n_);
    for (int k = 0; k < n_; ++k) {
        double s = 0.0;
        const double y = std::min(y0_ + k * step_, p.y_max());
        p.visible_s_at_y(y, s);
        const Profile::Point q = p.at(s);
        z_[k] = q.z;
        // a near-vertical part (never in contact) keeps a finite slope
        const double dy = std::abs(q.dy) < 1e-3 ? std::copysign(1e-3, q.dy) : q.dy;
        d_[k] = q.dz / dy;
    }
}

} // namespace creepwork::wheelrail
