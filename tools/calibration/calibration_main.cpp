// creepwork_calibration: measures the simplified models against the exact
// model over the training or evaluation set (the accuracy targets' error
// measures, doc/validation/calibrated.md), and fits the calibrated model's
// table on the training set.
//
//   creepwork_calibration evaluate training|evaluation [cache-dir] [--markdown]
//       median and worst of each error for FASTSIM (parabolic, elliptic),
//       the calibrated model and the exact model at 20 x 20 and 40 x 40;
//       --markdown: against the continuum yardstick only, and the count of
//       cases beyond each accuracy target (the documentation's tables)
//   creepwork_calibration cases training|evaluation [cache-dir]
//       the same errors per case (CSV)
//   creepwork_calibration fit [cache-dir]
//       the calibrated table from the training set (calibration_fit.cpp)
//   creepwork_calibration select-weights [cache-dir]
//       the fit's objective weights chosen by 3-fold cross-validation on
//       the training set (calibration_select.cpp)
//   creepwork_calibration time
//       ns per element, FASTSIM and calibrated, full mode
//   creepwork_calibration spin-sweep
//       Mz and W against normalised spin, a/b = 1 and 2, every model (CSV)
//   creepwork_calibration oracle training|evaluation [cache-dir]
//       the floor of the model's form: per partial-slip case the best map
//       and profile L1 any choice of its knobs gives (calibration_oracle.hpp)
//   creepwork_calibration discretisation [cache-dir]
//       elements needed for 1 % discretisation error, every model
//       (calibration_discretisation.hpp)
//
// Exploration before a fit (rows for evaluate and cases):
//   CW_CALIBRATION_TRY="pressure k_long k_lat k_spin_x k_spin_y equalise lateral edge_gain"
//       adds a row "trial" with these parameters in every case;
//   CW_TRY_OFFSET=s  solves the calibrated row with spin_offset s;
//   CW_TRY_BLEND=b   the calibrated row with the table's parameters but the
//                    traction bound blend b in [0, 1] (calibrated/blended_bound.hpp);
//   CW_FIT_PENALTY=w the fit's weight of force errors beyond the limit;
//   CW_FIT_FORCE_LIMIT=f where that penalty starts, in % of mu N;
//   CW_FIT_MAPW=w    the fit's weight of the map and profile terms
//                    (defaults: FitWeights in calibration_fit.hpp);
//   CW_TRY_H=h, CW_TRY_KEQ=1, CW_TRY_KSCALE=k (with CW_TRY_BLEND set, maybe
//                    empty): the calibrated row with equalisation h, all
//                    four factors 1, or the factors times 1 + k * blend.
//
// The exact references are cached in cache-dir (default: the current
// directory) as exact_<set>.txt; the first run of a set solves them
// (~1 minute per 100 cases on one core).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "calibrated/calibration_table.hpp"
#include "calibration_cases.hpp"
#include "calibration_discretisation.hpp"
#include "calibration_fit.hpp"
#include "calibration_metrics.hpp"
#include "calibration_oracle.hpp"
#include "calibration_reference.hpp"
#include "calibration_select.hpp"
#include "contact/kalker_coefficients.hpp"
#include "solver.hpp"

namespace cw = creepwork;
using namespace cwcal;

namespace {

struct Stats {
    std::vector<double> v;
    void add(double x) { v.push_back(x); }
    double median() const
    {
        if (v.empty()) return NAN;
        std::vector<double> s = v;
        std::sort(s.begin(), s.end());
        return s.size() % 2 ? s[s.size() / 2] : 0.5 * (s[s.size() / 2 - 1] + s[s.size() / 2]);
    }
    double worst() const { return v.empty() ? NAN : *std::max_element(v.begin(), v.end()); }
};

struct Summary {
    Stats fx, fy, mz_rel, mz_abs, w, map, profile;
    Stats force; // the larger of dFx, dFy, every case
    // Force errors over the cases where the force is not zero by symmetry
    // (Fx: xi_x given; Fy: xi_y or spin given); the worst is the same.
    void add(const CaseErrors& e, const cw::ContactInput& in)
    {
        if (in.xi_x != 0.0) fx.add(e.dFx);
        if (in.xi_y != 0.0 || in.phi != 0.0) fy.add(e.dFy);
        force.add(std::max(e.dFx, e.dFy));
        (e.mz_relative ? mz_rel : mz_abs).add(e.dMz);
        if (e.has_spin) w.add(e.dW);
        if (e.partial_slip && e.has_map) {
            map.add(e.map_L1);
            profile.add(e.profile_L1);
        }
    }
};

void print_row(const char* name, const Summary& s)
{
    std::printf("| %-20s | %5.2f / %5.2f | %5.2f / %5.2f | %5.1f / %5.1f | %5.2f | %5.1f / %5.1f ",
                name, s.fx.median(), s.fx.worst(), s.fy.median(), s.fy.worst(),
                s.mz_rel.median(), s.mz_rel.worst(), s.mz_abs.worst(), s.w.median(),
                s.w.worst());
    if (s.map.v.empty())
        std::printf("| - | - |\n");
    else
        std::printf("| %4.2f / %4.2f | %5.3f / %5.3f |\n", s.map.median(), s.map.worst(),
                    s.profile.median(), s.profile.worst());
}

// Cases beyond a bound, "k of n".
std::string beyond(const Stats& s, double bound)
{
    const long k = std::count_if(s.v.begin(), s.v.end(), [bound](double x) { return x > bound; });
    return std::to_string(k) + " of " + std::to_string(s.v.size());
}

// The accuracy targets (doc/validation/calibrated.md), one row each: per
// model the cases beyond the bound and the median or worst that matters.
void print_targets(const std::vector<std::string>& names, const std::vector<Summary>& sums)
{
    std::printf("| target |");
    for (const std::string& n : names) std::printf(" %s |", n.c_str());
    std::printf("\n|---|");
    for (size_t k = 0; k < names.size(); ++k) std::printf("---|");
    std::printf("\n");
    const auto row = [&](const char* target, const std::function<std::string(const Summary&)>& f) {
        std::printf("| %s |", target);
        for (const Summary& s : sums) std::printf(" %s |", f(s).c_str());
        std::printf("\n");
    };
    char b[96];
    row("forces: \\|dFx\\|, \\|dFy\\| <= 3 % of mu N in every case", [&](const Summary& s) {
        std::snprintf(b, sizeof b, "%s above, worst %.1f", beyond(s.force, 3.0).c_str(),
                      s.force.worst());
        return std::string(b);
    });
    row("creep moment: median dMz <= 8 %", [&](const Summary& s) {
        std::snprintf(b, sizeof b, "median %.1f %%", s.mz_rel.median());
        return std::string(b);
    });
    row("creep moment: dMz <= 20 % where \\|Mz\\| >= 0.01 mu N c", [&](const Summary& s) {
        std::snprintf(b, sizeof b, "%s above, worst %.0f %%", beyond(s.mz_rel, 20.0).c_str(),
                      s.mz_rel.worst());
        return std::string(b);
    });
    row("small moments: \\|dMz\\| <= 0.5 % of mu N c", [&](const Summary& s) {
        std::snprintf(b, sizeof b, "%s above, worst %.2f", beyond(s.mz_abs, 0.5).c_str(),
                      s.mz_abs.worst());
        return std::string(b);
    });
    row("work: dW <= 5 % in every case with spin", [&](const Summary& s) {
        std::snprintf(b, sizeof b, "%s above, worst %.1f", beyond(s.w, 5.0).c_str(), s.w.worst());
        return std::string(b);
    });
    row("work map: L1 <= 0.3 in partial slip", [&](const Summary& s) {
        if (s.map.v.empty()) return std::string("-");
        std::snprintf(b, sizeof b, "%s above, median %.2f", beyond(s.map, 0.3).c_str(),
                      s.map.median());
        return std::string(b);
    });
    row("lateral profile: L1 <= 0.08 in partial slip", [&](const Summary& s) {
        if (s.profile.v.empty()) return std::string("-");
        std::snprintf(b, sizeof b, "%s above, median %.3f", beyond(s.profile, 0.08).c_str(),
                      s.profile.median());
        return std::string(b);
    });
}

CaseSet parse_set(const char* s)
{
    if (!std::strcmp(s, "training")) return CaseSet::training;
    if (!std::strcmp(s, "evaluation")) return CaseSet::evaluation;
    std::fprintf(stderr, "set must be training or evaluation, not '%s'\n", s);
    std::exit(2);
}

// ns per contact element of a full-mode solve (totals and work sums, no
// field copied), best of many short samples as creepwork_bench does, for the
// bench's partial-slip contact on its Kalker strip grid and on the uniform
// map grid.
int time_models()
{
    cw::ContactInput in;
    in.a = 7.169984332e-3;
    in.b = 5.416941278e-3;
    in.normal_force = 100e3;
    in.mu = 0.3;
    in.G = 82e9;
    in.nu = 0.28;
    in.xi_x = 6e-4;
    in.xi_y = 3e-4;
    in.phi = 0.2;
    std::printf("| grid | FASTSIM parabolic | FASTSIM elliptic | calibrated | calibrated / "
                "parabolic |\n|---|---|---|---|---|\n");
    for (int kind = 0; kind < 2; ++kind)
        for (int n : {20, 40}) {
            cw::GridSpec g;
            g.kind = kind ? cw::GridKind::uniform : cw::GridKind::kalker_strips;
            g.nx = g.ny = n;
            cw::Solver s(g);
            double best[3] = {1e30, 1e30, 1e30};
            for (int sample = 0; sample < 200; ++sample)
                for (int m = 0; m < 3; ++m) {
                    in.model = m == 2 ? cw::ModelKind::calibrated : cw::ModelKind::fastsim;
                    in.pressure = m == 1 ? cw::PressureKind::elliptic : cw::PressureKind::parabolic;
                    const int reps = 50;
                    const auto t0 = std::chrono::steady_clock::now();
                    // The creepage alternates by 0.1 %, so that the calibrated
                    // model remakes its blended bound in every solve (as in a
                    // vehicle loop), not only the first.
                    for (int r = 0; r < reps; ++r) {
                        in.xi_x = r % 2 ? 6e-4 * 1.001 : 6e-4;
                        s.solve(in, cw::SolveMode::full);
                    }
                    const double ns = std::chrono::duration<double, std::nano>(
                                          std::chrono::steady_clock::now() - t0)
                                          .count() /
                                      (reps * double(s.grid().n_contact()));
                    best[m] = std::min(best[m], ns);
                }
            std::printf("| %s %d x %d | %.1f | %.1f | %.1f | %.2f |\n",
                        kind ? "uniform" : "Kalker strips", n, n, best[0], best[1], best[2],
                        best[2] / best[0]);
        }
    return 0;
}

// Pure spin from 2 % to 300 % of saturation (s = phi G c^3 C23 / (mu N)),
// a/b = 1 and 2, nu = 0.28: Mz / (mu N c) and W_macro / (mu N) of each
// model (CSV, for doc/validation/calibrated_spin.png; the exact model on 80 x 80).
int spin_sweep()
{
    std::printf("a_over_b,s_spin,model,Mz_over_muNc,W_over_muN\n");
    cw::Solver s40(uniform_grid(kMapN)), s80(uniform_grid(kRefN));
    for (double ab : {1.0, 2.0})
        for (int q = 0; q <= 24; ++q) {
            const double level = 0.02 * std::pow(150.0, q / 24.0);
            cw::ContactInput in;
            const double c = 6e-3;
            in.a = c * std::sqrt(ab);
            in.b = c / std::sqrt(ab);
            in.normal_force = 10e3;
            in.mu = 0.3;
            in.G = 82e9;
            in.nu = 0.28;
            const double muN = in.mu * in.normal_force;
            in.phi = level * muN / (in.G * c * c * c * cw::kalker_coefficients(ab, in.nu).C23);
            struct Row {
                const char* name;
                cw::ModelKind model;
                cw::PressureKind pressure;
                cw::Solver* solver;
            } rows[] = {{"FASTSIM parabolic", cw::ModelKind::fastsim, cw::PressureKind::parabolic, &s40},
                        {"FASTSIM elliptic", cw::ModelKind::fastsim, cw::PressureKind::elliptic, &s40},
                        {"calibrated", cw::ModelKind::calibrated, cw::PressureKind::parabolic, &s40},
                        {"exact 80 x 80", cw::ModelKind::exact, cw::PressureKind::elliptic, &s80}};
            for (const Row& r : rows) {
                in.model = r.model;
                in.pressure = r.pressure;
                in.warm_start = false;
                const cw::SolveTotals& t = r.solver->solve(in, cw::SolveMode::forces_only);
                std::printf("%g,%.5g,%s,%.6g,%.6g\n", ab, level, r.name, t.Mz / (muN * c),
                            t.W_macro / muN);
            }
        }
    return 0;
}

struct Model {
    using Run = std::function<ModelResult(const CalibrationCase&, const CaseReference&)>;
    const char* name;
    Run run;
};

// What the models are measured against (CaseReference).
enum class Yardstick { exact80, continuum };

// The summary table (evaluate) or the per-case CSV (cases) of every model
// against the yardstick.
void report(const std::string& cmd, CaseSet set, const std::vector<CalibrationCase>& cases,
            const std::vector<CaseReference>& refs, const std::vector<Model>& models, Yardstick y,
            bool markdown = false)
{
    const bool continuum = y == Yardstick::continuum;
    std::vector<std::string> target_names;
    std::vector<Summary> target_sums;
    if (markdown)
        ; // the tables alone: the documentation says what they measure
    else if (cmd == "cases")
        std::printf("yardstick,model,case,a_over_b,nu,level,combo,dFx,dFy,mz_relative,dMz,dW,"
                    "partial_slip,map_L1,profile_L1,Fx_ref,Fy_ref,Fx,Fy,adhesion_ref,adhesion,"
                    "Mz_ref,Mz\n");
    else if (continuum)
        std::printf("%s set, %zu cases; yardstick: the exact model's continuum estimate (totals: "
                    "Richardson from %d, %d, %d across with the observed order when clean, else "
                    "%d; maps: %d x %d summed onto %d x %d cells)\n\n",
                    set_name(set), cases.size(), kMapN, kRefN, kFineN, kFineN, kFineN, kFineN,
                    kMapN, kMapN);
    else
        std::printf("%s set, %zu cases; yardstick: exact model %d x %d (maps %d x %d)\n\n",
                    set_name(set), cases.size(), kRefN, kRefN, kMapN, kMapN);
    if (cmd == "evaluate")
        std::printf("| model | dFx %%muN med / max | dFy %%muN med / max | dMz %% med / max | "
                    "dMz small, max %%muNc | dW %% med / max (spin) | map L1 med / max | "
                    "profile L1 med / max |\n|---|---|---|---|---|---|---|---|\n");
    for (const Model& m : models) {
        Summary s;
        for (size_t k = 0; k < cases.size(); ++k) {
            const ModelResult r = m.run(cases[k], refs[k]);
            const ModelResult& ref = continuum ? refs[k].limit : refs[k].ref;
            const ModelResult& ref_map = continuum ? refs[k].limit : refs[k].exact40;
            const CaseErrors e = case_errors(cases[k].input, r, ref, ref_map, kMapN, kMapN);
            s.add(e, cases[k].input);
            // The signed forces (in mu N) and adhesion fractions show whether
            // a force error is one of magnitude or of direction.
            const double muN = cases[k].input.mu * cases[k].input.normal_force;
            const double c = std::sqrt(cases[k].input.a * cases[k].input.b);
            if (cmd == "cases")
                std::printf("%s,%s,%s,%g,%g,%g,%d,%.4g,%.4g,%d,%.4g,%.4g,%d,%.4g,%.4g,%.5f,%.5f,"
                            "%.5f,%.5f,%.3f,%.3f,%.5f,%.5f\n",
                            continuum ? "continuum" : "exact80", m.name, cases[k].id.c_str(),
                            cases[k].a_over_b, cases[k].nu, cases[k].level, cases[k].combo, e.dFx,
                            e.dFy, int(e.mz_relative), e.dMz, e.has_spin ? e.dW : NAN,
                            int(e.partial_slip), e.map_L1, e.profile_L1, ref.Fx / muN,
                            ref.Fy / muN, r.Fx / muN, r.Fy / muN, ref_map.adhesion_fraction,
                            r.adhesion_fraction, ref.Mz / (muN * c), r.Mz / (muN * c));
        }
        if (cmd == "evaluate") print_row(m.name, s);
        // The targets are about the simplified models (the exact rows are
        // the yardstick's own grids).
        if (markdown && std::strncmp(m.name, "exact", 5) != 0) {
            target_names.push_back(m.name);
            target_sums.push_back(s);
        }
    }
    if (markdown) {
        std::printf("\n");
        print_targets(target_names, target_sums);
    }
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: creepwork_calibration evaluate|cases|oracle <set> [cache-dir] | "
                             "fit [cache-dir] | select-weights [cache-dir]\n");
        return 2;
    }
    const std::string cmd = argv[1];
    if (cmd == "time") return time_models();
    if (cmd == "spin-sweep") return spin_sweep();
    if (cmd == "discretisation") return discretisation_study(argc > 2 ? argv[2] : ".");
    if (cmd == "fit" || cmd == "select-weights") {
        const std::string dir = argc > 2 ? argv[2] : ".";
        const std::vector<CalibrationCase> cases = make_cases(CaseSet::training);
        std::vector<CaseReference> refs = exact_references(cases, dir + "/exact_training.txt");
        continuum_references(cases, refs, dir + "/exact_training_160.txt");
        return cmd == "fit" ? fit_table(cases, refs) : select_weights(cases, refs);
    }
    if (cmd == "oracle" && argc > 2) return oracle_study(parse_set(argv[2]), argc > 3 ? argv[3] : ".");
    if (argc < 3 || (cmd != "evaluate" && cmd != "cases")) {
        std::fprintf(stderr, "unknown command '%s'\n", cmd.c_str());
        return 2;
    }
    const CaseSet set = parse_set(argv[2]);
    const bool markdown = argc > 4 && !std::strcmp(argv[4], "--markdown");
    const std::string dir = argc > 3 ? argv[3] : ".";
    const std::vector<CalibrationCase> cases = make_cases(set);
    std::vector<CaseReference> refs =
        exact_references(cases, dir + "/exact_" + set_name(set) + ".txt");

    cw::Solver solver(uniform_grid(kMapN));
    auto simplified = [&](cw::ModelKind kind, cw::PressureKind p) {
        return [&solver, kind, p](const CalibrationCase& c, const CaseReference&) {
            cw::ContactInput in = c.input;
            in.model = kind;
            in.pressure = p;
            if (kind == cw::ModelKind::calibrated && std::getenv("CW_TRY_OFFSET"))
                in.spin_offset = std::atof(std::getenv("CW_TRY_OFFSET"));
            return solved_result(solver, in);
        };
    };
    // CW_CALIBRATION_TRY="pressure k_long k_lat k_spin_x k_spin_y equalise lateral edge_gain" (pressure
    // 0 parabolic, 1 elliptic): one more row with these parameters for every
    // case, to explore before fitting.
    cw::CalibrationParams trial;
    const char* try_env = std::getenv("CW_CALIBRATION_TRY");
    if (try_env) {
        int p = 1;
        std::sscanf(try_env, "%d %lf %lf %lf %lf %lf %lf %lf", &p, &trial.k_long, &trial.k_lat,
                    &trial.k_spin_x, &trial.k_spin_y, &trial.equalise, &trial.lateral_moment,
                    &trial.edge_gain);
        trial.pressure = p ? cw::PressureKind::elliptic : cw::PressureKind::parabolic;
    }
    // CW_TRY_BLEND=b: the calibrated row with the table's parameters but the
    // traction bound blend b (calibrated/blended_bound.hpp; clamped to [0, 1]).
    const char* blend_env = std::getenv("CW_TRY_BLEND");
    std::vector<Model> models = {
        {"FASTSIM parabolic", simplified(cw::ModelKind::fastsim, cw::PressureKind::parabolic)},
        {"FASTSIM elliptic", simplified(cw::ModelKind::fastsim, cw::PressureKind::elliptic)},
        {"calibrated",
         blend_env ? Model::Run([&](const CalibrationCase& c, const CaseReference&) {
             cw::ContactInput in = c.input;
             in.model = cw::ModelKind::calibrated;
             cw::CalibrationParams p = cw::calibration_for(in);
             if (*blend_env) p.bound_blend = std::atof(blend_env);
             if (const char* x = std::getenv("CW_TRY_KSCALE")) {
                 const double f = 1.0 + std::atof(x) * p.bound_blend;
                 p.k_long *= f; p.k_lat *= f; p.k_spin_x *= f; p.k_spin_y *= f;
             }
             if (const char* x = std::getenv("CW_TRY_H")) p.equalise = std::atof(x);
             if (std::getenv("CW_TRY_KEQ")) p.k_long = p.k_lat = p.k_spin_x = p.k_spin_y = 1.0;
             return calibrated_result(solver.calibrated_model(), in, p);
         })
                   : Model::Run(simplified(cw::ModelKind::calibrated, cw::PressureKind::parabolic))},
        {"exact 20 x 20", [](const CalibrationCase&, const CaseReference& r) { return r.exact20; }},
        // Its map is the map reference itself: no map error to report.
        {"exact 40 x 40",
         [](const CalibrationCase&, const CaseReference& r) {
             ModelResult m = r.exact40;
             m.work_map.clear();
             return m;
         }},
    };
    if (try_env)
        models.push_back({"trial", [&](const CalibrationCase& c, const CaseReference&) {
                              cw::ContactInput in = c.input;
                              in.model = cw::ModelKind::calibrated;
                              return calibrated_result(solver.calibrated_model(), in, trial);
                          }});
    // Against the exact 80 x 80 totals and the exact 40 x 40 maps (a
    // yardstick with the exact model's own discretisation error) ...
    if (!markdown) report(cmd, set, cases, refs, models, Yardstick::exact80);
    // ... and against the exact model's continuum estimate (Richardson from
    // 40, 80, 160; maps of the 160 x 160 solve summed onto the 40 x 40
    // cells), with the simplified models also on 160 x 160 (maps summed the
    // same way): the models' own error, without the grid's.
    continuum_references(cases, refs, dir + "/exact_" + set_name(set) + "_160.txt");
    cw::Solver fine_solver(uniform_grid(kFineN));
    const auto on_fine_grid = [&fine_solver](cw::ModelKind kind, cw::PressureKind p) {
        return [&fine_solver, kind, p](const CalibrationCase& c, const CaseReference&) {
            cw::ContactInput in = c.input;
            in.model = kind;
            in.pressure = p;
            ModelResult r = solved_result(fine_solver, in);
            r.work_map = summed_onto_map_grid(r.work_map);
            return r;
        };
    };
    models.insert(models.begin() + 3,
                  {{"FASTSIM par. 160", on_fine_grid(cw::ModelKind::fastsim, cw::PressureKind::parabolic)},
                   {"calibrated 160", on_fine_grid(cw::ModelKind::calibrated, cw::PressureKind::parabolic)}});
    // Here the exact 40 x 40 map is a model's map like the others.
    for (Model& m : models)
        if (!std::strcmp(m.name, "exact 40 x 40"))
            m.run = [](const CalibrationCase&, const CaseReference& r) { return r.exact40; };
    models.push_back({"exact 80 x 80", [](const CalibrationCase&, const CaseReference& r) {
                          ModelResult m = r.ref;
                          m.work_map.clear();
                          return m;
                      }});
    if (cmd == "evaluate" && !markdown) std::printf("\n");
    report(cmd, set, cases, refs, models, Yardstick::continuum, markdown);
    return 0;
}
