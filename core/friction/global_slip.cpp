#include "friction/global_slip.hpp"

#include "contact/error.hpp"
#include "contact/kalker_coefficients.hpp"

#include <algorithm>
#include <cmath>

namespace creepwork {

GlobalSlip global_slip(const ContactInput& in, const SlipSpeedLaw& law, const SlopeReduction& sr,
                       double V, double GC11)
{
    constexpr double pi = 3.14159265358979323846;
    GlobalSlip g;
    g.slip_speed = V * std::hypot(in.xi_x, in.xi_y);
    g.mu = friction_value(law, g.slip_speed).mu;
    double nu_phi = in.xi_y + in.phi * in.a;
    if (std::fabs(nu_phi) < std::fabs(in.xi_y)) nu_phi = in.xi_y;
    const double nu = std::hypot(in.xi_x, nu_phi);
    const double muN = g.mu * in.normal_force;
    g.epsilon = muN > 0.0 ? pi * in.a * in.b * sr.k0 * GC11 * nu / (4.0 * muN) : 0.0;
    g.k = sr.k0 * (sr.alpha_inf + (1.0 - sr.alpha_inf) / (1.0 + sr.beta * g.epsilon));
    return g;
}

SemiAxes equivalent_ellipse(const ContactGrid& grid, double a, double b)
{
    constexpr double pi = 3.14159265358979323846;
    if (grid.spec().kind != GridKind::uniform) return {a, b};
    const int nx = grid.nx(), ny = grid.ny();
    int n = 0, m_min = nx, m_max = -1, j_min = ny, j_max = -1;
    for (int m = 0; m < nx; ++m)
        for (int j = 0; j < ny; ++j)
            if (grid.in_contact()[static_cast<Eigen::Index>(m) * ny + j] != 0.0) {
                ++n;
                m_min = std::min(m_min, m);
                m_max = std::max(m_max, m);
                j_min = std::min(j_min, j);
                j_max = std::max(j_max, j);
            }
    if (n == 0) return {a, b};
    const double dx = grid.x_length()[0] * a, dy = grid.y_width()[0] * b;
    const double length = dx * (m_max - m_min + 1), width = dy * (j_max - j_min + 1);
    const double r = std::sqrt(n * dx * dy / pi);
    return {r * std::sqrt(length / width), r * std::sqrt(width / length)};
}

ContactInput global_slip_input(const ContactInput& in, const ContactGrid& grid,
                               const SlipSpeedLaw& law, const SlopeReduction& sr, double V,
                               GlobalSlip* out)
{
    check_slip_speed_law(law);
    check_slope_reduction(sr);
    if (!(std::isfinite(V) && V >= 0.0) || (law.kind != SlipSpeedLawKind::coulomb && V == 0.0))
        throw Error(ErrorKind::invalid_input,
                    "V (the rolling speed) must be finite and > 0 [m/s] for a law of the slip speed");
    ContactInput r = in;
    const SemiAxes e = equivalent_ellipse(grid, in.a, in.b);
    Flexibilities L{in.L1, in.L2, in.L3};
    double GC11 = 0.0;
    if (in.flexibility == FlexibilitySource::kalker_from_material) {
        L = kalker_flexibilities(in.a, in.b, in.G, kalker_coefficients(in.a / in.b, in.nu));
        GC11 = in.G * kalker_coefficients(e.a / e.b, in.nu).C11;
    } else {
        GC11 = 8.0 * in.a / (3.0 * in.L1); // L1 = 8a / (3 C11 G) on the nominal ellipse
    }
    ContactInput on_e = in;
    on_e.a = e.a;
    on_e.b = e.b;
    const GlobalSlip g = global_slip(on_e, law, sr, V, GC11);
    r.mu = g.mu;
    r.flexibility = FlexibilitySource::given;
    r.L1 = L.L1 / g.k;
    r.L2 = L.L2 / g.k;
    r.L3 = L.L3 / g.k;
    if (out) *out = g;
    return r;
}

Jacobian global_slip_jacobian(const ContactInput& in, const ContactGrid& grid,
                              const SlipSpeedLaw& law, const SlopeReduction& sr, double V,
                              const Jacobian& J, const double F[3])
{
    if (in.flexibility_blending)
        throw Error(ErrorKind::invalid_input,
                    "flexibility_blending: the global-slip FASTSIM's Jacobian needs it off");
    GlobalSlip g;
    const ContactInput eff = global_slip_input(in, grid, law, sr, V, &g);
    const SemiAxes e = equivalent_ellipse(grid, in.a, in.b);
    // The creepages FASTSIM saw, c = (xi_x, xi_y, phi), and its Jacobian J in
    // them at mu(w), L/k.
    const double c[3] = {in.xi_x, in.xi_y, in.phi};
    double dF_dmu[3];
    for (int i = 0; i < 3; ++i) {
        double sum = 0.0;
        for (int k = 0; k < 3; ++k) sum += c[k] * J.d[i][k];
        dF_dmu[i] = eff.mu > 0.0 ? (F[i] - sum) / eff.mu : 0.0;
    }
    // F(c; L/k) = G(k c; L): dF/dk = sum_c c_k dG/dc_k = sum_c c_k J_ik / k.
    double dF_dk[3];
    for (int i = 0; i < 3; ++i) {
        double sum = 0.0;
        for (int k = 0; k < 3; ++k) sum += c[k] * J.d[i][k];
        dF_dk[i] = sum / g.k;
    }
    // mu(w), w = V |(xi_x, xi_y)|: dmu/dc.
    const double s = std::hypot(in.xi_x, in.xi_y);
    const double mu_slope = friction_value(law, g.slip_speed).dmu_ds;
    const double dmu[4] = {s > 0.0 ? mu_slope * V * in.xi_x / s : 0.0,
                           s > 0.0 ? mu_slope * V * in.xi_y / s : 0.0, 0.0, 0.0};
    // k(eps), eps proportional to nu / (mu N): deps/dc.
    double nu_phi = in.xi_y + in.phi * e.a;
    const bool spin_counts = !(std::fabs(nu_phi) < std::fabs(in.xi_y));
    if (!spin_counts) nu_phi = in.xi_y;
    const double nu = std::hypot(in.xi_x, nu_phi);
    double dnu[4] = {0.0, 0.0, 0.0, 0.0};
    if (nu > 0.0) {
        dnu[0] = in.xi_x / nu;
        dnu[1] = nu_phi / nu;
        dnu[2] = spin_counts ? nu_phi * e.a / nu : 0.0;
    }
    const double dk_deps = -sr.k0 * (1.0 - sr.alpha_inf) * sr.beta /
                           ((1.0 + sr.beta * g.epsilon) * (1.0 + sr.beta * g.epsilon));
    Jacobian out;
    for (int col = 0; col < 4; ++col) {
        double deps = 0.0;
        if (g.epsilon > 0.0) {
            deps = (nu > 0.0 ? g.epsilon * dnu[col] / nu : 0.0) - g.epsilon * dmu[col] / g.mu;
            if (col == 3) deps -= g.epsilon / in.normal_force;
        }
        const double dk = dk_deps * deps;
        for (int i = 0; i < 3; ++i)
            out.d[i][col] = J.d[i][col] + dF_dmu[i] * dmu[col] + dF_dk[i] * dk;
    }
    return out;
}

void check_slope_reduction(const SlopeReduction& sr)
{
    if (!(std::isfinite(sr.k0) && sr.k0 > 0.0))
        throw Error(ErrorKind::invalid_input, "k0 must be finite and > 0");
    if (!(std::isfinite(sr.alpha_inf) && sr.alpha_inf >= 0.0 && sr.alpha_inf <= 1.0))
        throw Error(ErrorKind::invalid_input, "alpha_inf must lie in [0, 1]");
    if (!(std::isfinite(sr.beta) && sr.beta >= 0.0))
        throw Error(ErrorKind::invalid_input, "beta must be finite and >= 0");
}

} // namespace creepwork
