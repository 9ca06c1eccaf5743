// Writes CONTACT's results for the shapes of gap_shapes.hpp to
// data/contact_cases.csv (totals) and data/contact_patches.csv (per patch,
// summed from CONTACT's element tractions over the 4-connected components of
// its contact elements). Built only with -DCREEPWORK_CONTACT_DIR=<a CONTACT
// build> (tests/nonhertz/data/README.md); never by CI.
//
//   make_contact_reference OUTPUT_DIR
//
// For each shape: CONTACT without creepage gives the contact area, from
// which the creepages are set as the DEV cases' (gap_shapes.hpp, rounded to
// four significant digits, written to the table as inputs); then the case is
// solved at EPS = 1e-12 (the reference) and at 1e-10 (the difference says
// how far CONTACT's own convergence reaches).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "contact_gap_shape.hpp"

namespace {

double round4(double v)
{
    if (v == 0.0) return 0.0;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return std::strtod(buf, nullptr);
}

// 4-connected components of eldiv > 0, numbered by first element in [i + nx j].
int label(int nx, int ny, const std::vector<int>& eldiv, std::vector<int>& lab)
{
    lab.assign(eldiv.size(), -1);
    int count = 0;
    std::vector<int> stack;
    for (int s = 0; s < nx * ny; ++s) {
        if (eldiv[s] <= 0 || lab[s] >= 0) continue;
        lab[s] = count;
        stack.push_back(s);
        while (!stack.empty()) {
            const int k = stack.back();
            stack.pop_back();
            const int i = k % nx, j = k / nx;
            const int nb[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
            for (const auto& p : nb) {
                if (p[0] < 0 || p[0] >= nx || p[1] < 0 || p[1] >= ny) continue;
                const int m = p[0] + nx * p[1];
                if (eldiv[m] > 0 && lab[m] < 0) {
                    lab[m] = count;
                    stack.push_back(m);
                }
            }
        }
        ++count;
    }
    return count;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUTPUT_DIR\n", argv[0]);
        return 2;
    }
    const std::string dir = argv[1];
    if (contact_gap_init() != 0) return 1;
    FILE* cases = std::fopen((dir + "/contact_cases.csv").c_str(), "w");
    FILE* patches = std::fopen((dir + "/contact_patches.csv").c_str(), "w");
    if (!cases || !patches) return 1;
    std::fprintf(cases,
                 "case_id,description,N_N,approach_given,approach_in_m,G_Pa,nu,mu,xi_x,xi_y,"
                 "phi_per_m,rolling_direction,Fn_N,Fx_N,Fy_N,Mz_Nm,p_max_Pa,approach_m,"
                 "n_contact,n_adhesion,n_slip,n_patches,W_macro_J_per_m,eps,"
                 "eps_1e10_max_force_diff,eps_1e10_count_diff\n");
    std::fprintf(patches, "case_id,patch,n_contact,Fn_N,Fx_N,Fy_N,Mz_Nm\n");
    for (gapshapes::Shape s : gapshapes::shapes()) {
        const size_t n = s.h.size();
        std::vector<int> eldiv(n);
        std::vector<double> pn(n), px(n), py(n);
        contact_gap_result r{};
        r.eldiv = eldiv.data();
        r.pn = pn.data();
        r.px = px.data();
        r.py = py.data();
        // Contact area without creepage -> creepages.
        contact_gap_case c = contact_case_of(s, 1e-12);
        contact_gap_setup(&c);
        if (contact_gap_solve(&c, 1, &r) != 0) return 1;
        const double N = r.Fn;
        const double cr = std::sqrt(r.n_contact * s.dx * s.dy / gapshapes::kPi);
        const double xi_sat = 3.0 * s.mu * N / (4.2 * s.G * cr * cr);
        const double th = s.theta_deg * gapshapes::kPi / 180.0;
        s.xi_x = round4(s.level * xi_sat * std::cos(th));
        s.xi_y = round4(s.level * xi_sat * std::sin(th));
        s.phi = round4(s.spin_frac * xi_sat / cr);
        if (std::fabs(s.xi_x) < 1e-12) s.xi_x = 0.0;
        if (std::fabs(s.xi_y) < 1e-12) s.xi_y = 0.0;

        c = contact_case_of(s, 1e-12);
        contact_gap_setup(&c);
        if (contact_gap_solve(&c, 1, &r) != 0) return 1;
        const contact_gap_result ref = r;
        std::vector<int> lab;
        const int count = label(s.nx, s.ny, eldiv, lab);
        // Per patch, from CONTACT's tractions.
        for (int p = 0; p < count; ++p) {
            double fn = 0, fx = 0, fy = 0, mz = 0;
            int m = 0;
            for (int j = 0; j < s.ny; ++j)
                for (int i = 0; i < s.nx; ++i) {
                    const size_t k = i + static_cast<size_t>(s.nx) * j;
                    if (lab[k] != p) continue;
                    const double x = s.x0 + i * s.dx, y = s.y0 + j * s.dy, a = s.dx * s.dy;
                    ++m;
                    fn += pn[k] * a;
                    fx += px[k] * a;
                    fy += py[k] * a;
                    mz += (x * py[k] - y * px[k]) * a;
                }
            std::fprintf(patches, "%s,%d,%d,%.12g,%.12g,%.12g,%.12g\n", s.id.c_str(), p, m, fn, fx,
                         fy, mz);
        }
        // CONTACT's own convergence: the same case at EPS = 1e-10.
        c = contact_case_of(s, 1e-10);
        contact_gap_setup(&c);
        contact_gap_result loose{};
        if (contact_gap_solve(&c, 1, &loose) != 0) return 1;
        const double muN = s.mu * ref.Fn;
        const double dF = std::max(std::fabs(loose.Fx - ref.Fx), std::fabs(loose.Fy - ref.Fy)) /
                          std::max(std::hypot(ref.Fx, ref.Fy), 0.01 * muN);
        const int dn = std::abs(loose.n_adhesion - ref.n_adhesion) + std::abs(loose.n_slip - ref.n_slip);
        const double W = -(ref.Fx * s.xi_x + ref.Fy * s.xi_y + ref.Mz * s.phi);
        std::fprintf(cases,
                     "%s,\"%s\",%.12g,%d,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%d,%.15g,%.15g,"
                     "%.15g,%.15g,%.15g,%.15g,%d,%d,%d,%d,%.15g,%g,%.2g,%d\n",
                     s.id.c_str(), s.description.c_str(), s.approach_given ? 0.0 : s.normal_force,
                     s.approach_given ? 1 : 0, s.approach_given ? s.approach : 0.0, s.G, s.nu, s.mu,
                     s.xi_x, s.xi_y, s.phi, s.rolling_direction, ref.Fn, ref.Fx, ref.Fy, ref.Mz,
                     ref.p_max, ref.approach, ref.n_contact, ref.n_adhesion, ref.n_slip, count, W,
                     1e-12, dF, dn);
        std::fprintf(stderr, "%s: %d elements, %d patches, %.3f s\n", s.id.c_str(), ref.n_contact,
                     count, ref.seconds);
    }
    std::fclose(cases);
    std::fclose(patches);
    contact_gap_finish();
    return 0;
}
