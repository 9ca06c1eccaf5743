#include "calibration_reference.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "calibration_limit.hpp"
#include "solver.hpp"

namespace cwcal {
namespace {

namespace cw = creepwork;

ModelResult solve_exact(cw::Solver& s, cw::ContactInput in, bool with_map)
{
    in.model = cw::ModelKind::exact;
    in.pressure = cw::PressureKind::elliptic;
    in.warm_start = false; // every case on its own: results do not depend on order
    const cw::SolveTotals& t = s.solve(in, cw::SolveMode::full);
    ModelResult r;
    r.Fx = t.Fx;
    r.Fy = t.Fy;
    r.Mz = t.Mz;
    r.W = t.W_macro;
    r.adhesion_fraction = t.adhesion_fraction;
    if (with_map) {
        r.work_map.resize(size_t(s.grid().nx()) * s.grid().ny());
        s.copy_field(cw::Field::work_consistent, r.work_map.data());
    }
    return r;
}

void write_result(std::ostream& o, const ModelResult& r)
{
    o << ' ' << r.Fx << ' ' << r.Fy << ' ' << r.Mz << ' ' << r.W << ' ' << r.adhesion_fraction
      << ' ' << r.work_map.size();
    for (double v : r.work_map) o << ' ' << v;
}

bool read_result(std::istream& in, ModelResult& r)
{
    size_t n = 0;
    if (!(in >> r.Fx >> r.Fy >> r.Mz >> r.W >> r.adhesion_fraction >> n)) return false;
    r.work_map.resize(n);
    for (double& v : r.work_map)
        if (!(in >> v)) return false;
    return true;
}

// Reads one line per case of the cache (id, then the results picked by
// slots); true when every case was there.
template <class Slots>
bool read_cache(const std::vector<CalibrationCase>& cases, std::vector<CaseReference>& refs,
                const std::string& path, Slots slots)
{
    std::ifstream in(path);
    std::string line;
    size_t k = 0;
    while (k < cases.size() && std::getline(in, line)) {
        std::istringstream row(line);
        std::string id;
        row >> id;
        if (id != cases[k].id) break;
        bool ok = true;
        for (ModelResult* r : slots(refs[k])) ok = ok && read_result(row, *r);
        if (!ok) break;
        ++k;
    }
    return k == cases.size();
}

// Solves every case (solve(case, ref) fills the slots) and writes the cache.
template <class Slots, class Solve>
void write_cache(const std::vector<CalibrationCase>& cases, std::vector<CaseReference>& refs,
                 const std::string& path, Slots slots, Solve solve)
{
    std::ofstream out(path);
    out.precision(17);
    for (size_t k = 0; k < cases.size(); ++k) {
        solve(cases[k], refs[k]);
        out << cases[k].id;
        for (ModelResult* r : slots(refs[k])) write_result(out, *r);
        out << '\n';
        std::fprintf(stderr, "\rexact references: %zu/%zu", k + 1, cases.size());
    }
    std::fprintf(stderr, "\n");
}

ModelResult continuum_estimate(const CaseReference& r, const cw::ContactInput& in)
{
    const double h[3] = {1.0 / kMapN, 1.0 / kRefN, 1.0 / kFineN};
    const double muN = in.mu * in.normal_force, c = std::sqrt(in.a * in.b);
    const auto limit = [&](double ModelResult::*q, double scale) {
        const double v[3] = {r.exact40.*q, r.ref.*q, r.fine.*q};
        return continuum_limit(h, v, scale).value;
    };
    ModelResult L = r.fine;
    L.Fx = limit(&ModelResult::Fx, muN);
    L.Fy = limit(&ModelResult::Fy, muN);
    L.Mz = limit(&ModelResult::Mz, muN * c);
    L.W = limit(&ModelResult::W, muN);
    return L;
}

} // namespace

cw::GridSpec uniform_grid(int n)
{
    cw::GridSpec g;
    g.kind = cw::GridKind::uniform;
    g.nx = g.ny = n;
    g.box_scale = 1.0;
    return g;
}

std::vector<double> summed_onto_map_grid(const std::vector<double>& fine)
{
    static_assert(kFineN % kMapN == 0, "the fine grid must nest in the map grid");
    return summed_onto_coarse_grid(fine, kFineN, kMapN);
}

std::vector<CaseReference> exact_references(const std::vector<CalibrationCase>& cases,
                                            const std::string& cache_path)
{
    std::vector<CaseReference> refs(cases.size());
    const auto slots = [](CaseReference& r) {
        return std::vector<ModelResult*>{&r.exact20, &r.exact40, &r.ref};
    };
    if (read_cache(cases, refs, cache_path, slots)) return refs;
    cw::Solver s20(uniform_grid(20)), s40(uniform_grid(kMapN)), sref(uniform_grid(kRefN));
    write_cache(cases, refs, cache_path, slots, [&](const CalibrationCase& c, CaseReference& r) {
        r.exact20 = solve_exact(s20, c.input, false);
        r.exact40 = solve_exact(s40, c.input, true);
        r.ref = solve_exact(sref, c.input, false);
    });
    return refs;
}

void continuum_references(const std::vector<CalibrationCase>& cases,
                          std::vector<CaseReference>& refs, const std::string& cache_path)
{
    const auto slots = [](CaseReference& r) { return std::vector<ModelResult*>{&r.fine}; };
    if (!read_cache(cases, refs, cache_path, slots)) {
        cw::Solver sfine(uniform_grid(kFineN));
        write_cache(cases, refs, cache_path, slots,
                    [&](const CalibrationCase& c, CaseReference& r) {
                        r.fine = solve_exact(sfine, c.input, true);
                        r.fine.work_map = summed_onto_map_grid(r.fine.work_map);
                    });
    }
    for (size_t k = 0; k < cases.size(); ++k)
        refs[k].limit = continuum_estimate(refs[k], cases[k].input);
}

} // namespace cwcal
