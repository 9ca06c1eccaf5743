// creepwork_bench_transient: the cost of one transient rolling step
// (core/transient) on CONTACT's example catt_to_cart: a sphere on a 34 x 33
// gap grid, a Cattaneo shift to Fx = -0.657 mu N, then 56 steps of dq = dx
// with Fx prescribed (the creepage found per step), by the exact model and
// by FASTSIM's transient form (transient_fastsim.hpp). Given CONTACT's program
// and its examples folder, the same run times CONTACT on the first 57 cases
// of its own input (the same problem, T = 2) as a child process. Not a
// test: it prints a table. Times are per-thread CPU time
// (CLOCK_THREAD_CPUTIME_ID) and wall time, medians of repeated sweeps;
// CONTACT's is its CPU time (getrusage of the child) over its 57 cases.
//
//   creepwork_bench_transient [SWEEPS [CONTACT EXAMPLES_DIR]]   (default 20)
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "transient/transient_contact.hpp"
#include "transient/transient_fastsim.hpp"
#include "transient_cases.hpp"

namespace {

double seconds(clockid_t clock)
{
    timespec t{};
    clock_gettime(clock, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// CPU time of CONTACT on the first `cases` cases of examples/catt_to_cart.inp
// (the input cut after them) in a scratch folder; -1 when it cannot run.
double contact_seconds(const std::string& program, const std::string& examples, int cases)
{
    std::ifstream in(examples + "/catt_to_cart.inp");
    if (!in) return -1.0;
    const std::string dir = "creepwork_bench_transient_contact";
    if (std::system(("rm -rf " + dir + " && mkdir " + dir).c_str()) != 0) return -1.0;
    std::ofstream out(dir + "/catt_to_cart.inp");
    std::string line;
    int seen = 0;
    while (std::getline(in, line)) {
        if (line.rfind(" 3  MODULE", 0) == 0 && ++seen > cases) break; // a case begins
        out << line << "\n";
    }
    out << " 0  MODULE\n";
    out.close();
    rusage before{}, after{};
    getrusage(RUSAGE_CHILDREN, &before);
    const std::string cmd = "cd " + dir + " && " + program + " 2 catt_to_cart > /dev/null 2>&1";
    if (std::system(cmd.c_str()) != 0) return -1.0;
    getrusage(RUSAGE_CHILDREN, &after);
    auto sec = [](const timeval& t) {
        return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
    };
    return sec(after.ru_utime) - sec(before.ru_utime) + sec(after.ru_stime) -
           sec(before.ru_stime);
}

struct Timing {
    std::vector<double> cpu, wall, shift_cpu; // per rolling step, per shift [s]
    long products = 0, newton = 0, force = 0; // of the first sweep's rolling steps
};

// sweeps x (the shift, then `steps` rolling steps of dx) on a transient
// model (TransientContact or TransientFastsim).
template <class Model>
Timing time_model(Model& m, creepwork::TransientStepInput s, double dx, int sweeps, int steps)
{
    Timing t;
    for (int k = 0; k < sweeps; ++k) {
        m.start_zero();
        s.dq = 0.0;
        double c0 = seconds(CLOCK_THREAD_CPUTIME_ID);
        m.step(s);
        m.commit();
        t.shift_cpu.push_back(seconds(CLOCK_THREAD_CPUTIME_ID) - c0);
        s.dq = dx;
        c0 = seconds(CLOCK_THREAD_CPUTIME_ID);
        const double w0 = seconds(CLOCK_MONOTONIC);
        for (int i = 0; i < steps; ++i) {
            const creepwork::TransientStepResult& r = m.step(s);
            m.commit();
            if (k == 0) {
                t.products += r.products;
                t.newton += r.newton_steps;
                t.force += r.force_iterations;
            }
        }
        t.cpu.push_back((seconds(CLOCK_THREAD_CPUTIME_ID) - c0) / steps);
        t.wall.push_back((seconds(CLOCK_MONOTONIC) - w0) / steps);
    }
    return t;
}

} // namespace

int main(int argc, char** argv)
{
    const int sweeps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 20;
    cwtest::TransientCase c = cwtest::catt_to_cart();
    creepwork::TransientContact tc(c.grid, c.input);
    creepwork::TransientStepInput s;
    s.prescribe_fx = true;
    s.Fx = -0.657 * c.input.mu * c.input.normal_force;
    const int steps = 56;
    const Timing e = time_model(tc, s, c.grid.dx, sweeps, steps);
    cwtest::TransientCase cf = c;
    cf.input.model = creepwork::ModelKind::fastsim;
    creepwork::TransientFastsim tf(cf.grid, cf.input);
    Timing f = time_model(tf, s, c.grid.dx, sweeps, steps);
    std::printf("Transient rolling, catt_to_cart (34 x 33, Fx prescribed), median of %d sweeps\n\n",
                sweeps);
    std::printf("| | CPU [ms] | wall [ms] |\n|---|---|---|\n");
    std::printf("| creepwork, one rolling step | %.2f | %.2f |\n", 1e3 * median(e.cpu),
                1e3 * median(e.wall));
    std::printf("| creepwork, the shift | %.2f | |\n", 1e3 * median(e.shift_cpu));
    std::printf("| creepwork FASTSIM, one rolling step | %.4f | %.4f |\n", 1e3 * median(f.cpu),
                1e3 * median(f.wall));
    std::printf("| creepwork FASTSIM, the shift | %.4f | |\n", 1e3 * median(f.shift_cpu));
    std::printf("\nper rolling step: %.1f FFT products, %.1f Newton steps, %.2f force iterations; "
                "FASTSIM %.2f passes\n",
                double(e.products) / steps, double(e.newton) / steps, double(e.force) / steps,
                double(f.newton) / steps);
    if (argc > 3) {
        const double t = contact_seconds(argv[2], argv[3], 57);
        if (t < 0.0)
            std::printf("\nCONTACT: could not run %s on %s/catt_to_cart.inp\n", argv[2], argv[3]);
        else
            std::printf("\n| CONTACT, 57 cases (shift + 56 steps), per case | %.2f | |\n",
                        1e3 * t / 57.0);
    }
    return 0;
}
