#include "transient/transient_base.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "contact/contact_input.hpp"
#include "contact/error.hpp"
#include "contact/number_text.hpp"
#include "normal/gap_grid.hpp"
#include "transient/state_bytes.hpp"

namespace creepwork {
namespace {

void check_finite(const char* name, double v)
{
    if (!std::isfinite(v)) reject_input(name, v, "must be finite");
}

} // namespace

TransientBase::TransientBase(const GridSpec& grid)
    : nx_(checked_gap_grid(grid).nx), ny_(grid.ny), n_(grid.nx * grid.ny), x0_(grid.x0),
      y0_(grid.y0), dx_(grid.dx), dy_(grid.dy)
{
}

void TransientBase::check_contact(const ContactInput& in, std::size_t n, KernelIsa isa)
{
    ContactInput check = in;
    check.xi_x = check.xi_y = check.phi = 0.0;
    check.rolling_direction = 1;
    validate_gap_input(check, n, isa);
    if (!(in.mu > 0.0))
        reject_input("mu", in.mu, "must be > 0 for transient rolling (without friction "
                                  "there are no tangential tractions to carry over)");
}

void TransientBase::check_loaded(double p_max)
{
    if (!(p_max > 0.0))
        throw Error(ErrorKind::invalid_input,
                    "the contact carries no load (no element of the gap grid is in contact): "
                    "transient rolling needs normal_force > 0 or an approach with contact");
}

void TransientBase::validate(const TransientStepInput& s, bool steady, double limit) const
{
    if (!steady) {
        check_finite("dq", s.dq);
        // dq within a rounding of dx counts as dx.
        if (s.dq < 0.0 || s.dq > dx_ * (1.0 + 1e-12))
            reject_input("dq", s.dq,
                         ("must be in [0, dx = " + number_text(dx_) +
                          " m] (the distance rolled in one step; 0 is a shift)")
                             .c_str());
    }
    check_finite("xi_x", s.xi_x);
    check_finite("xi_y", s.xi_y);
    check_finite("phi", s.phi);
    const std::string below = "must be below mu N = " + number_text(limit) +
                              " N in magnitude (at mu N the contact slides: no creepage gives it)";
    if (s.prescribe_fx) {
        check_finite("Fx", s.Fx);
        if (!(std::fabs(s.Fx) < limit)) reject_input("Fx", s.Fx, below.c_str());
    }
    if (s.prescribe_fy) {
        check_finite("Fy", s.Fy);
        if (!(std::fabs(s.Fy) < limit)) reject_input("Fy", s.Fy, below.c_str());
    }
    if (s.prescribe_fx && s.prescribe_fy && std::hypot(s.Fx, s.Fy) >= limit)
        reject_input("Fx", s.Fx,
                     ("and Fy together must stay below mu N = " + number_text(limit) + " N")
                         .c_str());
}

void TransientBase::clear_committed()
{
    std::fill(creep0_, creep0_ + 3, 0.0);
    steps_ = 0;
    trial_valid_ = false;
    has_solution_ = false;
}

void TransientBase::first_creepages(const TransientStepInput& s, bool rolling,
                                    double c[3]) const
{
    c[0] = s.xi_x;
    c[1] = s.xi_y;
    c[2] = s.phi;
    if (s.prescribe_fx) c[0] = rolling ? creep0_[0] : 0.0;
    if (s.prescribe_fy) c[1] = rolling ? creep0_[1] : 0.0;
}

void TransientBase::hold_trial(const double c[3], bool rolling)
{
    trial_valid_ = true;
    has_solution_ = true;
    trial_rolling_ = rolling;
    std::copy(c, c + 3, trial_creep_);
}

void TransientBase::commit_steady()
{
    trial_valid_ = false;
    std::copy(trial_creep_, trial_creep_ + 3, creep0_);
    steps_ = 0;
}

void TransientBase::require_trial() const
{
    if (!trial_valid_)
        throw Error(ErrorKind::invalid_input,
                    "commit: there is no step to commit (step() first; a trial is "
                    "committed once, and rewind drops it)");
}

void TransientBase::count_commit()
{
    if (trial_rolling_) std::copy(trial_creep_, trial_creep_ + 3, creep0_);
    ++steps_;
    trial_valid_ = false;
}

std::vector<unsigned char> TransientBase::save_committed(const char (&magic)[8], double id0,
                                                         double id1) const
{
    std::vector<unsigned char> out(magic, magic + 8);
    put_bytes(out, static_cast<std::int32_t>(nx_));
    put_bytes(out, static_cast<std::int32_t>(ny_));
    put_bytes(out, id0);
    put_bytes(out, id1);
    put_bytes(out, static_cast<std::int64_t>(steps_));
    for (double v : creep0_) put_bytes(out, v);
    return out;
}

TransientBase::Committed TransientBase::read_committed(const unsigned char* bytes,
                                                       std::size_t n, std::size_t size,
                                                       const char (&magic)[8],
                                                       const char* what, double id0,
                                                       double id1) const
{
    if (!bytes || n != size || std::memcmp(bytes, magic, 8) != 0)
        throw Error(ErrorKind::invalid_input,
                    "restore: the bytes (" + std::to_string(n) + ") are not a saved " + what +
                        " of this grid (" + std::to_string(size) + " bytes expected)");
    Committed c;
    c.p = bytes + 8;
    std::int32_t nx = 0, ny = 0;
    double saved0 = 0.0, saved1 = 0.0;
    std::int64_t steps = 0;
    get_bytes(c.p, nx);
    get_bytes(c.p, ny);
    get_bytes(c.p, saved0);
    get_bytes(c.p, saved1);
    get_bytes(c.p, steps);
    if (nx != nx_ || ny != ny_ || saved0 != id0 || saved1 != id1)
        throw Error(ErrorKind::invalid_input,
                    "restore: the bytes are the state of another contact (grid, load or "
                    "friction differ)");
    for (double& v : c.creep) get_bytes(c.p, v);
    for (double v : c.creep) check_finite("restored creepage", v);
    c.steps = static_cast<long>(steps);
    return c;
}

void TransientBase::set_committed(const Committed& c)
{
    std::copy(c.creep, c.creep + 3, creep0_);
    steps_ = c.steps;
    trial_valid_ = false;
    has_solution_ = false;
}

} // namespace creepwork
