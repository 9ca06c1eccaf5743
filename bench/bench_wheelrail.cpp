// creepwork_bench_wheelrail: the cost of the wheel/rail geometry per wheel
// (contact search, patch frames, undeformed distance grids, creepages) over
// the Manchester benchmark's 42 wheel positions at CONTACT's discretisation
// (dx = ds = 0.2 mm), of the contact search alone, and of a whole position:
// the wheelset height for 10 kN with every patch solved by the exact model
// (geometry and contact, CONTACT's module 1 with N = 1), and the same with
// the fast model (FASTSIM with the semi-Hertzian normal problem), forces
// only and with every field and work map. Given CONTACT's
// program, the same run times CONTACT's own examples (both wheels,
// the same 42 positions) as a child process. Not a test: it prints a table
// with a stamp. Times are per-thread CPU time (CLOCK_THREAD_CPUTIME_ID, not
// counting time the thread is descheduled) and wall time, medians of
// repeated sweeps, except where CONTACT's ratio or a target is read: the
// exact model's whole positions (the best of sweeps taken in turns with
// CONTACT's runs, the best of those) and the hunting cycle (the best of
// three cycles); CONTACT's is its CPU time (getrusage of the child).
//
//   creepwork_bench_wheelrail [SWEEPS [CONTACT EXAMPLES_DIR]]   (default 200)
//   creepwork_bench_wheelrail --hunting CALLS [exact|fast [print]]  one hunting cycle's model
//   creepwork_bench_wheelrail --positions exact|fast [print]   one sweep of whole positions (callgrind);
//       print: each position's height and forces
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "mbench_support.hpp"
#include "wheelrail/patch_contact.hpp"
#include "wheelrail/placement.hpp"

namespace wr = creepwork::wheelrail;

namespace {

double seconds(clockid_t clock)
{
    timespec t{};
    clock_gettime(clock, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::string cpu_model()
{
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// CPU time of CONTACT solving its examples mbench_a22_right and _left in a
// scratch directory (-1 when it cannot run).
double contact_seconds(const std::string& program, const std::string& examples)
{
    const std::string dir = "creepwork_bench_contact";
    std::string cmd = "rm -rf " + dir + " && mkdir " + dir + " && cp " + examples + "/MBench_* " + examples +
                      "/mbench_a22_right.inp " + examples + "/mbench_a22_left.inp " + dir + " && cd " + dir +
                      " && " + program + " 2 mbench_a22_right > /dev/null 2>&1 && " + program +
                      " 2 mbench_a22_left > /dev/null 2>&1";
    rusage before{}, after{};
    getrusage(RUSAGE_CHILDREN, &before);
    if (std::system(cmd.c_str()) != 0) return -1.0;
    getrusage(RUSAGE_CHILDREN, &after);
    auto sec = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
    return sec(after.ru_utime) - sec(before.ru_utime) + sec(after.ru_stime) - sec(before.ru_stime);
}

// A host's loop over one cycle of a hunting wheelset, as
// examples/rail_wear_hunting drives it (right wheel, UIC60 and S1002, 0.5 mm
// elements, 60 kN, y = A sin(theta), yaw = A k cos(theta), A = 5 mm,
// wavelength 15 m, 30 m/s), the vertical force prescribed, `calls` calls per
// cycle, each starting from the height the last call found (the first
// cycle not timed, then the best of `timed_cycles`). Per call: CPU time [s],
// evaluations, the largest relative error of Fz, of the cycle timed best
// (the cycles make the same calls from heights that agree to the force
// tolerance).
struct HuntingCost {
    double cpu = 0.0, evaluations = 0.0, fz_error = 0.0;
};

HuntingCost hunting_cycle(const cwtest::Benchmark& b, const wr::PatchContactSettings& set, int calls,
                          int timed_cycles, bool print = false)
{
    constexpr double kPi = 3.14159265358979323846;
    const double amplitude = 5e-3, k_wave = 2.0 * kPi / 15.0, speed = 30.0, radius = 0.46, load = 60e3;
    wr::Wheelset ws = b.wheelset;
    ws.nominal_radius = radius;
    wr::WheelRailContact c(wr::WheelRailGeometry(b.rail, b.wheel, b.track, ws, wr::Side::right,
                                                 b.options(0.5, 0.5)),
                           set);
    HuntingCost cost;
    cost.cpu = 1e300;
    double z = 0.0;
    for (int cycle = 0; cycle <= timed_cycles; ++cycle) {
        double cpu = 0.0, evaluations = 0.0, worst = 0.0;
        for (int m = 0; m < calls; ++m) {
            const double theta = 2.0 * kPi * m / calls;
            wr::WheelsetPosition pos;
            pos.y = amplitude * std::sin(theta);
            pos.yaw = amplitude * k_wave * std::cos(theta);
            pos.z = z;
            wr::WheelsetVelocity vel;
            vel.vs = speed;
            vel.vy = speed * pos.yaw;
            vel.vyaw = -speed * amplitude * k_wave * k_wave * std::sin(theta);
            vel.vpitch = -speed / radius;
            const double c0 = seconds(CLOCK_THREAD_CPUTIME_ID);
            const wr::WheelRailSolution& sol = c.solve_force(load, pos, vel);
            cpu += seconds(CLOCK_THREAD_CPUTIME_ID) - c0;
            evaluations += sol.evaluations;
            worst = std::max(worst, std::abs(sol.total.fz - load) / load);
            if (print && cycle == 1)
                std::printf("%d %.17g %.17g %.17g %.17g %d\n", m, sol.z, sol.total.fx, sol.total.fy,
                            sol.total.fz, sol.evaluations);
            z = sol.z;
        }
        if (cycle > 0 && cpu / calls < cost.cpu) cost = {cpu / calls, evaluations / calls, worst};
    }
    return cost;
}

// A whole position: the height for 10 kN, every patch by the exact model
// (as test_wheelrail_forces) or the fast one, over the benchmark's rows.
// heights[k]: the height found for row k (filled by the first call).
// Start::zero finds the height for 10 kN from z = 0; Start::near from 1 um
// off the height found before (a host's next time step); Start::given
// solves at that height (an MBS host's wheelset position).
enum class Start { zero, near, given };
struct Timing {
    double cpu, wall, evaluations; // per position: [s], [s], geometry evaluations
    double fz_error;               // the largest relative error of Fz (force balances)
};

// fresh: new objects each sweep, the positions one after the other from a
// cold start, as CONTACT runs its examples; otherwise one pair of objects
// for every sweep after a first one not timed, as a host's loop keeps its
// handles (their solvers made for the grids met before).
Timing whole_positions(const cwtest::Benchmark& b, const std::vector<cwtest::Row>& rows,
                       std::vector<double>& heights, const wr::PatchContactSettings& set, int force_sweeps,
                       Start start, bool fresh, bool print = false)
{
    const bool given_height = start == Start::given;
    std::vector<double> pos_cpu, pos_wall;
    double evaluations = 0.0, worst = 0.0;
    wr::WheelRailContact kept_r(b.geometry(wr::Side::right), set), kept_l(b.geometry(wr::Side::left), set);
    for (int s = fresh ? 0 : -1; s < force_sweeps; ++s) {
        wr::WheelRailContact fresh_r(b.geometry(wr::Side::right), set), fresh_l(b.geometry(wr::Side::left), set);
        wr::WheelRailContact& cr = fresh ? fresh_r : kept_r;
        wr::WheelRailContact& cl = fresh ? fresh_l : kept_l;
        double cpu = 0.0, wall = 0.0;
        for (std::size_t k = 0; k < rows.size(); ++k) {
            const cwtest::Row& r = rows[k];
            wr::WheelRailContact& c = cwtest::side_of(r) == wr::Side::right ? cr : cl;
            wr::WheelsetPosition pos = cwtest::position_of(r);
            pos.z = start == Start::zero ? 0.0 : start == Start::near ? heights[k] + 1e-6 : heights[k];
            const double c0 = seconds(CLOCK_THREAD_CPUTIME_ID), w0 = seconds(CLOCK_MONOTONIC);
            const wr::WheelRailSolution& sol = given_height ? c.solve_position(pos, cwtest::velocity_of(r))
                                                            : c.solve_force(1e4, pos, cwtest::velocity_of(r));
            cpu += seconds(CLOCK_THREAD_CPUTIME_ID) - c0;
            wall += seconds(CLOCK_MONOTONIC) - w0;
            if (start == Start::zero) heights[k] = sol.z;
            if (s == 0) evaluations += sol.evaluations;
            if (!given_height) worst = std::max(worst, std::abs(sol.total.fz - 1e4) / 1e4);
            if (print && s == 0)
                std::printf("%zu %.17g %.17g %.17g %.17g %d\n", k, sol.z, sol.total.fx, sol.total.fy, sol.total.fz,
                            sol.evaluations);
        }
        if (s < 0) continue; // the warm-up sweep
        pos_cpu.push_back(cpu / static_cast<double>(rows.size()));
        pos_wall.push_back(wall / static_cast<double>(rows.size()));
    }
    return Timing{median(pos_cpu), median(pos_wall), evaluations / static_cast<double>(rows.size()), worst};
}

} // namespace

int main(int argc, char** argv)
{
    const cwtest::Benchmark b;
    if (argc > 2 && std::string(argv[1]) == "--hunting") {
        // one model's hunting cycle alone (for callgrind): --hunting CALLS
        // [exact|fast [print]]; print: each call's height, forces and
        // evaluations in the second cycle
        wr::PatchContactSettings set;
        set.mode = creepwork::SolveMode::forces_only;
        if (!(argc > 3 && std::string(argv[3]) == "exact")) {
            set.model = creepwork::ModelKind::fastsim;
            set.normal_method = creepwork::NormalMethod::semi_hertz;
        }
        const bool print = argc > 4 && std::string(argv[4]) == "print";
        const HuntingCost h = hunting_cycle(b, set, std::max(1, std::atoi(argv[2])), 1, print);
        std::printf("%.1f us per call, %.2f evaluations per call, largest Fz error %.1e\n", 1e6 * h.cpu,
                    h.evaluations, h.fz_error);
        return 0;
    }
    if (argc > 2 && std::string(argv[1]) == "--positions") {
        // one sweep of the whole positions from z = 0 on fresh objects, one
        // model alone (for callgrind): --positions exact|fast; the exact
        // model as the table's row (every field), the fast one forces only
        wr::PatchContactSettings set;
        if (std::string(argv[2]) == "fast") {
            set.model = creepwork::ModelKind::fastsim;
            set.normal_method = creepwork::NormalMethod::semi_hertz;
            set.mode = creepwork::SolveMode::forces_only;
        }
        const auto rows = cwtest::read_rows(cwtest::wheelrail_data("contact_a22_geometry.csv"));
        std::vector<double> heights(rows.size(), 0.0);
        const bool print = argc > 3 && std::string(argv[3]) == "print";
        const Timing t = whole_positions(b, rows, heights, set, 1, Start::zero, true, print);
        std::printf("%.3f ms per position, %.2f evaluations per position, largest Fz error %.1e\n", 1e3 * t.cpu,
                    t.evaluations, t.fz_error);
        return 0;
    }
    const int sweeps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 200;
    const auto rows = cwtest::read_rows(cwtest::wheelrail_data("contact_a22_geometry.csv"));
    wr::WheelRailGeometry right = b.geometry(wr::Side::right), left = b.geometry(wr::Side::left);
    std::vector<wr::Region> regions;
    std::vector<double> full_cpu, full_wall, search_cpu, elements;
    long n_elements = 0;
    for (int s = 0; s < sweeps; ++s) {
        double cpu = 0.0, wall = 0.0, scpu = 0.0;
        for (const cwtest::Row& r : rows) {
            wr::WheelRailGeometry& g = cwtest::side_of(r) == wr::Side::right ? right : left;
            const wr::WheelsetPosition pos = cwtest::position_of(r);
            const wr::WheelsetVelocity vel = cwtest::velocity_of(r);
            const double c0 = seconds(CLOCK_THREAD_CPUTIME_ID), w0 = seconds(CLOCK_MONOTONIC);
            const wr::WheelRailState& st = g.evaluate(pos, vel);
            cpu += seconds(CLOCK_THREAD_CPUTIME_ID) - c0;
            wall += seconds(CLOCK_MONOTONIC) - w0;
            if (s == 0)
                for (const wr::ContactPatch& p : st.patches) n_elements += static_cast<long>(p.nx) * p.ny;
            // the contact search alone (lateral gap, regions; no grids)
            const wr::Frame wheel = wr::wheelset_in_track(pos, b.wheelset, cwtest::side_of(r))
                                        .compose(wr::wheel_in_wheelset(b.wheelset));
            wr::ContactSearch search = g.search();
            const double d0 = seconds(CLOCK_THREAD_CPUTIME_ID);
            search.find(wheel, regions);
            scpu += seconds(CLOCK_THREAD_CPUTIME_ID) - d0;
        }
        const double n = static_cast<double>(rows.size());
        full_cpu.push_back(cpu / n);
        full_wall.push_back(wall / n);
        search_cpu.push_back(scpu / n);
    }
    std::printf("Wheel/rail geometry, Manchester benchmark A-2.2, %zu wheel positions, dx = ds = 0.2 mm, "
                "%.0f grid elements per wheel on average; median of %d sweeps\n\n",
                rows.size(), static_cast<double>(n_elements) / static_cast<double>(rows.size()), sweeps);
    std::printf("| per wheel | thread CPU [us] | wall [us] |\n|---|---:|---:|\n");
    std::printf("| contact search, patch frames, grids, creepages | %.1f | %.1f |\n", 1e6 * median(full_cpu),
                1e6 * median(full_wall));
    std::printf("| contact search alone | %.1f | |\n\n", 1e6 * median(search_cpu));

    const int force_sweeps = std::max(1, sweeps / 40);
    wr::PatchContactSettings exact; // mu 0.3, G 82 GPa, nu 0.28: the benchmark's; every field
    wr::PatchContactSettings fast = exact;
    fast.model = creepwork::ModelKind::fastsim;
    fast.normal_method = creepwork::NormalMethod::semi_hertz;
    fast.mode = creepwork::SolveMode::forces_only;
    wr::PatchContactSettings fast_full = fast;
    fast_full.mode = creepwork::SolveMode::full;
    std::vector<double> heights(rows.size(), 0.0);
    // The exact model and CONTACT in turns, each the best of its turns: the
    // machine's speed drifts over minutes, so both meet the same spells.
    const bool with_contact = argc > 3;
    double contact = with_contact ? 1e300 : -1.0;
    Timing te{1e300, 1e300, 0.0, 0.0};
    for (int turn = 0; turn < force_sweeps; ++turn) {
        if (with_contact) {
            const double one = contact_seconds(argv[2], argv[3]);
            contact = one < 0.0 || contact < 0.0 ? -1.0 : std::min(contact, one / static_cast<double>(rows.size()));
        }
        const Timing t = whole_positions(b, rows, heights, exact, 1, Start::zero, true);
        if (t.cpu < te.cpu) te = t;
    }
    const auto tf = whole_positions(b, rows, heights, fast, 10 * force_sweeps, Start::zero, false);
    const auto tff = whole_positions(b, rows, heights, fast_full, 10 * force_sweeps, Start::zero, false);
    const auto tfn = whole_positions(b, rows, heights, fast, 10 * force_sweeps, Start::near, false);
    const auto tfh = whole_positions(b, rows, heights, fast, 10 * force_sweeps, Start::given, false);
    std::printf("Whole position, 10 kN per wheel: height, geometry and the contact of every patch; the best of %d "
                "sweeps from a cold start (exact model) taken in turns with as many runs of CONTACT's examples "
                "mbench_a22_right and _left (output files included; the best of them), the median of %d sweeps on "
                "kept handles after one sweep not timed (fast model)\n\n",
                force_sweeps, 10 * force_sweeps);
    std::printf("| per wheel position | CPU [ms] | wall [ms] | evaluations | CONTACT / creepwork |\n"
                "|---|---:|---:|---:|---:|\n");
    const auto row = [&](const char* what, const Timing& t) {
        std::printf("| %s | %.3f | %.3f | %.2f |", what, 1e3 * t.cpu, 1e3 * t.wall, t.evaluations);
        if (contact > 0.0) std::printf(" %.1f |\n", contact / t.cpu);
        else std::printf(" |\n");
    };
    row("creepwork, exact model per patch, every field", te);
    row("creepwork, fast model per patch, forces", tf);
    row("creepwork, fast model per patch, every field", tff);
    row("creepwork, fast model per patch, forces, from 1 um off the height (a time step)", tfn);
    row("creepwork, fast model per patch, forces, height given (one geometry evaluation)", tfh);
    if (contact > 0.0)
        std::printf("| CONTACT module 1 (%s) | %.2f | | | |\n", argv[2], 1e3 * contact);
    else if (with_contact)
        std::printf("| CONTACT module 1 | could not run %s | | | |\n", argv[2]);
    std::printf("\nA hunting wheelset (examples/rail_wear_hunting: right wheel, 60 kN, A = 5 mm, wavelength "
                "15 m, 30 m/s, 0.5 mm elements), the vertical force prescribed, each call from the height of "
                "the last; mean over a cycle, the best of three cycles after one not timed\n\n");
    std::printf("| fast model, forces, calls per cycle | CPU per call [us] | evaluations per call | "
                "largest Fz error [-] |\n|---|---:|---:|---:|\n");
    for (const int calls : {16, 500}) {
        const HuntingCost h = hunting_cycle(b, fast, calls, 3);
        std::printf("| %d | %.1f | %.2f | %.1e |\n", calls, 1e6 * h.cpu, h.evaluations, h.fz_error);
    }
    std::printf("\n");
    char date[32];
    const time_t now = time(nullptr);
    strftime(date, sizeof date, "%Y-%m-%d", gmtime(&now));
    // The machine only: scripts/bench-report.sh stamps the commit of the tree it measures.
    std::printf("Machine: %s; %s %s (%s); %s\n", cpu_model().c_str(), CW_BENCH_COMPILER, CW_BENCH_FLAGS,
                CW_BENCH_BUILD_TYPE, date);
    return 0;
}
