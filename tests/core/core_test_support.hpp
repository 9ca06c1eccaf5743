// Helpers for the core tests: CSV reading and common contact set-ups.
#pragma once

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver.hpp"

namespace cwtest {

// A CSV table with a header row; cells addressed by column name.
struct CsvTable {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;

    double number(size_t row, const std::string& column) const
    {
        return std::stod(text(row, column));
    }
    const std::string& text(size_t row, const std::string& column) const
    {
        for (size_t c = 0; c < header.size(); ++c)
            if (header[c] == column) return rows[row][c];
        throw std::runtime_error("no column " + column);
    }
};

inline CsvTable read_csv(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    CsvTable t;
    std::string line;
    bool first = true;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back(); // CRLF files
        if (line.empty()) continue;
        std::vector<std::string> cells;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) cells.push_back(cell);
        if (first) {
            t.header = cells;
            first = false;
        } else {
            cells.resize(t.header.size());
            t.rows.push_back(cells);
        }
    }
    return t;
}

// Half a unit of a printed number's last digit ("-0.4733" 5e-5,
// "1.870E-03" 5e-7): how far a value may lie from it and still print so.
inline double printed_half_digit(const std::string& text)
{
    const auto e = text.find_first_of("Ee");
    const std::string mant = text.substr(0, e);
    const auto dot = mant.find('.');
    const int decimals = dot == std::string::npos ? 0 : int(mant.size() - dot - 1);
    const int exponent = e == std::string::npos ? 0 : std::stoi(text.substr(e + 1));
    return 0.5 * std::pow(10.0, exponent - decimals);
}

// A file of the tests' reference data (tests/data, its README.md).
inline std::string test_data_path(const std::string& relative)
{
    return std::string(CW_TEST_DATA_DIR) + "/" + relative;
}

// A steel wheel on rail, SI units: the CONTACT reference case (a = b = 6 mm,
// N = 80 kN, mu = 0.3, G = 82 GPa, nu = 0.28) with a chosen a/b.
inline creepwork::ContactInput steel_contact(double a_over_b = 1.0)
{
    creepwork::ContactInput in;
    const double c = 6e-3;  // sqrt(ab)
    in.a = c * std::sqrt(a_over_b);
    in.b = c / std::sqrt(a_over_b);
    in.normal_force = 80e3;
    in.mu = 0.3;
    in.G = 82e9;
    in.nu = 0.28;
    return in;
}

inline creepwork::GridSpec kalker_grid(int nx, int ny)
{
    creepwork::GridSpec g;
    g.kind = creepwork::GridKind::kalker_strips;
    g.nx = nx;
    g.ny = ny;
    return g;
}

inline creepwork::GridSpec uniform_grid(int nx, int ny, double box_scale = 1.0)
{
    creepwork::GridSpec g;
    g.kind = creepwork::GridKind::uniform;
    g.nx = nx;
    g.ny = ny;
    g.box_scale = box_scale;
    return g;
}

// One field of the last solve in the caller layout [i + j*nx].
inline std::vector<double> field(const creepwork::Solver& s, creepwork::Field f)
{
    std::vector<double> out(static_cast<size_t>(s.grid().nx()) * s.grid().ny());
    s.copy_field(f, out.data());
    return out;
}

inline std::vector<int> states(const creepwork::Solver& s)
{
    std::vector<int> out(static_cast<size_t>(s.grid().nx()) * s.grid().ny());
    s.copy_state(out.data());
    return out;
}

inline double sum(const std::vector<double>& v)
{
    double t = 0.0;
    for (double x : v) t += x;
    return t;
}

} // namespace cwtest
