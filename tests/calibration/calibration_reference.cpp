#include "calibration_reference.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "solver.hpp"

namespace cwcal {
namespace {

namespace cw = creepwork;

cw::GridSpec uniform(int n)
{
    cw::GridSpec g;
    g.kind = cw::GridKind::uniform;
    g.nx = g.ny = n;
    g.box_scale = 1.0;
    return g;
}

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

} // namespace

std::vector<CaseReference> exact_references(const std::vector<CalibrationCase>& cases,
                                            const std::string& cache_path)
{
    std::vector<CaseReference> refs(cases.size());
    {
        std::ifstream in(cache_path);
        std::string line;
        size_t k = 0;
        while (k < cases.size() && std::getline(in, line)) {
            std::istringstream row(line);
            std::string id;
            row >> id;
            if (id != cases[k].id) break;
            if (!read_result(row, refs[k].exact20) || !read_result(row, refs[k].exact40) ||
                !read_result(row, refs[k].ref))
                break;
            ++k;
        }
        if (k == cases.size()) return refs;
    }
    cw::Solver s20(uniform(20)), s40(uniform(kMapN)), sref(uniform(kRefN));
    std::ofstream out(cache_path);
    out.precision(17);
    for (size_t k = 0; k < cases.size(); ++k) {
        refs[k].exact20 = solve_exact(s20, cases[k].input, false);
        refs[k].exact40 = solve_exact(s40, cases[k].input, true);
        refs[k].ref = solve_exact(sref, cases[k].input, false);
        out << cases[k].id;
        write_result(out, refs[k].exact20);
        write_result(out, refs[k].exact40);
        write_result(out, refs[k].ref);
        out << '\n';
        std::fprintf(stderr, "\rexact references: %zu/%zu", k + 1, cases.size());
    }
    std::fprintf(stderr, "\n");
    return refs;
}

} // namespace cwcal
