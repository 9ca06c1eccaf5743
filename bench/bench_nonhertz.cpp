// Cost of contacts of any shape: the exact model on a gap grid (cold and
// warm), the semi-Hertzian normal method, and -- when built with
// CREEPWORK_CONTACT_DIR -- CONTACT's full solve of the same gap in the same
// run (module 3, exact normal and tangential problems, cntc_calculate
// repeated: CONTACT recomputes everything on every call). Not a test: no
// timed assertion anywhere (doc/performance.md has the table).
//
//   creepwork_bench_nonhertz [--contact-eps E] [--quick] [--fast] [--cold-only K]
//                            [--rounds R] [--cases ID,ID...]
//
// Shapes from gap_shapes.hpp with the creepages of data/contact_cases.csv.
// Each shape is timed in R rounds (default 5, --quick 1): a round runs
// CONTACT's solve, two cold solves and the two warm runs one after the
// other, and every column is the best of its rounds, so that CONTACT and
// creepwork meet the same spells of a machine whose speed drifts.
//  cold       create a solver and solve once (CW_SOLVE_FULL)
//  warm       one solver, warm-started, creepages drifting by at most 1 % a
//             step (xi_x, xi_y, phi each x (1 + 0.1 sin(2 pi k/100 + offset)))
//             with the gap fixed (the normal solution is kept), and with the
//             gap drifting too (h x (1 + 0.01 sin(2 pi k/100)): the normal
//             problem re-solved from the last pressures); FFT products per
//             step of each, and of the normal problem with the gap drifting
//  semi-Hertz the fast normal method alone, N prescribed (per call)
// and a second table, FASTSIM on the gap grid with the semi-Hertzian normal
// method (the fast model, gap_fastsim_model.hpp): per solve on one solver,
// forces only (CW_SOLVE_FORCES) and full (CW_SOLVE_FULL: the work maps),
// best of three runs, beside the semi-Hertzian method alone in the same run
// (the difference is the labelling, the patches' flexibilities, the march
// and the totals). --fast prints only that table. --cold-only K runs K cold
// solves of each shape and prints their totals only (for a profiler such as
// callgrind: nothing else runs).
// Thread CPU time of the calling thread (CONTACT runs on it, one thread).
// Run CONTACT with GLIBC_TUNABLES=glibc.malloc.trim_threshold=536870912:
// glibc.malloc.mmap_threshold=33554432:glibc.malloc.top_pad=67108864 (it
// frees and reallocates its work arrays on every call).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "gap_shape_grid.hpp"
#include "gap_shapes.hpp"
#include "normal/semi_hertz.hpp"
#include "solver.hpp"

#ifdef CW_BENCH_CONTACT
#include "contact_gap_shape.hpp"
#endif

namespace cw = creepwork;

namespace {

double thread_seconds()
{
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

struct Inputs {
    double xi_x = 0, xi_y = 0, phi = 0;
};

// The creepages of data/contact_cases.csv (the table the tests use).
Inputs creepages_of(const std::string& id)
{
    Inputs in;
    FILE* f = std::fopen(CW_NONHERTZ_DATA_DIR "/contact_cases.csv", "r");
    if (!f) return in;
    char line[4096];
    std::vector<std::string> header;
    while (std::fgets(line, sizeof line, f)) {
        std::vector<std::string> cells(1);
        bool quoted = false;
        for (char* c = line; *c && *c != '\n'; ++c) {
            if (*c == '"')
                quoted = !quoted;
            else if (*c == ',' && !quoted)
                cells.emplace_back();
            else
                cells.back() += *c;
        }
        if (header.empty()) {
            header = cells;
            continue;
        }
        if (cells[0] != id) continue;
        for (size_t k = 0; k < header.size() && k < cells.size(); ++k) {
            if (header[k] == "xi_x") in.xi_x = std::atof(cells[k].c_str());
            if (header[k] == "xi_y") in.xi_y = std::atof(cells[k].c_str());
            if (header[k] == "phi_per_m") in.phi = std::atof(cells[k].c_str());
        }
    }
    std::fclose(f);
    return in;
}

// The shape named id, or nullptr (with a message).
const gapshapes::Shape* find_shape(const std::vector<gapshapes::Shape>& shapes,
                                   const std::string& id)
{
    for (const auto& s : shapes)
        if (s.id == id) return &s;
    std::fprintf(stderr, "no shape %s\n", id.c_str());
    return nullptr;
}

// The benchmark's creepages of a shape (H20_hertz: the elliptic benchmark's).
Inputs bench_creepages(const std::string& id)
{
    return id == "H20_hertz" ? Inputs{6e-4, 3e-4, 0.2} : creepages_of(id);
}

// The exact model's cold input on a shape with its benchmark creepages.
cw::ContactInput exact_input(const gapshapes::Shape& s)
{
    const Inputs c = bench_creepages(s.id);
    cw::ContactInput in = gapshapes::contact_input(s);
    in.model = cw::ModelKind::exact;
    in.xi_x = c.xi_x;
    in.xi_y = c.xi_y;
    in.phi = c.phi;
    in.warm_start = false;
    return in;
}

std::string sig3(double v)
{
    char b[32];
    std::snprintf(b, sizeof b, v >= 100 ? "%.0f" : v >= 10 ? "%.1f" : v >= 1 ? "%.2f" : "%.3f", v);
    return b;
}

int fast_table(const std::vector<std::string>& ids, const std::vector<gapshapes::Shape>& shapes,
               bool quick)
{
    std::printf("FASTSIM on the gap grid with the semi-Hertzian normal method, per solve on one "
                "solver (best of three runs), one core, thread CPU time.\n\n"
                "| shape | cells | contact elements | patches | semi-Hertz normal us | FASTSIM "
                "forces us | FASTSIM full us |\n|---|---:|---:|---:|---:|---:|---:|\n");
    for (const std::string& id : ids) {
        const gapshapes::Shape* sp = find_shape(shapes, id);
        if (!sp) return 2;
        const gapshapes::Shape& s = *sp;
        const Inputs c = bench_creepages(id);
        cw::ContactInput in = gapshapes::contact_input(s);
        in.model = cw::ModelKind::fastsim;
        in.normal_method = cw::NormalMethod::semi_hertz;
        in.xi_x = c.xi_x;
        in.xi_y = c.xi_y;
        in.phi = c.phi;
        const int reps = quick ? 200 : 2000;
        cw::SemiHertz sh(s.nx, s.ny);
        std::vector<double> p(s.h.size());
        cw::Solver solver(gapshapes::grid_of(s));
        cw::SolveTotals t = solver.solve(in, cw::SolveMode::full);
        double normal = 1e300, forces = 1e300, full = 1e300;
        for (int run = 0; run < 3; ++run) {
            double t0 = thread_seconds();
            for (int k = 0; k < reps; ++k)
                sh.solve(s.h.data(), s.dx, s.dy, s.G / (1.0 - s.nu), !s.approach_given,
                         s.approach_given ? s.approach : s.normal_force, p.data());
            normal = std::min(normal, (thread_seconds() - t0) / reps);
            t0 = thread_seconds();
            for (int k = 0; k < reps; ++k) t = solver.solve(in, cw::SolveMode::forces_only);
            forces = std::min(forces, (thread_seconds() - t0) / reps);
            t0 = thread_seconds();
            for (int k = 0; k < reps; ++k) t = solver.solve(in, cw::SolveMode::full);
            full = std::min(full, (thread_seconds() - t0) / reps);
        }
        std::printf("| %s | %d x %d | %d | %d | %s | %s | %s |\n", id.c_str(), s.nx, s.ny,
                    t.n_contact, t.n_patches, sig3(normal * 1e6).c_str(),
                    sig3(forces * 1e6).c_str(), sig3(full * 1e6).c_str());
        std::fflush(stdout);
    }
    return 0;
}

// K cold solves (create + solve, CW_SOLVE_FULL) of each shape, their totals
// printed to all digits: nothing else runs (a profiler's view of the cold path).
int cold_table(const std::vector<std::string>& ids, const std::vector<gapshapes::Shape>& shapes,
               int k_solves)
{
    for (const std::string& id : ids) {
        const gapshapes::Shape* sp = find_shape(shapes, id);
        if (!sp) return 2;
        cw::ContactInput in = exact_input(*sp);
        cw::SolveTotals t;
        cw::GapExactSolveInfo info;
        for (int k = 0; k < k_solves; ++k) {
            cw::Solver solver(gapshapes::grid_of(*sp));
            t = solver.solve(in, cw::SolveMode::full);
            info = solver.gap_model()->info();
        }
        std::printf("%s: Fx %.17g Fy %.17g Mz %.17g, %d contact, %d adhesion; %d grids, %d Newton "
                    "steps, %d FFT products, %d normal CG iterations\n",
                    id.c_str(), t.Fx, t.Fy, t.Mz, t.n_contact, t.n_adhesion, info.levels_used,
                    info.newton_steps, info.products, info.normal_iterations);
    }
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    double contact_eps = 1e-8;
    bool quick = false, fast_only = false;
    int cold_only = 0, rounds = 0;
    std::vector<std::string> ids = {"N07_wide", "N04_crescent", "N01_hollow", "N03_three_lobes",
                                    "N06_flange_root", "H20_hertz"};
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        if (a == "--contact-eps" && k + 1 < argc)
            contact_eps = std::atof(argv[++k]);
        else if (a == "--quick")
            quick = true;
        else if (a == "--fast")
            fast_only = true;
        else if (a == "--rounds" && k + 1 < argc)
            rounds = std::max(std::atoi(argv[++k]), 1);
        else if (a == "--cold-only" && k + 1 < argc)
            cold_only = std::max(std::atoi(argv[++k]), 1);
        else if (a == "--cases" && k + 1 < argc) {
            ids.clear();
            std::string list = argv[++k];
            for (size_t p = 0; p <= list.size();) {
                const size_t q = std::min(list.find(',', p), list.size());
                ids.push_back(list.substr(p, q - p));
                p = q + 1;
            }
        } else {
            std::fprintf(stderr,
                         "usage: %s [--contact-eps E] [--quick] [--fast] [--cold-only K] "
                         "[--rounds R] [--cases ID,...]\n",
                         argv[0]);
            return 2;
        }
    }
    std::vector<gapshapes::Shape> shapes = gapshapes::shapes();
    {
        // For scale: the elliptic exact model's benchmark contact (a = 7.17 mm,
        // b = 5.42 mm, N = 100 kN, 20 elements across, 24 x 24 cells) as its
        // Hertzian gap A x^2 + B y^2 (Hertz's A, B of those semi-axes).
        const double a = 7.17e-3, b = 5.42e-3, E = 82e9 / (1.0 - 0.28);
        const double p0 = 3.0 * 100e3 / (2.0 * gapshapes::kPi * a * b);
        const double k = std::sqrt(1.0 - (b / a) * (b / a));
        // Johnson eqs. 4.38-4.39 through the complete elliptic integrals.
        double K = 0, Ek = 0;
        {
            double an = 1.0, bn = std::sqrt(1.0 - k * k), sum = 0.5 * k * k, w = 0.5;
            for (int it = 0; it < 40; ++it) {
                const double c = 0.5 * (an - bn);
                w *= 2.0;
                sum += w * c * c;
                const double next = 0.5 * (an + bn);
                bn = std::sqrt(an * bn);
                an = next;
            }
            K = gapshapes::kPi / (2.0 * an);
            Ek = K * (1.0 - sum);
        }
        const double cA = p0 * b / (E * k * k * a * a);
        const double A = cA * (K - Ek), B = cA * ((a / b) * (a / b) * Ek - K);
        gapshapes::Shape h = gapshapes::make(
            "H20_hertz", "Hertzian gap of the elliptic benchmark contact", 24, 24,
            2.0 * 1.2 * a / 24, 2.0 * 1.2 * b / 24, 0, 0,
            [A, B](double x, double y) { return A * x * x + B * y * y; });
        h.normal_force = 100e3;
        shapes.push_back(h);
    }
    if (rounds == 0) rounds = quick ? 1 : 5;
    if (fast_only) return fast_table(ids, shapes, quick);
    if (cold_only) return cold_table(ids, shapes, cold_only);
#ifndef CW_BENCH_CONTACT
    (void)contact_eps; // read only when CONTACT runs side by side
#endif

    std::printf("Contacts of any shape: the exact model on the gap grid (tolerance 1e-8, "
                "CW_SOLVE_FULL), one core, thread CPU time; each column the best of %d rounds "
                "run one after the other (in each: ", rounds);
#ifdef CW_BENCH_CONTACT
    std::printf("CONTACT's solve, ");
#endif
    std::printf("2 cold solves, %d warm steps with the gap fixed, %d drifting).", quick ? 20 : 100,
                quick ? 20 : 100);
#ifdef CW_BENCH_CONTACT
    std::printf(" CONTACT (d431cdb, this build: no MKL, so no FFT) module 3, exact normal and "
                "tangential problems, EPS %g, the same gap, cntc_calculate once per round%s.",
                contact_eps,
                std::getenv("GLIBC_TUNABLES") ? "" : " (GLIBC_TUNABLES not set: page faults count)");
    if (contact_gap_init() != 0) return 1;
#endif
    std::printf("\n\n| shape | cells | contact elements | patches | cold ms | warm ms (gap fixed) | "
                "warm ms (gap drifting) | warm FFT products/step (fixed, drifting) | "
                "normal FFT products/step (gap drifting) | semi-Hertz normal us |");
#ifdef CW_BENCH_CONTACT
    std::printf(" CONTACT ms | CONTACT / cold | CONTACT / warm (gap fixed) | CONTACT / warm (gap "
                "drifting) |");
#endif
    std::printf("\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
#ifdef CW_BENCH_CONTACT
    std::printf("---:|---:|---:|---:|");
#endif
    std::printf("\n");
    for (const std::string& id : ids) {
        const gapshapes::Shape* sp = find_shape(shapes, id);
        if (!sp) return 2;
        const gapshapes::Shape& s = *sp;
        const Inputs c = bench_creepages(id);
        const cw::ContactInput in = exact_input(s);
        const cw::GridSpec g = gapshapes::grid_of(s);

#ifdef CW_BENCH_CONTACT
        contact_gap_case cc = contact_case_of(s, contact_eps);
        cc.xi_x = c.xi_x; // the benchmark's creepages (H20_hertz: the elliptic bench's)
        cc.xi_y = c.xi_y;
        cc.phi = c.phi;
        contact_gap_setup(&cc);
        contact_gap_result r{};
        double contact = 1e300;
#endif
        // Rounds: in each, CONTACT's solve, two cold solves, a warm run with
        // the gap fixed and one with it drifting, one after the other; each
        // column the best of its rounds. The machine's speed drifts over
        // minutes, so both programs meet the same spells.
        double cold = 1e300, warm_fixed = 1e300, warm_moving = 1e300;
        cw::SolveTotals t;
        const int steps = quick ? 20 : 100;
        double products[2] = {0, 0}; // FFT products per warm step: gap fixed, drifting
        double normal_products = 0;  // the normal problem's, gap drifting
        std::vector<double> h = s.h;
        for (int round = 0; round < rounds; ++round) {
#ifdef CW_BENCH_CONTACT
            contact_gap_solve(&cc, 1, &r);
            contact = std::min(contact, r.seconds);
#endif
            // Cold: create + solve.
            for (int k = 0; k < 2; ++k) {
                const double t0 = thread_seconds();
                cw::Solver solver(g);
                t = solver.solve(in, cw::SolveMode::full);
                cold = std::min(cold, thread_seconds() - t0);
            }
            // Warm: the gap fixed, then drifting.
            for (int moving = 0; moving < 2; ++moving) {
                cw::Solver solver(g);
                cw::ContactInput w = in;
                w.warm_start = true;
                w.gap = h.data();
                h = s.h;
                solver.solve(w, cw::SolveMode::full);
                long count = 0, normal_count = 0;
                const double t0 = thread_seconds();
                for (int k = 1; k <= steps; ++k) {
                    const double a = 2.0 * 3.14159265358979323846 * k / 100.0;
                    w.xi_x = c.xi_x * (1.0 + 0.1 * std::sin(a));
                    w.xi_y = c.xi_y * (1.0 + 0.1 * std::sin(a + 2.0));
                    w.phi = c.phi * (1.0 + 0.1 * std::sin(a + 4.0));
                    if (moving)
                        for (size_t q = 0; q < h.size(); ++q) h[q] = s.h[q] * (1.0 + 0.01 * std::sin(a));
                    solver.solve(w, cw::SolveMode::full);
                    count += solver.gap_model()->info().products;
                    normal_count += solver.gap_model()->info().normal_products;
                }
                const double per = (thread_seconds() - t0) / steps;
                products[moving] = double(count) / steps;
                if (moving) normal_products = double(normal_count) / steps;
                (moving ? warm_moving : warm_fixed) = std::min(moving ? warm_moving : warm_fixed, per);
            }
        }
        // The semi-Hertzian method alone.
        cw::SemiHertz sh(s.nx, s.ny);
        std::vector<double> p(s.h.size());
        const int reps = quick ? 200 : 2000;
        double fast = 1e300;
        for (int run = 0; run < 3; ++run) {
            const double t0 = thread_seconds();
            for (int k = 0; k < reps; ++k)
                sh.solve(s.h.data(), s.dx, s.dy, s.G / (1.0 - s.nu), !s.approach_given,
                         s.approach_given ? s.approach : s.normal_force, p.data());
            fast = std::min(fast, (thread_seconds() - t0) / reps);
        }
        std::printf("| %s | %d x %d | %d | %d | %s | %s | %s | %.1f, %.1f | %.1f | %s |", id.c_str(),
                    s.nx, s.ny, t.n_contact, t.n_patches, sig3(cold * 1e3).c_str(),
                    sig3(warm_fixed * 1e3).c_str(), sig3(warm_moving * 1e3).c_str(), products[0],
                    products[1], normal_products, sig3(fast * 1e6).c_str());
#ifdef CW_BENCH_CONTACT
        std::printf(" %s | %.0f | %.0f | %.0f |", sig3(contact * 1e3).c_str(), contact / cold,
                    contact / warm_fixed, contact / warm_moving);
        if (r.n_adhesion != t.n_adhesion || r.n_slip != t.n_slip)
            std::printf(" (CONTACT %d/%d elements at EPS %g)", r.n_adhesion, r.n_slip, contact_eps);
#endif
        std::printf("\n");
        std::fflush(stdout);
    }
#ifdef CW_BENCH_CONTACT
    contact_gap_finish();
#endif
    std::printf("\n");
    return fast_table(ids, shapes, quick);
}
