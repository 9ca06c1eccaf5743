#include "wheelrail/wheelrail_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/error.hpp"
#include "wheelrail/patch_combination.hpp"
#include "wheelrail/placement.hpp"

namespace creepwork::wheelrail {
namespace {

constexpr double kTableStep = 2e-5; // [m] wheel bottom tabulated every 20 um

void require(bool ok, const std::string& message)
{
    if (!ok) throw Error(ErrorKind::invalid_input, message);
}

bool finite_all(std::initializer_list<double> v)
{
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// Plausible ranges catch lengths given in millimetres and angles in degrees.
void check_inputs(const Profile& rail, const Profile& wheel, const Track& t, const Wheelset& w,
                  const SearchOptions& o)
{
    require(rail.kind() == ProfileKind::rail, "wheel/rail: the rail profile was read as a wheel profile");
    require(wheel.kind() == ProfileKind::wheel, "wheel/rail: the wheel profile was read as a rail profile");
    require(finite_all({t.gauge_height, t.gauge_width, t.cant, t.rail_y0, t.rail_z0, t.rail_dy, t.rail_dz,
                        t.rail_roll, t.curvature}),
            "wheel/rail: the track has a value that is not finite");
    require(t.gauge_height < 0.1, "wheel/rail: track gauge_height must be below 0.1 m (units are metres)");
    require(t.gauge_height <= 0.0 || (t.gauge_width > 0.3 && t.gauge_width < 3.0),
            "wheel/rail: track gauge_width must lie in (0.3, 3) m (units are metres)");
    require(std::abs(t.cant) < 0.5 && std::abs(t.rail_roll) < 0.5,
            "wheel/rail: track cant and rail_roll must be below 0.5 rad (units are radians)");
    require(std::abs(t.rail_y0) < 3.0 && std::abs(t.rail_z0) < 1.0 && std::abs(t.rail_dy) < 0.1 &&
                std::abs(t.rail_dz) < 0.1,
            "wheel/rail: track rail_y0, rail_z0, rail_dy or rail_dz out of range (units are metres)");
    require(std::abs(t.curvature) < 0.1, "wheel/rail: track curvature must be below 0.1 1/m (radius above 10 m)");
    require(finite_all({w.flange_back_distance, w.flange_back_position, w.nominal_radius}),
            "wheel/rail: the wheelset has a value that is not finite");
    require(w.nominal_radius > 0.05 && w.nominal_radius < 5.0,
            "wheel/rail: wheelset nominal_radius must lie in (0.05, 5) m (units are metres)");
    require(w.flange_back_distance > 0.0 && w.flange_back_distance < 3.0,
            "wheel/rail: wheelset flange_back_distance must lie in (0, 3) m (units are metres)");
    require(std::abs(w.flange_back_position) < 0.5,
            "wheel/rail: wheelset flange_back_position must lie within 0.5 m of the profile origin");
    require(finite_all({o.dx, o.ds, o.a_sep, o.d_sep, o.d_comb, o.d_turn, o.g_miss, o.lateral_step}),
            "wheel/rail: a search option is not finite");
    require(o.dx > 1e-6 && o.dx < 0.01 && o.ds > 1e-6 && o.ds < 0.01,
            "wheel/rail: search dx and ds must lie in (1e-6, 0.01) m (units are metres)");
    require(o.a_sep >= 0.0, "wheel/rail: search a_sep must be >= 0 [rad]");
    require(o.d_comb >= 0.0 && o.d_sep > o.d_comb && o.d_sep < 1.0,
            "wheel/rail: search distances need 0 <= d_comb < d_sep < 1 m");
    require(o.lateral_step > 0.0 && o.lateral_step <= 1.0, "wheel/rail: search lateral_step must lie in (0, 1]");
    require(o.max_elements >= 100, "wheel/rail: search max_elements must be >= 100");
}

void check_state(const WheelsetPosition& p, const WheelsetVelocity& v)
{
    require(finite_all({p.y, p.z, p.roll, p.yaw, p.pitch}), "wheel/rail: the wheelset position is not finite");
    require(finite_all({v.vs, v.vy, v.vz, v.vroll, v.vyaw, v.vpitch}),
            "wheel/rail: the wheelset velocity is not finite");
    require(std::abs(p.y) < 0.2 && std::abs(p.z) < 0.2,
            "wheel/rail: wheelset y and z must be below 0.2 m (units are metres)");
    require(std::abs(p.roll) < 0.3 && std::abs(p.yaw) < 0.3,
            "wheel/rail: wheelset roll and yaw must be below 0.3 rad (units are radians)");
    require(std::abs(v.vs) < 300.0 && std::abs(v.vy) < 300.0 && std::abs(v.vz) < 300.0,
            "wheel/rail: wheelset velocities must be below 300 m/s (units are m/s)");
    require(std::abs(v.vpitch) < 3000.0 && std::abs(v.vroll) < 3000.0 && std::abs(v.vyaw) < 3000.0,
            "wheel/rail: wheelset angular velocities must be below 3000 rad/s");
}

} // namespace

WheelRailGeometry::WheelRailGeometry(const Profile& rail, const Profile& wheel, const Track& track,
                                     const Wheelset& wheelset, Side side, const SearchOptions& options)
    : rail_(rail), wheel_(wheel), track_(track), wheelset_(wheelset), side_(side), opt_(options)
{
    check_inputs(rail, wheel, track, wheelset, options);
    rail_frame_ = place_rail(rail_, track_, side_);
    rail_track_ = rail_.placed(rail_frame_);
    wheel_ws_ = wheel_in_wheelset(wheelset_);
    wheel_table_ = ProfileTable(wheel_, kTableStep);
    search_ = ContactSearch(rail_track_, wheel_, opt_, wheelset_.nominal_radius);
}

const WheelRailState& WheelRailGeometry::evaluate(const WheelsetPosition& pos, const WheelsetVelocity& vel,
                                                  bool height_only)
{
    check_state(pos, vel);
    const double sgn = side_ == Side::right ? 1.0 : -1.0;
    const Frame ws = wheelset_in_track(pos, wheelset_, side_);
    const Frame wheel = ws.compose(wheel_ws_);
    state_.position = pos;
    state_.gap_min = search_.find(wheel, regions_, height_only);
    combine_regions(regions_, opt_);
    state_.patches.resize(regions_.size());
    wheel_nodes_.resize(regions_.size());
    for (size_t k = 0; k < regions_.size(); ++k) {
        const Region& reg = regions_[k];
        ContactPatch& cp = state_.patches[k];
        double s_rail = 0.0;
        const Frame ref = contact_reference(reg, rail_track_, s_rail);
        potential_contact(reg, rail_track_, s_rail, ref, opt_, grid_);
        undeformed_distance(ref, rail_track_, s_rail, wheel_table_, wheel, wheelset_.nominal_radius, grid_,
                            &wheel_nodes_[k], height_only);
        const Creepages c = creepages_at(ref, -grid_.h_min, ws, vel, track_, side_);
        // positions, un-mirrored for the left side
        const Frame in_rail = rail_frame_.local_of(ref), in_wheel = wheel.local_of(ref);
        cp.x_tr = ref.o(0);
        cp.y_tr = sgn * ref.o(1);
        cp.z_tr = ref.o(2);
        cp.delta = sgn * ref.roll();
        cp.y_r = sgn * in_rail.o(1);
        cp.z_r = in_rail.o(2);
        cp.s_r = s_rail;
        cp.x_w = in_wheel.o(0);
        cp.y_w = sgn * in_wheel.o(1);
        cp.z_w = in_wheel.o(2);
        if (!wheel_.visible_s_at_y(in_wheel.o(1), cp.s_w))
            cp.s_w = in_wheel.o(1) > wheel_.y_max() ? wheel_.s_first() : wheel_.s_last();
        cp.wheel_radius = wheelset_.nominal_radius + wheel_.at(cp.s_w).z;
        // the grid's s is the patch frame's (ref's second axis), reversed on
        // the left side; the profiles' y axes are their frames' second axes
        cp.rail_profile_y = in_rail.o(1);
        cp.rail_s_cos = sgn * ref.r.col(1).dot(rail_frame_.r.col(1));
        cp.wheel_profile_y = in_wheel.o(1);
        cp.wheel_s_cos = sgn * ref.r.col(1).dot(wheel.r.col(1));
        const Vec3 in_ws = ws.to_local(ref.o);
        cp.x_ws = in_ws(0);
        cp.y_ws = sgn * in_ws(1);
        cp.z_ws = in_ws(2);
        cp.rolling_radius = c.rolling_radius;
        cp.veloc = c.veloc;
        cp.cksi = c.cksi;
        cp.ceta = sgn * c.ceta;
        cp.cphi = sgn * c.cphi;
        cp.forward = c.forward;
        // the grid, its s axis reversed on the left side
        cp.nx = grid_.nx;
        cp.ny = grid_.ny;
        cp.dx = grid_.dx;
        cp.ds = grid_.ds;
        cp.x0 = grid_.ix_lo * grid_.dx;
        cp.s0 = side_ == Side::right ? grid_.iy_lo * grid_.ds : -(grid_.iy_lo + grid_.ny - 1) * grid_.ds;
        cp.h.resize(grid_.h.size());
        for (int j = 0; j < grid_.ny; ++j) {
            const int jj = side_ == Side::right ? j : grid_.ny - 1 - j;
            std::copy_n(&grid_.h[static_cast<size_t>(jj) * grid_.nx], grid_.nx,
                        &cp.h[static_cast<size_t>(j) * grid_.nx]);
        }
        cp.approach = -grid_.h_min;
        cp.gap_min = reg.gap_min;
        cp.sub_extent = reg.sub_extent;
        for (int m = 0; m < reg.n_sub() && side_ == Side::left; ++m) {
            double* e = &cp.sub_extent[6 * static_cast<size_t>(m)];
            const double lo = -e[3], hi = -e[2];
            e[2] = lo;
            e[3] = hi;
            std::swap(e[4], e[5]);
        }
        cp.sub_factor = reg.sub_factor;
    }
    return state_;
}

void WheelRailGeometry::profile_in_track(bool rail, std::vector<double>& y, std::vector<double>& z) const
{
    const double sgn = side_ == Side::right ? 1.0 : -1.0;
    const Profile& p = rail ? rail_track_ : wheel_;
    const Frame f = rail ? Frame{} : wheelset_in_track(state_.position, wheelset_, side_).compose(wheel_ws_);
    y.resize(static_cast<std::size_t>(p.size()));
    z.resize(y.size());
    for (std::size_t k = 0; k < y.size(); ++k) {
        const Vec3 t = f.to_parent(Vec3(0.0, p.knots_y()[k], p.knots_z()[k]));
        y[k] = sgn * t(1);
        z[k] = t(2);
    }
}

} // namespace creepwork::wheelrail
