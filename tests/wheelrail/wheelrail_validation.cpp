// creepwork_wheelrail_validation: the Manchester benchmark (case)
// geometry against CONTACT, for doc/validation/manchester.md.
//
//   creepwork_wheelrail_validation tables        print the page's tables
//   creepwork_wheelrail_validation check PAGE    exit 1 unless PAGE holds them
//   creepwork_wheelrail_validation update PAGE   put them into PAGE
//   creepwork_wheelrail_validation plot DIR      DIR/manchester_profiles.{gp,png} and data
//
// The tables sit in the page between the lines
//   <!-- BEGIN creepwork_wheelrail_validation tables -->
//   <!-- END creepwork_wheelrail_validation tables -->
// and are deterministic (fixed decimals), so a test can compare them.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "mbench_support.hpp"
#include "wheelrail/placement.hpp"

namespace wr = creepwork::wheelrail;

namespace {

const char* const kBegin = "<!-- BEGIN creepwork_wheelrail_validation tables -->";
const char* const kEnd = "<!-- END creepwork_wheelrail_validation tables -->";
constexpr double kDeg = 57.29577951308232;

std::string fmt(const char* f, double v)
{
    char b[64];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

// The wheel's radius at CONTACT's lateral contact position on the wheel
// (printed y_w, un-mirrored), the same function as the patch's wheel_radius.
double radius_at(const cwtest::Benchmark& b, const cwtest::Row& r)
{
    const double sgn = r.text("side") == "right" ? 1.0 : -1.0;
    double s = 0.0;
    b.wheel.visible_s_at_y(sgn * r.num("ycp_w") * 1e-3, s);
    return b.wheelset.nominal_radius + b.wheel.at(s).z;
}

struct Diff {
    int patches_equal = 0, rows = 0;
    double location = 0, angle = 0, cksi = 0, ceta = 0, cphi = 0, approach = 0;
    bool grids_equal = true;
    void add(const Diff& d)
    {
        location = std::max(location, d.location);
        angle = std::max(angle, d.angle);
        cksi = std::max(cksi, d.cksi);
        ceta = std::max(ceta, d.ceta);
        cphi = std::max(cphi, d.cphi);
        approach = std::max(approach, d.approach);
        grids_equal = grids_equal && d.grids_equal;
        patches_equal += d.patches_equal;
        rows += d.rows;
    }
};

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-6); }

// Evaluates one reference row, returns the patch and the differences.
Diff compare(const cwtest::Benchmark& b, const cwtest::Row& r, wr::ContactPatch& out)
{
    wr::WheelRailGeometry g = b.geometry(r);
    const wr::WheelRailState& st = g.evaluate(cwtest::position_of(r), cwtest::velocity_of(r));
    Diff d;
    d.rows = 1;
    d.patches_equal = static_cast<int>(st.patches.size()) == static_cast<int>(r.num("n_patches"));
    const size_t k = static_cast<size_t>(r.num("patch")) - 1;
    if (k >= st.patches.size()) return d;
    const wr::ContactPatch& p = out = st.patches[k];
    const double mm = 1e-3;
    for (const auto& [a, c] : std::vector<std::pair<double, const char*>>{
             {p.x_tr, "xcp_tr"}, {p.y_tr, "ycp_tr"}, {p.z_tr, "zcp_tr"}, {p.y_r, "ycp_r"}, {p.z_r, "zcp_r"},
             {p.x_w, "xcp_w"}, {p.y_w, "ycp_w"}, {p.z_w, "zcp_w"}})
        d.location = std::max(d.location, std::abs(a - r.num(c) * mm));
    d.angle = std::abs(p.delta - r.num("deltcp_tr"));
    d.cksi = rel(p.cksi, r.num("cksi"));
    d.ceta = rel(p.ceta, r.num("ceta"));
    d.cphi = rel(p.cphi * mm, r.num("cphi"));
    d.approach = rel(p.approach, r.num("pen") * mm);
    d.grids_equal = p.nx == static_cast<int>(r.num("mx")) && p.ny == static_cast<int>(r.num("my")) &&
                    std::abs(p.x0 - r.num("xc1") * mm) < 1e-12 && std::abs(p.s0 - r.num("yc1") * mm) < 1e-12;
    return d;
}

std::string tables()
{
    const cwtest::Benchmark b;
    const auto a22 = cwtest::read_rows(cwtest::wheelrail_data("contact_a22_geometry.csv"));
    std::map<std::string, std::map<double, std::pair<const cwtest::Row*, wr::ContactPatch>>> by_side;
    std::map<double, Diff> by_shift;
    Diff all_a22, all_new;
    for (const cwtest::Row& r : a22) {
        wr::ContactPatch p;
        const Diff d = compare(b, r, p);
        by_side[r.text("side")][r.num("y_ws_mm")] = {&r, p};
        by_shift[r.num("y_ws_mm")].add(d);
        all_a22.add(d);
    }
    for (const cwtest::Row& r : cwtest::read_rows(cwtest::wheelrail_data("contact_new_geometry.csv"))) {
        wr::ContactPatch p;
        all_new.add(compare(b, r, p));
    }
    std::ostringstream o;
    o << "**Contact over the lateral shift** (creepwork's values; the next table gives their differences to "
         "CONTACT). "
         "y_r: lateral position on the rail profile, y_w: on the wheel profile, delta: contact angle, r: "
         "the wheel's radius at y_w, dr = r_left - r_right.\n\n";
    o << "| y_ws [mm] | yaw [mrad] | left y_r [mm] | left y_w [mm] | left delta [deg] | right y_r [mm] | "
         "right y_w [mm] | right delta [deg] | dr [mm] | dr CONTACT [mm] |\n";
    o << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& [y, lp] : by_side["left"]) {
        const auto& rp = by_side["right"][y];
        const wr::ContactPatch &l = lp.second, &r = rp.second;
        const double dr = (l.wheel_radius - r.wheel_radius) * 1e3;
        const double dr_c = (radius_at(b, *lp.first) - radius_at(b, *rp.first)) * 1e3;
        o << "| " << fmt("%.1f", y) << " | " << fmt("%.1f", lp.first->num("yaw_rad") * 1e3) << " | "
          << fmt("%.3f", l.y_r * 1e3) << " | " << fmt("%.3f", l.y_w * 1e3) << " | " << fmt("%.3f", l.delta * kDeg)
          << " | " << fmt("%.3f", r.y_r * 1e3) << " | " << fmt("%.3f", r.y_w * 1e3) << " | "
          << fmt("%.3f", r.delta * kDeg) << " | " << fmt("%.4f", dr) << " | " << fmt("%.4f", dr_c) << " |\n";
    }
    o << "\n**Differences to CONTACT per lateral shift** (both wheels; location: the reference point in "
         "track, rail and wheel coordinates; creepages relative; approach: the least undeformed distance).\n\n";
    o << "| y_ws [mm] | patches equal | location [um] | delta [urad] | cksi | ceta | cphi | grid equal | "
         "approach |\n";
    o << "|---:|:---:|---:|---:|---:|---:|---:|:---:|---:|\n";
    auto row = [&](const std::string& label, const Diff& d) {
        o << "| " << label << " | " << d.patches_equal << "/" << d.rows << " | " << fmt("%.3f", d.location * 1e6)
          << " | " << fmt("%.2f", d.angle * 1e6) << " | " << fmt("%.1e", d.cksi) << " | " << fmt("%.1e", d.ceta)
          << " | " << fmt("%.1e", d.cphi) << " | " << (d.grids_equal ? "yes" : "no") << " | "
          << fmt("%.2f %%", d.approach * 100.0) << " |\n";
    };
    for (const auto& [y, d] : by_shift) row(fmt("%.1f", y), d);
    o << "\n**Worst differences to CONTACT** over the benchmark (42 wheel positions) and over the new "
         "cases (18 positions, 21 patches, not used to write the code).\n\n";
    o << "| cases | patches equal | location [um] | delta [urad] | cksi | ceta | cphi | grid equal | "
         "approach |\n";
    o << "|---|:---:|---:|---:|---:|---:|---:|:---:|---:|\n";
    row("A-2.2", all_a22);
    row("new", all_new);
    return o.str();
}

std::string read_file(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The page split around the tables block: before (up to and including
// kBegin's line), the block, after (from kEnd's line).
bool split(const std::string& page, std::string& before, std::string& block, std::string& after)
{
    const size_t a = page.find(kBegin), e = page.find(kEnd);
    if (a == std::string::npos || e == std::string::npos || e < a) return false;
    const size_t a_end = page.find('\n', a) + 1;
    before = page.substr(0, a_end);
    block = page.substr(a_end, e - a_end);
    after = page.substr(e);
    return true;
}

// Profiles in track coordinates with the contact points, for a few shifts.
int plot(const std::string& dir)
{
    const cwtest::Benchmark b;
    const auto a22 = cwtest::read_rows(cwtest::wheelrail_data("contact_a22_geometry.csv"));
    const double shifts[] = {0.0, 3.0, 5.0, 6.5, 10.0};
    std::ofstream dat(dir + "/manchester_profiles.dat");
    dat << "# y_track z_track [mm]; blocks: per side (left, right): rail, then per shift: wheel, "
           "contact point(s)\n";
    int block = 0;
    for (const char* side : {"left", "right"}) {
        const wr::Side s = std::string(side) == "left" ? wr::Side::left : wr::Side::right;
        const double sgn = s == wr::Side::right ? 1.0 : -1.0;
        wr::WheelRailGeometry g = b.geometry(s);
        const wr::Frame rail = g.rail_frame();
        dat << "# " << side << " rail\n";
        for (int i = 0; i < b.rail.size(); ++i) {
            const wr::Vec3 q = rail.to_parent(wr::Vec3(0, b.rail.knots_y()[i], b.rail.knots_z()[i]));
            dat << sgn * q(1) * 1e3 << " " << q(2) * 1e3 << "\n";
        }
        dat << "\n\n";
        ++block;
        for (double y : shifts)
            for (const cwtest::Row& r : a22) {
                if (r.text("side") != side || r.num("y_ws_mm") != y) continue;
                const wr::WheelsetPosition pos = cwtest::position_of(r);
                const wr::WheelRailState& st = g.evaluate(pos, cwtest::velocity_of(r));
                const wr::Frame w = wr::wheelset_in_track(pos, b.wheelset, s).compose(wr::wheel_in_wheelset(b.wheelset));
                dat << "# " << side << " wheel at y_ws = " << y << " mm\n";
                for (int i = 0; i < b.wheel.size(); ++i) {
                    const wr::Vec3 q = w.to_parent(wr::Vec3(0, b.wheel.knots_y()[i], b.wheel.knots_z()[i]));
                    dat << sgn * q(1) * 1e3 << " " << q(2) * 1e3 << "\n";
                }
                dat << "\n\n# contact points\n";
                for (const wr::ContactPatch& p : st.patches) dat << p.y_tr * 1e3 << " " << p.z_tr * 1e3 << "\n";
                dat << "\n\n";
                block += 2;
            }
    }
    dat.close();
    std::ofstream gp(dir + "/manchester_profiles.gp");
    gp << "# Manchester benchmark A-2.2: rails and wheels in track coordinates (z down) with the contact\n"
          "# reference points, at five lateral shifts. Made by creepwork_wheelrail_validation plot.\n"
          "set terminal pngcairo size 1100,540 enhanced font 'DejaVu Sans,10'\n"
          "set output 'manchester_profiles.png'\n"
          "set multiplot layout 1,2\n"
          "set yrange [45:-25]\nset ylabel 'z_{track} [mm] (down)'\nset xlabel 'y_{track} [mm]'\n"
          "set key below maxrows 2\nset grid\nset size ratio -1\n";
    const char* colours[] = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e"};
    for (int side = 0; side < 2; ++side) {
        const int base = side * (1 + 2 * 5);
        gp << "set title '" << (side == 0 ? "left" : "right") << " wheel and rail'\n";
        gp << (side == 0 ? "set xrange [-800:-690]\n" : "set xrange [690:800]\n");
        gp << "plot 'manchester_profiles.dat' index " << base << " with lines lw 2 lc rgb 'black' title 'rail'";
        for (int k = 0; k < 5; ++k) {
            gp << ", \\\n  '' index " << base + 1 + 2 * k << " with lines lw 1.2 lc rgb '" << colours[k]
               << "' title 'wheel, y_{ws} = " << shifts[k] << " mm'";
            gp << ", \\\n  '' index " << base + 2 + 2 * k << " with points pt 7 ps 1.2 lc rgb '" << colours[k]
               << "' notitle";
        }
        gp << "\n";
    }
    gp << "unset multiplot\n";
    gp.close();
    const std::string cmd = "cd '" + dir + "' && gnuplot manchester_profiles.gp";
    return std::system(cmd.c_str()) == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
    try {
        const std::string mode = argc > 1 ? argv[1] : "";
        if (mode == "tables") {
            std::fputs(tables().c_str(), stdout);
            return 0;
        }
        if ((mode == "check" || mode == "update") && argc > 2) {
            const std::string page = read_file(argv[2]);
            std::string before, block, after;
            if (!split(page, before, block, after)) {
                std::fprintf(stderr, "%s: no tables block (%s ... %s)\n", argv[2], kBegin, kEnd);
                return 1;
            }
            const std::string now = tables();
            if (mode == "check") {
                if (block == now) return 0;
                std::fprintf(stderr, "%s: the tables differ from what the code computes; run\n"
                                     "  creepwork_wheelrail_validation update %s\n", argv[2], argv[2]);
                return 1;
            }
            std::ofstream(argv[2]) << before << now << after;
            return 0;
        }
        if (mode == "plot" && argc > 2) return plot(argv[2]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "creepwork_wheelrail_validation: %s\n", e.what());
        return 1;
    }
    std::fprintf(stderr, "usage: creepwork_wheelrail_validation tables | check PAGE | update PAGE | plot DIR\n");
    return 2;
}
