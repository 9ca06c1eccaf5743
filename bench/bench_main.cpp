// creepwork_bench: time per solve and per contact element (the tables of
// doc/performance.md), for Kalker strip grids 10x10 .. 200x200, partial and full
// slip, three amounts of output:
//   forces  CW_SOLVE_FORCES, totals only
//   full    CW_SOLVE_FULL, totals including the work sums (no field copied)
//   fields  CW_SOLVE_FULL, then every field copied out: the 11 CW_FIELD_*
//           maps, the state map and the lateral profile
// through three layers (C++ core, C ABI, Fortran module when built), on one
// core, and batched over many contacts with all cores (cw_batch_solve).
// Prints Markdown tables for doc/performance.md. Each time is the best of many short
// samples: other work on the machine only ever adds time, and a short sample
// has a fair chance to run undisturbed on a busy machine. The layers are
// sampled in turn so that drift hits them alike.
//
// It also checks, outside the timing, that every layer (and the batch)
// returns bitwise the same totals: a failed check exits with status 1.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "creepwork/creepwork.h"
#include "solver.hpp"

#ifdef CW_BENCH_FORTRAN
// bench_fortran.f90: the same loop written against module creepwork.
extern "C" {
int cwb_fortran_create(int nx, int ny);
void cwb_fortran_destroy(void);
int cwb_fortran_run(long reps, int mode, int fields, const cw_params* params, double* totals);
}
#endif

namespace cw = creepwork;

namespace {

// ------------------------------------------------------------------ inputs

// A steel wheel on a rail head: the Hertz example of doc/validation/index.md (wheel radius
// 457 mm, crown radius 300 mm, N = 100 kN, G = 82 GPa, nu = 0.28).
constexpr double kA = 7.169984332e-3, kB = 5.416941278e-3, kN = 100e3;
constexpr double kMu = 0.3, kG = 82e9, kNu = 0.28;

struct Case {
    const char* name;
    double xi_x, xi_y, phi; // [-], [-], [1/m]
};
// Partial slip: about half the patch adheres; full slip: none of it.
const Case kCases[] = {{"partial", 6e-4, 3e-4, 0.2}, {"full", 1e-2, 5e-3, 2.0}};

enum Mode { kForces = 0, kFull = 1, kFields = 2 };
const char* const kModeNames[] = {"forces", "full", "fields"};

cw_params c_params(const Case& c)
{
    cw_params p;
    cw_params_init(&p);
    p.a = kA;
    p.b = kB;
    p.normal_force = kN;
    p.mu = kMu;
    p.G = kG;
    p.nu = kNu;
    p.xi_x = c.xi_x;
    p.xi_y = c.xi_y;
    p.phi = c.phi;
    return p;
}

cw::ContactInput core_input(const Case& c)
{
    cw::ContactInput in;
    in.a = kA;
    in.b = kB;
    in.normal_force = kN;
    in.mu = kMu;
    in.G = kG;
    in.nu = kNu;
    in.xi_x = c.xi_x;
    in.xi_y = c.xi_y;
    in.phi = c.phi;
    return in;
}

// ----------------------------------------------------------------- options

struct Options {
    bool quick = false;
    bool batch = true;
    std::vector<int> grids{10, 20, 40, 100, 200};
    double min_time = 0.002; // seconds per sample
    int samples = 41;
    int threads = 0;        // batch threads; 0 = all cores
    bool fastsim = true;
    std::vector<int> exact_grids{20, 40, 100}; // N across the ellipse; empty: none
    int exact_steps = 1000; // warm-started sequence length (fewer on the largest grids)
};

void usage(FILE* f)
{
    std::fprintf(f,
                 "usage: creepwork_bench [--quick] [--grids N,N,...] [--no-batch]\n"
                 "                       [--min-time SECONDS] [--samples K] [--threads T]\n"
                 "  --quick      fewer, shorter samples; numbers are noisier\n"
                 "  --grids      square Kalker strip grids to run (default 10,20,40,100,200)\n"
                 "  --no-batch   skip cw_batch_solve\n"
                 "  --min-time   length of one timing sample (default 0.002 s)\n"
                 "  --samples    samples per measurement, the best is shown (default 41)\n"
                 "  --threads    batch threads (default 0: all cores)\n"
                 "  --exact-grids N,N,...  exact model: N elements across the ellipse\n"
                 "               (MX = MY = N + 4, box scale (N + 4)/N; default 20,40,100;\n"
                 "               0 = none)\n"
                 "  --exact-steps K  length of the warm-started sequence (default 1000)\n"
                 "  --exact-only skip the FASTSIM tables\n");
}

Options parse(int argc, char** argv)
{
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "creepwork_bench: %s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--quick") {
            o.quick = true;
            o.min_time = 0.001;
            o.samples = 9;
        } else if (a == "--no-batch") {
            o.batch = false;
        } else if (a == "--grids") {
            o.grids.clear();
            const std::string list = value();
            size_t pos = 0;
            while (pos <= list.size()) {
                const size_t comma = std::min(list.find(',', pos), list.size());
                const int n = std::atoi(list.substr(pos, comma - pos).c_str());
                if (n < 1 || n > CW_MAX_GRID_CELLS) {
                    std::fprintf(stderr, "creepwork_bench: --grids: bad size in '%s'\n",
                                 list.c_str());
                    std::exit(2);
                }
                o.grids.push_back(n);
                pos = comma + 1;
            }
        } else if (a == "--min-time") {
            o.min_time = std::atof(value().c_str());
        } else if (a == "--samples") {
            o.samples = std::max(1, std::atoi(value().c_str()));
        } else if (a == "--exact-only") {
            o.fastsim = false;
        } else if (a == "--exact-steps") {
            o.exact_steps = std::max(1, std::atoi(value().c_str()));
        } else if (a == "--exact-grids") {
            o.exact_grids.clear();
            const std::string list = value();
            size_t pos = 0;
            while (pos <= list.size()) {
                const size_t end = std::min(list.find(',', pos), list.size());
                const int n = std::atoi(list.substr(pos, end - pos).c_str());
                if (n > 0) o.exact_grids.push_back(n);
                pos = end + 1;
            }
        } else if (a == "--threads") {
            o.threads = std::atoi(value().c_str());
        } else if (a == "--help" || a == "-h") {
            usage(stdout);
            std::exit(0);
        } else {
            std::fprintf(stderr, "creepwork_bench: unknown option %s\n", a.c_str());
            usage(stderr);
            std::exit(2);
        }
    }
    if (!(o.min_time > 0.0)) o.min_time = 0.002;
    return o;
}

// ------------------------------------------------------------------ timing

using Clock = std::chrono::steady_clock;

// A runner performs `reps` solves (with their output) per call.
using Runner = std::function<void(long reps)>;

double seconds(const Runner& run, long reps)
{
    const auto t0 = Clock::now();
    run(reps);
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Repetitions that make one sample last about min_time.
long calibrate(const Runner& run, double min_time)
{
    run(1); // warm caches and pages
    long reps = 1;
    for (;;) {
        const double t = seconds(run, reps);
        if (t >= 0.2 * min_time || reps >= (1L << 40)) {
            const double per = t / reps;
            return std::max(1L, static_cast<long>(min_time / std::max(per, 1e-12)));
        }
        reps *= 4;
    }
}

// Seconds per solve of each runner: samples taken in turn, the best of each.
std::vector<double> time_in_turn(const std::vector<Runner>& runners, const Options& o)
{
    std::vector<long> reps;
    for (const Runner& r : runners) reps.push_back(calibrate(r, o.min_time));
    std::vector<std::vector<double>> samples(runners.size());
    for (int s = 0; s < o.samples; ++s)
        for (size_t k = 0; k < runners.size(); ++k)
            samples[k].push_back(seconds(runners[k], reps[k]) / reps[k]);
    std::vector<double> out;
    for (auto& s : samples) out.push_back(*std::min_element(s.begin(), s.end()));
    return out;
}

// ----------------------------------------------------------------- layers

// Totals compared across layers, bit for bit.
struct Totals {
    double v[6] = {0, 0, 0, 0, 0, 0}; // Fx, Fy, Mz, W_macro, W_micro_paper, W_consistent
    bool operator==(const Totals& o) const { return std::memcmp(v, o.v, sizeof v) == 0; }
};

volatile double g_sink = 0.0; // keeps the outputs alive

[[noreturn]] void die(const char* what, int status)
{
    std::fprintf(stderr, "creepwork_bench: %s failed: status %d (%s)\n", what, status,
                 cw_status_string(status));
    std::exit(1);
}

const cw::Field kAllFields[] = {cw::Field::x,  cw::Field::y,          cw::Field::area,
                             cw::Field::pz, cw::Field::px,         cw::Field::py,
                             cw::Field::sx, cw::Field::sy,         cw::Field::mz,
                             cw::Field::work_paper, cw::Field::work_consistent};

struct CoreLayer {
    cw::Solver solver;
    cw::ContactInput input;
    std::vector<double> field;
    std::vector<int> state;
    std::vector<double> py, pw, pp;

    CoreLayer(const cw::GridSpec& g, const Case& c)
        : solver(g), input(core_input(c)), field(static_cast<size_t>(g.nx) * g.ny),
          state(field.size()), py(g.ny), pw(g.ny), pp(g.ny)
    {
    }

    void run(long reps, Mode mode)
    {
        const cw::SolveMode m = mode == kForces ? cw::SolveMode::forces_only : cw::SolveMode::full;
        double sink = 0.0;
        for (long r = 0; r < reps; ++r) {
            sink += solver.solve(input, m).Fx;
            if (mode == kFields) {
                for (cw::Field f : kAllFields) {
                    solver.copy_field(f, field.data());
                    sink += field[0];
                }
                solver.copy_state(state.data());
                solver.copy_profile(py.data(), pw.data(), pp.data());
                sink += state[0] + pw[0];
            }
        }
        g_sink = g_sink + sink;
    }

    Totals totals(Mode mode)
    {
        const cw::SolveTotals& t = solver.solve(
            input, mode == kForces ? cw::SolveMode::forces_only : cw::SolveMode::full);
        return {{t.Fx, t.Fy, t.Mz, t.W_macro, t.W_micro_paper, t.W_consistent}};
    }
};

struct CLayer {
    cw_solver* solver = nullptr;
    cw_params params;
    cw_result result;
    std::vector<double> field;
    std::vector<int> state;
    std::vector<double> py, pw, pp;

    CLayer(const cw_grid& g, const Case& c)
        : params(c_params(c)), field(static_cast<size_t>(g.nx) * g.ny), state(field.size()),
          py(g.ny), pw(g.ny), pp(g.ny)
    {
        const int s = cw_solver_create(&g, &solver, nullptr, 0);
        if (s != CW_OK) die("cw_solver_create", s);
        cw_result_init(&result);
    }
    ~CLayer() { cw_solver_destroy(solver); }
    CLayer(const CLayer&) = delete;
    CLayer& operator=(const CLayer&) = delete;

    void run(long reps, Mode mode)
    {
        const int m = mode == kForces ? CW_SOLVE_FORCES : CW_SOLVE_FULL;
        const size_t n = field.size(), ny = py.size();
        int status = CW_OK;
        double sink = 0.0;
        for (long r = 0; r < reps; ++r) {
            status |= cw_solver_solve(solver, &params, m, &result);
            sink += result.Fx;
            if (mode == kFields) {
                for (int f = CW_FIELD_X; f <= CW_FIELD_WORK_CONSISTENT; ++f) {
                    status |= cw_solver_get_field(solver, f, field.data(), n);
                    sink += field[0];
                }
                status |= cw_solver_get_state(solver, state.data(), n);
                status |= cw_solver_get_profile(solver, py.data(), pw.data(), pp.data(), ny);
                sink += state[0] + pw[0];
            }
        }
        if (status != CW_OK) die("the C ABI loop", status);
        g_sink = g_sink + sink;
    }

    Totals totals(Mode mode)
    {
        const int s = cw_solver_solve(solver, &params, mode == kForces ? CW_SOLVE_FORCES : CW_SOLVE_FULL,
                                      &result);
        if (s != CW_OK) die("cw_solver_solve", s);
        const cw_result& r = result;
        return {{r.Fx, r.Fy, r.Mz, r.W_macro, r.W_micro_paper, r.W_consistent}};
    }
};

// Many contacts per call: creepages spread by a few per cent so that the
// contacts differ, as the wheels of a vehicle do.
struct BatchLayer {
    cw_batch* batch = nullptr;
    std::vector<cw_params> params;
    std::vector<cw_result> results;
    std::vector<int> statuses;

    BatchLayer(const cw_grid& g, const Case& c, int threads, size_t count)
        : params(count), results(count), statuses(count)
    {
        const int s = cw_batch_create(&g, threads, &batch, nullptr, 0);
        if (s != CW_OK) die("cw_batch_create", s);
        for (size_t i = 0; i < count; ++i) {
            Case ci = c;
            const double spread = 1.0 + 0.05 * static_cast<double>(i % 16) / 16.0;
            ci.xi_x *= spread;
            ci.xi_y *= spread;
            ci.phi *= spread;
            params[i] = c_params(ci);
            cw_result_init(&results[i]);
        }
    }
    ~BatchLayer() { cw_batch_destroy(batch); }
    BatchLayer(const BatchLayer&) = delete;
    BatchLayer& operator=(const BatchLayer&) = delete;

    void run(long reps, Mode mode)
    {
        const int m = mode == kForces ? CW_SOLVE_FORCES : CW_SOLVE_FULL;
        for (long r = 0; r < reps; ++r) {
            const int s = cw_batch_solve(batch, params.size(), params.data(), m, results.data(),
                                         statuses.data());
            if (s != CW_OK) die("cw_batch_solve", s);
        }
        g_sink = g_sink + results[0].Fx;
    }
};

#ifdef CW_BENCH_FORTRAN
struct FortranLayer {
    cw_params params;
    FortranLayer(const cw_grid& g, const Case& c) : params(c_params(c))
    {
        const int s = cwb_fortran_create(g.nx, g.ny);
        if (s != CW_OK) die("the Fortran solver", s);
    }
    ~FortranLayer() { cwb_fortran_destroy(); }
    FortranLayer(const FortranLayer&) = delete;
    FortranLayer& operator=(const FortranLayer&) = delete;

    void run(long reps, Mode mode)
    {
        double t[6];
        const int s = cwb_fortran_run(reps, mode == kForces ? CW_SOLVE_FORCES : CW_SOLVE_FULL,
                                      mode == kFields, &params, t);
        if (s != CW_OK) die("the Fortran loop", s);
        g_sink = g_sink + t[0];
    }
    Totals totals(Mode mode)
    {
        Totals t;
        const int s = cwb_fortran_run(1, mode == kForces ? CW_SOLVE_FORCES : CW_SOLVE_FULL, 0,
                                      &params, t.v);
        if (s != CW_OK) die("the Fortran loop", s);
        return t;
    }
};
constexpr bool kHaveFortran = true;
#else
constexpr bool kHaveFortran = false;
#endif

// ------------------------------------------------------------------ report

std::string cpu_model()
{
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            const size_t colon = line.find(':');
            if (colon != std::string::npos) return line.substr(colon + 2);
        }
    return "unknown CPU";
}

// The 1-minute load average: other processes make the timings (the
// batch's above all: its threads wait for free cores) unreliable.
double load_average()
{
    std::ifstream in("/proc/loadavg");
    double load = -1.0;
    in >> load;
    return load;
}

// Three significant figures, with k/M for large counts.
std::string sig3(double v)
{
    char buf[32];
    const double a = std::fabs(v);
    if (a >= 100) std::snprintf(buf, sizeof buf, "%.0f", v);
    else if (a >= 10) std::snprintf(buf, sizeof buf, "%.1f", v);
    else if (a >= 1) std::snprintf(buf, sizeof buf, "%.2f", v);
    else std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
}

std::string rate(double per_second)
{
    if (per_second >= 1e6) return sig3(per_second / 1e6) + " M";
    if (per_second >= 1e3) return sig3(per_second / 1e3) + " k";
    return sig3(per_second);
}

std::string percent(double layer, double core)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%+.1f %%", 100.0 * (layer - core) / core);
    return buf;
}

// ------------------------------------------------------------ exact model
//
// Kalker's exact theory on CONTACT's grid: N elements across the
// ellipse, MX = MY = N + 4, box scale (N + 4)/N, the benchmark contact
// (a = 7.17 mm, b = 5.42 mm, N = 100 kN, mu = 0.3, G = 82 GPa, nu = 0.28).
//  cold: create a solver and solve once (CW_SOLVE_FULL), as a CONTACT call
//        recomputes its coefficients: influence coefficients, FFT plans and
//        spectra, the normal problem, the tangential problem, the work maps;
//  warm: a sequence of solves on one solver, warm-started, the creepages
//        changing by at most 1 % per step (xi_x, xi_y, phi each
//        x (1 + 0.1 sin(2 pi k / 100 + offset))).
// Times are the best of several samples (cold) or the mean over the sequence
// (warm; the best of three runs of it below N = 100), in CPU time of the
// calling thread: on a shared machine wall time also counts the waits for a
// core. Through the C++ core: the C ABI adds ~30 ns per call.
double thread_seconds()
{
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

void exact_bench(const Options& o)
{
    if (o.exact_grids.empty()) return;
    std::printf("\nExact model (Kalker's exact theory, CONTACT's grid MX = MY = N + 4, box scale "
                "(N + 4)/N), a = 7.17 mm, b = 5.42 mm, N = 100 kN, mu = 0.3, G = 82 GPa, "
                "nu = 0.28, CW_SOLVE_FULL, one core, thread CPU time:\n\n");
    std::printf("| N | slip | adhesion | cold ms (create + solve) | Newton steps | FFT products | "
                "warm ms/step | steps | warm products/step |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int N : o.exact_grids) {
        const cw::GridSpec spec{cw::GridKind::uniform, N + 4, N + 4, (N + 4.0) / N};
        for (const Case& c : kCases) {
            cw::ContactInput in;
            in.model = cw::ModelKind::exact;
            in.a = 7.17e-3;
            in.b = 5.42e-3;
            in.normal_force = 100e3;
            in.mu = kMu;
            in.G = kG;
            in.nu = kNu;
            in.xi_x = c.xi_x;
            in.xi_y = c.xi_y;
            in.phi = c.phi;
            // Cold: best of a few samples (create + solve).
            const int samples = N >= 100 ? 3 : o.quick ? 5 : 15;
            double best = 1e300, adhesion = 0.0;
            int newton = 0, products = 0;
            for (int k = 0; k < samples; ++k) {
                const auto t0 = thread_seconds();
                cw::Solver s(spec);
                const cw::SolveTotals& t = s.solve(in, cw::SolveMode::full);
                const auto t1 = thread_seconds();
                best = std::min(best, t1 - t0);
                adhesion = t.adhesion_fraction;
                newton = t.iterations;
                products = s.exact_model()->info().products;
            }
            // Warm: one solver, creepages drifting.
            const int steps =
                o.quick ? std::min(o.exact_steps, N >= 100 ? 10 : 100) : o.exact_steps;
            // The sequence is run a few times from the same start and the
            // fastest run counts (other work on the machine only adds time).
            const int runs = o.quick || N >= 100 ? 1 : 3;
            double warm = 1e300;
            long warm_products = 0;
            for (int run = 0; run < runs; ++run) {
                cw::Solver s(spec);
                s.solve(in, cw::SolveMode::full);
                warm_products = 0;
                const auto t0 = thread_seconds();
                for (int k = 1; k <= steps; ++k) {
                    const double t = 2.0 * 3.14159265358979323846 * k / 100.0;
                    cw::ContactInput step = in;
                    step.xi_x = c.xi_x * (1.0 + 0.1 * std::sin(t));
                    step.xi_y = c.xi_y * (1.0 + 0.1 * std::sin(t + 2.0));
                    step.phi = c.phi * (1.0 + 0.1 * std::sin(t + 4.0));
                    s.solve(step, cw::SolveMode::full);
                    warm_products += s.exact_model()->info().products;
                }
                warm = std::min(warm, (thread_seconds() - t0) / steps);
            }
            std::printf("| %d | %s | %.2f | %s | %d | %d | %s | %d | %.1f |\n", N, c.name,
                        adhesion, sig3(best * 1e3).c_str(), newton, products,
                        sig3(warm * 1e3).c_str(), steps, double(warm_products) / steps);
            std::fflush(stdout);
        }
    }
}

} // namespace

int main(int argc, char** argv)
{
    const Options o = parse(argc, argv);
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const int batch_threads = o.threads > 0 ? o.threads : cores;

    std::printf("creepwork_bench: %s, %d cores; %s, %s build; kernel %s%s\n",
                cpu_model().c_str(), cores, CW_BENCH_COMPILER, CW_BENCH_BUILD_TYPE,
                cw::kernel_isa_name(cw::best_kernel_isa()), o.quick ? "; --quick (noisy)" : "");
    std::printf("Contact: a = %.3g mm, b = %.3g mm, N = %.0f kN, mu = %.1f, steel; Kalker strip "
                "grid n x n.\n",
                kA * 1e3, kB * 1e3, kN / 1e3, kMu);
    for (const Case& c : kCases) {
        cw::Solver s(cw::GridSpec{cw::GridKind::kalker_strips, 20, 20, 1.0});
        const cw::SolveTotals& t = s.solve(core_input(c));
        std::printf("  %-8s xi_x = %g, xi_y = %g, phi = %g 1/m: adhesion fraction %.2f (20x20)\n",
                    c.name, c.xi_x, c.xi_y, c.phi, t.adhesion_fraction);
    }
    std::printf("Modes: forces = CW_SOLVE_FORCES; full = CW_SOLVE_FULL (work sums, no copy);\n"
                "fields = CW_SOLVE_FULL + all 11 fields, the state map and the profile copied "
                "out.\n");
    std::printf("ns/el = time per solve / (nx*ny), best of %d samples; single core unless "
                "'batch' (%d threads, cw_batch_solve).\n",
                o.samples, batch_threads);
    const double load = load_average();
    if (load >= 0.0)
        std::printf("Load average at start: %.2f%s\n", load,
                    load > 0.5 ? " -- the machine is busy: expect noise, and batch times that "
                                 "measure waiting for a free core"
                               : "");
    std::printf("\n");

    if (!o.fastsim) {
        exact_bench(o);
        return 0;
    }
    std::printf("| grid | slip | mode | core ns/el | C ABI ns/el | C ABI us/solve | C ABI "
                "solves/s | C ABI vs core | Fortran vs core | batch ns/el | batch solves/s |\n");
    std::printf("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");

    bool agree = true;
    for (int n : o.grids) {
        cw_grid g;
        cw_grid_init(&g);
        g.kind = CW_GRID_KALKER_STRIPS;
        g.nx = g.ny = n;
        const cw::GridSpec spec{cw::GridKind::kalker_strips, n, n, 1.0};
        const double elements = static_cast<double>(n) * n;
        for (const Case& c : kCases) {
            CoreLayer core(spec, c);
            CLayer capi(g, c);
#ifdef CW_BENCH_FORTRAN
            FortranLayer fortran(g, c);
#endif
            // Enough contacts per batch call for every thread to stay busy.
            const size_t count = static_cast<size_t>(
                std::max(8.0 * batch_threads, std::ceil(2e5 / elements)));
            std::unique_ptr<BatchLayer> batch;
            if (o.batch) batch.reset(new BatchLayer(g, c, o.threads, count));

            for (Mode mode : {kForces, kFull, kFields}) {
                const Totals ref = core.totals(mode);
                agree = agree && capi.totals(mode) == ref;
                std::vector<Runner> runners{[&](long r) { core.run(r, mode); },
                                            [&](long r) { capi.run(r, mode); }};
#ifdef CW_BENCH_FORTRAN
                agree = agree && fortran.totals(mode) == ref;
                runners.push_back([&](long r) { fortran.run(r, mode); });
#endif
                const std::vector<double> t = time_in_turn(runners, o);
                const double t_core = t[0], t_c = t[1];
                std::string fortran_col = "n/a";
                if (kHaveFortran) fortran_col = percent(t[2], t_core);

                std::string batch_ns = "-", batch_rate = "-";
                if (batch && mode != kFields) {
                    batch->run(1, mode);
                    // The batch must give what one-by-one solves give.
                    for (size_t i = 0; i < count; i += std::max<size_t>(1, count / 4)) {
                        cw_result r;
                        cw_result_init(&r);
                        cw_solver_solve(capi.solver, &batch->params[i],
                                        mode == kForces ? CW_SOLVE_FORCES : CW_SOLVE_FULL, &r);
                        const cw_result& b = batch->results[i];
                        agree = agree && r.Fx == b.Fx && r.Fy == b.Fy && r.Mz == b.Mz &&
                                r.W_consistent == b.W_consistent;
                    }
                    const double per_call =
                        time_in_turn({[&](long r) { batch->run(r, mode); }}, o)[0];
                    const double per_solve = per_call / static_cast<double>(count);
                    batch_ns = sig3(per_solve * 1e9 / elements);
                    batch_rate = rate(1.0 / per_solve);
                }
                std::printf("| %dx%d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", n, n,
                            c.name, kModeNames[mode], sig3(t_core * 1e9 / elements).c_str(),
                            sig3(t_c * 1e9 / elements).c_str(), sig3(t_c * 1e6).c_str(),
                            rate(1.0 / t_c).c_str(), percent(t_c, t_core).c_str(),
                            fortran_col.c_str(), batch_ns.c_str(), batch_rate.c_str());
                std::fflush(stdout);
            }
        }
    }
    std::printf("\nLayers%s agree bitwise: %s\n", o.batch ? " and batch" : "",
                agree ? "yes" : "NO");
    exact_bench(o);
    return agree ? 0 : 1;
}
