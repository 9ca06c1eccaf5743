#include "calibration_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "calibrated/calibration_table.hpp"

namespace cwcal {

namespace cw = creepwork;

ModelResult solved_result(cw::Solver& solver, const cw::ContactInput& in)
{
    const cw::SolveTotals& t = solver.solve(in, cw::SolveMode::full);
    ModelResult r;
    r.Fx = t.Fx;
    r.Fy = t.Fy;
    r.Mz = t.Mz;
    r.W = t.W_macro;
    r.adhesion_fraction = t.adhesion_fraction;
    r.work_map.resize(size_t(solver.grid().nx()) * solver.grid().ny());
    solver.copy_field(cw::Field::work_consistent, r.work_map.data());
    return r;
}

ModelResult calibrated_result(cw::CalibratedModel& model, const cw::ContactInput& in,
                              const cw::CalibrationParams& params)
{
    const cw::SolveTotals t = model.solve_with(in, cw::SolveMode::full, params);
    ModelResult r;
    r.Fx = t.Fx;
    r.Fy = t.Fy;
    r.Mz = t.Mz;
    r.W = t.W_macro;
    r.adhesion_fraction = t.adhesion_fraction;
    r.work_map.resize(size_t(model.grid().nx()) * model.grid().ny());
    model.copy_field(cw::Field::work_consistent, r.work_map.data());
    return r;
}

namespace {

// Issue 10's targets as the scales of the objective: each error counts in
// units of its required bound.
double case_cost(const CaseErrors& e)
{
    // CW_FIT_PENALTY, CW_FIT_FORCE_LIMIT and CW_FIT_MAPW explore other
    // weights (the committed table: 20 from 2.5 % of mu N, and 1.5). A
    // force penalty from 2.5 % keeps a margin below the bound of 3 % for
    // cases the training set does not sample; the map weight 1.5 keeps the
    // map median where the blended bound put it despite that penalty.
    static const double kMapWeight =
        std::getenv("CW_FIT_MAPW") ? std::atof(std::getenv("CW_FIT_MAPW")) : 1.5;
    static const double kOverPenalty =
        std::getenv("CW_FIT_PENALTY") ? std::atof(std::getenv("CW_FIT_PENALTY")) : 20.0;
    double c = (e.dFx / 3.0) * (e.dFx / 3.0) + (e.dFy / 3.0) * (e.dFy / 3.0);
    // Beyond 2.5 %, a force error costs twenty times more: the bound holds
    // in every case, the others are medians.
    static const double kLimit =
        std::getenv("CW_FIT_FORCE_LIMIT") ? std::atof(std::getenv("CW_FIT_FORCE_LIMIT")) : 2.5;
    for (double f : {e.dFx, e.dFy})
        if (f > kLimit) c += kOverPenalty * (f / 3.0 - kLimit / 3.0) * (f / 3.0 - kLimit / 3.0);
    const double mz = e.mz_relative ? e.dMz / 8.0 : e.dMz / 0.5;
    c += mz * mz;
    if (e.has_spin) c += (e.dW / 5.0) * (e.dW / 5.0);
    if (e.partial_slip)
        c += kMapWeight * ((e.map_L1 / 0.3) * (e.map_L1 / 0.3) +
                           (e.profile_L1 / 0.08) * (e.profile_L1 / 0.08));
    return c;
}

} // namespace

int fit_table(const std::vector<CalibrationCase>& cases, const std::vector<CaseReference>& refs)
{
    cw::GridSpec g;
    g.kind = cw::GridKind::uniform;
    g.nx = g.ny = kMapN;
    cw::CalibratedModel model(g);
    // Each node is fitted on the training cases near it: weight
    // exp(-(ln(ab/ab_node))^2 / (2 w^2)), w = 0.45 (about a factor 1.6).
    const double nodes[cw::kCalibrationNodes] = {0.2, 0.5, 1.0, 2.0, 5.0};
    std::printf("    // node a/b, alpha_long, alpha_lat, alpha_spin_x, alpha_spin_y, fade, equalise, edge, "
                "blend, blend_half (weighted cost before -> after)\n");
    for (double ab : nodes) {
        std::vector<size_t> near;
        std::vector<double> weight;
        for (size_t k = 0; k < cases.size(); ++k) {
            const double d = std::log(cases[k].a_over_b / ab) / 0.45;
            const double w = std::exp(-0.5 * d * d);
            if (w < 0.05) continue;
            near.push_back(k);
            weight.push_back(w);
        }
        constexpr int kParams = 9;
        auto cost = [&](const double alpha[kParams]) {
            const cw::CalibrationNode n{ab,       alpha[0], alpha[1], alpha[2], alpha[3],
                                         alpha[4], alpha[5], alpha[6], alpha[7], alpha[8]};
            double total = 0;
            for (size_t q = 0; q < near.size(); ++q) {
                const CalibrationCase& c = cases[near[q]];
                cw::ContactInput in = c.input;
                in.model = cw::ModelKind::calibrated;
                const cw::CalibrationParams p =
                    cw::calibration_params(n, cw::normalised_creepage(in));
                const ModelResult r = calibrated_result(model, in, p);
                total += weight[q] * case_cost(case_errors(in, r, refs[near[q]].ref,
                                                           refs[near[q]].exact40, kMapN, kMapN));
            }
            return total;
        };
        // Coordinate search: each alpha up or down by the step while that
        // lowers the cost, the step halved when nothing does.
        double alpha[kParams] = {0, 0, 0, 0, 1, 0, 0, 0, 0.35};
        const double start = cost(alpha);
        double best = start;
        for (double step = 0.4; step >= 0.01; step *= 0.5) {
            bool improved = true;
            while (improved) {
                improved = false;
                for (int q = 0; q < kParams; ++q)
                    for (double dir : {1.0, -1.0}) {
                        double trial[kParams];
                        std::copy(alpha, alpha + kParams, trial);
                        trial[q] += dir * step;
                        // Factors stay positive; fade and equalise in [0, ..], h <= 1.
                        if (q < 4 ? trial[q] <= -0.9 : q < 6 ? trial[q] < 0.0 : trial[q] <= -0.9) continue;
                        if (q == 5 && trial[q] > 4.0) continue;
                        // The blend stays in [0, 1] (parabolic .. elliptic),
                        // its half-way creepage in [0.05, 3].
                        if (q == 7 && (trial[q] < 0.0 || trial[q] > 1.0)) continue;
                        if (q == 8 && (trial[q] < 0.05 || trial[q] > 3.0)) continue;
                        const double c = cost(trial);
                        if (c < best) {
                            best = c;
                            std::copy(trial, trial + kParams, alpha);
                            improved = true;
                        }
                    }
            }
        }
        std::printf("    {%g, %.4f, %.4f, %.4f, %.4f, %.4f, %.4f, %.4f, %.4f, %.4f}, // %zu cases, cost %.1f -> %.1f\n",
                    ab, alpha[0], alpha[1], alpha[2], alpha[3], alpha[4], alpha[5], alpha[6], alpha[7],
                    alpha[8], near.size(), start, best);
        std::fflush(stdout);
    }
    return 0;
}

} // namespace cwcal
