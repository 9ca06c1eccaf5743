#include "csv_output.hpp"

#include <cstdio>
#include <fstream>

#include "cli_error.hpp"
#include "json.hpp"

namespace cwcli {

const char* const kFieldColumns = "i,j,x,y,area,state,pz,px,py,sx,sy,mz,work_paper,work_consistent";

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
    f << kFieldColumns << "\n";
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
    f << "j,y,w,parabola\n";
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
