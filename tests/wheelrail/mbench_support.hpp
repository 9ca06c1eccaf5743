// The Manchester benchmark set-up (case, CONTACT's
// examples/mbench_a22_*.inp) and CONTACT's reference rows, for the tests and
// the validation tool. CONTACT's units (mm, mm/s) are converted to SI here.
#pragma once

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "wheelrail/profile_io.hpp"
#include "wheelrail/wheelrail_geometry.hpp"

namespace cwtest {

namespace wr = creepwork::wheelrail;

inline std::string wheelrail_data(const std::string& name)
{
    return std::string(CW_WHEELRAIL_DATA) + "/" + name;
}

// CONTACT's printed results of the Manchester benchmark (tests/data/nonhertz).
inline std::string contact_benchmark_results(const std::string& name)
{
    return std::string(CW_TEST_DATA_DIR) + "/nonhertz/" + name;
}

// One row of a CSV file with a header, cells by column name.
struct Row {
    std::map<std::string, std::string> cell;
    double num(const std::string& k) const
    {
        const auto it = cell.find(k);
        if (it == cell.end()) throw std::runtime_error("no column " + k);
        return std::stod(it->second);
    }
    // an optional column: `fallback` when absent or empty
    double num(const std::string& k, double fallback) const
    {
        const auto it = cell.find(k);
        return it == cell.end() || it->second.empty() ? fallback : std::stod(it->second);
    }
    const std::string& text(const std::string& k) const { return cell.at(k); }
};

inline std::vector<Row> read_rows(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::string line;
    std::vector<std::string> head;
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> cells;
        std::stringstream ss(line);
        std::string c;
        while (std::getline(ss, c, ',')) cells.push_back(c);
        if (head.empty()) {
            head = cells;
            continue;
        }
        Row r;
        for (size_t k = 0; k < head.size() && k < cells.size(); ++k) r.cell[head[k]] = cells[k];
        rows.push_back(r);
    }
    return rows;
}

struct Benchmark {
    wr::Profile rail = wr::read_profile_file(wheelrail_data("MBench_UIC60_v3.prr"), wr::ProfileKind::rail);
    wr::Profile wheel = wr::read_profile_file(wheelrail_data("MBench_S1002_v3.prw"), wr::ProfileKind::wheel);
    wr::Track track;     // gauge 1435 mm at 14 mm, no cant (it is in the profile)
    wr::Wheelset wheelset; // 1360 mm, -70 mm, 460 mm
    wr::SearchOptions options(double dx_mm, double ds_mm) const
    {
        wr::SearchOptions o;
        o.dx = dx_mm * 1e-3;
        o.ds = ds_mm * 1e-3;
        return o; // A_SEP 90 deg, D_SEP 8 mm, D_COMB 4 mm: the defaults
    }
    wr::WheelRailGeometry geometry(wr::Side side, double dx_mm = 0.2, double ds_mm = 0.2) const
    {
        return wr::WheelRailGeometry(rail, wheel, track, wheelset, side, options(dx_mm, ds_mm));
    }
    // The geometry of a reference row (its side, track and options).
    wr::WheelRailGeometry geometry(const Row& r) const;
};

// A reference row's inputs in SI.
inline wr::Side side_of(const Row& r) { return r.text("side") == "left" ? wr::Side::left : wr::Side::right; }
inline wr::WheelsetPosition position_of(const Row& r)
{
    wr::WheelsetPosition p;
    p.y = r.num("y_ws_mm") * 1e-3;
    p.z = r.num("z_ws_mm") * 1e-3;
    p.roll = r.num("roll_rad");
    p.yaw = r.num("yaw_rad");
    return p;
}
inline wr::WheelsetVelocity velocity_of(const Row& r)
{
    wr::WheelsetVelocity v;
    v.vs = r.num("vs_mm_s") * 1e-3;
    v.vy = r.num("vy_mm_s", 0.0) * 1e-3;
    v.vz = r.num("vz_mm_s", 0.0) * 1e-3;
    v.vroll = r.num("vroll_rad_s", 0.0);
    v.vyaw = r.num("vyaw_rad_s", 0.0);
    v.vpitch = r.num("vpitch_rad_s");
    return v;
}
// The track of a row (the benchmark's unless the row says otherwise).
inline wr::Track track_of(const Row& r)
{
    wr::Track t;
    t.gauge_height = r.num("gaught_mm", 14.0) * 1e-3;
    t.gauge_width = r.num("gaugwd_mm", 1435.0) * 1e-3;
    t.rail_y0 = r.num("raily0_mm", 0.0) * 1e-3;
    t.rail_z0 = r.num("railz0_mm", 0.0) * 1e-3;
    t.cant = r.num("cant_rad", 0.0);
    t.curvature = r.num("curv_1_mm", 0.0) * 1e3;
    t.rail_dy = r.num("rail_dy_mm", 0.0) * 1e-3;
    t.rail_dz = r.num("rail_dz_mm", 0.0) * 1e-3;
    t.rail_roll = r.num("rail_roll_rad", 0.0);
    return t;
}
inline wr::SearchOptions options_of(const Row& r)
{
    wr::SearchOptions o;
    o.dx = r.num("dx_mm") * 1e-3;
    o.ds = r.num("ds_mm") * 1e-3;
    o.a_sep = r.num("a_sep_rad", o.a_sep);
    o.d_sep = r.num("d_sep_mm", o.d_sep * 1e3) * 1e-3;
    o.d_comb = r.num("d_comb_mm", o.d_comb * 1e3) * 1e-3;
    return o;
}

inline wr::WheelRailGeometry Benchmark::geometry(const Row& r) const
{
    return wr::WheelRailGeometry(rail, wheel, track_of(r), wheelset, side_of(r), options_of(r));
}

} // namespace cwtest
