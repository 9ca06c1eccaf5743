// Cost of the flash temperature and the damage indices beside the solve
// they post-process (doc/theory/temperature.md): per contact, FASTSIM's full
// solve, the fields the post-processors read, the heat and both bodies'
// temperatures (consistent discretisation), the damage indices. The
// partial-slip contact of creepwork_bench, Kalker strip grid n x n, best of
// 21 samples. Second table: one row of the moving-source kernel, direct sum,
// recursion and FFT, for the break-even (MovingSourceKernel::kDirectMaxLength).
// Not a test: prints tables (`build/bin/creepwork_bench_temperature`).
#include <chrono>
#include <cstdio>
#include <vector>

#include "damage/damage_indices.hpp"
#include "solver.hpp"
#include "thermal/flash_temperature.hpp"
#include "thermal/heat_source.hpp"
#include "thermal/moving_source.hpp"

namespace cw = creepwork;
namespace th = creepwork::thermal;
namespace dm = creepwork::damage;

namespace {

double now()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// Best time per call [s] of body() over samples x reps calls.
template <class Body>
double best_of(int samples, int reps, Body&& body)
{
    double best = 1e9;
    for (int s = 0; s < samples; ++s) {
        const double t0 = now();
        for (int r = 0; r < reps; ++r) body();
        best = std::min(best, (now() - t0) / reps);
    }
    return best;
}

void contact_table()
{
    std::printf("FASTSIM, Kalker strip grid, core, one core; us per contact (best of 21 samples)\n\n");
    std::printf("| grid | solve (full) us | fields us | temperature us | damage us | "
                "(fields + temperature + damage) / solve |\n"
                "|---|---:|---:|---:|---:|---:|\n");
    for (int n : {10, 20, 40, 100}) {
        cw::GridSpec g;
        g.nx = g.ny = n;
        cw::Solver s(g);
        cw::ContactInput in;
        in.a = 7.17e-3;
        in.b = 5.42e-3;
        in.normal_force = 100e3;
        in.mu = 0.3;
        in.G = 82e9;
        in.nu = 0.28;
        in.xi_x = 6e-4;
        in.xi_y = 3e-4;
        in.phi = 0.2;
        const size_t N = static_cast<size_t>(n) * n;
        std::vector<double> x(N), y(N), area(N), pz(N), px(N), py(N), work(N), q(N), T1(N),
            T2(N), rcf(N), tg(N), strip_y(n), strip_w(n), row_dx(n);
        std::vector<int> state(N);
        th::FlashTemperature flash(n, n);
        th::ThermalParams tp;
        tp.rolling_speed = 30.0;
        dm::DamageParams dp;
        dp.k_yield = 300e6;
        const int reps = n <= 40 ? 400 : 40;
        const double solve = best_of(21, reps, [&] { s.solve(in, cw::SolveMode::full); });
        auto gather = [&] {
            using F = cw::Field;
            s.copy_field(F::x, x.data());
            s.copy_field(F::y, y.data());
            s.copy_field(F::area, area.data());
            s.copy_field(F::pz, pz.data());
            s.copy_field(F::px, px.data());
            s.copy_field(F::py, py.data());
            s.copy_field(F::work_consistent, work.data());
            s.copy_state(state.data());
            s.copy_strips(strip_y.data(), strip_w.data());
            for (int j = 0; j < n; ++j) row_dx[j] = area[n / 2 + j * n] / strip_w[j];
        };
        const double fields = best_of(21, reps, gather);
        th::HeatedContact hc{n, n, x.data(), y.data(), row_dx.data(), state.data(), q.data(), 1};
        const double temperature = best_of(21, reps, [&] {
            th::heat_from_work(static_cast<long>(N), work.data(), area.data(), 30.0, q.data());
            flash.compute(hc, tp, T1.data(), T2.data());
        });
        const cw::SolveTotals& t = s.totals();
        dm::DamageInput di;
        di.nx = di.ny = n;
        di.area = area.data();
        di.pz = pz.data();
        di.px = px.data();
        di.py = py.data();
        di.state = state.data();
        di.work = work.data();
        di.Fx = t.Fx;
        di.Fy = t.Fy;
        di.normal_force = t.normal_force;
        di.W_macro = t.W_macro;
        di.contact_area = 3.14159 * t.a * t.b;
        const double damage =
            best_of(21, reps, [&] { dm::damage_indices(di, dp, {rcf.data(), tg.data()}); });
        std::printf("| %d x %d | %.2f | %.2f | %.2f | %.2f | %.0f %% |\n", n, n, 1e6 * solve,
                    1e6 * fields, 1e6 * temperature, 1e6 * damage,
                    100 * (fields + temperature + damage) / solve);
    }
}

void kernel_table()
{
    using Method = th::MovingSourceKernel::Method;
    std::printf("\nThe moving-source kernel on one row, two rows per call; ns per element (best of 11 "
                "samples)\n\n");
    std::printf("| row length | direct ns/element | recursive ns/element (exponentials) | "
                "FFT ns/element | automatic |\n|---:|---:|---:|---:|---|\n");
    for (int n : {16, 32, 48, 64, 80, 96, 128, 256, 512, 1000}) {
        th::MovingSourceKernel direct(n, Method::direct), recursive(n, Method::recursive),
            fft(n, Method::fft), chosen(n);
        std::vector<double> qa(n), qb(n), oa(n), ob(n);
        for (int t = 0; t < n; ++t) qa[t] = qb[t] = 1.0 + 0.001 * t;
        const int reps = 200000 / n + 1;
        auto time = [&](th::MovingSourceKernel& k) {
            return 1e9 *
                   best_of(11, reps, [&] { k.apply(qa.data(), qb.data(), oa.data(), ob.data(), 0.7); }) /
                   (2 * n);
        };
        const double td = time(direct), tr = time(recursive), tf = time(fft);
        std::printf("| %d | %.2f | %.2f (%d) | %.2f | %s |\n", n, td, tr, recursive.exponentials(),
                    tf, chosen.method() == Method::direct ? "direct" : "recursive");
    }
}

} // namespace

int main()
{
    contact_table();
    kernel_table();
    return 0;
}
