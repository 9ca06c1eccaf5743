// creepwork_bench_wheelrail: the cost of the wheel/rail geometry per wheel
// (contact search, patch frames, undeformed distance grids, creepages) over
// the Manchester benchmark's 42 wheel positions at CONTACT's discretisation
// (dx = ds = 0.2 mm), and of the contact search alone. Not a test: it prints
// a table with a stamp. Times are per-thread CPU time (CLOCK_THREAD_CPUTIME_ID,
// not counting time the thread is descheduled) and wall time, medians of
// repeated sweeps.
//
//   creepwork_bench_wheelrail [SWEEPS]   (default 200)
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "mbench_support.hpp"
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

} // namespace

int main(int argc, char** argv)
{
    const int sweeps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 200;
    const cwtest::Benchmark b;
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
    char date[32];
    const time_t now = time(nullptr);
    strftime(date, sizeof date, "%Y-%m-%d", gmtime(&now));
    std::printf("Stamp: %s; %s %s (%s); commit %s (at configure time); %s; measured under load on a "
                "shared machine\n",
                cpu_model().c_str(), CW_BENCH_COMPILER, CW_BENCH_FLAGS, CW_BENCH_BUILD_TYPE, CW_BENCH_COMMIT, date);
    return 0;
}
