#include "transient_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_error.hpp"
#include "gap_plots.hpp"
#include "gnuplot.hpp"
#include "patch_maps.hpp"
#include "plot_style.hpp"
#include "report.hpp"
#include "units.hpp"

namespace cwcli {

bool transient_step_drawn(size_t k, size_t n)
{
    if (n <= kMaxTransientStepPictures || k + 1 == n) return true;
    // kMaxTransientStepPictures - 1 evenly spread, from the first; the last besides.
    const size_t every = (n + kMaxTransientStepPictures - 2) / (kMaxTransientStepPictures - 1);
    return k % every == 0;
}

Solution transient_fields(const cw_transient* t, const cw_grid& g, const cw_params& p,
                          const cw_transient_result& r)
{
    Solution s;
    s.grid = g;
    s.params = p;
    s.nx = g.nx;
    s.ny = g.ny;
    const size_t n = s.size();
    for (std::vector<double>* v : {&s.x, &s.y, &s.area, &s.pz, &s.px, &s.py, &s.sx, &s.sy, &s.mz,
                                   &s.work_paper, &s.work_consistent})
        v->assign(n, 0.0);
    s.state.assign(n, CW_STATE_EXTERIOR);
    const std::pair<int, std::vector<double>*> fields[] = {
        {CW_FIELD_X, &s.x},   {CW_FIELD_Y, &s.y},   {CW_FIELD_PZ, &s.pz}, {CW_FIELD_PX, &s.px},
        {CW_FIELD_PY, &s.py}, {CW_FIELD_SX, &s.sx}, {CW_FIELD_SY, &s.sy}};
    for (const auto& f : fields)
        if (cw_transient_get_field(t, f.first, f.second->data(), n) != CW_OK)
            throw CliError(kExitFailure, std::string("reading a field of the step: ") +
                                             cw_transient_last_error(t));
    if (cw_transient_get_state(t, s.state.data(), n) != CW_OK)
        throw CliError(kExitFailure, std::string("reading the element states of the step: ") +
                                         cw_transient_last_error(t));
    cw_result_init(&s.result);
    s.result.model = CW_MODEL_EXACT;
    s.result.Fx = r.Fx;
    s.result.Fy = r.Fy;
    s.result.Mz = r.Mz;
    s.result.n_contact = r.n_contact;
    s.result.n_adhesion = r.n_adhesion;
    s.result.n_slip = r.n_slip;
    s.result.adhesion_fraction = r.n_contact > 0 ? double(r.n_adhesion) / r.n_contact : 0.0;
    const double cell = g.dx * g.dy;
    double load = 0.0, p_max = 0.0;
    for (size_t k = 0; k < n; ++k) {
        if (s.state[k] == CW_STATE_EXTERIOR) continue;
        s.area[k] = cell;
        load += s.pz[k] * cell;
        p_max = std::max(p_max, s.pz[k]);
    }
    s.result.normal_force = load;
    s.result.p_max = p_max;
    // The radius of a circle of the contact's area: the moment's scale.
    s.result.a = s.result.b = std::sqrt(r.n_contact * cell / M_PI);
    s.result.W_consistent = r.W_step;
    return s;
}

void write_transient_history(const std::string& dir, const std::vector<TransientRecord>& steps)
{
    const std::string path = dir + "/history.csv";
    std::ofstream f(path);
    f << "step,line,dq_m,xi_x,xi_y,phi,Fx_N,Fy_N,Mz_N_m,n_contact,n_adhesion,n_slip,W_step_J,W_slip_J\n";
    char buf[512];
    for (size_t k = 0; k < steps.size(); ++k) {
        const cw_transient_result& r = steps[k].result;
        std::snprintf(buf, sizeof buf,
                      "%zu,%ld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d,%d,%.17g,%.17g\n", k + 1,
                      steps[k].line, steps[k].input.dq, r.xi_x, r.xi_y, r.phi, r.Fx, r.Fy, r.Mz,
                      r.n_contact, r.n_adhesion, r.n_slip, r.W_step, r.W_slip);
        f << buf;
    }
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

namespace {

std::string step_name(size_t k)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "step_%03zu", k + 1);
    return buf;
}

// row_NNN.dat: along the row of elements nearest y = 0, x [mm], p_x on the
// wheel and the bound +-mu p_z [N/mm^2], the state; exterior cells too (0).
size_t write_row_data(const std::string& path, const Solution& s, const Units& u)
{
    size_t row = 0;
    for (int j = 0; j < s.ny; ++j)
        if (std::fabs(s.grid.y0 + j * s.grid.dy) < std::fabs(s.grid.y0 + row * s.grid.dy))
            row = static_cast<size_t>(j);
    const double k = u.plot_factor(Quantity::length), stress = u.plot_factor(Quantity::stress);
    std::ofstream f(path);
    f << "# x [" << u.plot_label(Quantity::length) << "] p_x mu*p_z -mu*p_z ["
      << u.plot_label(Quantity::stress) << "] state, along y = "
      << fmt(k * (s.grid.y0 + row * s.grid.dy), 4) << " " << u.plot_label(Quantity::length)
      << "; p_x on the wheel\n";
    char buf[160];
    for (int i = 0; i < s.nx; ++i) {
        const size_t e = static_cast<size_t>(i) + static_cast<size_t>(s.nx) * row;
        const double bound = s.params.mu * s.pz[e];
        std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g %.9g %d\n", k * s.x[e], stress * s.px[e],
                      stress * bound, -stress * bound, s.state[e]);
        f << buf;
    }
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
    return row;
}

// What a step is, in words: a shift and its displacement, or the distance
// rolled and the creepages.
std::string step_words(const TransientRecord& r, const Units& u)
{
    const double mm = u.plot_factor(Quantity::length);
    const std::string l = " " + u.plot_label(Quantity::length);
    std::ostringstream s;
    if (r.input.dq == 0.0)
        s << "a shift: u_x = " << fmt(mm * r.result.xi_x, 4) << l << ", u_y = "
          << fmt(mm * r.result.xi_y, 4) << l << ", rotation " << fmt(r.result.phi, 4) << " rad";
    else
        s << "rolled dq = " << fmt(mm * r.input.dq, 4) << l << ": ξ_x = " << fmt(r.result.xi_x, 4)
          << ", ξ_y = " << fmt(r.result.xi_y, 4) << ", φ = " << fmt(r.result.phi, 4) << " 1/m";
    return s.str();
}

std::string step_commands(const std::string& dir, size_t k, const TransientRecord& r,
                          size_t n_steps, const std::string& gap_file, const Units& u)
{
    const Solution& s = r.fields;
    const std::string name = step_name(k);
    GridMapFiles files;
    files.elements = "gnuplot/" + name + ".dat";
    files.outline = "gnuplot/" + name + "_outline.dat";
    files.patches = "gnuplot/" + name + "_patches.dat";
    const GridMaps maps = write_grid_maps(dir, files, s, {}, u, PlotStyle());
    const std::string row_file = "gnuplot/" + name + "_row.dat";
    const size_t row = write_row_data(dir + "/" + row_file, s, u);
    const double mu_n = s.params.mu * s.result.normal_force;
    const std::string stress = u.plot_label(Quantity::stress);
    const cw_result shown = shown_totals(s); // rounding noise (Fy of a pure Fx) as 0
    std::ostringstream g;
    const std::vector<std::string> caption = {
        std::string("Transient rolling (") +
            (s.params.model == CW_MODEL_FASTSIM ? "FASTSIM" : "exact model") + "), step " +
            std::to_string(k + 1) + " of " + std::to_string(n_steps) +
            " (line " + std::to_string(r.line) + "): " + step_words(r, u),
        "Fx = " + fmt(shown.Fx, 5) + " N (" + fmt(shown.Fx / mu_n, 4) + " μN), Fy = " +
            fmt(shown.Fy, 5) + " N (" + fmt(shown.Fy / mu_n, 4) + " μN) on the wheel; " +
            std::to_string(r.result.n_adhesion) + " adhesion, " +
            std::to_string(r.result.n_slip) + " slip elements; gap " +
            std::filesystem::path(gap_file).filename().string() + ", N = " +
            fmt(s.result.normal_force, 5) + " N, μ = " + fmt(s.params.mu, 4) +
            "; rolling towards +x (material enters at the leading edge, +x)"};
    g << gp_png(name + ".png", 1400, 1250) << "set multiplot layout 2,2 title "
      << gp_title(caption, 1400, 12) << " font ',12'\n"
      << maps.frame << maps.slip.commands << maps.traction_x.commands << maps.traction_y.commands;
    // The centre row: the traction against its bound, the slip elements marked.
    g << "unset object\nunset arrow\nunset label\nunset colorbox\nset autoscale\nset size noratio\n"
      << "set key top left opaque\nset xlabel 'x [" << u.plot_label(Quantity::length) << "]'\n"
      << "set ylabel 'traction on the wheel [" << stress << "]'\n"
      << "set title " << gp_quote("Along y = " + fmt(u.plot_factor(Quantity::length) *
                                                      (s.grid.y0 + row * s.grid.dy), 4) + " " +
                                  u.plot_label(Quantity::length) +
                                  ": p_x and the traction bound ±μ p_z")
      << "\nplot " << gp_quote(row_file)
      << " using 1:3 with lines lw 1.5 lc rgb '#808080' title 'μ p_z', \\\n     "
      << gp_quote(row_file) << " using 1:4 with lines lw 1.5 lc rgb '#808080' dt 2 title '-μ p_z', \\\n     "
      << gp_quote(row_file)
      << " using 1:($5 > 0 ? $2 : NaN) with linespoints lw 2 pt 7 ps 0.6 lc rgb '#2166ac' "
         "title 'p_x', \\\n     "
      << gp_quote(row_file)
      << " using 1:($5 == 2 ? $2 : NaN) with points pt 6 ps 1.4 lc rgb '#d95f02' title 'slip'\n"
      << "unset multiplot\nset key default\n";
    return g.str();
}

// history.dat: step, distance rolled up to its end [length unit], rolling
// (1) or a shift (0), xi_x, xi_y, phi, Fx/(mu N), Fy/(mu N), slip fraction.
void write_history_data(const std::string& path, const std::vector<TransientRecord>& steps,
                        double mu_n, const Units& u)
{
    std::ofstream f(path);
    f << "# step distance_rolled[" << u.plot_label(Quantity::length)
      << "] rolling xi_x xi_y phi Fx/muN Fy/muN slip_fraction\n";
    double rolled = 0.0;
    char buf[256];
    for (size_t k = 0; k < steps.size(); ++k) {
        const cw_transient_result& r = steps[k].result;
        rolled += steps[k].input.dq;
        std::snprintf(buf, sizeof buf, "%zu %.9g %d %.9g %.9g %.9g %.9g %.9g %.9g\n", k + 1,
                      u.plot_factor(Quantity::length) * rolled, steps[k].input.dq > 0.0 ? 1 : 0,
                      r.xi_x, r.xi_y, r.phi, r.Fx / mu_n, r.Fy / mu_n,
                      r.n_contact > 0 ? double(r.n_slip) / r.n_contact : 0.0);
        f << buf;
    }
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

std::string history_commands(const std::vector<TransientRecord>& steps, double mu_n,
                             const std::string& gap_file, const Units& u)
{
    bool spin = false, lateral = false;
    std::vector<std::string> shifts;
    for (size_t k = 0; k < steps.size(); ++k) {
        const cw_transient_result& r = steps[k].result;
        if (steps[k].input.dq == 0.0) {
            shifts.push_back("step " + std::to_string(k + 1) + " " + step_words(steps[k], u));
            continue;
        }
        spin = spin || r.phi != 0.0;
        lateral = lateral || r.xi_y != 0.0;
    }
    std::vector<std::string> caption = {
        std::string("Transient rolling (") +
        (steps.front().fields.params.model == CW_MODEL_FASTSIM ? "FASTSIM" : "exact model") +
        ") over " + std::to_string(steps.size()) + " steps, gap " +
        std::filesystem::path(gap_file).filename().string() + ", μN = " + fmt(mu_n, 5) + " N"};
    if (!shifts.empty()) {
        std::string s = "shifts (drawn as crosses at 0): ";
        for (size_t k = 0; k < shifts.size() && k < 3; ++k) s += (k ? "; " : "") + shifts[k];
        if (shifts.size() > 3) s += "; ... (history.csv lists all)";
        caption.push_back(s);
    }
    std::ostringstream g;
    g << gp_png("history.png", 1200, 1100) << "set multiplot layout 2,1 title "
      << gp_title(caption, 1200, 12) << " font ',12'\n"
      << "set key top right opaque\nset grid\nset xlabel 'step'\nset xrange [0.5:"
      << steps.size() + 0.5 << "]\n"
      << "set title 'Creepages of the rolling steps (given or found)'\n"
      << "set ylabel 'creepage [-]'\n";
    if (spin) g << "set y2tics\nset ytics nomirror\nset y2label 'spin φ [1/m]'\n";
    g << "plot 'gnuplot/history.dat' using 1:($3 > 0 ? $4 : NaN) with linespoints lw 2 pt 7 ps 0.5 "
         "lc rgb '#2166ac' title 'ξ_x', \\\n     'gnuplot/history.dat' using 1:($3 > 0 ? NaN : 0) "
         "with points pt 2 ps 1.5 lc rgb 'black' title 'a shift'";
    if (lateral)
        g << ", \\\n     'gnuplot/history.dat' using 1:($3 > 0 ? $5 : NaN) with linespoints lw 2 pt 7 "
             "ps 0.5 lc rgb '#b2182b' title 'ξ_y'";
    if (spin)
        g << ", \\\n     'gnuplot/history.dat' using 1:($3 > 0 ? $6 : NaN) axes x1y2 with linespoints "
             "lw 2 pt 7 ps 0.5 lc rgb '#1b7837' title 'φ (right axis)'";
    g << "\nunset y2tics\nunset y2label\nset ytics mirror\nset key center right opaque\n"
      << "set title 'Creep forces on the wheel and the slip fraction'\n"
      << "set ylabel 'F / (μ N), slip fraction [-]'\n"
      << "plot 'gnuplot/history.dat' using 1:7 with linespoints lw 2 pt 7 ps 0.5 lc rgb '#2166ac' "
         "title 'F_x / μN', \\\n     'gnuplot/history.dat' using 1:8 with linespoints lw 2 pt 7 "
         "ps 0.5 lc rgb '#b2182b' title 'F_y / μN', \\\n     'gnuplot/history.dat' using 1:9 "
         "with lines lw 1.5 dt 2 lc rgb '#808080' title 'slip elements / contact elements'\n"
      << "unset multiplot\n";
    return g.str();
}

} // namespace

void write_transient_pictures(const std::string& dir, const std::vector<TransientRecord>& steps,
                              const cw_params& p, const std::string& gap_file)
{
    std::filesystem::create_directories(dir + "/gnuplot");
    const Units u = Units::si();
    // mu N from the first step's pressure (the load is the same at every step).
    const double mu_n = p.mu * steps.front().fields.result.normal_force;
    write_history_data(dir + "/gnuplot/history.dat", steps, mu_n, u);
    std::ostringstream g;
    g << "# creepwork transient: pictures of each drawn step and of the history. Run from the "
         "output directory:\n#   gnuplot gnuplot/transient.gp\n"
      << "set datafile missing NaN\nset style fill solid 1.0 noborder\n";
    g << history_commands(steps, mu_n, gap_file, u) << "reset\nset datafile missing NaN\n"
      << "set style fill solid 1.0 noborder\n";
    for (size_t k = 0; k < steps.size(); ++k)
        if (steps[k].drawn)
            g << step_commands(dir, k, steps[k], steps.size(), gap_file, u)
              << "reset\nset datafile missing NaN\nset style fill solid 1.0 noborder\n";
    g << "unset output\n";
    run_gnuplot(dir, "gnuplot/transient.gp", g.str());
}

} // namespace cwcli
