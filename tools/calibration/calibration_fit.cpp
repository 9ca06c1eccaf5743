#include "calibration_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "calibrated/calibration_table.hpp"

namespace cwcal {

namespace cw = creepwork;

namespace {

// The totals of a full solve and the energy-consistent map that solved
// (a Solver or a CalibratedModel: both have grid() and solved()).
template <class Solved>
ModelResult result_of(const cw::SolveTotals& t, const Solved& solved)
{
    ModelResult r;
    r.Fx = t.Fx;
    r.Fy = t.Fy;
    r.Mz = t.Mz;
    r.W = t.W_macro;
    r.adhesion_fraction = t.adhesion_fraction;
    r.work_map.resize(size_t(solved.grid().nx()) * solved.grid().ny());
    cw::export_field(solved.solved(), cw::Field::work_consistent, r.work_map.data());
    return r;
}

} // namespace

ModelResult solved_result(cw::Solver& solver, const cw::ContactInput& in)
{
    return result_of(solver.solve(in, cw::SolveMode::full), solver);
}

ModelResult calibrated_result(cw::CalibratedModel& model, const cw::ContactInput& in,
                              const cw::CalibrationParams& params)
{
    return result_of(model.solve_with(in, cw::SolveMode::full, params), model);
}

FitModel::FitModel() : map_grid_(uniform_grid(kMapN)), fine_grid_(uniform_grid(kFineN)) {}

CaseErrors FitModel::errors(const CalibrationCase& c, const CaseReference& ref,
                            const cw::CalibrationParams& params, bool fine_grid)
{
    cw::ContactInput in = c.input;
    in.model = cw::ModelKind::calibrated;
    ModelResult r = calibrated_result(fine_grid ? fine_grid_ : map_grid_, in, params);
    if (fine_grid) r.work_map = summed_onto_map_grid(r.work_map);
    return case_errors(in, r, ref.limit, ref.limit, kMapN, kMapN);
}

double FitModel::cost(const CalibrationCase& c, const CaseReference& ref,
                      const cw::CalibrationParams& params, const FitWeights& w)
{
    return 0.5 * (case_cost(errors(c, ref, params, false), w) +
                  case_cost(errors(c, ref, params, true), w));
}

FitWeights fit_weights_from_env()
{
    FitWeights w;
    if (const char* v = std::getenv("CW_FIT_FORCE_LIMIT")) w.force_limit = std::atof(v);
    if (const char* v = std::getenv("CW_FIT_PENALTY")) w.penalty = std::atof(v);
    if (const char* v = std::getenv("CW_FIT_MAPW")) w.map_weight = std::atof(v);
    return w;
}

// The accuracy targets as the scales of the objective: each error counts in
// units of its required bound. A force error beyond w.force_limit costs
// w.penalty times more again: the force bound holds in every case, the
// others are medians, and the margin below 3 % is for cases the training
// set samples thinly. The map weight keeps the map median where the blended
// bound put it despite that penalty.
double case_cost(const CaseErrors& e, const FitWeights& w)
{
    double c = (e.dFx / 3.0) * (e.dFx / 3.0) + (e.dFy / 3.0) * (e.dFy / 3.0);
    for (double f : {e.dFx, e.dFy})
        if (f > w.force_limit) {
            const double over = (f - w.force_limit) / 3.0;
            c += w.penalty * over * over;
        }
    const double mz = e.mz_relative ? e.dMz / 8.0 : e.dMz / 0.5;
    c += mz * mz;
    if (e.has_spin) c += (e.dW / 5.0) * (e.dW / 5.0);
    if (e.partial_slip)
        c += w.map_weight * ((e.map_L1 / 0.3) * (e.map_L1 / 0.3) +
                             (e.profile_L1 / 0.08) * (e.profile_L1 / 0.08));
    return c;
}

FitResult fit_nodes(const std::vector<CalibrationCase>& cases, const std::vector<CaseReference>& refs,
                    const std::vector<size_t>& use, const FitWeights& weights)
{
    FitModel model;
    FitResult result;
    // Each node is fitted on the cases near it: weight
    // exp(-(ln(ab/ab_node))^2 / (2 w^2)), w = 0.45 (about a factor 1.6).
    const double nodes[cw::kCalibrationNodes] = {0.2, 0.5, 1.0, 2.0, 5.0};
    for (int node = 0; node < cw::kCalibrationNodes; ++node) {
        const double ab = nodes[node];
        std::vector<size_t> near;
        std::vector<double> weight;
        for (size_t k : use) {
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
                const cw::CalibrationParams p =
                    cw::calibration_params(n, cw::normalised_creepage(c.input));
                total += weight[q] * model.cost(c, refs[near[q]], p, weights);
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
        result.table[node] = {ab,       alpha[0], alpha[1], alpha[2], alpha[3],
                              alpha[4], alpha[5], alpha[6], alpha[7], alpha[8]};
        result.cases[node] = near.size();
        result.cost_start[node] = start;
        result.cost_fitted[node] = best;
    }
    return result;
}

int fit_table(const std::vector<CalibrationCase>& cases, const std::vector<CaseReference>& refs)
{
    const FitWeights w = fit_weights_from_env();
    std::vector<size_t> all(cases.size());
    for (size_t k = 0; k < all.size(); ++k) all[k] = k;
    const FitResult r = fit_nodes(cases, refs, all, w);
    std::printf(
        "// Generated by `creepwork_calibration fit` (tools/calibration/) from the\n"
        "// training set (%zu cases; the model on %d x %d and %d x %d against the\n"
        "// exact model's continuum estimate, Richardson from 40, 80, %d across); do not\n"
        "// edit by hand (doc/theory/calibrated.md). Objective weights: force\n"
        "// penalty %g from %g %% of mu N, map weight %g (chosen by select-weights\n"
        "// on the training set).\n"
        "#include \"calibrated/calibration_table.hpp\"\n\n"
        "namespace creepwork {\n\n"
        "const CalibrationNode kCalibrationTable[kCalibrationNodes] = {\n"
        "    // node a/b, alpha_long, alpha_lat, alpha_spin_x, alpha_spin_y, fade, equalise, edge,\n"
        "    // blend, blend_half (weighted training cost with all alphas, equalise, edge and blend 0,\n"
        "    // fade 1 and blend_half 0.35 -> fitted)\n",
        cases.size(), kMapN, kMapN, kFineN, kFineN, kFineN, w.penalty, w.force_limit, w.map_weight);
    for (int k = 0; k < cw::kCalibrationNodes; ++k) {
        const cw::CalibrationNode& n = r.table[k];
        std::printf("    {%g, %.4f, %.4f, %.4f, %.4f, %.4f, %.4f, %.4f, %.4f, %.4f}, // %zu cases, "
                    "cost %.1f -> %.1f\n",
                    n.a_over_b, n.alpha_long, n.alpha_lat, n.alpha_spin_x, n.alpha_spin_y, n.fade,
                    n.equalise, n.edge, n.blend, n.blend_half, r.cases[k], r.cost_start[k],
                    r.cost_fitted[k]);
    }
    std::printf("};\n\n} // namespace creepwork\n");
    return 0;
}

} // namespace cwcal
