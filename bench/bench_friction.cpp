// Cost of FASTSIM with a friction law of the slip speed, side by side in one
// run with Coulomb's FASTSIM on the same contact: CONTACT's tractcurv
// contact (48 x 44, a = 6.304 mm, b = 12.61 mm, N = 106.7 kN, steel),
// Polach's mu0 = 0.36, A = 0.38, B = 0.7 s/m at V = 10 m/s. Per forces-only
// solve, thread CPU time, best of five runs:
//   coulomb   FastsimModel, mu = 0.36 (the SIMD march)
//   global    CONTACT's FASTSIM with a law: mu at the contact's rigid slip
//             speed and Spiryagin's reduction (friction/global_slip.hpp: the
//             set-up, then FastsimModel)
//   local     FastsimLawModel: the law at every element's slip speed
//   local+J   the same with its Jacobian
// Not a test: no timed assertion anywhere.
//
//   creepwork_bench_friction [--repeats N]
//
// With --instructions GRID XI (GRID tractcurv, the 48 x 44 grid above, or
// ellipse, Kalker's 40 x 40 strips over the same contact; XI the rolling
// creepage) nothing is timed: each kind of solve runs ten times inside a
// function of its own, never inlined, after one solve outside it, so that
// callgrind's inclusive count of the function over ten is the instructions
// of one solve:
//   valgrind --tool=callgrind --callgrind-out-file=cg.out
//       build/bin/creepwork_bench_friction --instructions tractcurv 0.1
//   callgrind_annotate --inclusive=yes cg.out | grep count_solves
// (Counted 0, 1, 2: forces, full, Jacobian; of FastsimModel, Coulomb's, and
// FastsimLawModel, Polach's mu0 = 0.36, A = 0.38, B = 0.7 s/m at 10 m/s).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

#include "contact/contact_grid.hpp"
#include "fastsim/fastsim_law_model.hpp"
#include "fastsim/fastsim_model.hpp"
#include "friction/global_slip.hpp"
#include "tractcurv_contact.hpp"

namespace cw = creepwork;

namespace {

double thread_seconds()
{
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

// Best of five runs of n calls of f, seconds per call.
template <class F>
double per_call(int n, F&& f)
{
    double best = 1e300;
    for (int run = 0; run < 5; ++run) {
        const double t0 = thread_seconds();
        for (int i = 0; i < n; ++i) f();
        best = std::min(best, (thread_seconds() - t0) / n);
    }
    return best;
}

// One kind of solve of one model, ten times (--instructions): each
// instantiation is a function of its own in callgrind's profile.
constexpr int kCounted = 10;
enum class Counted { forces, full, jacobian };

template <Counted kind, class Model>
__attribute__((noinline)) double count_solves(Model& m, const cw::ContactInput& in)
{
    double s = 0.0;
    cw::Jacobian J;
    for (int i = 0; i < kCounted; ++i)
        s += kind == Counted::jacobian
                 ? m.solve_jacobian(in, cw::SolveMode::forces_only, J).Fx
                 : m.solve(in, kind == Counted::full ? cw::SolveMode::full : cw::SolveMode::forces_only).Fx;
    return s;
}

int instructions(const char* grid_name, double xi)
{
    cw::GridSpec g = cwtest::tractcurv_grid();
    if (!std::strcmp(grid_name, "ellipse")) {
        g = cw::GridSpec{};
        g.nx = g.ny = 40;
    } else if (std::strcmp(grid_name, "tractcurv")) {
        std::fprintf(stderr, "--instructions: GRID is tractcurv or ellipse, not %s\n", grid_name);
        return 1;
    }
    cw::FastsimModel coulomb(g);
    cw::FastsimLawModel local(g);
    local.set_law(cw::polach_law(0.36, 0.38, 0.7), 10.0);
    cw::ContactInput in = cwtest::tractcurv_contact(xi);
    in.mu = 0.36;
    cw::Jacobian J;
    // One solve of each kind first: the counted ones allocate nothing.
    coulomb.solve_jacobian(in, cw::SolveMode::full, J);
    local.solve_jacobian(in, cw::SolveMode::full, J);
    const cw::SolveTotals t = local.solve(in, cw::SolveMode::full);
    double sink = count_solves<Counted::forces>(coulomb, in) + count_solves<Counted::full>(coulomb, in) +
                  count_solves<Counted::jacobian>(coulomb, in);
    sink += count_solves<Counted::forces>(local, in) + count_solves<Counted::full>(local, in) +
            count_solves<Counted::jacobian>(local, in);
    std::printf("%s xi_x %.4f: %d slipping elements, %.3f law evaluations each (%g)\n", grid_name,
                xi, t.n_slip, t.n_slip ? double(local.friction_iterations()) / t.n_slip : 0.0,
                sink);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    for (int i = 1; i + 2 < argc; ++i)
        if (!std::strcmp(argv[i], "--instructions")) return instructions(argv[i + 1], std::atof(argv[i + 2]));
    int n = 200;
    for (int i = 1; i + 1 < argc; ++i)
        if (!std::strcmp(argv[i], "--repeats")) n = std::atoi(argv[i + 1]);
    const cw::GridSpec g = cwtest::tractcurv_grid();
    const cw::ContactGrid grid(g);
    cw::FastsimModel coulomb(g);
    cw::FastsimLawModel local(g);
    const cw::SlipSpeedLaw law = cw::polach_law(0.36, 0.38, 0.7);
    local.set_law(law, 10.0);
    const cw::SlopeReduction spiryagin{0.54, 0.02, 0.62};

    std::printf("FASTSIM with a law of the slip speed, 48 x 44 (1376 contact elements), per "
                "forces-only solve [us]\n\n");
    std::printf("| xi_x | slip el. | coulomb | global | local | local+J | local/coulomb | "
                "law evaluations per slip el. |\n|---|---|---|---|---|---|---|---|\n");
    for (double xi : {0.001, 0.004, 0.02, 0.1}) {
        cw::ContactInput in = cwtest::tractcurv_contact(xi);
        in.mu = 0.36;
        volatile double sink = 0.0;
        const double tc = per_call(n, [&] { sink = sink + coulomb.solve(in, cw::SolveMode::forces_only).Fx; });
        const double tg = per_call(n, [&] {
            const cw::ContactInput gi = cw::global_slip_input(in, grid, law, spiryagin, 10.0);
            sink = sink + coulomb.solve(gi, cw::SolveMode::forces_only).Fx;
        });
        const double tl = per_call(n, [&] { sink = sink + local.solve(in, cw::SolveMode::forces_only).Fx; });
        cw::Jacobian J;
        const double tj = per_call(n, [&] {
            sink = sink + local.solve_jacobian(in, cw::SolveMode::forces_only, J).Fx;
        });
        const cw::SolveTotals t = local.solve(in, cw::SolveMode::forces_only);
        std::printf("| %.3f | %d | %.1f | %.1f | %.1f | %.1f | %.1f | %.2f |\n", xi, t.n_slip,
                    1e6 * tc, 1e6 * tg, 1e6 * tl, 1e6 * tj, tl / tc,
                    t.n_slip ? double(local.friction_iterations()) / t.n_slip : 0.0);
    }
    return 0;
}
