// creepwork_bench_jacobian: the cost of the Jacobian (doc/theory/jacobians.md),
// through the C ABI on one core. For FASTSIM and the calibrated model, each
// grid and regime it times
//   forces    cw_solver_solve(CW_SOLVE_FORCES)
//   jacobian  cw_solver_solve_jacobian(CW_SOLVE_FORCES): the same totals and
//             the 4 x 4 Jacobian
// and prints ns per contact element and the ratio (target: <= 3). The exact
// model is timed the same way (warm-started sequence, small grids), beside
// the Jacobian by central differences (6 more warm solves) and a cold solve.
// Each number is the best of many short samples of thread CPU time, the
// calls sampled in turn (other work on the machine only ever adds time). Not
// a test: nothing here asserts a speed.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <vector>

#include "creepwork/creepwork.h"

namespace {

// The contact of creepwork_bench: wheel radius 457 mm on a 300 mm crown,
// N = 100 kN, steel (the Hertz example of doc/validation/index.md).
constexpr double kA = 7.169984332e-3, kB = 5.416941278e-3, kN = 100e3;

struct Regime {
    const char* name;
    double xi_x, xi_y, phi;
};
const Regime kRegimes[] = {{"partial", 6e-4, 3e-4, 0.2}, {"full", 1e-2, 5e-3, 2.0}};

cw_params params_of(const Regime& r, int model)
{
    cw_params p;
    cw_params_init(&p);
    p.a = kA;
    p.b = kB;
    p.normal_force = kN;
    p.xi_x = r.xi_x;
    p.xi_y = r.xi_y;
    p.phi = r.phi;
    p.model = model;
    return p;
}

// This thread's CPU time: on a shared machine (here 2 cores under a load of
// ~8) wall time mostly measures the other processes; CPU time leaves out the
// time the thread waits descheduled.
double now()
{
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Best time per call of each runner over samples of about min_time each,
// sampled in turn.
std::vector<double> best_times(const std::vector<std::function<void()>>& runs, double min_time,
                               int samples)
{
    std::vector<long> reps(runs.size(), 1);
    for (size_t k = 0; k < runs.size(); ++k) {
        const double t0 = now();
        runs[k]();
        const double per = std::max(now() - t0, 1e-9);
        reps[k] = std::max(1L, static_cast<long>(min_time / per));
    }
    std::vector<double> best(runs.size(), 1e300);
    for (int s = 0; s < samples; ++s)
        for (size_t k = 0; k < runs.size(); ++k) {
            const double t0 = now();
            for (long r = 0; r < reps[k]; ++r) runs[k]();
            best[k] = std::min(best[k], (now() - t0) / reps[k]);
        }
    return best;
}

void check(int status, const char* what)
{
    if (status != CW_OK) {
        std::fprintf(stderr, "%s failed: %s\n", what, cw_status_string(status));
        std::exit(1);
    }
}

} // namespace

int main(int argc, char** argv)
{
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    const double min_time = quick ? 0.001 : 0.003;
    const int samples = quick ? 7 : 61;

    std::printf("FASTSIM and the calibrated model, Kalker strip grid, C ABI, one core; ns per "
                "contact element (best of %d samples)\n\n", samples);
    std::printf("| model | grid | regime | forces ns/elem | jacobian ns/elem | ratio |\n");
    std::printf("|---|---|---|---:|---:|---:|\n");
    for (int model : {CW_MODEL_FASTSIM, CW_MODEL_CALIBRATED})
        for (int n : {20, 40, 100, 200}) {
            cw_grid g;
            cw_grid_init(&g);
            g.nx = g.ny = n;
            cw_solver* s = nullptr;
            check(cw_solver_create(&g, &s, nullptr, 0), "cw_solver_create");
            for (const Regime& r : kRegimes) {
                const cw_params p = params_of(r, model);
                cw_result res;
                cw_result_init(&res);
                double jac[CW_JACOBIAN_LEN];
                check(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &res), "solve");
                const int elements = res.n_contact;
                check(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &res, jac, CW_JACOBIAN_LEN),
                      "solve_jacobian");
                const std::vector<double> t = best_times(
                    {[&] { cw_solver_solve(s, &p, CW_SOLVE_FORCES, &res); },
                     [&] { cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &res, jac,
                                                    CW_JACOBIAN_LEN); }},
                    min_time, samples);
                std::printf("| %s | %dx%d | %s | %.2f | %.2f | %.2f |\n",
                            model == CW_MODEL_FASTSIM ? "FASTSIM" : "calibrated", n, n, r.name,
                            t[0] / elements * 1e9, t[1] / elements * 1e9, t[1] / t[0]);
            }
            cw_solver_destroy(s);
        }

    // The exact model: a warm-started sequence (the vehicle-dynamics use), so
    // each solve starts from the last one; the creepage alternates between
    // two nearby values so that every solve iterates.
    std::printf("\nExact model, uniform grid N x N over the ellipse, warm-started; ms per "
                "solve (best of %d)\n\n", quick ? 3 : 15);
    std::printf("| grid | regime | forces ms | jacobian (implicit) ms | ratio | central "
                "differences ms | ratio | cold solve ms |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|\n");
    for (int n : {16, 24, 40}) {
        cw_grid g;
        cw_grid_init(&g);
        g.kind = CW_GRID_UNIFORM;
        g.nx = g.ny = n;
        cw_solver* s = nullptr;
        check(cw_solver_create(&g, &s, nullptr, 0), "cw_solver_create");
        check(cw_solver_prepare(s, CW_MODEL_EXACT), "prepare");
        for (const Regime& r : kRegimes) {
            cw_params p = params_of(r, CW_MODEL_EXACT);
            cw_result res;
            cw_result_init(&res);
            double jac[CW_JACOBIAN_LEN];
            long k = 0;
            auto next = [&] { // alternate creepage: 1 and 1.001 times the regime's
                p.xi_x = r.xi_x * (1.0 + 1e-3 * static_cast<double>(k++ & 1));
            };
            check(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &res), "exact solve");
            const std::vector<double> t = best_times(
                {[&] {
                     next();
                     check(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &res), "exact solve");
                 },
                 [&] {
                     next();
                     check(cw_solver_solve_jacobian(s, &p, CW_SOLVE_FORCES, &res, jac,
                                                    CW_JACOBIAN_LEN),
                           "exact jacobian");
                 },
                 [&] {
                     next();
                     cw_params q = p;
                     q.warm_start = 0;
                     check(cw_solver_solve(s, &q, CW_SOLVE_FORCES, &res), "exact cold solve");
                 },
                 [&] {
                     next();
                     cw_params q = p;
                     check(cw_solver_solve(s, &q, CW_SOLVE_FORCES, &res), "exact solve");
                     const double steps[3] = {1e-6, 1e-6, 1e-6 / kA};
                     double* fields[3] = {&q.xi_x, &q.xi_y, &q.phi};
                     for (int c = 0; c < 3; ++c) {
                         const double v = *fields[c];
                         *fields[c] = v + steps[c];
                         check(cw_solver_solve(s, &q, CW_SOLVE_FORCES, &res), "exact +h");
                         *fields[c] = v - steps[c];
                         check(cw_solver_solve(s, &q, CW_SOLVE_FORCES, &res), "exact -h");
                         *fields[c] = v;
                     }
                 }},
                0.0, quick ? 3 : 15);
            std::printf("| %dx%d | %s | %.3f | %.3f | %.2f | %.3f | %.2f | %.3f |\n", n, n,
                        r.name, t[0] * 1e3, t[1] * 1e3, t[1] / t[0], t[3] * 1e3, t[3] / t[0],
                        t[2] * 1e3);
        }
        cw_solver_destroy(s);
    }
    return 0;
}
