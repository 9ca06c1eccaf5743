#include "sweep_plots.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_error.hpp"
#include "gnuplot.hpp"
#include "report.hpp"

namespace cwcli {

namespace {

// Which creepages a figure varies: only those appear in its panel titles.
struct Varies {
    bool x = false, y = false, spin = false;
};

Varies varies(const SweepFigure& fig)
{
    Varies v;
    for (const SweepCase& c : fig.cases) {
        v.x = v.x || c.sx != 0.0;
        v.y = v.y || c.sy != 0.0;
        v.spin = v.spin || c.sphi != 0.0;
    }
    return v;
}

// Two lines: the creepages as multiples of the saturation creepages, then
// their values and the adhesion fraction.
std::string panel_title(const SweepPanel& p, const Varies& v, const Units& u)
{
    const SweepCase& c = p.c;
    const auto times = [](double m, const char* symbol) {
        return m == 0.0 ? std::string("0") : fmt(m, 3) + " " + symbol;
    };
    std::vector<std::string> rel, abs;
    if (v.x && v.y && c.xi_x == c.xi_y) {
        rel.push_back("ξ_x = ξ_y = " + times(c.sx, "ξ_c"));
        abs.push_back("ξ_x = ξ_y = " + fmt(c.xi_x, 3));
    } else {
        if (v.x) {
            rel.push_back("ξ_x = " + times(c.sx, "ξ_c"));
            abs.push_back("ξ_x = " + fmt(c.xi_x, 3));
        }
        if (v.y) {
            rel.push_back("ξ_y = " + times(c.sy, "η_c"));
            abs.push_back("ξ_y = " + fmt(c.xi_y, 3));
        }
    }
    if (v.spin) {
        rel.push_back("φ = " + times(c.sphi, "φ_c"));
        abs.push_back("φ = " + fmt(u.from_si(Quantity::spin, c.phi), 3) + " " +
                      u.label(Quantity::spin));
    }
    const auto join = [](const std::vector<std::string>& parts) {
        std::string out;
        for (const std::string& s : parts) out += (out.empty() ? "" : ", ") + s;
        return out;
    };
    return gp_text_lines(
        {join(rel), join(abs) + "; adhesion " + fmt(100 * p.result.adhesion_fraction, 3) + " %"});
}

void write_data(const std::string& path, const std::vector<SweepPanel>& panels,
                const PatchGeometry& g)
{
    std::ofstream f(path);
    f << "# one block per panel (gnuplot index k): x/a y/b half_dx/a half_dy/b state\n";
    for (size_t k = 0; k < panels.size(); ++k) {
        if (k) f << "\n\n";
        for (size_t e = 0; e < g.X.size(); ++e)
            if (g.inside[e])
                f << g.X[e] << " " << g.Y[e] << " " << g.half_x[e] << " " << g.half_y[e] << " "
                  << panels[k].state[e] << "\n";
    }
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

} // namespace

void write_sweep_pictures(const std::string& dir, const std::vector<SweepFigure>& figs,
                          const std::vector<std::vector<SweepPanel>>& panels,
                          const PatchGeometry& geometry, int rolling_direction,
                          const std::string& caption, const Units& u)
{
    std::filesystem::create_directories(dir + "/gnuplot");
    std::ostringstream g;
    g << "# creepwork sweep: slip/adhesion maps. Run from the output directory:\n"
      << "#   gnuplot gnuplot/sweep.gp\n";
    for (size_t f = 0; f < figs.size(); ++f) {
        const SweepFigure& fig = figs[f];
        const std::string data = "gnuplot/" + fig.name + ".dat";
        write_data(dir + "/" + data, panels[f], geometry);
        g << gp_png(fig.name + ".png", 360 * fig.cols, 380 * fig.rows + 90)
          << "set multiplot layout " << fig.rows << "," << fig.cols << " title "
          << gp_title({fig.caption, caption + "; slip orange, adhesion blue"}, 360 * fig.cols, 12)
          << " font ',12'\n"
          << gp_patch_frame(rolling_direction)
          << "unset label 2; unset label 3\n"
          << gp_state_scale() << "unset colorbox\n";
        for (size_t k = 0; k < panels[f].size(); ++k)
            g << "set title " << panel_title(panels[f][k], varies(fig), u) << " font ',9'\n"
              << "plot '" << data << "' index " << k << " using " << kPaddedBoxes
              << ":5 with boxxyerror fs solid 1.0 noborder fc palette z notitle\n";
        g << "unset multiplot\n";
    }
    g << "unset output\n";
    run_gnuplot(dir, "gnuplot/sweep.gp", g.str());
}

} // namespace cwcli
