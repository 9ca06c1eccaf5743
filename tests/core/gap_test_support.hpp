// Helpers for the non-Hertzian tests: gap files (x_m,y_m,h_m at the cell
// centres of a regular grid, tests/data/README.md), the
// DEV cases of tests/data/nonhertz/dev/cases.csv and the cases of
// tests/core/data/nonhertz (CONTACT commit d431cdb, module 3) as solver
// inputs, a reading of CONTACT's element fields, and the elliptic contact of
// the Hertzian-gap checks.
#pragma once

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core_test_support.hpp"

namespace cwtest {

// A CSV table whose cells may be quoted ("a, b"), as cases.csv's descriptions.
inline CsvTable read_quoted_csv(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    CsvTable t;
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        std::vector<std::string> cells(1);
        bool quoted = false;
        for (char ch : line) {
            if (ch == '"')
                quoted = !quoted;
            else if (ch == ',' && !quoted)
                cells.emplace_back();
            else
                cells.back() += ch;
        }
        if (t.header.empty())
            t.header = cells;
        else
            t.rows.push_back(cells);
    }
    return t;
}

struct GapFile {
    creepwork::GridSpec grid; // kind gap
    std::vector<double> h;    // [i + nx j]
};

// Sorted distinct values of v, merged within tol.
inline std::vector<double> distinct(std::vector<double> v, double tol)
{
    std::sort(v.begin(), v.end());
    std::vector<double> out;
    for (double x : v)
        if (out.empty() || x - out.back() > tol) out.push_back(x);
    return out;
}

// The regular grid of a table with columns x, y and the value column.
inline GapFile grid_of(const CsvTable& t, const std::string& xc, const std::string& yc,
                       const std::string& vc)
{
    std::vector<double> xs, ys;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        xs.push_back(t.number(r, xc));
        ys.push_back(t.number(r, yc));
    }
    const auto span = [](const std::vector<double>& v) {
        return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
    };
    const std::vector<double> ux = distinct(xs, 1e-9 * span(xs)), uy = distinct(ys, 1e-9 * span(ys));
    GapFile g;
    g.grid.kind = creepwork::GridKind::gap;
    g.grid.nx = static_cast<int>(ux.size());
    g.grid.ny = static_cast<int>(uy.size());
    g.grid.x0 = ux.front();
    g.grid.y0 = uy.front();
    g.grid.dx = (ux.back() - ux.front()) / (g.grid.nx - 1);
    g.grid.dy = (uy.back() - uy.front()) / (g.grid.ny - 1);
    if (t.rows.size() != ux.size() * uy.size()) throw std::runtime_error("not a regular grid");
    g.h.assign(t.rows.size(), 0.0);
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const int i = static_cast<int>(std::lround((xs[r] - g.grid.x0) / g.grid.dx));
        const int j = static_cast<int>(std::lround((ys[r] - g.grid.y0) / g.grid.dy));
        g.h[i + static_cast<size_t>(g.grid.nx) * j] = t.number(r, vc);
    }
    return g;
}

inline GapFile read_gap(const std::string& path)
{
    return grid_of(read_csv(path), "x_m", "y_m", "h_m");
}

// One non-Hertzian case with CONTACT's exact results (SI units).
struct GapCase {
    std::string id, description;
    GapFile gap;
    creepwork::ContactInput input; // model exact, gap pointer set by bind()
    double Fn, Fx, Fy, Mz, p_max, approach, W_macro;
    int n_contact, n_adhesion, n_slip, n_patches;

    // The input with the gap pointer of this (not a copied) case.
    creepwork::ContactInput bind() const
    {
        creepwork::ContactInput in = input;
        in.gap = gap.h.data();
        in.gap_len = gap.h.size();
        return in;
    }
};

// Rows of a cases table in the DEV layout (cases.csv): gap files relative to
// the table's folder.
inline std::vector<GapCase> gap_cases(const std::string& folder, const std::string& table)
{
    const CsvTable t = read_quoted_csv(folder + "/" + table);
    std::vector<GapCase> cases;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        GapCase c;
        c.id = t.text(r, "case_id");
        c.description = t.text(r, "description");
        c.gap = read_gap(folder + "/" + t.text(r, "gap_file"));
        creepwork::ContactInput& in = c.input;
        in.model = creepwork::ModelKind::exact;
        in.normal_force = t.number(r, "N_N");
        in.G = t.number(r, "G_Pa");
        in.nu = t.number(r, "nu");
        in.mu = t.number(r, "mu");
        in.xi_x = t.number(r, "xi_x");
        in.xi_y = t.number(r, "xi_y");
        in.phi = t.number(r, "phi_per_m");
        in.warm_start = false;
        c.Fn = t.number(r, "Fn_N");
        c.Fx = t.number(r, "Fx_N");
        c.Fy = t.number(r, "Fy_N");
        c.Mz = t.number(r, "Mz_Nm");
        c.p_max = t.number(r, "p_max_Pa");
        c.approach = t.number(r, "approach_m");
        c.W_macro = t.number(r, "W_macro_J_per_m");
        c.n_contact = static_cast<int>(t.number(r, "n_contact"));
        c.n_adhesion = static_cast<int>(t.number(r, "n_adhesion"));
        c.n_slip = static_cast<int>(t.number(r, "n_slip"));
        c.n_patches = static_cast<int>(t.number(r, "n_patches"));
        cases.push_back(std::move(c));
    }
    return cases;
}

inline std::vector<GapCase> dev_cases()
{
    return gap_cases(test_data_path("nonhertz/dev"), "cases.csv");
}

// CONTACT's element fields of a case (x_m,y_m,eldiv,pn_Pa,px_Pa,py_Pa) on the
// case's grid [i + nx j].
struct ContactFields {
    std::vector<int> eldiv;
    std::vector<double> pn, px, py;
};

inline ContactFields read_contact_fields(const std::string& path, const creepwork::GridSpec& g)
{
    const CsvTable t = read_csv(path);
    ContactFields f;
    const size_t n = static_cast<size_t>(g.nx) * g.ny;
    f.eldiv.assign(n, 0);
    f.pn.assign(n, 0.0);
    f.px.assign(n, 0.0);
    f.py.assign(n, 0.0);
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const int i = static_cast<int>(std::lround((t.number(r, "x_m") - g.x0) / g.dx));
        const int j = static_cast<int>(std::lround((t.number(r, "y_m") - g.y0) / g.dy));
        const size_t k = i + static_cast<size_t>(g.nx) * j;
        f.eldiv[k] = static_cast<int>(t.number(r, "eldiv"));
        f.pn[k] = t.number(r, "pn_Pa");
        f.px[k] = t.number(r, "px_Pa");
        f.py[k] = t.number(r, "py_Pa");
    }
    return f;
}

// The elliptic contact whose Hertzian gap the gap models must reproduce:
// steel, a / b = 1.4, partial slip with spin, the exact model at tolerance
// 1e-12, cold; on a kHertzianGapCells-square uniform grid of box scale
// kHertzianGapScale (gapshapes::hertzian_gap builds that grid's gap).
constexpr int kHertzianGapCells = 24;
constexpr double kHertzianGapScale = 1.2;
inline creepwork::ContactInput hertzian_gap_reference()
{
    creepwork::ContactInput e = steel_contact(1.4);
    e.model = creepwork::ModelKind::exact;
    e.xi_x = 4e-4;
    e.xi_y = -3e-4;
    e.phi = 0.3;
    e.tolerance = 1e-12;
    e.warm_start = false;
    return e;
}

} // namespace cwtest
