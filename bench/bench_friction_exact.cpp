// creepwork_bench_friction_exact: the exact model with a friction law of the
// slip speed on CONTACT's tractcurv contact (48 x 44, a = 6.304 mm,
// b = 12.61 mm, N = 106.7 kN, steel, V = 10 m/s), the exponential law
// FKIN 0.14, FEXP1 0.19, SABSH1 1.25 m/s, over the 36 creepages of
// tests/data/contact_tractcurv_exponential.csv; beside it the same model
// with Coulomb's 0.33 and, given CONTACT's program, CONTACT on the same 36
// cases (tests/data/tractcurv_exponential.inp at its EPS set to 1e-6, as
// CONTACT's tractcurv example runs) as a child process. Not a test: it
// prints a table. creepwork's times are per-thread CPU time
// (CLOCK_THREAD_CPUTIME_ID) per solve, the median of the sweeps over the 36
// cases, forces only, tolerance 1e-8: cold (every solve from the coarse
// grids) and warm (each from the last); CONTACT's is its CPU time
// (getrusage of the child) over its 36 cases.
//
//   creepwork_bench_friction_exact [SWEEPS [CONTACT_PROGRAM]]   (default 5)
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "core_test_support.hpp"
#include "exact/exact_model.hpp"
#include "tractcurv_exact.hpp"

namespace cw = creepwork;

namespace {

double thread_seconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// CPU time of CONTACT on the input with its EPS 1e-10 set to eps, in a
// scratch folder; -1 when it cannot run.
double contact_seconds(const std::string& program, const std::string& input, const char* eps)
{
    std::ifstream in(input);
    if (!in) return -1.0;
    const std::string dir = "creepwork_bench_friction_exact_contact";
    if (std::system(("rm -rf " + dir + " && mkdir " + dir).c_str()) != 0) return -1.0;
    std::ofstream out(dir + "/tractcurv_exponential.inp");
    std::string line;
    while (std::getline(in, line)) {
        const auto at = line.find("1e-10");
        if (at != std::string::npos && line.find("EPS") != std::string::npos)
            line.replace(at, 5, eps);
        out << line << "\n";
    }
    out.close();
    rusage before{}, after{};
    getrusage(RUSAGE_CHILDREN, &before);
    const std::string cmd =
        "cd " + dir + " && " + program + " 2 tractcurv_exponential > /dev/null 2>&1";
    const int status = std::system(cmd.c_str()); // (CONTACT ends on the input's end: not 0)
    (void)status;
    getrusage(RUSAGE_CHILDREN, &after);
    auto sec = [](const timeval& t) {
        return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
    };
    std::ifstream printed(dir + "/tractcurv_exponential.out");
    if (!printed) return -1.0;
    return sec(after.ru_utime) - sec(before.ru_utime) + sec(after.ru_stime) - sec(before.ru_stime);
}

struct Sweep {
    double cpu = 0;    // per solve [s]
    long newton = 0, products = 0;
    double local_steps = 0; // per slipping element, final sweep, summed over the cases
};

Sweep sweep(cw::ExactModel& m, const std::vector<cw::ContactInput>& cases, bool warm)
{
    Sweep s;
    volatile double sink = 0.0;
    const double t0 = thread_seconds();
    for (cw::ContactInput in : cases) {
        in.warm_start = warm;
        const cw::SolveTotals t = m.solve(in, cw::SolveMode::forces_only);
        sink = sink + t.Fx;
        s.newton += m.info().newton_steps;
        s.products += m.info().products;
        s.local_steps += m.info().friction_steps_per_element;
    }
    s.cpu = (thread_seconds() - t0) / static_cast<double>(cases.size());
    return s;
}

} // namespace

int main(int argc, char** argv)
{
    const int sweeps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    const cwtest::CsvTable t = cwtest::read_csv(cwtest::test_data_path("contact_tractcurv_exponential.csv"));
    std::vector<cw::ContactInput> cases;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        cases.push_back(cwtest::tractcurv_exact(t.number(r, "CKSI"), t.number(r, "CETA"),
                                                1e3 * t.number(r, "CPHI_per_mm")));
    }
    const cw::SlipSpeedLaw law = cwtest::tractcurv_exponential_law();
    cw::ExactModel coulomb(cwtest::tractcurv_grid()), falling(cwtest::tractcurv_grid());
    falling.set_law(law, cwtest::kTractcurvV);

    std::printf("The exact model with the exponential law, tractcurv 48 x 44, %zu cases, median of "
                "%d sweeps\n\n",
                cases.size(), sweeps);
    std::printf("| per solve | CPU [ms] | Newton steps | FFT products | local Newton steps of a "
                "slipping element |\n|---|---:|---:|---:|---:|\n");
    for (bool warm : {false, true}) {
        for (int which = 0; which < 2; ++which) {
            cw::ExactModel& m = which ? falling : coulomb;
            std::vector<double> cpu;
            Sweep first;
            for (int k = 0; k < sweeps; ++k) {
                const Sweep s = sweep(m, cases, warm);
                if (k == 0) first = s;
                cpu.push_back(s.cpu);
            }
            const double n = static_cast<double>(cases.size());
            char local[32] = "";
            if (which) std::snprintf(local, sizeof local, "%.2f", first.local_steps / n);
            std::printf("| %s, %s | %.2f | %.1f | %.1f | %s |\n",
                        which ? "exponential law" : "Coulomb", warm ? "warm" : "cold",
                        1e3 * median(cpu), first.newton / n, first.products / n, local);
        }
    }
    if (argc > 2) {
        const double c = contact_seconds(argv[2], cwtest::test_data_path("tractcurv_exponential.inp"), "1e-6");
        if (c < 0.0)
            std::printf("\nCONTACT: could not run %s\n", argv[2]);
        else
            std::printf("\n| CONTACT, exponential law, EPS 1e-6, per case | %.2f | | | |\n",
                        1e3 * c / static_cast<double>(cases.size()));
    }
    return 0;
}
