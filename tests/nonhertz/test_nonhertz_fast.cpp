// The semi-Hertzian normal method (normal/semi_hertz.hpp) against the
// exact half-space normal problem on the same gaps, with the exact model's
// tangential problem on each pressure: the DEV shapes of
// tests/data/nonhertz/dev and the shapes of gap_shapes.hpp.
//
// Bounds: contact area (element count) within 10 % of the exact problem's on
// the DEV shapes (issue 24's target) and within 12 % on the new shapes (the
// lateral ripple of N11 is 11.3 % short; doc/validation/non-hertzian.md).
// `test_nonhertz_fast --markdown dev|new` prints the page's tables (the same
// comparisons; scripts/doc-tables.sh pastes and checks them).
#include "gap_shape_grid.hpp"
#include "gap_shapes.hpp"
#include "gap_test_support.hpp"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace cw = creepwork;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string pct(double v, bool sign = true)
{
    char b[16];
    std::snprintf(b, sizeof b, sign ? "%+.1f" : "%.1f", 100.0 * v);
    return b;
}

// Exact and fast on one case; returns |area error| and appends the row.
double compare(const std::string& id, const cw::GridSpec& g, cw::ContactInput in,
               std::string& table)
{
    in.warm_start = false;
    cw::Solver s(g);
    const cw::SolveTotals e = s.solve(in, cw::SolveMode::full);
    cw::ContactInput f = in;
    f.normal_method = cw::NormalMethod::semi_hertz;
    const cw::SolveTotals t = s.solve(f, cw::SolveMode::full);
    const bool approach = in.normal_load == cw::NormalLoad::approach;
    const double muN = in.mu * e.normal_force;
    const double c = std::sqrt(e.n_contact * g.dx * g.dy / kPi);
    const double area = double(t.n_contact) / e.n_contact - 1.0;
    table += "| " + id + " | " + pct(area) + " | " + pct(t.p_max / e.p_max - 1.0) + " | " +
             (approach ? pct(t.normal_force / e.normal_force - 1.0) + " (Fn)"
                       : pct((t.approach - e.approach) / std::fabs(e.approach))) +
             " | " + pct(std::max(std::fabs(t.Fx - e.Fx), std::fabs(t.Fy - e.Fy)) / muN, false) +
             " | " + pct(std::fabs(t.Mz - e.Mz) / (muN * c), false) + " |\n";
    return std::fabs(area);
}

std::string header()
{
    return "| case | area | p_max | approach | forces / mu N | Mz / (mu N c) |\n"
           "|---|---:|---:|---:|---:|---:|\n";
}

// The table of a set and its worst area error.
double run_dev(std::string& table)
{
    table = header();
    double worst = 0.0;
    for (const cwtest::GapCase& c : cwtest::dev_cases())
        worst = std::max(worst, compare(c.id, c.gap.grid, c.bind(), table));
    return worst;
}

double run_new(std::string& table)
{
    const cwtest::CsvTable t =
        cwtest::read_quoted_csv(std::string(CW_NONHERTZ_DATA_DIR) + "/contact_cases.csv");
    table = header();
    double worst = 0.0;
    const std::vector<gapshapes::Shape> shapes = gapshapes::shapes();
    for (size_t r = 0; r < shapes.size(); ++r) {
        const gapshapes::Shape& s = shapes[r];
        const cw::GridSpec g = gapshapes::grid_of(s);
        cw::ContactInput in = gapshapes::contact_input(s);
        in.model = cw::ModelKind::exact;
        in.xi_x = t.number(r, "xi_x");
        in.xi_y = t.number(r, "xi_y");
        in.phi = t.number(r, "phi_per_m");
        worst = std::max(worst, compare(s.id, g, in, table));
    }
    return worst;
}

void dev_shapes(void**)
{
    std::string table;
    const double worst = run_dev(table);
    print_message("DEV: area within %.1f %%\n", 100.0 * worst);
    assert_true(worst <= 0.10);
}

void new_shapes(void**)
{
    std::string table;
    const double worst = run_new(table);
    print_message("new shapes: area within %.1f %%\n", 100.0 * worst);
    assert_true(worst <= 0.12);
}

} // namespace

int main(int argc, char** argv)
{
    if (argc == 3 && std::strcmp(argv[1], "--markdown") == 0) {
        std::string table;
        if (std::strcmp(argv[2], "new") == 0)
            run_new(table);
        else
            run_dev(table);
        std::fputs(table.c_str(), stdout);
        return 0;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(dev_shapes),
        cmocka_unit_test(new_shapes),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
