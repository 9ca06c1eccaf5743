// Wear: the laws on the work map of a solved contact (cw_wear) and the
// accumulation on a host's profile grid (cw_wear_profile). The core's
// wear/ functions do the physics; this file reads the solver's fields into
// the handle's workspace, checks the inputs and translates errors.
#include "capi_internal.hpp"

#include <cmath>
#include <memory>

#include "capi_wear_law.hpp"
#include "contact/number_text.hpp"
#include "wear/wear_map.hpp"
#include "wear/wear_profile.hpp"

namespace cww = creepwork::wear;

struct cw_wear {
    cw::GridSpec grid;
    int nx = 0, ny = 0;
    // Inputs read from the solver (per element), and the strip geometry.
    std::vector<double> area, pz, px, py, sx, sy, work, strip_y, strip_width;
    // Outputs of the last compute.
    std::vector<double> rate, depth, mass, work_density, sliding, strip_depth, strip_parabola;
    std::vector<int> regime;
    bool computed = false;
    cw_wear_result result{};
    mutable std::string last_error; // the last call's message, const getters' included
};

namespace {

cw_wear_params wear_defaults()
{
    const cww::WearLaw d;
    cw_wear_params p{};
    p.struct_size = sizeof p;
    p.law = CW_WEAR_USFD;
    p.source = CW_WEAR_SOURCE_CONSISTENT;
    p.density = d.density;
    p.rolling_speed = d.rolling_speed;
    p.pass_length = d.pass_length;
    p.usfd_k1 = d.usfd.k1;
    p.usfd_t1 = d.usfd.t1;
    p.usfd_k2 = d.usfd.k2;
    p.usfd_t2 = d.usfd.t2;
    p.usfd_k3 = d.usfd.k3;
    p.usfd_c3 = d.usfd.c3;
    p.hardness = d.kth.hardness;
    p.kth_v1 = d.kth.v1;
    p.kth_v2 = d.kth.v2;
    p.kth_seizure_ratio = d.kth.seizure_ratio;
    p.kth_k_seizure = d.kth.k_seizure;
    p.kth_k_slow = d.kth.k_slow;
    p.kth_k_severe = d.kth.k_severe;
    p.kth_k_fast = d.kth.k_fast;
    return p;
}

} // namespace

// solve_V: the solve's cw_params.V, Archard's rolling speed when its own is
// 0; negative where there is no such solve (transient rolling), so that
// Archard's own rolling_speed must be given.
cww::WearLaw to_wear_law(const cw_wear_params* caller, double solve_V)
{
    cw_wear_params p = read_struct(caller, wear_defaults(), "params");
    if (p.law == CW_WEAR_ARCHARD_KTH) {
        if (solve_V >= 0.0)
            p.rolling_speed = rolling_speed_of(p.rolling_speed, "rolling_speed", solve_V);
        else if (!(p.rolling_speed > 0.0))
            fail(CW_ERR_INVALID_INPUT, "rolling_speed = " + creepwork::number_text(p.rolling_speed) +
                                           " is invalid: Archard's law needs the rolling "
                                           "speed > 0 [m/s]");
    }
    if (p.law != CW_WEAR_USFD && p.law != CW_WEAR_ARCHARD_KTH)
        fail(CW_ERR_UNKNOWN_OPTION, "law = " + std::to_string(p.law) +
                                        " is not CW_WEAR_USFD (0) or CW_WEAR_ARCHARD_KTH (1)");
    if (p.source != CW_WEAR_SOURCE_CONSISTENT && p.source != CW_WEAR_SOURCE_PAPER &&
        p.source != CW_WEAR_SOURCE_SLIP)
        fail(CW_ERR_UNKNOWN_OPTION,
             "source = " + std::to_string(p.source) +
                 " is not CW_WEAR_SOURCE_CONSISTENT (0), _PAPER (1) or _SLIP (2)");
    cww::WearLaw w;
    w.law = static_cast<cww::Law>(p.law);
    w.source = static_cast<cww::Source>(p.source);
    w.density = p.density;
    w.rolling_speed = p.rolling_speed;
    w.pass_length = p.pass_length;
    w.usfd = {p.usfd_k1, p.usfd_t1, p.usfd_k2, p.usfd_t2, p.usfd_k3, p.usfd_c3};
    w.kth = {p.hardness,      p.kth_v1,     p.kth_v2,       p.kth_seizure_ratio,
             p.kth_k_seizure, p.kth_k_slow, p.kth_k_severe, p.kth_k_fast};
    cww::validate(w); // names the parameter
    return w;
}

namespace {

bool same_grid(const cw::GridSpec& a, const cw::GridSpec& b)
{
    return a.kind == b.kind && a.nx == b.nx && a.ny == b.ny && a.box_scale == b.box_scale;
}

void require_computed(const cw_wear* w)
{
    if (!w->computed)
        fail(CW_ERR_NO_SOLUTION, "no successful cw_wear_compute on this handle yet (or the last "
                                 "failed)");
}

size_t checked_count(size_t n, size_t limit, const char* name)
{
    if (n > limit)
        fail(CW_ERR_INVALID_INPUT, std::string(name) + " = " + std::to_string(n) +
                                       " exceeds " + std::to_string(limit));
    return n;
}

} // namespace

extern "C" {

int cw_wear_params_init(cw_wear_params* params)
{
    if (!params) return CW_ERR_NULL_POINTER;
    *params = wear_defaults();
    return CW_OK;
}

int cw_wear_result_init(cw_wear_result* result)
{
    if (!result) return CW_ERR_NULL_POINTER;
    std::memset(result, 0, sizeof *result);
    result->struct_size = sizeof *result;
    return CW_OK;
}

int cw_wear_create(const cw_solver* solver, cw_wear** wear)
{
    if (!wear) return CW_ERR_NULL_POINTER;
    *wear = nullptr;
    if (!solver) return CW_ERR_NULL_POINTER;
    return guarded(nullptr, [&] {
        std::unique_ptr<cw_wear> w(new cw_wear);
        const cw::ContactGrid& g = solver->solver.grid();
        w->grid = g.spec();
        w->nx = g.nx();
        w->ny = g.ny();
        const size_t n = element_count(solver->solver), ny = static_cast<size_t>(g.ny());
        for (auto* v : {&w->area, &w->pz, &w->px, &w->py, &w->sx, &w->sy, &w->work, &w->rate,
                        &w->depth, &w->mass, &w->work_density, &w->sliding})
            v->assign(n, 0.0);
        for (auto* v : {&w->strip_y, &w->strip_width, &w->strip_depth, &w->strip_parabola})
            v->assign(ny, 0.0);
        w->regime.assign(n, 0);
        cw_wear_result_init(&w->result);
        *wear = w.release();
        return CW_OK;
    });
}

int cw_wear_destroy(cw_wear* wear)
{
    delete wear;
    return CW_OK;
}

int cw_wear_compute(cw_wear* wear, const cw_solver* solver, const cw_wear_params* params,
                    cw_wear_result* result)
{
    if (!wear) return CW_ERR_NULL_POINTER;
    return guarded(&wear->last_error, [&] {
        wear->computed = false;
        require(solver, "solver");
        require(params, "params");
        require_result_size(result, "cw_wear_result_init");
        const cw::Solver& s = solver->solver;
        if (!same_grid(s.grid().spec(), wear->grid))
            fail(CW_ERR_GRID_MISMATCH, "the solver's grid differs from the one wear was made for");
        const cww::WearLaw law = to_wear_law(params, solver->V);
        require_solution(s, true);
        const cw::SolvedContact& view = s.solved(); // the solve's fields, read once
        cw::export_field(view, cw::Field::area, wear->area.data());
        cw::export_field(view, cw::Field::pz, wear->pz.data());
        cw::export_field(view, cw::Field::px, wear->px.data());
        cw::export_field(view, cw::Field::py, wear->py.data());
        if (law.source == cww::Source::slip) {
            cw::export_field(view, cw::Field::sx, wear->sx.data());
            cw::export_field(view, cw::Field::sy, wear->sy.data());
        } else {
            cw::export_field(view,
                             law.source == cww::Source::paper ? cw::Field::work_paper
                                                              : cw::Field::work_consistent,
                             wear->work.data());
        }
        const double b = s.totals().b;
        s.copy_strips(wear->strip_y.data(), wear->strip_width.data());
        cww::ContactFields in;
        in.nx = wear->nx;
        in.ny = wear->ny;
        in.b = b;
        in.area = wear->area.data();
        in.pz = wear->pz.data();
        in.px = wear->px.data();
        in.py = wear->py.data();
        in.sx = wear->sx.data();
        in.sy = wear->sy.data();
        in.work = wear->work.data();
        in.strip_y = wear->strip_y.data();
        in.strip_width = wear->strip_width.data();
        cww::WearFields out;
        out.rate = wear->rate.data();
        out.depth = wear->depth.data();
        out.mass = wear->mass.data();
        out.work_density = wear->work_density.data();
        out.sliding = wear->sliding.data();
        out.regime = wear->regime.data();
        out.strip_depth = wear->strip_depth.data();
        out.strip_parabola = wear->strip_parabola.data();
        const cww::WearTotals t = cww::wear_map(in, law, out);
        cw_wear_result r{};
        r.struct_size = sizeof r;
        r.mass_per_distance = t.mass_per_distance;
        r.mass_per_pass = t.mass_per_pass;
        r.volume_per_distance = t.volume_per_distance;
        r.max_depth = t.max_depth;
        r.work = t.work;
        for (int k = 0; k < 4; ++k) r.regime_area[k] = t.regime_area[k];
        r.law = static_cast<int>(law.law);
        r.source = static_cast<int>(law.source);
        wear->result = r;
        wear->computed = true;
        if (result) write_struct(result, r);
        return CW_OK;
    });
}

int cw_wear_get_field(const cw_wear* wear, int field, double* out, size_t out_len)
{
    if (!wear) return CW_ERR_NULL_POINTER;
    return guarded(&wear->last_error, [&] {
        const std::vector<double>* src = nullptr;
        switch (field) {
        case CW_WEAR_FIELD_RATE: src = &wear->rate; break;
        case CW_WEAR_FIELD_DEPTH: src = &wear->depth; break;
        case CW_WEAR_FIELD_MASS: src = &wear->mass; break;
        case CW_WEAR_FIELD_WORK_DENSITY: src = &wear->work_density; break;
        case CW_WEAR_FIELD_SLIDING: src = &wear->sliding; break;
        default:
            fail(CW_ERR_UNKNOWN_OPTION,
                 "field = " + std::to_string(field) + " is not a CW_WEAR_FIELD_* (0..4)");
        }
        require(out, "out");
        require_computed(wear);
        require_length(out_len, src->size(), "out");
        std::copy(src->begin(), src->end(), out);
        return CW_OK;
    });
}

int cw_wear_get_regimes(const cw_wear* wear, int* out, size_t out_len)
{
    if (!wear) return CW_ERR_NULL_POINTER;
    return guarded(&wear->last_error, [&] {
        require(out, "out");
        require_computed(wear);
        require_length(out_len, wear->regime.size(), "out");
        std::copy(wear->regime.begin(), wear->regime.end(), out);
        return CW_OK;
    });
}

int cw_wear_get_strips(const cw_wear* wear, double* y, double* width, double* depth,
                       double* parabola, size_t len)
{
    if (!wear) return CW_ERR_NULL_POINTER;
    return guarded(&wear->last_error, [&] {
        require_computed(wear);
        const size_t ny = static_cast<size_t>(wear->ny);
        if (y || width || depth || parabola) require_length(len, ny, "len");
        if (y) std::copy(wear->strip_y.begin(), wear->strip_y.end(), y);
        if (width) std::copy(wear->strip_width.begin(), wear->strip_width.end(), width);
        if (depth) std::copy(wear->strip_depth.begin(), wear->strip_depth.end(), depth);
        if (parabola) std::copy(wear->strip_parabola.begin(), wear->strip_parabola.end(), parabola);
        return CW_OK;
    });
}

int cw_wear_get_result(const cw_wear* wear, cw_wear_result* result)
{
    if (!wear) return CW_ERR_NULL_POINTER;
    return guarded(&wear->last_error, [&] {
        require(result, "result");
        require_computed(wear);
        write_struct(result, wear->result);
        return CW_OK;
    });
}

const char* cw_wear_last_error(const cw_wear* wear)
{
    if (!wear) return "wear handle is NULL";
    return wear->last_error.c_str();
}

int cw_wear_profile_totals_init(cw_wear_profile_totals* totals)
{
    if (!totals) return CW_ERR_NULL_POINTER;
    std::memset(totals, 0, sizeof *totals);
    totals->struct_size = sizeof *totals;
    return CW_OK;
}

int cw_wear_profile_create(const double* s, size_t n, cw_wear_profile** profile, char* message,
                           size_t message_len)
{
    if (profile) *profile = nullptr;
    return guarded_free(message, message_len, [&] {
        require(profile, "profile");
        require(s, "s");
        const long count =
            static_cast<long>(checked_count(n, CW_WEAR_MAX_PROFILE_NODES, "n"));
        *profile = new cw_wear_profile(s, count);
        return CW_OK;
    });
}

int cw_wear_profile_destroy(cw_wear_profile* profile)
{
    delete profile;
    return CW_OK;
}

int cw_wear_profile_reset(cw_wear_profile* profile)
{
    if (!profile) return CW_ERR_NULL_POINTER;
    profile->acc.reset();
    profile->last_error.clear();
    return CW_OK;
}

int cw_wear_profile_add(cw_wear_profile* profile, const cw_wear* wear, double s0,
                        int orientation, double contact_angle, double passes)
{
    if (!profile) return CW_ERR_NULL_POINTER;
    return guarded(&profile->last_error, [&] {
        require(wear, "wear");
        require_computed(wear);
        cww::StripWear st;
        st.y = wear->strip_y.data();
        st.width = wear->strip_width.data();
        st.depth = wear->strip_depth.data();
        st.count = wear->ny;
        profile->acc.add(st, {s0, orientation, contact_angle, passes});
        return CW_OK;
    });
}

int cw_wear_profile_add_strips(cw_wear_profile* profile, const double* y, const double* width,
                               const double* depth, size_t count, double s0, int orientation,
                               double contact_angle, double passes)
{
    if (!profile) return CW_ERR_NULL_POINTER;
    return guarded(&profile->last_error, [&] {
        require(y, "y");
        require(width, "width");
        require(depth, "depth");
        cww::StripWear st;
        st.y = y;
        st.width = width;
        st.depth = depth;
        st.count = static_cast<long>(checked_count(count, 1000000, "count"));
        profile->acc.add(st, {s0, orientation, contact_angle, passes});
        return CW_OK;
    });
}

int cw_wear_profile_get_depth(const cw_wear_profile* profile, int kind, double* out,
                              size_t out_len)
{
    if (!profile) return CW_ERR_NULL_POINTER;
    return guarded(&profile->last_error, [&] {
        if (kind != CW_WEAR_DEPTH_NORMAL && kind != CW_WEAR_DEPTH_HEIGHT)
            fail(CW_ERR_UNKNOWN_OPTION, "kind = " + std::to_string(kind) +
                                            " is not CW_WEAR_DEPTH_NORMAL (0) or _HEIGHT (1)");
        require(out, "out");
        require_length(out_len, static_cast<size_t>(profile->acc.size()), "out");
        profile->acc.depth(kind == CW_WEAR_DEPTH_NORMAL ? cww::DepthKind::normal
                                                        : cww::DepthKind::height,
                           out);
        return CW_OK;
    });
}

int cw_wear_profile_get_totals(const cw_wear_profile* profile, cw_wear_profile_totals* totals)
{
    if (!profile) return CW_ERR_NULL_POINTER;
    return guarded(&profile->last_error, [&] {
        require(totals, "totals");
        const cww::ProfileTotals t = profile->acc.totals();
        cw_wear_profile_totals c{};
        c.struct_size = sizeof c;
        c.passes = t.passes;
        c.volume = t.volume;
        c.volume_lost = t.volume_lost;
        c.adds = t.adds;
        write_struct(totals, c);
        return CW_OK;
    });
}

int cw_wear_profile_merge(cw_wear_profile* into, const cw_wear_profile* from)
{
    if (!into) return CW_ERR_NULL_POINTER;
    return guarded(&into->last_error, [&] {
        require(from, "from");
        if (from->acc.nodes() != into->acc.nodes())
            fail(CW_ERR_GRID_MISMATCH, "from has other nodes s than into");
        into->acc.merge(from->acc);
        return CW_OK;
    });
}

int cw_wear_profile_state_size(const cw_wear_profile* profile, size_t* words)
{
    if (!profile || !words) return CW_ERR_NULL_POINTER;
    *words = static_cast<size_t>(profile->acc.state_words());
    return CW_OK;
}

int cw_wear_profile_get_state(const cw_wear_profile* profile, uint64_t* state, size_t len)
{
    if (!profile) return CW_ERR_NULL_POINTER;
    return guarded(&profile->last_error, [&] {
        require(state, "state");
        require_length(len, static_cast<size_t>(profile->acc.state_words()), "state");
        profile->acc.save(state);
        return CW_OK;
    });
}

int cw_wear_profile_add_state(cw_wear_profile* profile, const uint64_t* state, size_t len)
{
    if (!profile) return CW_ERR_NULL_POINTER;
    return guarded(&profile->last_error, [&] {
        require(state, "state");
        try {
            profile->acc.add_saved(state, static_cast<long>(std::min<size_t>(len, 1ul << 62)));
        } catch (const cw::Error& e) {
            if (e.kind() == cw::ErrorKind::invalid_input) fail(CW_ERR_GRID_MISMATCH, e.what());
            throw;
        }
        return CW_OK;
    });
}

const char* cw_wear_profile_last_error(const cw_wear_profile* profile)
{
    if (!profile) return "profile handle is NULL";
    return profile->last_error.c_str();
}

int cw_wear_profile_update(const double* s, const double* old_profile, const double* depth,
                           size_t n, double smoothing, double* new_profile, size_t new_len,
                           char* message, size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(s, "s");
        require(old_profile, "old_profile");
        require(depth, "depth");
        require(new_profile, "new_profile");
        const long count =
            static_cast<long>(checked_count(n, CW_WEAR_MAX_PROFILE_NODES, "n"));
        require_length(new_len, n, "new_profile");
        cww::update_profile(s, old_profile, depth, count, smoothing, new_profile);
        return CW_OK;
    });
}

} // extern "C"
