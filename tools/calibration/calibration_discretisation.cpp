#include "calibration_discretisation.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdio>
#include <memory>
#include <vector>

#include "calibration_cases.hpp"
#include "calibration_limit.hpp"
#include "calibration_metrics.hpp"
#include "calibration_reference.hpp"
#include "solver.hpp"

namespace cwcal {
namespace {

namespace cw = creepwork;

// Elements across the ellipse (uniform grid, box scale 1), each about sqrt(2)
// finer than the last, for every model (the whole study takes ~10 s).
constexpr int kGrids[] = {10, 14, 20, 28, 40, 56, 80, 112, 160};
constexpr int kGridCount = int(sizeof kGrids / sizeof kGrids[0]);
constexpr double kTarget = 0.01; // 1 %

struct ModelSpec {
    const char* name;
    cw::ModelKind kind;
    cw::PressureKind pressure;
    int finest;
};

const ModelSpec kModels[] = {
    {"FASTSIM parabolic", cw::ModelKind::fastsim, cw::PressureKind::parabolic, 160},
    {"FASTSIM elliptic", cw::ModelKind::fastsim, cw::PressureKind::elliptic, 160},
    {"calibrated", cw::ModelKind::calibrated, cw::PressureKind::parabolic, 160},
    {"exact", cw::ModelKind::exact, cw::PressureKind::elliptic, 160},
};

enum Quantity { kFx, kFy, kMz, kW, kQuantities };

// The measured partial-slip subset: for each of the 7 creepage combinations,
// the two evaluation cases whose exact 40 x 40 adhesion fraction is nearest
// 30 % and 70 % (14 cases, spanning a/b, nu and the level).
std::vector<size_t> pick_subset(const std::vector<CalibrationCase>& cases,
                                const std::vector<CaseReference>& refs)
{
    std::vector<size_t> picked;
    for (int combo = 1; combo <= 7; ++combo)
        for (double target : {0.3, 0.7}) {
            size_t best = cases.size();
            double best_d = 1e30;
            for (size_t k = 0; k < cases.size(); ++k) {
                const double adh = refs[k].exact40.adhesion_fraction;
                if (cases[k].combo != combo || adh < 0.05 || adh > 0.95) continue;
                if (std::find(picked.begin(), picked.end(), k) != picked.end()) continue;
                const double d = std::fabs(adh - target);
                if (d < best_d) best_d = d, best = k;
            }
            if (best < cases.size()) picked.push_back(best);
        }
    return picked;
}

// The errors of one grid's totals against the limit (fractions):
// forces max(|dFx|, |dFy|)/max(|F|, 0.1 mu N) (with xi_y and spin the two
// parts of Fy can cancel, and a force near zero has no relative error worth
// the name); moment |dMz|/max(|Mz|, 0.01 mu N c) (the accuracy targets' threshold for a
// moment measured relatively); work |dW|/W.
struct GridErrors {
    double F = 0, Mz = 0, W = 0;
    double worst() const { return std::max(F, std::max(Mz, W)); }
};

GridErrors grid_errors(const double q[kQuantities], const double lim[kQuantities],
                       const cw::ContactInput& in)
{
    const double muN = in.mu * in.normal_force, c = std::sqrt(in.a * in.b);
    GridErrors e;
    e.F = std::max(std::fabs(q[kFx] - lim[kFx]), std::fabs(q[kFy] - lim[kFy])) /
          std::max(std::hypot(lim[kFx], lim[kFy]), 0.1 * muN);
    e.Mz = std::fabs(q[kMz] - lim[kMz]) / std::max(std::fabs(lim[kMz]), 0.01 * muN * c);
    e.W = std::fabs(q[kW] - lim[kW]) / std::fabs(lim[kW]);
    return e;
}

// Smallest grid index from which every finer grid is within the target
// (kGridCount when even the finest is not).
template <class Error>
int first_within(int grids, Error error)
{
    int first = grids;
    for (int g = grids - 1; g >= 0 && error(g) <= kTarget; --g) first = g;
    return first;
}

struct ModelStudy {
    std::vector<int> n_needed[4];          // per case: all totals, forces, Mz, W (grid index)
    std::vector<double> order[kQuantities]; // clean Richardson orders
    int richardson = 0, finest_used = 0, resolved = 0;
    std::vector<double> err20, err40;       // worst total error at 20 and 40 across [%]
};

std::string needed_text(const std::vector<int>& idx, int grids, const std::vector<int>& n_contact,
                        bool worst)
{
    std::vector<int> v = idx;
    std::sort(v.begin(), v.end());
    const int g = worst ? v.back() : v[(v.size() - 1) / 2]; // lower median: a grid tried
    char buf[64];
    if (g >= grids)
        std::snprintf(buf, sizeof buf, "> %d", kGrids[grids - 1]);
    else
        std::snprintf(buf, sizeof buf, "%d (%d)", kGrids[g], n_contact[g]);
    return buf;
}

std::string order_text(std::vector<double> v)
{
    if (v.empty()) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", median_of(v));
    return buf;
}

} // namespace

int discretisation_study(const std::string& cache_dir)
{
    const std::vector<CalibrationCase> cases = make_cases(CaseSet::evaluation);
    const std::vector<CaseReference> refs =
        exact_references(cases, cache_dir + "/exact_evaluation.txt");
    const std::vector<size_t> subset = pick_subset(cases, refs);

    std::vector<std::unique_ptr<cw::Solver>> solvers;
    std::vector<int> n_contact;
    for (int n : kGrids) {
        solvers.push_back(std::make_unique<cw::Solver>(uniform_grid(n)));
        n_contact.push_back(solvers.back()->grid().n_contact());
    }

    std::printf("Discretisation error of the totals, %zu partial-slip cases of the evaluation "
                "set\n(uniform n x n grids, box scale 1: n elements across the ellipse)\n\n"
                "| case | a/b | nu | level | xi_x xi_y phi | exact 40 x 40 adhesion |\n"
                "|---|---|---|---|---|---|\n",
                subset.size());
    for (size_t k : subset)
        std::printf("| %s | %g | %g | %.3f | %d %d %d | %.2f |\n", cases[k].id.c_str(),
                    cases[k].a_over_b, cases[k].nu, cases[k].level, cases[k].combo & 1,
                    (cases[k].combo >> 1) & 1, (cases[k].combo >> 2) & 1,
                    refs[k].exact40.adhesion_fraction);

    std::vector<ModelStudy> studies;
    for (const ModelSpec& m : kModels) {
        ModelStudy st;
        int grids = 0;
        while (grids < kGridCount && kGrids[grids] <= m.finest) ++grids;
        for (size_t k : subset) {
            cw::ContactInput in = cases[k].input;
            in.model = m.kind;
            in.pressure = m.pressure;
            in.warm_start = false;
            std::vector<std::array<double, kQuantities>> q(grids);
            for (int g = 0; g < grids; ++g) {
                const cw::SolveTotals& t = solvers[g]->solve(in, cw::SolveMode::forces_only);
                q[g] = {t.Fx, t.Fy, t.Mz, t.W_macro};
            }
            const double h[3] = {1.0 / kGrids[grids - 3], 1.0 / kGrids[grids - 2],
                                 1.0 / kGrids[grids - 1]};
            const double muN = in.mu * in.normal_force, c = std::sqrt(in.a * in.b);
            const double scale[kQuantities] = {muN, muN, muN * c, std::fabs(q[grids - 1][kW])};
            double lim[kQuantities];
            // The force that carries the case (the other may vanish by symmetry)
            // and Mz, W give the orders reported.
            const int main_force = std::fabs(q[grids - 1][kFx]) >= std::fabs(q[grids - 1][kFy])
                                       ? kFx
                                       : kFy;
            for (int Q = 0; Q < kQuantities; ++Q) {
                const double v[3] = {q[grids - 3][Q], q[grids - 2][Q], q[grids - 1][Q]};
                const ContinuumLimit L = continuum_limit(h, v, scale[Q]);
                lim[Q] = L.value;
                if (Q == main_force || Q == kMz || Q == kW) {
                    if (L.resolved)
                        ++st.resolved;
                    else if (L.richardson) {
                        ++st.richardson;
                        st.order[Q == main_force ? kFx : Q].push_back(L.order);
                    } else
                        ++st.finest_used;
                }
            }
            std::vector<GridErrors> e(grids);
            for (int g = 0; g < grids; ++g) e[g] = grid_errors(q[g].data(), lim, in);
            st.n_needed[0].push_back(first_within(grids, [&](int g) { return e[g].worst(); }));
            st.n_needed[1].push_back(first_within(grids, [&](int g) { return e[g].F; }));
            st.n_needed[2].push_back(first_within(grids, [&](int g) { return e[g].Mz; }));
            st.n_needed[3].push_back(first_within(grids, [&](int g) { return e[g].W; }));
            st.err20.push_back(100.0 * e[2].worst());
            st.err40.push_back(100.0 * e[4].worst());
            std::fprintf(stderr, "\r%s: case %s done   ", m.name, cases[k].id.c_str());
        }
        std::fprintf(stderr, "\n");
        studies.push_back(st);
    }

    std::printf("\nn across the ellipse (elements in contact) at which every finer grid's "
                "totals are within 1 %% of the model's own continuum limit; median / worst "
                "over the cases\n\n"
                "| model | grids | all totals | forces | Mz | W | error at 20 / 40 across, %% "
                "med (max) | observed order F / Mz / W | limit: Richardson / finest / "
                "resolved |\n|---|---|---|---|---|---|---|---|---|\n");
    for (size_t mi = 0; mi < studies.size(); ++mi) {
        const ModelStudy& st = studies[mi];
        int grids = 0;
        while (grids < kGridCount && kGrids[grids] <= kModels[mi].finest) ++grids;
        std::printf("| %s | %d-%d |", kModels[mi].name, kGrids[0], kGrids[grids - 1]);
        for (int w = 0; w < 4; ++w)
            std::printf(" %s / %s |", needed_text(st.n_needed[w], grids, n_contact, false).c_str(),
                        needed_text(st.n_needed[w], grids, n_contact, true).c_str());
        std::printf(" %.2f (%.2f) / %.2f (%.2f) | %s / %s / %s | %d / %d / %d |\n",
                    median_of(st.err20), *std::max_element(st.err20.begin(), st.err20.end()),
                    median_of(st.err40), *std::max_element(st.err40.begin(), st.err40.end()),
                    order_text(st.order[kFx]).c_str(), order_text(st.order[kMz]).c_str(),
                    order_text(st.order[kW]).c_str(), st.richardson, st.finest_used,
                    st.resolved);
    }
    // Per case: n for all totals within 1 % and the worst error at 40 across.
    std::printf("\nper case: n for all totals within 1 %% (worst total error at 40 across, %%)\n\n"
                "| case |");
    for (const ModelSpec& m : kModels) std::printf(" %s |", m.name);
    std::printf("\n|---|---|---|---|---|\n");
    for (size_t c = 0; c < subset.size(); ++c) {
        std::printf("| %s |", cases[subset[c]].id.c_str());
        for (size_t mi = 0; mi < studies.size(); ++mi) {
            const int g = studies[mi].n_needed[0][c];
            if (g >= kGridCount)
                std::printf(" > %d", kGrids[kGridCount - 1]);
            else
                std::printf(" %d", kGrids[g]);
            std::printf(" (%.2f) |", studies[mi].err40[c]);
        }
        std::printf("\n");
    }
    return 0;
}

} // namespace cwcal
