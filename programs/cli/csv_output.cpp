#include "csv_output.hpp"

#include <cstdio>
#include <fstream>

#include "cli_error.hpp"
#include "json.hpp"

namespace cwcli {

std::string field_columns(const Units& u)
{
    using Q = Quantity;
    const auto c = [&u](const char* name, Q q) { return "," + std::string(name) + "_" + u.csv_suffix(q); };
    return "i,j" + c("x", Q::length) + c("y", Q::length) + c("area", Q::area) + ",state" +
           c("pz", Q::stress) + c("px_wheel", Q::stress) + c("py_wheel", Q::stress) + ",sx,sy" +
           c("mz_wheel", Q::moment) + c("work_paper", Q::work) + c("work_consistent", Q::work);
}

std::string profile_columns(const Units& u)
{
    const std::string w = u.csv_suffix(Quantity::profile);
    return "j,y_" + u.csv_suffix(Quantity::length) + ",w_" + w + ",parabola_" + w;
}

namespace {

std::ofstream open_for_writing(const std::string& path)
{
    std::ofstream f(path);
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
    return f;
}

void finish(std::ofstream& f, const std::string& path)
{
    f.close();
    if (!f) throw CliError(kExitFailure, "error while writing " + path);
}

// Exact: the CSV reads back as the library's doubles.
void put(std::ostream& os, double v)
{
    os << ',' << shortest_exact(v);
}

} // namespace

void write_fields_csv(const std::string& path, const Solution& s, const Units& u)
{
    std::ofstream f = open_for_writing(path);
    f << field_columns(u) << "\n";
    using Q = Quantity;
    for (int j = 0; j < s.ny; ++j) {
        for (int i = 0; i < s.nx; ++i) {
            const size_t k = static_cast<size_t>(i) + static_cast<size_t>(j) * s.nx;
            f << i << "," << j;
            put(f, u.from_si(Q::length, s.x[k]));
            put(f, u.from_si(Q::length, s.y[k]));
            put(f, u.from_si(Q::area, s.area[k]));
            f << "," << s.state[k];
            put(f, u.from_si(Q::stress, s.pz[k]));
            put(f, u.from_si(Q::stress, s.px[k]));
            put(f, u.from_si(Q::stress, s.py[k]));
            put(f, s.sx[k]);
            put(f, s.sy[k]);
            put(f, u.from_si(Q::moment, s.mz[k]));
            put(f, u.from_si(Q::work, s.work_paper[k]));
            put(f, u.from_si(Q::work, s.work_consistent[k]));
            f << "\n";
        }
    }
    finish(f, path);
}

void write_profile_csv(const std::string& path, const Solution& s, const Units& u)
{
    std::ofstream f = open_for_writing(path);
    f << profile_columns(u) << "\n";
    for (int j = 0; j < s.ny; ++j) {
        f << j;
        put(f, u.from_si(Quantity::length, s.profile_y[j]));
        put(f, u.from_si(Quantity::profile, s.profile_w[j]));
        put(f, u.from_si(Quantity::profile, s.profile_parabola[j]));
        f << "\n";
    }
    finish(f, path);
}

} // namespace cwcli
