// The wheel/rail handle (cw_wheelrail_*): profiles, the geometry and the
// exact contact of every patch (core/wheelrail/patch_contact.hpp).
#include <cmath>
#include <memory>
#include <sstream>

#include "capi_wheelrail_internal.hpp"
#include "contact/number_text.hpp"
#include "wheelrail/profile_io.hpp"

namespace {

cw_wheelrail_params default_wheelrail_params()
{
    cw_wheelrail_params p;
    std::memset(&p, 0, sizeof p);
    p.struct_size = sizeof p;
    const wr::Track t;
    const wr::Wheelset w;
    const wr::SearchOptions o;
    const wr::PatchContactSettings c;
    p.side = CW_WHEELRAIL_RIGHT;
    p.gauge_height = t.gauge_height;
    p.gauge_width = t.gauge_width;
    p.cant = t.cant;
    p.flange_back_distance = w.flange_back_distance;
    p.flange_back_position = w.flange_back_position;
    p.nominal_radius = w.nominal_radius;
    p.dx = o.dx;
    p.ds = o.ds;
    p.a_sep = o.a_sep;
    p.d_sep = o.d_sep;
    p.d_comb = o.d_comb;
    p.mu = c.mu;
    p.G = c.G;
    p.nu = c.nu;
    p.model = CW_MODEL_EXACT;
    p.normal_method = CW_NORMAL_EXACT;
    p.solve_mode = CW_SOLVE_FULL;
    return p;
}

cw_wheelrail_motion default_motion()
{
    cw_wheelrail_motion m;
    std::memset(&m, 0, sizeof m);
    m.struct_size = sizeof m;
    return m;
}

void check_params(const cw_wheelrail_params& p)
{
    if (p.side != CW_WHEELRAIL_RIGHT && p.side != CW_WHEELRAIL_LEFT)
        fail(CW_ERR_UNKNOWN_OPTION, "params->side = " + std::to_string(p.side) +
                                        " is neither CW_WHEELRAIL_RIGHT (0) nor CW_WHEELRAIL_LEFT (1)");
    const std::pair<const char*, double> all[] = {
        {"gauge_height", p.gauge_height}, {"gauge_width", p.gauge_width}, {"cant", p.cant},
        {"rail_y0", p.rail_y0}, {"rail_z0", p.rail_z0}, {"rail_dy", p.rail_dy}, {"rail_dz", p.rail_dz},
        {"rail_roll", p.rail_roll}, {"curvature", p.curvature},
        {"flange_back_distance", p.flange_back_distance}, {"flange_back_position", p.flange_back_position},
        {"nominal_radius", p.nominal_radius}, {"dx", p.dx}, {"ds", p.ds}, {"a_sep", p.a_sep},
        {"d_sep", p.d_sep}, {"d_comb", p.d_comb}, {"mu", p.mu}, {"G", p.G}, {"nu", p.nu},
        {"tolerance", p.tolerance}, {"profile_unit", p.profile_unit},
        {"rail_y_offset", p.rail_y_offset}, {"wheel_y_offset", p.wheel_y_offset},
        {"mu_e1", p.mu_e1}, {"s_h1", p.s_h1}, {"mu_e2", p.mu_e2}, {"s_h2", p.s_h2},
        {"memory_distance", p.memory_distance}, {"memory_s0", p.memory_s0}, {"layer_h", p.layer_h},
        {"layer_G", p.layer_G}, {"tau_c0", p.tau_c0}, {"k_tau", p.k_tau}};
    for (const auto& [name, v] : all) require_finite((std::string("params->") + name).c_str(), v);
    if (p.model != CW_MODEL_EXACT && p.model != CW_MODEL_FASTSIM)
        fail(CW_ERR_UNKNOWN_OPTION, "params->model = " + std::to_string(p.model) +
                                        " is neither CW_MODEL_EXACT (1) nor CW_MODEL_FASTSIM (0)");
    if (p.normal_method != CW_NORMAL_EXACT && p.normal_method != CW_NORMAL_SEMI_HERTZ)
        fail(CW_ERR_UNKNOWN_OPTION, "params->normal_method = " + std::to_string(p.normal_method) +
                                        " is neither CW_NORMAL_EXACT (0) nor CW_NORMAL_SEMI_HERTZ (1)");
    if (p.solve_mode != CW_SOLVE_FULL && p.solve_mode != CW_SOLVE_FORCES)
        fail(CW_ERR_UNKNOWN_OPTION, "params->solve_mode = " + std::to_string(p.solve_mode) +
                                        " is neither CW_SOLVE_FORCES (0) nor CW_SOLVE_FULL (1)");
    if (!(p.dx > 0.0 && p.dx <= 0.1 && p.ds > 0.0 && p.ds <= 0.1))
        fail(CW_ERR_INVALID_INPUT, "params->dx = " + creepwork::number_text(p.dx) + ", ds = " + creepwork::number_text(p.ds) +
                                       " must lie in (0, 0.1] m");
    if (!(p.nominal_radius > 0.05 && p.nominal_radius < 5.0))
        fail(CW_ERR_INVALID_INPUT, "params->nominal_radius = " + creepwork::number_text(p.nominal_radius) +
                                       " must lie in (0.05, 5) m (a radius in mm?)");
    for (const auto& [name, v] : {std::pair<const char*, double>{"rail_y_offset", p.rail_y_offset},
                                  {"wheel_y_offset", p.wheel_y_offset}})
        if (!(std::fabs(v) <= 1.0))
            fail(CW_ERR_INVALID_INPUT, std::string("params->") + name + " = " +
                                           creepwork::number_text(v) + " must lie within +-1 m");
    if (p.mirror_wheel != 0 && p.mirror_wheel != 1)
        fail(CW_ERR_INVALID_INPUT, "params->mirror_wheel = " + std::to_string(p.mirror_wheel) +
                                       " must be 0 or 1");
    if (p.friction_law != CW_FRICTION_COULOMB && p.friction_law != CW_FRICTION_LINEAR &&
        p.friction_law != CW_FRICTION_RATIONAL && p.friction_law != CW_FRICTION_EXPONENTIAL)
        fail(CW_ERR_UNKNOWN_OPTION, "params->friction_law = " + std::to_string(p.friction_law) +
                                        " is none of CW_FRICTION_COULOMB (0), _LINEAR (2), _RATIONAL (3), "
                                        "_EXPONENTIAL (4)");
    if (!(p.profile_unit >= 0.0 && p.profile_unit <= 1.0))
        fail(CW_ERR_INVALID_INPUT, "params->profile_unit = " + creepwork::number_text(p.profile_unit) +
                                       " must lie in [0, 1] m per unit");
}

wr::WheelRailContact make_contact(const cw_wheelrail_params& p, const wr::Profile& rail,
                                  const wr::Profile& wheel)
{
    wr::Track t;
    t.gauge_height = p.gauge_height;
    t.gauge_width = p.gauge_width;
    t.cant = p.cant;
    t.rail_y0 = p.rail_y0;
    t.rail_z0 = p.rail_z0;
    t.rail_dy = p.rail_dy;
    t.rail_dz = p.rail_dz;
    t.rail_roll = p.rail_roll;
    t.curvature = p.curvature;
    wr::Wheelset w;
    w.flange_back_distance = p.flange_back_distance;
    w.flange_back_position = p.flange_back_position;
    w.nominal_radius = p.nominal_radius;
    wr::SearchOptions o;
    o.dx = p.dx;
    o.ds = p.ds;
    o.a_sep = p.a_sep;
    o.d_sep = p.d_sep;
    o.d_comb = p.d_comb;
    wr::PatchContactSettings c;
    c.mu = p.mu;
    c.G = p.G;
    c.nu = p.nu;
    c.tolerance = p.tolerance;
    c.friction_law = static_cast<cw::FrictionLaw>(p.friction_law);
    c.mu_e1 = p.mu_e1;
    c.s_h1 = p.s_h1;
    c.mu_e2 = p.mu_e2;
    c.s_h2 = p.s_h2;
    c.memory_distance = p.memory_distance;
    c.memory_s0 = p.memory_s0;
    c.layer_h = p.layer_h;
    c.layer_G = p.layer_G;
    c.tau_c0 = p.tau_c0;
    c.k_tau = p.k_tau;
    c.model = p.model == CW_MODEL_FASTSIM ? cw::ModelKind::fastsim : cw::ModelKind::exact;
    c.normal_method =
        p.normal_method == CW_NORMAL_SEMI_HERTZ ? cw::NormalMethod::semi_hertz : cw::NormalMethod::exact;
    c.mode = p.solve_mode == CW_SOLVE_FORCES ? cw::SolveMode::forces_only : cw::SolveMode::full;
    const wr::Side side = p.side == CW_WHEELRAIL_LEFT ? wr::Side::left : wr::Side::right;
    return wr::WheelRailContact(wr::WheelRailGeometry(rail, wheel, t, w, side, o), c);
}

// The handle, with what cw_wheelrail_check reads of the parameters.
cw_wheelrail* make_handle(const cw_wheelrail_params& p, const wr::Profile& rail,
                          const wr::Profile& wheel)
{
    auto* w = new cw_wheelrail(make_contact(p, rail, wheel));
    w->inputs.mu = p.mu;
    w->inputs.G = p.G;
    w->inputs.layer_h = p.layer_h;
    w->inputs.layer_G = p.layer_G;
    w->inputs.tau_c0 = p.tau_c0;
    return w;
}

// The reading options of one profile: the unit, and the offset and mirror
// that bring its origin and direction to this module's.
wr::ProfileReadOptions read_options(const cw_wheelrail_params& p, wr::ProfileKind kind)
{
    wr::ProfileReadOptions opt;
    opt.length_unit = p.profile_unit;
    opt.y_offset = kind == wr::ProfileKind::rail ? p.rail_y_offset : p.wheel_y_offset;
    opt.mirror_y = kind == wr::ProfileKind::wheel && p.mirror_wheel == 1;
    return opt;
}

cw_wheelrail_params read_params(const cw_wheelrail_params* params)
{
    const cw_wheelrail_params p =
        params ? read_struct(params, default_wheelrail_params(), "params") : default_wheelrail_params();
    check_params(p);
    return p;
}

// Points as a table in the profile readers' format: their ordering,
// mirroring and checks apply, and errors name the point.
wr::Profile profile_of_points(const double* y, const double* z, size_t n, wr::ProfileKind kind,
                              const char* name, const cw_wheelrail_params& p)
{
    require(y, (std::string(name) + "_y").c_str());
    require(z, (std::string(name) + "_z").c_str());
    if (n < 4 || n > 1000000)
        fail(CW_ERR_INVALID_INPUT, std::string(name) + "_n = " + std::to_string(n) + " must lie in [4, 1e6]");
    std::ostringstream table;
    table.precision(17);
    for (size_t k = 0; k < n; ++k) {
        if (!std::isfinite(y[k]) || !std::isfinite(z[k]))
            fail(CW_ERR_INVALID_INPUT, std::string(name) + " point " + std::to_string(k) + " is not finite");
        table << y[k] << ' ' << z[k] << '\n';
    }
    std::istringstream in(table.str());
    wr::ProfileReadOptions opt = read_options(p, kind);
    if (!(opt.length_unit > 0.0)) opt.length_unit = 1.0;
    return wr::read_profile(in, kind, wr::ProfileFormat::table, std::string(name) + " points", opt);
}

void check_finite_out(const char* what, double v)
{
    if (!std::isfinite(v)) fail(CW_ERR_NUMERIC, std::string("the ") + what + " is not finite");
}

} // namespace

const wr::PatchSolution& creepwork::capi::solved_patch(const cw_wheelrail& w, size_t k)
{
    if (!w.solved) fail(CW_ERR_NO_SOLUTION, "no successful cw_wheelrail_solve on this handle");
    const wr::WheelRailSolution& s = w.contact.solution();
    if (k >= s.patches.size())
        fail(CW_ERR_INVALID_INPUT,
             "k = " + std::to_string(k) + " is not below the number of patches, " + std::to_string(s.patches.size()));
    return s.patches[k];
}

extern "C" {

int cw_wheelrail_params_init(cw_wheelrail_params* params)
{
    if (!params) return CW_ERR_NULL_POINTER;
    *params = default_wheelrail_params();
    return CW_OK;
}

int cw_wheelrail_motion_init(cw_wheelrail_motion* motion)
{
    if (!motion) return CW_ERR_NULL_POINTER;
    *motion = default_motion();
    return CW_OK;
}

int cw_wheelrail_totals_init(cw_wheelrail_totals* totals)
{
    if (!totals) return CW_ERR_NULL_POINTER;
    std::memset(totals, 0, sizeof *totals);
    totals->struct_size = sizeof *totals;
    return CW_OK;
}

int cw_wheelrail_patch_init(cw_wheelrail_patch* patch)
{
    if (!patch) return CW_ERR_NULL_POINTER;
    std::memset(patch, 0, sizeof *patch);
    patch->struct_size = sizeof *patch;
    return CW_OK;
}

int cw_wheelrail_create(const cw_wheelrail_params* params, const char* rail_file, const char* wheel_file,
                        cw_wheelrail** wheelrail, char* message, size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(wheelrail, "wheelrail");
        *wheelrail = nullptr;
        require(rail_file, "rail_file");
        require(wheel_file, "wheel_file");
        const cw_wheelrail_params p = read_params(params);
        const wr::Profile rail =
            wr::read_profile_file(rail_file, wr::ProfileKind::rail, read_options(p, wr::ProfileKind::rail));
        const wr::Profile wheel = wr::read_profile_file(wheel_file, wr::ProfileKind::wheel,
                                                        read_options(p, wr::ProfileKind::wheel));
        *wheelrail = make_handle(p, rail, wheel);
        return CW_OK;
    });
}

int cw_wheelrail_create_points(const cw_wheelrail_params* params, const double* rail_y, const double* rail_z,
                               size_t rail_n, const double* wheel_y, const double* wheel_z, size_t wheel_n,
                               cw_wheelrail** wheelrail, char* message, size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(wheelrail, "wheelrail");
        *wheelrail = nullptr;
        const cw_wheelrail_params p = read_params(params);
        const wr::Profile rail = profile_of_points(rail_y, rail_z, rail_n, wr::ProfileKind::rail, "rail", p);
        const wr::Profile wheel = profile_of_points(wheel_y, wheel_z, wheel_n, wr::ProfileKind::wheel, "wheel", p);
        *wheelrail = make_handle(p, rail, wheel);
        return CW_OK;
    });
}

int cw_wheelrail_destroy(cw_wheelrail* wheelrail)
{
    delete wheelrail;
    return CW_OK;
}

int cw_wheelrail_solve(cw_wheelrail* wheelrail, const cw_wheelrail_motion* motion, int load, double Fz,
                       cw_wheelrail_totals* totals)
{
    if (!wheelrail) return CW_ERR_NULL_POINTER;
    wheelrail->solved = false;
    return guarded(&wheelrail->last_error, [&] {
        require(motion, "motion");
        require(totals, "totals");
        require_result_size(totals, "cw_wheelrail_totals_init");
        const cw_wheelrail_motion m = read_struct(motion, default_motion(), "motion");
        wr::WheelRailInputs& checked = wheelrail->inputs;
        checked.has_motion = true;
        checked.solved = false;
        checked.position = {m.y, m.z, m.roll, m.yaw, m.pitch};
        checked.vs = m.vs;
        checked.vpitch = m.vpitch;
        checked.force_given = load == CW_WHEELRAIL_FORCE;
        checked.Fz = Fz;
        const std::pair<const char*, double> all[] = {
            {"motion->y", m.y}, {"motion->z", m.z}, {"motion->roll", m.roll}, {"motion->yaw", m.yaw},
            {"motion->pitch", m.pitch}, {"motion->vs", m.vs}, {"motion->vy", m.vy}, {"motion->vz", m.vz},
            {"motion->vroll", m.vroll}, {"motion->vyaw", m.vyaw}, {"motion->vpitch", m.vpitch}};
        for (const auto& [name, v] : all) require_finite(name, v);
        if (load != CW_WHEELRAIL_FORCE && load != CW_WHEELRAIL_HEIGHT)
            fail(CW_ERR_UNKNOWN_OPTION, "load = " + std::to_string(load) +
                                            " is neither CW_WHEELRAIL_FORCE (0) nor CW_WHEELRAIL_HEIGHT (1)");
        if (load == CW_WHEELRAIL_FORCE && !(Fz > 0.0 && Fz < 1e7))
            fail(CW_ERR_INVALID_INPUT, "Fz = " + creepwork::number_text(Fz) + " must lie in (0, 1e7) N");
        wr::WheelsetPosition pos;
        pos.y = m.y;
        pos.z = m.z;
        pos.roll = m.roll;
        pos.yaw = m.yaw;
        pos.pitch = m.pitch;
        wr::WheelsetVelocity vel;
        vel.vs = m.vs;
        vel.vy = m.vy;
        vel.vz = m.vz;
        vel.vroll = m.vroll;
        vel.vyaw = m.vyaw;
        vel.vpitch = m.vpitch;
        wr::WheelRailContact& c = wheelrail->contact;
        const wr::WheelRailSolution& s =
            load == CW_WHEELRAIL_FORCE ? c.solve_force(Fz, pos, vel) : c.solve_position(pos, vel);
        cw_wheelrail_totals t;
        cw_wheelrail_totals_init(&t);
        t.z = s.z;
        t.Fx = s.total.fx;
        t.Fy = s.total.fy;
        t.Fz = s.total.fz;
        t.n_patches = static_cast<int>(s.patches.size());
        t.evaluations = s.evaluations;
        check_finite_out("wheelset height", t.z);
        check_finite_out("total force", t.Fx + t.Fy + t.Fz);
        for (const wr::PatchSolution& p : s.patches)
            check_finite_out("patch force", p.fn + p.fx + p.fs + p.mn + p.p_max);
        write_struct(totals, t);
        wheelrail->solved = true;
        checked.solved = true;
        checked.z = s.z;
        return CW_OK;
    });
}

int cw_wheelrail_get_patch(const cw_wheelrail* wheelrail, size_t k, cw_wheelrail_patch* patch)
{
    if (!wheelrail) return CW_ERR_NULL_POINTER;
    return guarded(&wheelrail->last_error, [&] {
        require(patch, "patch");
        const wr::PatchSolution& p = solved_patch(*wheelrail, k);
        const wr::ContactPatch& g = wheelrail->contact.geometry().state().patches.at(k);
        cw_wheelrail_patch c;
        cw_wheelrail_patch_init(&c);
        c.x_contact = g.x_tr;
        c.y_contact = g.y_tr;
        c.z_contact = g.z_tr;
        c.y_contact_rail = g.y_r;
        c.z_contact_rail = g.z_r;
        c.y_contact_wheel = g.y_w;
        c.z_contact_wheel = g.z_w;
        c.contact_angle = g.delta;
        c.cksi = g.cksi;
        c.ceta = g.ceta;
        c.cphi = g.cphi;
        c.veloc = g.veloc;
        c.Fn = p.fn;
        c.Fx = p.fx;
        c.Fs = p.fs;
        c.Mn = p.mn;
        c.p_max = p.p_max;
        c.approach = p.approach;
        c.Fx_track = p.track.fx;
        c.Fy_track = p.track.fy;
        c.Fz_track = p.track.fz;
        c.rolling_radius = g.rolling_radius;
        c.n_contact = p.n_contact;
        c.n_adhesion = p.n_adhesion;
        c.n_slip = p.n_slip;
        c.nx = g.nx;
        c.ny = g.ny;
        // the solver's grid, rows in s order (creepwork's y = -s)
        c.field_nx = p.nx;
        c.field_ny = p.ny;
        c.field_x0 = p.x0;
        c.field_s0 = -(p.y0 + (p.ny - 1) * p.dy);
        c.field_dx = p.dx;
        c.field_ds = p.dy;
        c.rail_profile_y = g.rail_profile_y;
        c.rail_s_cos = g.rail_s_cos;
        c.wheel_profile_y = g.wheel_profile_y;
        c.wheel_s_cos = g.wheel_s_cos;
        if (!valid_struct_size(patch->struct_size))
            fail(CW_ERR_STRUCT_SIZE, "patch->struct_size = " + std::to_string(patch->struct_size) +
                                         " is invalid (call cw_wheelrail_patch_init first)");
        write_struct(patch, c);
        return CW_OK;
    });
}

const char* cw_wheelrail_last_error(const cw_wheelrail* wheelrail)
{
    return wheelrail ? wheelrail->last_error.c_str() : "";
}

} // extern "C"
