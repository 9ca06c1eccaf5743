#include "row_solver.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "../cli/contact_solver.hpp" // options_named_in
#include "../cli/surface_outputs.hpp" // hottest_point

namespace cwcampaign {

namespace {

void fail_row(Outcome& out, int status, const std::string& message)
{
    out.status = status;
    out.message = message;
    out.wear.clear();
    out.surface.clear();
    cw_result_init(&out.result);
}

// A post-processor's message, with the campaign options that set the
// fields it names.
std::string surface_message(const char* what, const char* detail, int status)
{
    const std::string text = detail && *detail ? detail : cw_status_string(status);
    return std::string(what) + ": " + text + cwcli::options_named_in(text);
}

} // namespace

void RowChunkSolver::Handles::release()
{
    cw_damage_destroy(damage);
    cw_temperature_destroy(temperature);
    cw_wear_destroy(wear);
    cw_solver_destroy(solver);
    damage = nullptr;
    temperature = nullptr;
    wear = nullptr;
    solver = nullptr;
}

RowChunkSolver::Lane::~Lane()
{
    for (Handles& h : grids) h.release();
    for (cw_wear_profile* p : profile) cw_wear_profile_destroy(p);
}

RowChunkSolver::RowChunkSolver(int threads, size_t max_grids, const WearSetup* wear,
                               const SurfaceSetup* surface)
    : threads_(threads < 1 ? 1 : threads), max_grids_(max_grids < 1 ? 1 : max_grids),
      wear_(wear), surface_(surface)
{
    char message[512] = "";
    for (int t = 0; t < threads_; ++t) {
        auto lane = std::make_unique<Lane>();
        if (wear_)
            for (cw_wear_profile*& p : lane->profile)
                if (cw_wear_profile_create(wear_->nodes.data(), wear_->nodes.size(), &p, message,
                                           sizeof message) != CW_OK)
                    throw std::runtime_error(std::string("the wear profile grid: ") + message);
        lanes_.push_back(std::move(lane));
    }
}

RowChunkSolver::~RowChunkSolver() = default;

RowChunkSolver::Handles* RowChunkSolver::handles_for(Lane& lane, const cw_grid& grid,
                                                     int& status, std::string& message)
{
    for (auto it = lane.grids.begin(); it != lane.grids.end(); ++it)
        if (same_grid_shape(it->grid, grid)) {
            lane.grids.splice(lane.grids.begin(), lane.grids, it);
            return &lane.grids.front();
        }
    if (lane.grids.size() >= max_grids_) {
        lane.grids.back().release();
        lane.grids.pop_back();
    }
    Handles h;
    h.grid = grid;
    char text[512] = "";
    status = cw_solver_create(&grid, &h.solver, text, sizeof text);
    if (status != CW_OK) {
        message = text[0] ? text : cw_status_string(status);
        return nullptr;
    }
    if (wear_) status = cw_wear_create(h.solver, &h.wear);
    if (status == CW_OK && surface_ && surface_->temperature)
        status = cw_temperature_create(h.solver, &h.temperature);
    if (status == CW_OK && surface_ && surface_->damage)
        status = cw_damage_create(h.solver, &h.damage);
    if (status != CW_OK) {
        h.release();
        message = cw_status_string(status);
        return nullptr;
    }
    lane.grids.push_front(h);
    return &lane.grids.front();
}

int RowChunkSolver::add_wear(Lane& lane, Handles& h, const ContactCase& c, Outcome& out)
{
    const cw_wear_params wp = row_wear_params(*wear_, c.wear);
    cw_wear_result w;
    cw_wear_result_init(&w);
    int status = cw_wear_compute(h.wear, h.solver, &wp, &w);
    if (status != CW_OK) {
        fail_row(out, status, std::string("wear: ") + cw_wear_last_error(h.wear));
        return status;
    }
    cw_wear_profile* profile = lane.profile[c.wear.body == kWheel ? kWheel : kRail];
    status = cw_wear_profile_add(profile, h.wear, c.wear.s0, wear_->orientation, c.wear.angle,
                                 c.wear.passes);
    if (status != CW_OK) { // nothing was added (the call's promise)
        fail_row(out, status, std::string("wear profile: ") + cw_wear_profile_last_error(profile));
        return status;
    }
    out.wear.assign(kWearValues, 0.0);
    out.wear[kWearPasses] = c.wear.passes;
    out.wear[kWearWork] = w.work;
    out.wear[kWearMassPerDistance] = w.mass_per_distance;
    out.wear[kWearMassPerPass] = w.mass_per_pass;
    out.wear[kWearMaxDepth] = w.max_depth;
    out.wear[kWearMass] = c.wear.passes * w.mass_per_pass;
    for (int k = 0; k < 4; ++k) out.wear[kWearArea1 + k] = w.regime_area[k];
    return CW_OK;
}

int RowChunkSolver::add_surface(Handles& h, const cw_solver* solver, const ContactCase& c,
                                const cw_temperature_result* solved, Outcome& out)
{
    out.surface.assign(kSurfaceValues, 0.0);
    if (surface_->temperature) {
        cw_temperature_result t;
        cw_temperature_result_init(&t);
        if (solved) {
            t = *solved;
        } else {
            const cw_temperature_params p = row_temperature_params(*surface_, c);
            const int status = cw_temperature_compute(h.temperature, solver, &p, &t);
            if (status != CW_OK) {
                fail_row(out, status,
                         surface_message("temperature", cw_temperature_last_error(h.temperature),
                                         status));
                return status;
            }
        }
        out.surface[kSurfaceTMax1] = t.T_max_1;
        out.surface[kSurfaceTMax2] = t.T_max_2;
        cwcli::hottest_point(t, out.surface[kSurfaceTMaxX], out.surface[kSurfaceTMaxY]);
        out.surface[kSurfaceIterations] = t.iterations;
    }
    if (surface_->damage) {
        cw_damage_result d;
        cw_damage_result_init(&d);
        const int status = cw_damage_compute(h.damage, solver, &surface_->damage_params, &d);
        if (status != CW_OK) {
            fail_row(out, status,
                     surface_message("damage", cw_damage_last_error(h.damage), status));
            return status;
        }
        out.surface[kSurfaceRcfIndexMax] = d.rcf_index_max;
        out.surface[kSurfaceFISurf] = d.FI_surf;
        out.surface[kSurfaceTGamma] = d.T_gamma;
        out.surface[kSurfaceWlrmDamage] = d.wlrm_damage;
    }
    return CW_OK;
}

void RowChunkSolver::solve_row(Lane& lane, const ContactCase& c, Outcome& out)
{
    if (!c.rejected.empty()) return fail_row(out, c.rejected_status, c.rejected);
    int status = CW_OK;
    std::string message;
    Handles* h = handles_for(lane, c.grid, status, message);
    if (!h) return fail_row(out, status, message);

    cw_params params = c.params;
    // A gap row's values travel with the chunk, which outlives the solve.
    if (c.gap_values) {
        params.gap = c.gap_values->data();
        params.gap_len = c.gap_values->size();
    }
    cw_result_init(&out.result);
    out.status = CW_OK;
    out.message.clear();
    if (surface_ && surface_->mu_T()) {
        // The loop's first pass starts cold on a new solver and its passes
        // warm, as `creepwork solve --mu-T`'s: its own handle, whoever
        // solved on this thread before.
        Handles row = *h;
        row.solver = nullptr;
        char text[512] = "";
        status = cw_solver_create(&c.grid, &row.solver, text, sizeof text);
        if (status != CW_OK) return fail_row(out, status, text[0] ? text : cw_status_string(status));
        struct Own {
            cw_solver* s;
            ~Own() { cw_solver_destroy(s); }
        } own{row.solver};
        cw_mu_temperature m;
        cw_mu_temperature_init(&m);
        m.count = surface_->mu_T_temperature.size();
        m.temperature = surface_->mu_T_temperature.data();
        m.mu = surface_->mu_T_mu.data();
        const cw_temperature_params tp = row_temperature_params(*surface_, c);
        cw_temperature_result t;
        cw_temperature_result_init(&t);
        status = cw_temperature_solve(row.temperature, row.solver, &params, &tp, &m, nullptr, &t);
        if (status != CW_OK)
            return fail_row(out, status,
                            surface_message("temperature", cw_temperature_last_error(row.temperature),
                                            status));
        cw_solver_get_result(row.solver, &out.result);
        if (wear_ && add_wear(lane, row, c, out) != CW_OK) return;
        add_surface(row, row.solver, c, &t, out);
        return;
    }
    params.warm_start = 0; // as the batch: no memory of the thread's last row
    status = cw_solver_solve(h->solver, &params, CW_SOLVE_FULL, &out.result);
    if (status != CW_OK) return fail_row(out, status, cw_solver_last_error(h->solver));
    if (wear_ && add_wear(lane, *h, c, out) != CW_OK) return;
    if (surface_ && surface_->any()) add_surface(*h, h->solver, c, nullptr, out);
}

ChunkResult RowChunkSolver::solve(const Chunk& chunk)
{
    ChunkResult result;
    result.id = chunk.id;
    result.first_row = chunk.first_row;
    const size_t n = chunk.cases.size();
    result.outcomes.resize(n);
    for (auto& lane : lanes_)
        for (cw_wear_profile* p : lane->profile)
            if (p) cw_wear_profile_reset(p);

    // Rows are claimed one at a time, so a thread that draws a costly row
    // (an exact solve in full slip) does not hold up the others.
    std::atomic<size_t> next{0};
    std::mutex failure_mutex;
    std::exception_ptr failure;
    const auto work = [&](Lane& lane) {
        try {
            for (size_t i = next++; i < n; i = next++)
                solve_row(lane, chunk.cases[i], result.outcomes[i]);
        } catch (...) { // out of memory: the campaign stops, the checkpoint keeps the rest
            std::lock_guard<std::mutex> lock(failure_mutex);
            if (!failure) failure = std::current_exception();
        }
    };
    const size_t helpers = std::min(lanes_.size(), std::max<size_t>(n, 1)) - 1;
    std::vector<std::thread> pool;
    for (size_t t = 1; t <= helpers; ++t) pool.emplace_back(work, std::ref(*lanes_[t]));
    work(*lanes_[0]);
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
    if (!wear_) return result;

    // The chunk's profile per body: the lanes' exact sums merged (exactly),
    // then its state, the words the checkpoint keeps.
    for (int body = 0; body < kWearBodies; ++body) {
        cw_wear_profile* total = lanes_[0]->profile[body];
        for (size_t t = 1; t < lanes_.size(); ++t)
            if (cw_wear_profile_merge(total, lanes_[t]->profile[body]) != CW_OK)
                throw std::runtime_error(std::string("merging wear profiles: ") +
                                         cw_wear_profile_last_error(total));
        cw_wear_profile_totals totals;
        cw_wear_profile_totals_init(&totals);
        cw_wear_profile_get_totals(total, &totals);
        if (totals.adds == 0) continue;
        size_t words = 0;
        cw_wear_profile_state_size(total, &words);
        result.wear_states[body].resize(words);
        if (cw_wear_profile_get_state(total, result.wear_states[body].data(), words) != CW_OK)
            throw std::runtime_error("reading a wear profile's state");
    }
    return result;
}

} // namespace cwcampaign
