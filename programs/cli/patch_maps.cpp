#include "patch_maps.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "cli_error.hpp"
#include "report.hpp"

namespace cwcli {

std::string plot_total(double si, Quantity q, const Units& u, int digits)
{
    return fmt(si * u.plot_factor(q), digits) + " " + u.plot_label(q);
}

std::string sign_note(ForceSign sign)
{
    return sign == ForceSign::wheel
               ? "tractions, forces, moment on and micro-slips of the wheel (creepwork's, "
                 "Kalker's and CONTACT's sign)"
               : "tractions, forces, moment on and micro-slips of the rail (the paper's sign)";
}

namespace {

// Half width and half height of element k [m]. A gap grid's elements are its
// cells; on a strip grid each strip has its own element length (area over
// strip width), the uniform grid's box is box_scale a x box_scale b.
void half_sizes(const Solution& s, size_t k, double& hx, double& hy)
{
    if (s.grid.kind == CW_GRID_GAP) {
        hx = 0.5 * s.grid.dx;
        hy = 0.5 * s.grid.dy;
        return;
    }
    hy = s.result.b * (s.grid.kind == CW_GRID_UNIFORM ? s.grid.box_scale : 1.0) / s.ny;
    hx = s.area[k] / (4.0 * hy);
}

} // namespace

std::vector<std::vector<double>> write_patch_data(const std::string& path, const Solution& s,
                                                  const Units& u, ForceSign sign,
                                                  const PatchAxes& axes, double per_metre_x,
                                                  double per_metre_y)
{
    const cw_result& r = s.result;
    const double stress = u.plot_factor(Quantity::stress);
    const double work = u.plot_factor(Quantity::work_per_area);
    const double moment = u.plot_factor(Quantity::moment_per_area);
    std::vector<std::vector<double>> cols(kPatchColumns);
    std::ofstream f(path);
    f << "# x y half_dx half_dy (" << axes.xlabel << ", " << axes.ylabel
      << ") state work/area K*work_paper/area px py sx sy mz/area utilisation pz; px py mz on "
         "the "
      << body_name(sign) << ", sx sy of the " << body_name(sign) << "\n";
    for (size_t k = 0; k < s.size(); ++k) {
        const double area = s.area[k];
        // Exterior: not part of the patch (area 0; the state says so too).
        if (!(area > 0.0) || s.state[k] == CW_STATE_EXTERIOR) continue;
        const double bound = s.params.mu * s.pz[k];
        const double utilisation = bound > 0.0 ? std::hypot(s.px[k], s.py[k]) / bound : 0.0;
        double hx = 0.0, hy = 0.0;
        half_sizes(s, k, hx, hy);
        const double row[kPatchColumns] = {per_metre_x * s.x[k],
                                           per_metre_y * s.y[k],
                                           per_metre_x * hx + 0.004 * axes.ax,
                                           per_metre_y * hy + 0.004 * axes.by,
                                           static_cast<double>(s.state[k]),
                                           work * s.work_consistent[k] / area,
                                           work * r.K * s.work_paper[k] / area,
                                           stress * on_body(sign, s.px[k]),
                                           stress * on_body(sign, s.py[k]),
                                           on_body(sign, s.sx[k]),
                                           on_body(sign, s.sy[k]),
                                           moment * on_body(sign, s.mz[k]) / area,
                                           utilisation,
                                           stress * s.pz[k]};
        gp_data_row(f, row, kPatchColumns, cols);
    }
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
    return cols;
}

namespace {

// Below 1e-9 of mu N (of mu N a for the moment): rounding noise.
void zero_noise(const Solution& s, double& Fx, double& Fy, double& Mz)
{
    const double force_scale = s.params.mu * s.result.normal_force;
    if (std::fabs(Fx) < 1e-9 * force_scale) Fx = 0.0;
    if (std::fabs(Fy) < 1e-9 * force_scale) Fy = 0.0;
    if (std::fabs(Mz) < 1e-9 * force_scale * s.result.a) Mz = 0.0;
}

} // namespace

cw_result shown_totals(const Solution& s)
{
    cw_result r = s.result;
    zero_noise(s, r.Fx, r.Fy, r.Mz);
    return r;
}

cw_patch shown_patch(const Solution& s, cw_patch p)
{
    zero_noise(s, p.Fx, p.Fy, p.Mz);
    return p;
}

std::vector<Panel> patch_panels(const Solution& s, const Units& u, ForceSign sign,
                                const std::string& lateral)
{
    const cw_result r = shown_totals(s);
    const std::string body = body_name(sign);
    const std::string stress = " [" + u.plot_label(Quantity::stress) + "]";
    const std::string on = " on the " + body, of = " of the " + body;
    const std::string per_area = " [" + u.plot_label(Quantity::work_per_area) + "]";
    return {
        {"work.png",
         "Work per unit area (energy-consistent; slip elements outlined), W = " +
             plot_total(r.W_consistent, Quantity::work, u),
         kPatchWork, "work per unit area" + per_area, true},
        {"traction_x.png",
         "Longitudinal traction" + on + ", Fx = " +
             plot_total(on_body(sign, r.Fx), Quantity::force, u),
         kPatchTractionX, "p_x" + on + stress, false},
        {"slip_x.png", "Longitudinal micro-slip W_x/V" + of + " (0 in adhesion)", kPatchSlipX,
         "W_x/V" + of + " [-]", false},
        {"traction_y.png",
         "Lateral traction" + on + ", F" + lateral + " = " +
             plot_total(on_body(sign, r.Fy), Quantity::force, u),
         kPatchTractionY, "p_" + lateral + on + stress, false},
        {"slip_y.png", "Lateral micro-slip W_" + lateral + "/V" + of + " (0 in adhesion)",
         kPatchSlipY, "W_" + lateral + "/V" + of + " [-]", false},
        {"moment.png",
         "Creep moment per unit area" + on + ", Mz = " +
             plot_total(on_body(sign, r.Mz), Quantity::moment, u),
         kPatchMoment,
         "m_z per unit area" + on + " [" + u.plot_label(Quantity::moment_per_area) + "]", false},
        {"utilisation.png", "Traction-bound utilisation |p|/(μ p_z): 1 in slip", kPatchUtilisation,
         "|p|/(μ p_z) [-]", false},
        {"work_paper.png",
         "Paper's local work x K per unit area (slip elements outlined), K = " + fmt(r.K, 4) +
             ", K W_{micro} = " + plot_total(r.K * r.W_micro_paper, Quantity::work, u),
         kPatchWorkPaperK, "K x local work per unit area" + per_area, true},
    };
}

Panel pressure_panel(const Solution& s, const Units& u)
{
    return {"pressure.png",
            "Normal pressure, Fn = " + plot_total(s.result.normal_force, Quantity::force, u) +
                ", p_{max} = " + plot_total(s.result.p_max, Quantity::stress, u, 4),
            kPatchPressure, "p_z [" + u.plot_label(Quantity::stress) + "]", false};
}

const char* const kPatchData = "gnuplot/patch.dat";

std::string slip_map_commands(const Solution& s, const std::string& extra, const std::string& data)
{
    const cw_result& r = s.result;
    std::ostringstream g;
    g << "set title "
      << gp_quote("Slip/adhesion: " + std::to_string(r.n_adhesion) + " adhesion, " +
                  std::to_string(r.n_slip) + " slip elements (adhesion " +
                  fmt(100.0 * r.adhesion_fraction, 3) + " %)")
      << "\n"
      << gp_state_scale();
    // Element outlines help on coarse grids and would hide the map on fine ones.
    g << "plot " << gp_quote(data) << " using 1:2:3:4:5 with boxxyerror fs solid 1.0 "
      << (std::max(s.nx, s.ny) <= 30 ? "border lc rgb '#808080'" : "noborder")
      << " fc palette z notitle" << extra << "\n";
    return g.str();
}

std::string heat_commands(const Panel& p, const std::vector<double>& values, bool outline,
                          const std::string& extra, const std::string& data)
{
    std::ostringstream g;
    g << "set title " << gp_title({p.title}, 700, 10) << "\n"
      << gp_colour_scale(values, p.scale) << "plot " << gp_quote(data) << " using 1:2:3:4:" << p.column
      << " with boxxyerror fs solid 1.0 noborder fc palette z notitle";
    if (p.outline_slip && outline) g << gp_slip_outline(kPatchState);
    g << extra << "\n";
    return g.str();
}

} // namespace cwcli
