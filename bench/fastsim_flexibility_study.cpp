// A measured study, not a test: which flexibility rule would FASTSIM need on
// a non-elliptic patch? A scalar reference march of Kalker's simplified
// theory over every contact segment of every grid row (from the segment's
// leading edge, traction bound mu p_n with the exact normal pressure, rigid
// slip (xi - phi y, eta + phi x) from the grid's origin), against the exact
// model's forces and moment on the same gap. Flexibilities L_i = c_i / G by
// Kalker's formulas (L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G),
// L3 = pi a sqrt(a/b)/(4 C23 G)) with the semi-axes from
//   ellipse: each patch's equivalent ellipse (a = half its largest row
//            length, b = area / (pi a));
//   strip:   each segment's own half length a_s, b of its patch (so the
//            flexibility follows the local length, as STRIPES does);
//   global:  one ellipse for the whole contact (a = half the largest row
//            length, b = total area / (pi a)).
// Prints the error table (per cent of mu N for the forces, of mu N c for
// Mz) over the DEV and new shapes.
//
//   creepwork_fastsim_flexibility_study
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "contact/kalker_coefficients.hpp"
#include "gap_shape_grid.hpp"
#include "gap_shapes.hpp"
#include "gap_test_support.hpp"
#include "solver.hpp"

namespace cw = creepwork;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Totals {
    double Fx = 0, Fy = 0, Mz = 0;
};

enum class Rule { ellipse_origin, ellipse, strip, global };

cw::Flexibilities flex(double a, double b, double G, double nu)
{
    const double ratio = std::min(std::max(a / b, cw::kMinAspect), cw::kMaxAspect);
    return cw::kalker_flexibilities(a, b, G, cw::kalker_coefficients(ratio, nu));
}

Totals march(const cw::GridSpec& g, const std::vector<double>& pz, const std::vector<int>& patch,
             const std::vector<cw::PatchTotals>& centroids, const cw::ContactInput& in, Rule rule)
{
    const int patches = static_cast<int>(centroids.size());
    const int nx = g.nx, ny = g.ny;
    // Per patch: area and largest row length (elements).
    std::vector<double> area(patches, 0.0), longest(patches, 0.0);
    double total = 0.0, longest_all = 0.0;
    for (int j = 0; j < ny; ++j) {
        int run = 0, p = -1;
        for (int i = 0; i <= nx; ++i) {
            const int k = i + nx * j;
            if (i < nx && pz[k] > 0.0) {
                ++run;
                p = patch[k];
                area[p] += g.dx * g.dy;
                total += g.dx * g.dy;
            } else if (run) {
                longest[p] = std::max(longest[p], run * g.dx);
                longest_all = std::max(longest_all, run * g.dx);
                run = 0;
            }
        }
    }
    Totals t;
    const double T = in.mu;
    for (int j = 0; j < ny; ++j) {
        const double y = g.y0 + j * g.dy;
        int i = nx - 1;
        while (i >= 0) {
            if (!(pz[i + nx * j] > 0.0)) {
                --i;
                continue;
            }
            int lo = i; // the segment [lo, i], marched from i (leading edge at +x)
            while (lo - 1 >= 0 && pz[lo - 1 + nx * j] > 0.0) --lo;
            const int p = patch[i + nx * j];
            double a = 0.5 * longest[p], b = area[p] / (kPi * a);
            if (rule == Rule::strip) a = 0.5 * (i - lo + 1) * g.dx;
            if (rule == Rule::global) a = 0.5 * longest_all, b = total / (kPi * a);
            const cw::Flexibilities L = flex(a, b, in.G, in.nu);
            // The rigid slip split into a creepage and a spin about the
            // patch's centroid (or about the grid's origin).
            const bool origin = rule == Rule::ellipse_origin;
            const double xc = origin ? 0.0 : centroids[p].x_centroid;
            const double yc = origin ? 0.0 : centroids[p].y_centroid;
            const double cx = in.xi_x - in.phi * yc, cy = in.xi_y + in.phi * xc;
            double px = 0.0, py = 0.0;
            for (int m = i; m >= lo; --m) {
                const double x = g.x0 + m * g.dx;
                px -= g.dx * (cx / L.L1 - in.phi * (y - yc) / L.L3);
                py -= g.dx * (cy / L.L2 + in.phi * (x - xc) / L.L3);
                const double bound = T * pz[m + nx * j], mag = std::hypot(px, py);
                if (mag > bound) px *= bound / mag, py *= bound / mag;
                t.Fx += px * g.dx * g.dy;
                t.Fy += py * g.dx * g.dy;
                t.Mz += (x * py - y * px) * g.dx * g.dy;
            }
            i = lo - 1;
        }
    }
    return t;
}

void study(const std::string& id, const cw::GridSpec& g, cw::ContactInput in, double worst[4][3])
{
    in.warm_start = false;
    cw::Solver s(g);
    const cw::SolveTotals e = s.solve(in, cw::SolveMode::full);
    const std::vector<double> pz = cwtest::field(s, cw::Field::pz);
    // Patches from the solver's labels: the centroids' nearest patch.
    std::vector<int> patch(pz.size(), -1);
    const std::vector<cw::PatchTotals>& P = s.patches();
    for (size_t k = 0; k < pz.size(); ++k) {
        if (!(pz[k] > 0.0)) continue;
        const double x = g.x0 + (k % g.nx) * g.dx, y = g.y0 + (k / g.nx) * g.dy;
        double best = 1e300;
        for (size_t q = 0; q < P.size(); ++q) {
            const double d = std::hypot(x - P[q].x_centroid, y - P[q].y_centroid);
            if (d < best) best = d, patch[k] = static_cast<int>(q);
        }
    }
    const double muN = in.mu * e.normal_force;
    const double c = std::sqrt(e.n_contact * g.dx * g.dy / kPi);
    std::printf("| %s |", id.c_str());
    const Rule rules[4] = {Rule::ellipse_origin, Rule::ellipse, Rule::strip, Rule::global};
    for (int r = 0; r < 4; ++r) {
        const Totals t = march(g, pz, patch, P, in, rules[r]);
        const double eF = std::max(std::fabs(t.Fx - e.Fx), std::fabs(t.Fy - e.Fy)) / muN;
        const double eM = std::fabs(t.Mz - e.Mz) / (muN * c);
        std::printf(" %.1f / %.1f |", 100 * eF, 100 * eM);
        worst[r][0] = std::max(worst[r][0], eF);
        worst[r][1] = std::max(worst[r][1], eM);
        worst[r][2] += eF;
    }
    std::printf("\n");
}

} // namespace

int main()
{
    std::printf("FASTSIM march on the exact pressure vs the exact model: forces %% of mu N / Mz "
                "%% of mu N c\n\n| case | patch ellipse, spin about the origin | patch ellipse | "
                "per strip | one ellipse |\n|---|---:|---:|---:|---:|\n");
    double worst[4][3] = {};
    int cases = 0;
    for (const cwtest::GapCase& c : cwtest::dev_cases()) {
        study(c.id, c.gap.grid, c.bind(), worst);
        ++cases;
    }
    const cwtest::CsvTable t =
        cwtest::read_quoted_csv(std::string(CW_NONHERTZ_DATA_DIR) + "/contact_cases.csv");
    const std::vector<gapshapes::Shape> shapes = gapshapes::shapes();
    for (size_t r = 0; r < shapes.size(); ++r) {
        const gapshapes::Shape& s = shapes[r];
        const cw::GridSpec g = gapshapes::grid_of(s);
        cw::ContactInput in = gapshapes::contact_input(s);
        in.rolling_direction = 1; // the march rolls towards +x
        in.xi_x = t.number(r, "xi_x"), in.xi_y = t.number(r, "xi_y"), in.phi = t.number(r, "phi_per_m");
        study(s.id, g, in, worst);
        ++cases;
    }
    std::printf("| worst (mean forces) |");
    for (int r = 0; r < 4; ++r)
        std::printf(" %.1f / %.1f (%.1f) |", 100 * worst[r][0], 100 * worst[r][1],
                    100 * worst[r][2] / cases);
    std::printf("\n");
    return 0;
}
