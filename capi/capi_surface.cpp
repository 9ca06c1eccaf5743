// Surface temperature (cw_temperature) and damage indices (cw_damage) of a
// solved contact. The core's thermal/ and damage/ functions do the physics;
// this file reads the solver's fields (read_solved_contact: the one place
// that knows where they come from), checks the inputs and translates errors.
#include "capi_internal.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "damage/damage_indices.hpp"
#include "thermal/flash_temperature.hpp"
#include "contact/number_text.hpp"
#include "thermal/friction_temperature.hpp"
#include "thermal/heat_source.hpp"

namespace th = creepwork::thermal;
namespace dm = creepwork::damage;

// Helpers in a namespace of their own: the C ABI is compiled as one unity
// translation unit, where every file's anonymous namespace is the same one.
namespace surface {

// The per-element fields and totals of a solver's last solve that the
// surface post-processors read, in the caller's layout [i + j*nx].
struct SolvedContact {
    cw::GridSpec grid;
    int nx = 0, ny = 0;
    std::vector<double> x, y, area, pz, px, py, sx, sy, work, row_dx;
    std::vector<int> state;
    cw::SolveTotals totals;
    double contact_area = 0.0; // pi a b; on a gap grid the contact elements' area

    explicit SolvedContact(const cw::Solver& s) : grid(s.grid().spec())
    {
        nx = s.grid().nx();
        ny = s.grid().ny();
        const size_t n = element_count(s);
        for (auto* v : {&x, &y, &area, &pz, &px, &py, &sx, &sy, &work}) v->assign(n, 0.0);
        state.assign(n, 0);
        row_dx.assign(static_cast<size_t>(ny), 0.0);
    }
};

// Reads the last CW_SOLVE_FULL solve of s into c (sized for s's grid).
void read_solved_contact(const cw::Solver& s, SolvedContact& c)
{
    require_solution(s, true);
    using F = cw::Field;
    const cw::SolvedContact& view = s.solved();
    cw::export_field(view, F::x, c.x.data());
    cw::export_field(view, F::y, c.y.data());
    cw::export_field(view, F::area, c.area.data());
    cw::export_field(view, F::pz, c.pz.data());
    cw::export_field(view, F::px, c.px.data());
    cw::export_field(view, F::py, c.py.data());
    cw::export_field(view, F::sx, c.sx.data());
    cw::export_field(view, F::sy, c.sy.data());
    cw::export_field(view, F::work_consistent, c.work.data());
    cw::export_state(view, c.state.data());
    c.totals = s.totals();
    // Element length along x per row: the gap grid's spacing, or the
    // strip's normalised length times the semi-axis a.
    for (int j = 0; j < c.ny; ++j)
        c.row_dx[j] = c.grid.kind == cw::GridKind::gap ? c.grid.dx
                                                        : s.grid().x_length()[j] * c.totals.a;
    if (c.grid.kind == cw::GridKind::gap) {
        c.contact_area = 0.0;
        for (size_t e = 0; e < c.area.size(); ++e)
            if (c.state[e] >= 1) c.contact_area += c.area[e];
    } else {
        c.contact_area = 3.141592653589793238462643383279502884 * c.totals.a * c.totals.b;
    }
}

bool same_grid(const cw::GridSpec& a, const cw::GridSpec& b)
{
    return a.kind == b.kind && a.nx == b.nx && a.ny == b.ny && a.box_scale == b.box_scale &&
           a.x0 == b.x0 && a.y0 == b.y0 && a.dx == b.dx && a.dy == b.dy;
}

void require_grid(const cw::Solver& s, const cw::GridSpec& handle_grid, const char* handle)
{
    if (!same_grid(s.grid().spec(), handle_grid))
        fail(CW_ERR_GRID_MISMATCH,
             std::string("the solver's grid differs from the one ") + handle + " was made for");
}

template <class Body>
int create_on(const cw_solver* solver, Body** out)
{
    if (!out) return CW_ERR_NULL_POINTER;
    *out = nullptr;
    if (!solver) return CW_ERR_NULL_POINTER;
    return guarded(nullptr, [&] {
        *out = new Body(solver->solver);
        return CW_OK;
    });
}

void copy_out(const std::vector<double>& src, double* out, size_t out_len)
{
    require(out, "out");
    require_length(out_len, src.size(), "out");
    std::copy(src.begin(), src.end(), out);
}

// ------------------------------------------------------------ temperature

cw_temperature_params temperature_defaults()
{
    const th::Body steel;
    cw_temperature_params p{};
    p.struct_size = sizeof p;
    p.T0_1 = p.T0_2 = 20.0;
    p.heat_capacity_1 = p.heat_capacity_2 = steel.heat_capacity;
    p.conductivity_1 = p.conductivity_2 = steel.conductivity;
    p.density_1 = p.density_2 = steel.density;
    p.rolling_speed = 0.0;
    p.rolling_direction = 1;
    p.discretisation = CW_TEMPERATURE_CONSISTENT;
    return p;
}

th::ThermalParams to_thermal(const cw_temperature_params& p)
{
    if (p.discretisation != CW_TEMPERATURE_CONSISTENT && p.discretisation != CW_TEMPERATURE_CONTACT)
        fail(CW_ERR_UNKNOWN_OPTION,
             "discretisation = " + std::to_string(p.discretisation) +
                 " is not CW_TEMPERATURE_CONSISTENT (0) or CW_TEMPERATURE_CONTACT (1)");
    th::ThermalParams t;
    t.rail = {p.T0_1, p.heat_capacity_1, p.conductivity_1, p.density_1};
    t.wheel = {p.T0_2, p.heat_capacity_2, p.conductivity_2, p.density_2};
    t.rolling_speed = p.rolling_speed;
    t.discretisation = static_cast<th::Discretisation>(p.discretisation);
    th::validate(t); // names the parameter
    return t;
}

// The temperature's rolling direction: its own, or 0 for the solve's; both
// known must agree.
int rolling_direction_of(int own, const cw_solver& solver)
{
    const int solve = solver.rolling_direction;
    if (own == 0 && solve != 0) return solve;
    if (own != 1 && own != -1)
        fail(CW_ERR_INVALID_INPUT, "rolling_direction = " + std::to_string(own) +
                                       " is invalid: must be +1, -1 or 0 (the solve's)");
    if (solve != 0 && own != solve)
        fail(CW_ERR_INVALID_INPUT,
             "rolling_direction = " + std::to_string(own) +
                 " differs from the solve's cw_params.rolling_direction = " +
                 std::to_string(solve) + ": the heat would run the wrong way (0 takes the solve's)");
    return own;
}

// The temperatures of s's last full solve into t (its fields, its result
// without iterations); p's rolling speed and direction resolved.
void compute_temperature(cw_temperature& t, const cw::Solver& s, const cw_temperature_params& p,
                         const th::ThermalParams& tp);

cw_mu_temperature mu_temperature_defaults()
{
    cw_mu_temperature m{};
    m.struct_size = sizeof m;
    m.count = 0;
    m.temperature = nullptr;
    m.mu = nullptr;
    m.tolerance = 1e-6;
    m.max_iterations = 100;
    return m;
}

// The loop's own inputs (the table's are th::validate's).
void check_loop(const cw_mu_temperature& m)
{
    require_finite("mu_T.tolerance", m.tolerance);
    if (!(m.tolerance >= 1e-12 && m.tolerance <= 0.1))
        fail(CW_ERR_INVALID_INPUT, "mu_T.tolerance = " + cw::number_text(m.tolerance) +
                                       " is outside [1e-12, 0.1] (a change of the forces per "
                                       "normal force)");
    if (m.max_iterations < 1 || m.max_iterations > 1000)
        fail(CW_ERR_INVALID_INPUT, "mu_T.max_iterations = " + std::to_string(m.max_iterations) +
                                       " is outside [1, 1000]");
}

} // namespace surface

using surface::SolvedContact;

struct cw_temperature {
    explicit cw_temperature(const cw::Solver& s)
        : contact(s), flash(s.grid().nx(), s.grid().ny())
    {
        for (auto* v : {&q, &T1, &T2, &factor}) v->assign(contact.area.size(), 0.0);
        cw_temperature_result_init(&result);
    }
    SolvedContact contact;
    th::FlashTemperature flash;
    std::vector<double> q, T1, T2;
    std::vector<double> factor; // cw_temperature_solve's friction factors
    bool computed = false;
    cw_temperature_result result{};
    mutable std::string last_error; // the last call's message, const getters' included
};

struct cw_damage {
    explicit cw_damage(const cw::Solver& s) : contact(s)
    {
        for (auto* v : {&rcf, &density}) v->assign(contact.area.size(), 0.0);
        cw_damage_result_init(&result);
    }
    SolvedContact contact;
    std::vector<double> rcf, density;
    bool computed = false;
    cw_damage_result result{};
    mutable std::string last_error; // the last call's message, const getters' included
};

void surface::compute_temperature(cw_temperature& t, const cw::Solver& s,
                                  const cw_temperature_params& p, const th::ThermalParams& tp)
{
    SolvedContact& c = t.contact;
    surface::read_solved_contact(s, c);
    const long n = static_cast<long>(c.area.size());
    if (tp.discretisation == th::Discretisation::consistent)
        th::heat_from_work(n, c.work.data(), c.area.data(), tp.rolling_speed, t.q.data());
    else
        th::heat_from_slip(n, c.px.data(), c.py.data(), c.sx.data(), c.sy.data(),
                           tp.rolling_speed, t.q.data());
    th::HeatedContact in;
    in.nx = c.nx;
    in.ny = c.ny;
    in.x = c.x.data();
    in.y = c.y.data();
    in.row_dx = c.row_dx.data();
    in.state = c.state.data();
    in.q = t.q.data();
    in.rolling_direction = p.rolling_direction;
    const th::TemperatureTotals tt = t.flash.compute(in, tp, t.T1.data(), t.T2.data());
    const int heats = tp.discretisation == th::Discretisation::consistent ? 1 : 2;
    cw_temperature_result r{};
    r.struct_size = sizeof r;
    r.T_max_1 = tt.rail.T;
    r.x_max_1 = tt.rail.x;
    r.y_max_1 = tt.rail.y;
    r.T_max_2 = tt.wheel.T;
    r.x_max_2 = tt.wheel.x;
    r.y_max_2 = tt.wheel.y;
    r.contact_temperature = tt.contact_temperature;
    for (long e = 0; e < n; ++e)
        if (c.state[e] >= heats) r.power += t.q[e] * c.area[e];
    r.discretisation = p.discretisation;
    t.result = r;
}

extern "C" {

int cw_temperature_params_init(cw_temperature_params* params)
{
    if (!params) return CW_ERR_NULL_POINTER;
    *params = surface::temperature_defaults();
    return CW_OK;
}

int cw_temperature_result_init(cw_temperature_result* result)
{
    if (!result) return CW_ERR_NULL_POINTER;
    std::memset(result, 0, sizeof *result);
    result->struct_size = sizeof *result;
    return CW_OK;
}

int cw_temperature_create(const cw_solver* solver, cw_temperature** temperature)
{
    return surface::create_on(solver, temperature);
}

int cw_temperature_destroy(cw_temperature* temperature)
{
    delete temperature;
    return CW_OK;
}

int cw_temperature_compute(cw_temperature* t, const cw_solver* solver,
                           const cw_temperature_params* params, cw_temperature_result* result)
{
    if (!t) return CW_ERR_NULL_POINTER;
    return guarded(&t->last_error, [&] {
        t->computed = false;
        require(solver, "solver");
        require(params, "params");
        require_result_size(result, "cw_temperature_result_init");
        surface::require_grid(solver->solver, t->contact.grid, "temperature");
        cw_temperature_params p = read_struct(params, surface::temperature_defaults(), "params");
        p.rolling_speed = rolling_speed_of(p.rolling_speed, "rolling_speed", solver->V);
        p.rolling_direction = surface::rolling_direction_of(p.rolling_direction, *solver);
        surface::compute_temperature(*t, solver->solver, p, surface::to_thermal(p));
        t->result.iterations = 1;
        t->computed = true;
        if (result) write_struct(result, t->result);
        return CW_OK;
    });
}

int cw_mu_temperature_init(cw_mu_temperature* mu_T)
{
    if (!mu_T) return CW_ERR_NULL_POINTER;
    *mu_T = surface::mu_temperature_defaults();
    return CW_OK;
}

int cw_temperature_solve(cw_temperature* t, cw_solver* solver, const cw_params* params,
                         const cw_temperature_params* temperature_params,
                         const cw_mu_temperature* mu_T, cw_result* result,
                         cw_temperature_result* temperature_result)
{
    if (!t) return CW_ERR_NULL_POINTER;
    if (!solver) return CW_ERR_NULL_POINTER;
    const int status = guarded(&t->last_error, [&] {
        t->computed = false;
        require(params, "params");
        require(temperature_params, "temperature_params");
        require(mu_T, "mu_T");
        require_result_size(result, "cw_result_init");
        require_result_size(temperature_result, "cw_temperature_result_init");
        cw::Solver& s = solver->solver;
        surface::require_grid(s, t->contact.grid, "temperature");
        cw::ContactInput in = to_input(params);
        cw_temperature_params p =
            read_struct(temperature_params, surface::temperature_defaults(), "temperature_params");
        p.rolling_speed = rolling_speed_of(p.rolling_speed, "rolling_speed", in.V);
        if (p.rolling_direction == 0) p.rolling_direction = in.rolling_direction;
        solver->V = 0.0;
        solver->rolling_direction = in.rolling_direction;
        p.rolling_direction = surface::rolling_direction_of(p.rolling_direction, *solver);
        const th::ThermalParams tp = surface::to_thermal(p);
        const cw_mu_temperature m = read_struct(mu_T, surface::mu_temperature_defaults(), "mu_T");
        const th::FrictionTemperature table{m.count, m.temperature, m.mu};
        th::validate(table); // names the entry
        surface::check_loop(m);
        // The law's unit: Coulomb's mu is the table's largest, a law keeps its own.
        if (in.friction_law == cw::FrictionLaw::coulomb) in.mu = th::mu_max(table);
        const double mu_ref = in.mu + (in.friction_law == cw::FrictionLaw::coulomb
                                           ? 0.0
                                           : in.mu_e1 + in.mu_e2);
        const long n = static_cast<long>(t->factor.size());
        // First pass: every element at mu of the bulk contact temperature.
        std::fill(t->T1.begin(), t->T1.end(), th::bulk_contact_temperature(tp));
        cw::SolveTotals totals;
        int pass = 0;
        for (double fx = 0.0, fy = 0.0;; ) {
            th::friction_factors(table, mu_ref, n, t->T1.data(), t->factor.data());
            s.set_friction_factors(t->factor.data());
            totals = s.solve(in, cw::SolveMode::full);
            s.set_friction_factors(nullptr);
            ++pass;
            surface::compute_temperature(*t, s, p, tp);
            const double dx = std::fabs(totals.Fx - fx), dy = std::fabs(totals.Fy - fy);
            if (pass > 1 && dx <= m.tolerance * in.normal_force &&
                dy <= m.tolerance * in.normal_force)
                break;
            if (pass == m.max_iterations)
                fail(CW_ERR_NOT_CONVERGED,
                     "mu_T.max_iterations = " + std::to_string(m.max_iterations) +
                         " passes of solve and temperature without convergence: the forces "
                         "still change by " + cw::number_text(std::max(dx, dy) / in.normal_force) +
                         " N per pass (mu_T.tolerance = " + cw::number_text(m.tolerance) + ")");
            fx = totals.Fx;
            fy = totals.Fy;
        }
        solver->V = in.V;
        t->result.iterations = pass;
        t->computed = true;
        if (result) write_struct(result, to_result(totals));
        if (temperature_result) write_struct(temperature_result, t->result);
        return CW_OK;
    });
    if (status != CW_OK) {
        solver->solver.set_friction_factors(nullptr);
        solver->solver.discard();
        solver->V = 0.0;
        solver->rolling_direction = 0;
        solver->last_error = t->last_error;
    }
    return status;
}

int cw_temperature_get_field(const cw_temperature* t, int field, double* out, size_t out_len)
{
    if (!t) return CW_ERR_NULL_POINTER;
    return guarded(&t->last_error, [&] {
        const std::vector<double>* src = nullptr;
        switch (field) {
        case CW_TEMPERATURE_FIELD_RAIL: src = &t->T1; break;
        case CW_TEMPERATURE_FIELD_WHEEL: src = &t->T2; break;
        case CW_TEMPERATURE_FIELD_HEAT: src = &t->q; break;
        default:
            fail(CW_ERR_UNKNOWN_OPTION,
                 "field = " + std::to_string(field) + " is not a CW_TEMPERATURE_FIELD_* (0..2)");
        }
        require(out, "out");
        if (!t->computed)
            fail(CW_ERR_NO_SOLUTION, "no successful cw_temperature_compute on this handle yet "
                                     "(or the last failed)");
        surface::copy_out(*src, out, out_len);
        return CW_OK;
    });
}

int cw_temperature_get_result(const cw_temperature* t, cw_temperature_result* result)
{
    if (!t) return CW_ERR_NULL_POINTER;
    return guarded(&t->last_error, [&] {
        require(result, "result");
        if (!t->computed)
            fail(CW_ERR_NO_SOLUTION, "no successful cw_temperature_compute on this handle yet "
                                     "(or the last failed)");
        write_struct(result, t->result);
        return CW_OK;
    });
}

const char* cw_temperature_last_error(const cw_temperature* t)
{
    if (!t) return "temperature handle is NULL";
    return t->last_error.c_str();
}

// ------------------------------------------------------------------ damage

int cw_damage_params_init(cw_damage_params* params)
{
    if (!params) return CW_ERR_NULL_POINTER;
    const dm::WlrmFunction w;
    std::memset(params, 0, sizeof *params);
    params->struct_size = sizeof *params;
    params->k_yield = 0.0;
    params->wlrm_onset = w.onset;
    params->wlrm_peak = w.peak;
    params->wlrm_zero = w.zero;
    params->wlrm_peak_damage = w.peak_damage;
    return CW_OK;
}

int cw_damage_result_init(cw_damage_result* result)
{
    if (!result) return CW_ERR_NULL_POINTER;
    std::memset(result, 0, sizeof *result);
    result->struct_size = sizeof *result;
    return CW_OK;
}

int cw_damage_create(const cw_solver* solver, cw_damage** damage)
{
    return surface::create_on(solver, damage);
}

int cw_damage_destroy(cw_damage* damage)
{
    delete damage;
    return CW_OK;
}

int cw_damage_compute(cw_damage* d, const cw_solver* solver, const cw_damage_params* params,
                      cw_damage_result* result)
{
    if (!d) return CW_ERR_NULL_POINTER;
    return guarded(&d->last_error, [&] {
        d->computed = false;
        require(solver, "solver");
        require(params, "params");
        require_result_size(result, "cw_damage_result_init");
        const cw::Solver& s = solver->solver;
        surface::require_grid(s, d->contact.grid, "damage");
        cw_damage_params defaults;
        cw_damage_params_init(&defaults);
        const cw_damage_params p = read_struct(params, defaults, "params");
        dm::DamageParams dp;
        dp.k_yield = p.k_yield;
        dp.wlrm = {p.wlrm_onset, p.wlrm_peak, p.wlrm_zero, p.wlrm_peak_damage};
        dm::validate(dp); // names the parameter
        SolvedContact& c = d->contact;
        surface::read_solved_contact(s, c);
        dm::DamageInput in;
        in.nx = c.nx;
        in.ny = c.ny;
        in.area = c.area.data();
        in.pz = c.pz.data();
        in.px = c.px.data();
        in.py = c.py.data();
        in.state = c.state.data();
        in.work = c.work.data();
        in.Fx = c.totals.Fx;
        in.Fy = c.totals.Fy;
        in.normal_force = c.totals.normal_force;
        in.W_macro = c.totals.W_macro;
        in.contact_area = c.contact_area;
        const dm::DamageTotals t = dm::damage_indices(in, dp, {d->rcf.data(), d->density.data()});
        cw_damage_result r{};
        r.struct_size = sizeof r;
        r.rcf_index_max = t.rcf_index_max;
        if (t.rcf_element >= 0) {
            r.x_rcf_max = c.x[t.rcf_element];
            r.y_rcf_max = c.y[t.rcf_element];
        }
        r.mu_eff = t.mu_eff;
        r.FI_surf = t.FI_surf;
        r.contact_area = c.contact_area;
        r.T_gamma = t.T_gamma;
        r.wlrm_damage = t.wlrm_damage;
        d->result = r;
        d->computed = true;
        if (result) write_struct(result, r);
        return CW_OK;
    });
}

int cw_damage_get_field(const cw_damage* d, int field, double* out, size_t out_len)
{
    if (!d) return CW_ERR_NULL_POINTER;
    return guarded(&d->last_error, [&] {
        const std::vector<double>* src = nullptr;
        switch (field) {
        case CW_DAMAGE_FIELD_RCF_INDEX: src = &d->rcf; break;
        case CW_DAMAGE_FIELD_T_GAMMA_DENSITY: src = &d->density; break;
        default:
            fail(CW_ERR_UNKNOWN_OPTION,
                 "field = " + std::to_string(field) + " is not a CW_DAMAGE_FIELD_* (0..1)");
        }
        require(out, "out");
        if (!d->computed)
            fail(CW_ERR_NO_SOLUTION,
                 "no successful cw_damage_compute on this handle yet (or the last failed)");
        surface::copy_out(*src, out, out_len);
        return CW_OK;
    });
}

int cw_damage_get_result(const cw_damage* d, cw_damage_result* result)
{
    if (!d) return CW_ERR_NULL_POINTER;
    return guarded(&d->last_error, [&] {
        require(result, "result");
        if (!d->computed)
            fail(CW_ERR_NO_SOLUTION,
                 "no successful cw_damage_compute on this handle yet (or the last failed)");
        write_struct(result, d->result);
        return CW_OK;
    });
}

const char* cw_damage_last_error(const cw_damage* d)
{
    if (!d) return "damage handle is NULL";
    return d->last_error.c_str();
}

} // extern "C"
