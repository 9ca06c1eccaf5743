// A solved wheel/rail position in depth (cw_wheelrail_get_patch_field,
// _get_patch_state, _patch_solver, cw_wheelrail_add_wear,
// cw_wheelrail_get_profile): a patch's solver fields turned into the
// wheel/rail conventions, its wear placed on the profiles, and the profiles
// where the position put them.
//
// The patch solver works in creepwork's frame: x along the track, y = -s,
// forces and slips of the wheel (doc/wheelrail.md). Its row j holds s =
// field_s0 + (ny - 1 - j) ds, so rows are read in reverse; the rail's
// traction along x and its slip relative to the wheel are the negatives of
// the wheel's, and along s (= -y) they keep their sign.
#include <algorithm>
#include <cmath>
#include <vector>

#include "capi_wheelrail_internal.hpp"
#include "contact/number_text.hpp"
#include "wear/wear_profile.hpp"

namespace {

const cw::Solver& patch_solver(const wr::PatchSolution& p)
{
    if (!p.solver) fail(CW_ERR_INTERNAL, "the patch has no solver");
    return *p.solver;
}

// Copies rows into s order: out[i + nx j] = in[i + nx (ny - 1 - j)], times sign.
template <class T>
void rows_in_s_order(const std::vector<T>& in, int nx, int ny, T sign, T* out)
{
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            out[i + static_cast<size_t>(nx) * j] = sign * in[i + static_cast<size_t>(nx) * (ny - 1 - j)];
}

void patch_field(const wr::PatchSolution& p, int field, double* out)
{
    const cw::Solver& s = patch_solver(p);
    const cw::Field f = to_field(field);
    require_solution(s, cw::Solver::needs_work(f));
    const cw::SolvedContact& view = s.solved();
    const size_t n = static_cast<size_t>(p.nx) * p.ny;
    std::vector<double> v(n);
    if (field == CW_FIELD_MZ) {
        // about n through the reference point, on the rail: x ps - s px per
        // element, which equals the wheel's (x py - y px) about the point
        std::vector<double> x(n), y(n), px(n), py(n), area(n);
        cw::export_field(view, cw::Field::x, x.data());
        cw::export_field(view, cw::Field::y, y.data());
        cw::export_field(view, cw::Field::px, px.data());
        cw::export_field(view, cw::Field::py, py.data());
        cw::export_field(view, cw::Field::area, area.data());
        for (size_t e = 0; e < n; ++e)
            v[e] = ((x[e] + p.x0) * py[e] - (y[e] + p.y0) * px[e]) * area[e];
        rows_in_s_order(v, p.nx, p.ny, 1.0, out);
        return;
    }
    cw::export_field(view, f, v.data());
    double sign = 1.0, shift = 0.0;
    switch (field) {
    case CW_FIELD_X: shift = p.x0; break;
    case CW_FIELD_Y: sign = -1.0; shift = p.y0; break; // s = -(y + y0)
    case CW_FIELD_PX:
    case CW_FIELD_SX: sign = -1.0; break;
    default: break;
    }
    for (double& e : v) e += shift;
    rows_in_s_order(v, p.nx, p.ny, sign, out);
}

double placement_angle(double s_cos, const char* body, size_t k)
{
    const double c = std::fabs(s_cos);
    if (!(c >= std::cos(creepwork::wear::kMaxContactAngle)))
        fail(CW_ERR_INVALID_INPUT, std::string("patch ") + std::to_string(k) + " meets the " + body +
                                       " profile at more than 85 degrees to its y axis (d y / d s = " +
                                       creepwork::number_text(s_cos) + ")");
    return std::acos(c < 1.0 ? c : 1.0);
}

// One patch's strips: centre s from the reference point, width, depth per pass.
struct PatchStrips {
    std::vector<double> s, width, depth;
};

} // namespace

extern "C" {

int cw_wheelrail_get_patch_field(const cw_wheelrail* wheelrail, size_t k, int field, double* out,
                                 size_t out_len)
{
    if (!wheelrail) return CW_ERR_NULL_POINTER;
    return guarded(&wheelrail->last_error, [&] {
        require(out, "out");
        const wr::PatchSolution& p = solved_patch(*wheelrail, k);
        to_field(field); // an unknown field before the length
        require_length(out_len, static_cast<size_t>(p.nx) * p.ny, "out");
        patch_field(p, field, out);
        return CW_OK;
    });
}

int cw_wheelrail_get_patch_state(const cw_wheelrail* wheelrail, size_t k, int* out, size_t out_len)
{
    if (!wheelrail) return CW_ERR_NULL_POINTER;
    return guarded(&wheelrail->last_error, [&] {
        require(out, "out");
        const wr::PatchSolution& p = solved_patch(*wheelrail, k);
        const cw::Solver& s = patch_solver(p);
        require_solution(s, false);
        require_length(out_len, static_cast<size_t>(p.nx) * p.ny, "out");
        std::vector<int> v(static_cast<size_t>(p.nx) * p.ny);
        cw::export_state(s.solved(), v.data());
        rows_in_s_order(v, p.nx, p.ny, 1, out);
        return CW_OK;
    });
}

const cw_solver* cw_wheelrail_patch_solver(const cw_wheelrail* wheelrail, size_t k)
{
    if (!wheelrail) return nullptr;
    const cw_solver* view = nullptr;
    const int status = guarded(&wheelrail->last_error, [&] {
        const cw::Solver& s = patch_solver(solved_patch(*wheelrail, k));
        auto it = wheelrail->views.find(&s);
        if (it == wheelrail->views.end()) it = wheelrail->views.emplace(&s, std::make_unique<cw_solver>(s)).first;
        // The patch's rolling direction, for cw_temperature_compute with
        // rolling_direction 0. Not its speed (veloc) as cw_params.V: a wear
        // law's rolling_speed given as the wheelset's would then disagree.
        const wr::ContactPatch& g = wheelrail->contact.geometry().state().patches.at(k);
        it->second->rolling_direction = g.forward ? 1 : -1;
        view = it->second.get();
        return CW_OK;
    });
    return status == CW_OK ? view : nullptr;
}

int cw_wheelrail_add_wear(const cw_wheelrail* wheelrail, const cw_wear_params* params, double passes,
                          cw_wear_profile* rail, cw_wear_profile* wheel, cw_wear_result* result)
{
    if (!wheelrail) return CW_ERR_NULL_POINTER;
    return guarded(&wheelrail->last_error, [&] {
        require(params, "params");
        require_result_size(result, "cw_wear_result_init");
        if (!wheelrail->solved) fail(CW_ERR_NO_SOLUTION, "no successful cw_wheelrail_solve on this handle");
        const wr::WheelRailSolution& sol = wheelrail->contact.solution();
        const auto& geo = wheelrail->contact.geometry().state().patches;
        // Every patch's wear first (the wear laws on its solver), then the
        // additions on copies of the accumulators: nothing changes on error.
        std::vector<PatchStrips> strips(sol.patches.size());
        cw_wear_result sum{};
        sum.struct_size = sizeof sum;
        for (size_t k = 0; k < sol.patches.size(); ++k) {
            const cw_solver* view = cw_wheelrail_patch_solver(wheelrail, k);
            if (!view) fail(CW_ERR_INTERNAL, "patch " + std::to_string(k) + " has no solver");
            cw_wear* raw = nullptr;
            int st = cw_wear_create(view, &raw);
            const std::unique_ptr<cw_wear, int (*)(cw_wear*)> wear(raw, cw_wear_destroy);
            if (st != CW_OK) fail(st, "wear of patch " + std::to_string(k) + ": " + cw_status_string(st));
            cw_wear_result r{};
            r.struct_size = sizeof r;
            st = cw_wear_compute(wear.get(), view, params, &r);
            if (st != CW_OK) fail(st, cw_wear_last_error(wear.get()));
            sum.mass_per_distance += r.mass_per_distance;
            sum.mass_per_pass += r.mass_per_pass;
            sum.volume_per_distance += r.volume_per_distance;
            sum.max_depth = std::fmax(sum.max_depth, r.max_depth);
            sum.work += r.work;
            for (int m = 0; m < 4; ++m) sum.regime_area[m] += r.regime_area[m];
            sum.law = r.law;
            sum.source = r.source;
            const wr::PatchSolution& p = sol.patches[k];
            PatchStrips& ps = strips[k];
            ps.s.resize(static_cast<size_t>(p.ny));
            ps.width.resize(ps.s.size());
            ps.depth.resize(ps.s.size());
            cw_wear_get_strips(wear.get(), ps.s.data(), ps.width.data(), ps.depth.data(), nullptr, ps.s.size());
            for (double& s : ps.s) s = -(s + p.y0); // the solver's y to the patch's s
        }
        if (rail && rail == wheel) fail(CW_ERR_INVALID_INPUT, "rail and wheel are the same profile accumulator");
        std::vector<creepwork::wear::ProfileAccumulator> next;
        for (cw_wear_profile* acc : {rail, wheel}) {
            if (!acc) continue;
            const bool on_rail = acc == rail;
            next.push_back(acc->acc);
            for (size_t k = 0; k < strips.size(); ++k) {
                const wr::ContactPatch& g = geo.at(k);
                const double y = on_rail ? g.rail_profile_y : g.wheel_profile_y;
                const double c = on_rail ? g.rail_s_cos : g.wheel_s_cos;
                const double angle = placement_angle(c, on_rail ? "rail" : "wheel", k);
                creepwork::wear::StripWear w;
                w.y = strips[k].s.data();
                w.width = strips[k].width.data();
                w.depth = strips[k].depth.data();
                w.count = static_cast<long>(strips[k].s.size());
                next.back().add(w, {y, c < 0.0 ? -1 : 1, angle, passes});
            }
        }
        size_t m = 0;
        for (cw_wear_profile* acc : {rail, wheel})
            if (acc) acc->acc = std::move(next[m++]);
        if (result) write_struct(result, sum);
        return CW_OK;
    });
}

int cw_wheelrail_get_profile(const cw_wheelrail* wheelrail, int which, double* y, double* z, size_t len,
                             size_t* count)
{
    if (!wheelrail) return CW_ERR_NULL_POINTER;
    return guarded(&wheelrail->last_error, [&] {
        require(count, "count");
        if (which != CW_WHEELRAIL_RAIL && which != CW_WHEELRAIL_WHEEL)
            fail(CW_ERR_UNKNOWN_OPTION, "which = " + std::to_string(which) +
                                            " is neither CW_WHEELRAIL_RAIL (0) nor CW_WHEELRAIL_WHEEL (1)");
        if (!wheelrail->solved) fail(CW_ERR_NO_SOLUTION, "no successful cw_wheelrail_solve on this handle");
        std::vector<double> py, pz;
        wheelrail->contact.geometry().profile_in_track(which == CW_WHEELRAIL_RAIL, py, pz);
        *count = py.size();
        if (len < py.size())
            fail(CW_ERR_BUFFER_TOO_SMALL, "len = " + std::to_string(len) + " is below the profile's " +
                                              std::to_string(py.size()) + " points");
        require(y, "y");
        require(z, "z");
        std::copy(py.begin(), py.end(), y);
        std::copy(pz.begin(), pz.end(), z);
        return CW_OK;
    });
}

} // extern "C"
