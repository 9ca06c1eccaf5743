#include "wheelrail_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "cli_error.hpp"
#include "gap_plots.hpp"
#include "gnuplot.hpp"
#include "patch_maps.hpp"
#include "report.hpp"

namespace cwcli {

namespace {

constexpr double kMm = 1e3;
constexpr double kDegree = 180.0 / 3.14159265358979323846;

// A window [y0 - half_y, y0 + half_y] x [z0 - half_z, z0 + half_z] in mm.
struct Window {
    double y0, z0, half_y, half_z;
};

void write_points(const std::string& path, const ProfilePoints& p, const char* body)
{
    std::ofstream f(path);
    f << "# y z [mm], track coordinates (z down): the " << body << "'s profile points\n";
    char buf[64];
    for (size_t k = 0; k < p.y.size(); ++k) {
        std::snprintf(buf, sizeof buf, "%.9g %.9g\n", kMm * p.y[k], kMm * p.z[k]);
        f << buf;
    }
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

// Where a patch lies in the track's y, z plane, in mm: its reference point,
// the normal e_n = (-sin delta, cos delta), e_s = (cos delta, sin delta),
// and the intervals of s (in the tangent plane) its contact elements cover:
// one per lobe of a patch of several.
struct ContactMark {
    double y, z, ny, nz, sy, sz;
    std::vector<std::pair<double, double>> s_ranges;
};

ContactMark contact_mark(const PatchView& v)
{
    const cw_wheelrail_patch& p = v.patch;
    const Solution& s = v.solution;
    const double sn = std::sin(p.contact_angle), cs = std::cos(p.contact_angle);
    ContactMark m{kMm * p.y_contact, kMm * p.z_contact, -sn, cs, cs, sn, {}};
    bool open = false; // rows j ascend in s
    for (int j = 0; j < s.ny; ++j) {
        bool row = false;
        for (int i = 0; i < s.nx && !row; ++i)
            row = s.state[i + static_cast<size_t>(s.nx) * j] != CW_STATE_EXTERIOR;
        const double at = kMm * (s.grid.y0 + j * s.grid.dy), half = 0.5 * kMm * s.grid.dy;
        if (row && !open) m.s_ranges.push_back({at - half, at + half});
        if (row) m.s_ranges.back().second = at + half;
        open = row;
    }
    return m;
}

// contacts.dat: one row per patch, its point, normal, lateral axis, force
// on the rail [kN] and contact angle [deg]; extents.dat: one row per
// interval of ContactMark::s_ranges, its start and its span in y, z.
void write_contacts(const std::string& dir, const std::vector<PatchView>& patches)
{
    const std::string contacts = dir + "/gnuplot/contacts.dat", extents = dir + "/gnuplot/extents.dat";
    std::ofstream f(contacts), e(extents);
    f << "# k y z [mm] n_y n_z s_y s_z [-] Fy Fz [kN] delta [deg]: per patch its contact point, "
         "normal (into the rail), lateral axis s and force on the rail, track coordinates (z "
         "down)\n";
    e << "# k y z dy dz [mm]: per patch the intervals of s its contact elements cover, in the "
         "tangent plane\n";
    char buf[320];
    for (size_t k = 0; k < patches.size(); ++k) {
        const cw_wheelrail_patch& p = patches[k].patch;
        const ContactMark m = contact_mark(patches[k]);
        std::snprintf(buf, sizeof buf, "%zu %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.6g\n", k,
                      m.y, m.z, m.ny, m.nz, m.sy, m.sz, 1e-3 * p.Fy_track, 1e-3 * p.Fz_track,
                      kDegree * p.contact_angle);
        f << buf;
        for (const auto& [lo, hi] : m.s_ranges) {
            std::snprintf(buf, sizeof buf, "%zu %.9g %.9g %.9g %.9g\n", k, m.y + lo * m.sy,
                          m.z + lo * m.sz, (hi - lo) * m.sy, (hi - lo) * m.sz);
            e << buf;
        }
    }
    if (!f) throw CliError(kExitFailure, "cannot write " + contacts);
    if (!e) throw CliError(kExitFailure, "cannot write " + extents);
}

// The profiles, the contacts and their forces in one window; normals and
// force arrows `arrow` mm long (the force of the largest patch). The key, if
// asked for, goes to the top corner towards the track centre: air above the
// wheel, whichever rail.
std::string profile_plot(const Window& w, double arrow, double force_ref, const std::string& title,
                         bool key)
{
    std::ostringstream g;
    g.precision(9);
    g << "unset arrow; unset label; unset object\nunset colorbox\nset size ratio -1\n"
      << "set xrange [" << w.y0 - w.half_y << ":" << w.y0 + w.half_y << "]\n"
      // z down is drawn downwards: the range reversed.
      << "set yrange [" << w.z0 + w.half_z << ":" << w.z0 - w.half_z << "]\n"
      << "set xtics auto\nset ytics auto\nset grid\n"
      << "set xlabel 'y, across the track [mm]'\nset ylabel 'z, down [mm]'\n"
      << (key ? std::string("set key top ") + (w.y0 > 0.0 ? "left" : "right") +
                    " opaque box font ',9'\n"
              : "unset key\n")
      << "set title " << gp_title({title}, 700, 10) << "\n"
      << "L = " << arrow << "\nFref = " << force_ref << "\n"
      << "plot 'gnuplot/rail.dat' using 1:2 with lines lw 2 lc rgb '#404040' title 'rail', \\\n"
      << "     'gnuplot/wheel.dat' using 1:2 with lines lw 2 lc rgb '#2166ac' title 'wheel', \\\n"
      << "     'gnuplot/extents.dat' using 2:3:4:5 with vectors nohead lw 6 lc rgb '#f4a582' "
         "title 'patch along s (tangent plane)', \\\n"
      << "     'gnuplot/contacts.dat' using ($2-L*$4):($3-L*$5):(2*L*$4):(2*L*$5) with vectors head size "
         "screen 0.008,20 dt 2 lc rgb 'black' title 'normal n (into the rail)', \\\n"
      << "     '' using 2:3:(L*$8/Fref):(L*$9/Fref) with vectors head filled size screen "
         "0.012,20 lw 2.5 lc rgb '#b2182b' title 'force on the rail', \\\n"
      << "     '' using 2:3 with points pt 7 ps 1.1 lc rgb 'black' title 'contact point', \\\n"
      << "     '' using ($2-0.75*L*$4):($3-0.75*L*$5):(sprintf('%d: %.1f°', int($1), $10)) "
         "with labels font ',9' offset 0,0.8 notitle\n"
      // What the maps after it expect: a colour box, no key.
      << "unset grid\nset colorbox\nunset key\n";
    return g.str();
}

// The overview: the wheel's extent across, both profiles' extent down (5 mm
// to spare); the zoom: every contact and its extent with 5 mm to spare, at
// least 16 mm square.
Window overview(const ProfilePoints& rail, const ProfilePoints& wheel)
{
    const auto [ylo, yhi] = std::minmax_element(wheel.y.begin(), wheel.y.end());
    double ztop = HUGE_VAL, zbottom = -HUGE_VAL;
    for (const ProfilePoints* p : {&rail, &wheel})
        for (size_t k = 0; k < p->y.size(); ++k)
            if (p->y[k] >= *ylo && p->y[k] <= *yhi) {
                ztop = std::min(ztop, p->z[k]);
                zbottom = std::max(zbottom, p->z[k]);
            }
    return {0.5 * kMm * (*ylo + *yhi), 0.5 * kMm * (ztop + zbottom),
            0.5 * kMm * (*yhi - *ylo) + 5.0, 0.5 * kMm * (zbottom - ztop) + 5.0};
}

Window zoom(const std::vector<PatchView>& patches)
{
    double ylo = HUGE_VAL, yhi = -HUGE_VAL, zlo = HUGE_VAL, zhi = -HUGE_VAL;
    for (const PatchView& v : patches) {
        const ContactMark m = contact_mark(v);
        std::vector<double> at = {0.0};
        for (const auto& [lo, hi] : m.s_ranges) at.insert(at.end(), {lo, hi});
        for (double a : at) {
            ylo = std::min(ylo, m.y + a * m.sy);
            yhi = std::max(yhi, m.y + a * m.sy);
            zlo = std::min(zlo, m.z + a * m.sz);
            zhi = std::max(zhi, m.z + a * m.sz);
        }
    }
    const double half = std::max({8.0, 0.5 * (yhi - ylo) + 5.0, 0.5 * (zhi - zlo) + 5.0});
    return {0.5 * (ylo + yhi), 0.5 * (zlo + zhi), half, half};
}

std::string kn(double newton, int digits = 5)
{
    return plot_total(newton, Quantity::force, Units::si(), digits);
}

std::vector<std::string> patch_caption(const PatchView& v, size_t k, size_t n,
                                       const std::string& model)
{
    const cw_wheelrail_patch& p = v.patch;
    const Units u = Units::si();
    std::ostringstream where, forces;
    where << "patch " << k << " of " << n << " (" << model << " model) at y = "
          << fmt(kMm * p.y_contact, 5) << " mm, z = " << fmt(kMm * p.z_contact, 4)
          << " mm, contact angle " << fmt(kDegree * p.contact_angle, 4)
          << "°; CKSI = " << fmt(p.cksi, 4) << ", CETA = " << fmt(p.ceta, 4)
          << ", CPHI = " << fmt(p.cphi, 4) << " 1/m";
    forces << "Fn = " << kn(p.Fn) << ", Fx = " << kn(p.Fx) << ", Fs = " << kn(p.Fs)
           << ", Mn = " << plot_total(p.Mn, Quantity::moment, u, 4)
           << ", p_{max} = " << plot_total(p.p_max, Quantity::stress, u, 4) << "; "
           << p.n_contact << " elements, " << p.n_adhesion << " in adhesion, " << p.n_slip
           << " in slip";
    return {where.str(), forces.str(),
            "tractions, forces, moment on and micro-slips of the rail (CONTACT's module-1 "
            "sign); x along the track, s lateral in the tangent plane; the wheel rolls towards "
            "+x"};
}

} // namespace

void write_wheelrail_pictures(const std::string& dir, const ProfilePoints& rail,
                              const ProfilePoints& wheel, const std::vector<PatchView>& patches,
                              const cw_wheelrail_totals& t, const std::string& model)
{
    std::filesystem::create_directories(dir + "/gnuplot");
    write_points(dir + "/gnuplot/rail.dat", rail, "rail");
    write_points(dir + "/gnuplot/wheel.dat", wheel, "wheel");
    write_contacts(dir, patches);
    double force_ref = 0.0;
    for (const PatchView& v : patches)
        force_ref = std::max(force_ref, 1e-3 * std::hypot(v.patch.Fy_track, v.patch.Fz_track));
    if (!(force_ref > 0.0)) force_ref = 1.0;
    const Window all = overview(rail, wheel);
    const Window near = patches.empty() ? all : zoom(patches);
    const double near_arrow = 0.45 * near.half_y;
    const std::string zoomed = profile_plot(
        near, near_arrow, force_ref,
        "The contacts zoomed (normals, forces " + fmt(near_arrow, 3) + " mm)", true);

    std::ostringstream g;
    g << "# creepwork wheelrail: the profiles and every patch. Run from the output directory:\n"
      << "#   gnuplot gnuplot/wheelrail.gp\n"
      << "set datafile missing NaN\nset style fill solid 1.0 noborder\n"
      << "set style textbox opaque fillcolor rgb 'white' border lc rgb 'black'\n";
    std::ostringstream heading;
    heading << "Wheel on rail (" << model << " model): wheelset height z_{ws} = "
            << fmt(kMm * t.z, 5) << " mm, " << patches.size()
            << (patches.size() == 1 ? " contact patch" : " contact patches")
            << "; total force on the rail (track coordinates) Fx = " << kn(t.Fx)
            << ", Fy = " << kn(t.Fy) << ", Fz = " << kn(t.Fz);
    // The overview as wide as the profiles are, the zoom square beside it.
    g << gp_png("profiles.png", 1600, 720) << "set multiplot title "
      << gp_title({heading.str(), "track coordinates: y across the track, z down (drawn "
                                  "downwards); contact angle: rotation about x from z to n"},
                  1600, 12)
      << " font ',12'\nset origin 0,0\nset size 0.6,0.9\n"
      << profile_plot(all, 10.0, force_ref, "Rail and wheel profiles (normals, forces 10 mm)",
                      false)
      << "set origin 0.6,0\nset size 0.4,0.9\n" << zoomed << "unset multiplot\nset size 1,1\nset origin 0,0\n";

    for (size_t k = 0; k < patches.size(); ++k) {
        const PatchView& v = patches[k];
        const std::string name = "patch_" + std::to_string(k);
        GridMapFiles files;
        files.elements = "gnuplot/" + name + ".dat";
        files.outline = "gnuplot/" + name + "_outline.dat";
        files.patches = "gnuplot/" + name + "_lobes.dat";
        files.label = "lobe";
        const std::vector<cw_patch> lobes =
            v.lobes.size() > 1 ? v.lobes : std::vector<cw_patch>();
        PlotStyle style;
        style.sign = ForceSign::rail;
        const GridMaps maps =
            write_grid_maps(dir, files, v.solution, lobes, Units::si(), style, "s");
        // A patch more than 2.5 times as long as wide (a flange contact) is
        // stretched along s, as its caption says, to stay readable.
        const Solution& s = v.solution;
        const double aspect = (s.ny * s.grid.dy) / (s.nx * s.grid.dx);
        std::vector<std::string> caption = patch_caption(v, k, patches.size(), model);
        std::string frame = maps.frame;
        if (aspect < 0.4) {
            frame += "set size ratio 0.55\n";
            caption.back() += "; the maps stretched along s";
        }
        g << gp_png(name + ".png", 1400, 2000) << "set multiplot layout 3,2 title "
          << gp_title(caption, 1400, 12) << " font ',12'\n"
          << frame << maps.pressure.commands << maps.slip.commands
          << maps.traction_x.commands << maps.traction_y.commands << maps.work.commands
          << zoomed << "unset multiplot\n";
    }
    g << "unset output\n";
    run_gnuplot(dir, "gnuplot/wheelrail.gp", g.str());
}

} // namespace cwcli
