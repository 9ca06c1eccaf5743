#include "wheelrail_data.hpp"

#include <cmath>
#include <fstream>

#include "cli_error.hpp"
#include "json.hpp"

namespace cwcli {

namespace {

void check(const cw_wheelrail* w, int status, const char* call)
{
    if (status != CW_OK)
        throw CliError(kExitFailure, std::string("cannot read the wheel/rail solution (") + call +
                                         "): " + cw_wheelrail_last_error(w));
}

std::vector<double> patch_field(const cw_wheelrail* w, size_t k, const cw_wheelrail_patch& p,
                                int field)
{
    std::vector<double> out(static_cast<size_t>(p.field_nx) * static_cast<size_t>(p.field_ny));
    check(w, cw_wheelrail_get_patch_field(w, k, field, out.data(), out.size()),
          "cw_wheelrail_get_patch_field");
    return out;
}

void finish(std::ofstream& f, const std::string& path)
{
    f.close();
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

// The same contact seen with y reversed (rows j -> ny-1-j): lateral
// components and moments change sign, everything else keeps its value.
void mirror_lateral(Solution& s)
{
    const auto rows = [&s](auto& v, auto sign) {
        const auto old = v;
        for (int j = 0; j < s.ny; ++j)
            for (int i = 0; i < s.nx; ++i)
                v[i + static_cast<size_t>(s.nx) * j] =
                    sign * old[i + static_cast<size_t>(s.nx) * (s.ny - 1 - j)];
    };
    for (auto* v : {&s.x, &s.area, &s.pz, &s.px, &s.sx, &s.work_paper, &s.work_consistent})
        rows(*v, 1.0);
    for (auto* v : {&s.y, &s.py, &s.sy, &s.mz}) rows(*v, -1.0);
    rows(s.state, 1);
    std::vector<double> py = s.profile_y, pw = s.profile_w, pp = s.profile_parabola;
    for (int j = 0; j < s.ny; ++j) {
        s.profile_y[j] = -py[s.ny - 1 - j];
        s.profile_w[j] = pw[s.ny - 1 - j];
        s.profile_parabola[j] = pp[s.ny - 1 - j];
    }
    s.result.Fy = -s.result.Fy;
    s.result.Mz = -s.result.Mz;
    s.params.xi_y = -s.params.xi_y;
    s.params.phi = -s.params.phi;
}

} // namespace

ProfilePoints read_profile(const cw_wheelrail* w, int which)
{
    size_t count = 0;
    const int asked = cw_wheelrail_get_profile(w, which, nullptr, nullptr, 0, &count);
    if (asked != CW_OK && asked != CW_ERR_BUFFER_TOO_SMALL)
        check(w, asked, "cw_wheelrail_get_profile");
    ProfilePoints p;
    p.y.resize(count);
    p.z.resize(count);
    check(w, cw_wheelrail_get_profile(w, which, p.y.data(), p.z.data(), count, &count),
          "cw_wheelrail_get_profile");
    return p;
}

void write_profiles_csv(const std::string& path, const ProfilePoints& rail,
                        const ProfilePoints& wheel)
{
    std::ofstream f(path);
    f << "body,y_m,z_m\n";
    for (const auto& [body, p] : {std::pair<const char*, const ProfilePoints*>{"rail", &rail},
                                  {"wheel", &wheel}})
        for (size_t k = 0; k < p->y.size(); ++k)
            f << body << "," << shortest_exact(p->y[k]) << "," << shortest_exact(p->z[k]) << "\n";
    finish(f, path);
}

void write_patch_fields_csv(const std::string& path, const cw_wheelrail* w, size_t k,
                            const cw_wheelrail_patch& patch)
{
    const int ids[] = {CW_FIELD_X,  CW_FIELD_Y,  CW_FIELD_AREA, CW_FIELD_PZ, CW_FIELD_PX,
                       CW_FIELD_PY, CW_FIELD_SX, CW_FIELD_SY};
    std::vector<std::vector<double>> columns;
    for (int id : ids) columns.push_back(patch_field(w, k, patch, id));
    const std::vector<double> work = patch_field(w, k, patch, CW_FIELD_WORK_CONSISTENT);
    std::vector<int> state(work.size());
    check(w, cw_wheelrail_get_patch_state(w, k, state.data(), state.size()),
          "cw_wheelrail_get_patch_state");
    std::ofstream f(path);
    f << "x_m,s_m,area_m2,pz_Pa,px_Pa,ps_Pa,sx,ss,state,work_J_per_m\n";
    for (size_t e = 0; e < work.size(); ++e) {
        // + 0.0: an exact zero prints as 0, never -0.
        for (const std::vector<double>& c : columns) f << shortest_exact(c[e] + 0.0) << ",";
        f << state[e] << "," << shortest_exact(work[e] + 0.0) << "\n";
    }
    finish(f, path);
}

PatchView read_patch_view(const cw_wheelrail* w, size_t k, const cw_wheelrail_params& params)
{
    PatchView v;
    cw_wheelrail_patch_init(&v.patch);
    check(w, cw_wheelrail_get_patch(w, k, &v.patch), "cw_wheelrail_get_patch");
    const cw_wheelrail_patch& p = v.patch;
    const cw_solver* solver = cw_wheelrail_patch_solver(w, k);
    if (!solver) check(w, CW_ERR_INVALID_INPUT, "cw_wheelrail_patch_solver");

    // The problem the patch's solver solved, in creepwork's conventions
    // (doc/wheelrail.md): xi_x = -CKSI, xi_y = CETA, phi = CPHI, rolling
    // forward.
    cw_params c;
    cw_params_init(&c);
    c.model = params.model;
    c.normal_method = params.normal_method;
    c.mu = params.mu;
    c.G = params.G;
    c.nu = params.nu;
    c.normal_force = p.Fn;
    c.xi_x = -p.cksi;
    c.xi_y = p.ceta;
    c.phi = p.cphi;
    c.rolling_direction = 1;
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_GAP;
    g.nx = p.field_nx;
    g.ny = p.field_ny;
    g.dx = p.field_dx;
    g.dy = p.field_ds;
    g.x0 = p.field_x0;
    g.y0 = -(p.field_s0 + (p.field_ny - 1) * p.field_ds);
    v.solution = read_solution(solver, c, g);
    Solution& s = v.solution;
    if (s.nx != p.field_nx || s.ny != p.field_ny)
        throw CliError(kExitFailure, "patch " + std::to_string(k) + ": its solver's grid (" +
                                         std::to_string(s.nx) + "x" + std::to_string(s.ny) +
                                         ") is not its field grid");
    v.lobes = read_patches(solver);
    // The solver's own coordinates start at its element (0, 0), which lies
    // at (x0, y0) from the reference point: moments about the reference
    // point, as the patch's Mn, and centroids from it.
    const double x0 = g.x0, y0 = g.y0;
    const auto about_reference = [x0, y0](double& Mz, double Fx, double Fy) {
        Mz += x0 * Fy - y0 * Fx;
    };
    about_reference(s.result.Mz, s.result.Fx, s.result.Fy);
    for (cw_patch& l : v.lobes) {
        about_reference(l.Mz, l.Fx, l.Fy);
        l.x_centroid += x0;
        l.y_centroid = -(l.y_centroid + y0);
        l.Fy = -l.Fy;
        l.Mz = -l.Mz;
    }
    mirror_lateral(s);
    s.grid.y0 = p.field_s0;
    // The element centres from the reference point, as the field grid has
    // them; the pressures of both doors must agree element by element, or
    // the two grids are not laid out as the header says.
    s.x = patch_field(w, k, p, CW_FIELD_X);
    s.y = patch_field(w, k, p, CW_FIELD_Y);
    const std::vector<double> pz = patch_field(w, k, p, CW_FIELD_PZ);
    for (size_t e = 0; e < pz.size(); ++e)
        if (std::fabs(pz[e] - s.pz[e]) > 1e-9 * p.p_max)
            throw CliError(kExitFailure, "patch " + std::to_string(k) +
                                             ": its solver's fields do not match its field grid");
    return v;
}

} // namespace cwcli
