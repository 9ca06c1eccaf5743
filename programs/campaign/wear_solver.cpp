#include "wear_solver.hpp"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace cwcampaign {

namespace {

bool same_grid(const cw_grid& a, const cw_grid& b)
{
    return a.kind == b.kind && a.nx == b.nx && a.ny == b.ny &&
           (a.kind != CW_GRID_UNIFORM ||
            std::memcmp(&a.box_scale, &b.box_scale, sizeof(double)) == 0);
}

void fail_row(Outcome& out, int status, const std::string& message)
{
    out.status = status;
    out.message = message;
    out.wear.clear();
    cw_result_init(&out.result);
}

} // namespace

WearChunkSolver::Lane::~Lane()
{
    for (Handles& h : grids) {
        cw_wear_destroy(h.wear);
        cw_solver_destroy(h.solver);
    }
    for (cw_wear_profile* p : profile) cw_wear_profile_destroy(p);
}

WearChunkSolver::WearChunkSolver(int threads, size_t max_grids, const WearSetup& setup)
    : threads_(threads < 1 ? 1 : threads), max_grids_(max_grids < 1 ? 1 : max_grids),
      setup_(setup)
{
    char message[512] = "";
    for (int t = 0; t < threads_; ++t) {
        auto lane = std::make_unique<Lane>();
        for (cw_wear_profile*& p : lane->profile)
            if (cw_wear_profile_create(setup.nodes.data(), setup.nodes.size(), &p, message,
                                       sizeof message) != CW_OK)
                throw std::runtime_error(std::string("the wear profile grid: ") + message);
        lanes_.push_back(std::move(lane));
    }
}

WearChunkSolver::~WearChunkSolver() = default;

WearChunkSolver::Handles* WearChunkSolver::handles_for(Lane& lane, const cw_grid& grid,
                                                       int& status, std::string& message)
{
    for (auto it = lane.grids.begin(); it != lane.grids.end(); ++it)
        if (same_grid(it->grid, grid)) {
            lane.grids.splice(lane.grids.begin(), lane.grids, it);
            return &lane.grids.front();
        }
    if (lane.grids.size() >= max_grids_) {
        cw_wear_destroy(lane.grids.back().wear);
        cw_solver_destroy(lane.grids.back().solver);
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
    status = cw_wear_create(h.solver, &h.wear);
    if (status != CW_OK) {
        cw_solver_destroy(h.solver);
        message = cw_status_string(status);
        return nullptr;
    }
    lane.grids.push_front(h);
    return &lane.grids.front();
}

void WearChunkSolver::solve_row(Lane& lane, const ContactCase& c, Outcome& out)
{
    if (!c.rejected.empty()) return fail_row(out, c.rejected_status, c.rejected);
    int status = CW_OK;
    std::string message;
    Handles* h = handles_for(lane, c.grid, status, message);
    if (!h) return fail_row(out, status, message);

    cw_params params = c.params;
    params.warm_start = 0; // as the batch: no memory of the thread's last row
    cw_result_init(&out.result);
    status = cw_solver_solve(h->solver, &params, CW_SOLVE_FULL, &out.result);
    if (status != CW_OK) return fail_row(out, status, cw_solver_last_error(h->solver));

    const cw_wear_params wp = row_wear_params(setup_, c.wear);
    cw_wear_result w;
    cw_wear_result_init(&w);
    status = cw_wear_compute(h->wear, h->solver, &wp, &w);
    if (status != CW_OK)
        return fail_row(out, status, std::string("wear: ") + cw_wear_last_error(h->wear));
    cw_wear_profile* profile = lane.profile[c.wear.body == kWheel ? kWheel : kRail];
    status = cw_wear_profile_add(profile, h->wear, c.wear.s0, setup_.orientation, c.wear.angle,
                                 c.wear.passes);
    if (status != CW_OK) // nothing was added (the call's promise)
        return fail_row(out, status,
                        std::string("wear profile: ") + cw_wear_profile_last_error(profile));

    out.status = CW_OK;
    out.message.clear();
    out.wear.assign(kWearValues, 0.0);
    out.wear[kWearPasses] = c.wear.passes;
    out.wear[kWearWork] = w.work;
    out.wear[kWearMassPerDistance] = w.mass_per_distance;
    out.wear[kWearMassPerPass] = w.mass_per_pass;
    out.wear[kWearMaxDepth] = w.max_depth;
    out.wear[kWearMass] = c.wear.passes * w.mass_per_pass;
    for (int k = 0; k < 4; ++k) out.wear[kWearArea1 + k] = w.regime_area[k];
}

ChunkResult WearChunkSolver::solve(const Chunk& chunk)
{
    ChunkResult result;
    result.id = chunk.id;
    result.first_row = chunk.first_row;
    const size_t n = chunk.cases.size();
    result.outcomes.resize(n);
    for (auto& lane : lanes_)
        for (cw_wear_profile* p : lane->profile) cw_wear_profile_reset(p);

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
