// Helpers for the compatibility tests (users coming from other FASTSIM
// codes): reading CONTACT's example data (data/, written by
// extract_contact_example.py) and the shared CSV references, and comparing a
// value with a number as another program printed it.
#pragma once

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "creepwork/creepwork.h"

namespace compat {

// One case of data/contact_fastsim_example.txt: CONTACT's printed tokens by
// key, and its element division map.
struct ContactCase {
    int number = 0;
    std::map<std::string, std::vector<std::string>> values; // key -> printed tokens
    int map_rows = 0, map_cols = 0, first_ix = 0, first_iy = 0;
    std::map<int, std::string> map; // iy -> one char per column ('.', '*', 'S')

    const std::string& token(const std::string& key, size_t k = 0) const
    {
        auto it = values.find(key);
        if (it == values.end() || it->second.size() <= k)
            throw std::runtime_error("case " + std::to_string(number) + ": no value " + key);
        return it->second[k];
    }
    double number_of(const std::string& key, size_t k = 0) const
    {
        return std::strtod(token(key, k).c_str(), nullptr);
    }
};

inline std::vector<ContactCase> read_contact_cases(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::vector<ContactCase> cases;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ss(line);
        std::string key;
        ss >> key;
        if (key == "case") {
            cases.emplace_back();
            ss >> cases.back().number;
        } else if (key == "map") {
            ContactCase& c = cases.back();
            ss >> c.map_rows >> c.map_cols >> c.first_ix >> c.first_iy;
        } else if (key == "row") {
            int iy = 0;
            ss >> iy;
            std::string run, cells;
            while (ss >> run) {
                const char ch = run[0] == 'o' ? '.' : run[0]; // 'o' marks a corner
                cells.append(static_cast<size_t>(std::atoi(run.c_str() + 1)), ch);
            }
            cases.back().map[iy] = cells;
        } else if (key != "end") {
            std::string token;
            std::vector<std::string>& v = cases.back().values[key];
            while (ss >> token) v.push_back(token);
        }
    }
    return cases;
}

// Half a unit in the last printed digit of a Fortran-printed number
// ("-1.505E+04", "0.4937E-04", "-509.3", "1629.", "0.000").
inline double half_unit_of(const std::string& printed)
{
    const size_t e = printed.find_first_of("Ee");
    const std::string mantissa = printed.substr(0, e);
    const int exponent = e == std::string::npos ? 0 : std::atoi(printed.c_str() + e + 1);
    const size_t dot = mantissa.find('.');
    const int decimals = dot == std::string::npos ? 0 : int(mantissa.size() - dot - 1);
    return 0.5 * std::pow(10.0, exponent - decimals);
}

// value, converted to the printed unit, rounds to the printed number: the
// claim "reproduced to rounding". A relative 1e-12 covers our own unit
// conversion.
inline bool rounds_to(double value, const std::string& printed)
{
    const double p = std::strtod(printed.c_str(), nullptr);
    return std::fabs(value - p) <= half_unit_of(printed) + 1e-12 * std::fabs(p);
}

// A CSV table with a header row; cells addressed by column name.
struct CsvTable {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;

    const std::string& text(size_t row, const std::string& column) const
    {
        for (size_t c = 0; c < header.size(); ++c)
            if (header[c] == column) return rows[row][c];
        throw std::runtime_error("no column " + column);
    }
    double number(size_t row, const std::string& column) const
    {
        return std::strtod(text(row, column).c_str(), nullptr);
    }
};

inline CsvTable read_csv(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    CsvTable t;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        std::vector<std::string> cells;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) cells.push_back(cell);
        if (t.header.empty()) {
            t.header = cells;
        } else {
            cells.resize(t.header.size());
            t.rows.push_back(cells);
        }
    }
    return t;
}

} // namespace compat
