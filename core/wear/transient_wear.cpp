#include "wear/transient_wear.hpp"

#include <algorithm>
#include <cmath>

#include "contact/contact_input.hpp"
#include "contact/error.hpp"

namespace creepwork {

void TransientWear::init(int nx, int ny, double dx, double dy, double y0)
{
    nx_ = nx;
    ny_ = ny;
    dx_ = dx;
    dy_ = dy;
    y0_ = y0;
    const std::size_t n = static_cast<std::size_t>(nx_) * ny_;
    for (auto* v : {&map_, &area_, &pz_, &px_, &py_, &sx_, &sy_, &work_, &step_mass_}) v->assign(n, 0.0);
    strip_width_.assign(ny_, dy_);
    strip_y_.resize(ny_);
    for (int j = 0; j < ny_; ++j) strip_y_[j] = y0_ + j * dy_;
}

void TransientWear::reset()
{
    std::fill(map_.begin(), map_.end(), 0.0);
    mass_ = 0.0;
    steps_ = 0;
}

void TransientWear::check(int nx, int ny, bool has_solution, double dq,
                          const wear::WearLaw& law)
{
    if (nx != nx_ || ny != ny_)
        throw Error(ErrorKind::invalid_input, "transient wear: the contact is not of this grid");
    if (!has_solution)
        throw Error(ErrorKind::invalid_input, "transient wear: there is no step (step() first)");
    require_non_negative("dq", dq);
    if (!(dq <= dx_ * (1.0 + 1e-12)))
        reject_input("dq", dq, "must be at most the grid's dx (the distance rolled in one step)");
    wear::validate(law);
    ++steps_;
}

wear::WearTotals TransientWear::add_fields(double dq, const wear::WearLaw& law)
{
    const std::size_t n = map_.size();
    for (std::size_t k = 0; k < n; ++k) {
        area_[k] = pz_[k] > 0.0 ? dx_ * dy_ : 0.0;
        sx_[k] /= dq;
        sy_[k] /= dq;
        work_[k] /= dq;
    }
    wear::ContactFields in;
    in.nx = nx_;
    in.ny = ny_;
    in.b = 0.5 * ny_ * dy_;
    in.area = area_.data();
    in.pz = pz_.data();
    in.px = px_.data();
    in.py = py_.data();
    in.sx = sx_.data();
    in.sy = sy_.data();
    in.work = work_.data();
    in.strip_y = strip_y_.data();
    in.strip_width = strip_width_.data();
    wear::WearLaw step_law = law;
    step_law.pass_length = dq;
    wear::WearFields out;
    out.mass = step_mass_.data();
    const wear::WearTotals t = wear::wear_map(in, step_law, out);
    for (std::size_t k = 0; k < n; ++k) map_[k] += step_mass_[k];
    mass_ += t.mass_per_pass;
    return t;
}

} // namespace creepwork
