// Element-wise factors on the friction coefficient (contact/friction_law.hpp,
// ElementFriction; Solver::set_friction_factors) in every model that takes
// them, element by element: a factor field that varies along x and y
// (0.4 ... 1), full sliding (xi_x = 0.3), both rolling directions. Each
// slipping element carries |p_t| = f_e mu(s_e) p_e, f_e its own factor in
// the caller's layout -- so a factor read mirrored, shifted by the gap
// model's box or not applied fails -- to 1e-12 relative (measured 6e-16:
// the projection onto the bound, and under the rational law its Newton root
// to rounding with the exported slip). Every element slides. Models:
// FASTSIM on the uniform and gap grids (Coulomb's law; the rational law at
// each element's slip speed), the exact model on the gap grid (Coulomb's
// law). Without factors the next solve is bitwise a fresh solver's. The gap
// grid's models' Jacobians hold the factors (the N column against central
// differences).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "contact/hertz.hpp"
#include "solver.hpp"
#include "test_support.h"

namespace cw = creepwork;

namespace {

constexpr int kNx = 30, kNy = 26;
constexpr double kMu = 0.3;

cw::ContactInput contact()
{
    cw::ContactInput in;
    in.a = 6e-3;
    in.b = 9e-3;
    in.normal_force = 80e3;
    in.mu = kMu;
    in.G = 82e9;
    in.nu = 0.28;
    in.V = 20.0;
    in.xi_x = 0.3;
    in.tolerance = 1e-12;
    return in;
}

// f(i, j) = 0.4 + 0.6 u v, u = (i + 1/2)/nx, v = 1/2 + (j + 1/2)/(2 ny):
// rising along x (the march's mirror image differs) and along y.
std::vector<double> factors()
{
    std::vector<double> f(static_cast<size_t>(kNx) * kNy);
    for (int j = 0; j < kNy; ++j)
        for (int i = 0; i < kNx; ++i)
            f[i + static_cast<size_t>(kNx) * j] =
                0.4 + 0.6 * ((i + 0.5) / kNx) * (0.5 + (j + 0.5) / (2.0 * kNy));
    return f;
}

// mu(s) of the input's law (Coulomb's or the rational law).
double mu_of(const cw::ContactInput& in, double s)
{
    if (in.friction_law == cw::FrictionLaw::coulomb) return in.mu;
    return in.mu + in.mu_e1 / (1.0 + s / in.s_h1);
}

// Solves in with the factors and checks every element; returns Fx.
double check_elements(cw::Solver& s, const cw::ContactInput& in, double tol, const char* what)
{
    const std::vector<double> f = factors();
    s.set_friction_factors(f.data());
    const cw::SolveTotals t = s.solve(in, cw::SolveMode::full);
    s.set_friction_factors(nullptr);
    const size_t n = f.size();
    std::vector<double> pz(n), px(n), py(n), sx(n), sy(n);
    std::vector<int> state(n);
    s.copy_field(cw::Field::pz, pz.data());
    s.copy_field(cw::Field::px, px.data());
    s.copy_field(cw::Field::py, py.data());
    s.copy_field(cw::Field::sx, sx.data());
    s.copy_field(cw::Field::sy, sy.data());
    s.copy_state(state.data());
    double worst = 0.0;
    int contact = 0;
    for (size_t e = 0; e < n; ++e) {
        if (state[e] == 0) continue;
        ++contact;
        assert_int_equal(state[e], 2);
        const double speed = in.V * std::hypot(sx[e], sy[e]);
        const double bound = f[e] * mu_of(in, speed) * pz[e];
        const double err = std::fabs(std::hypot(px[e], py[e]) - bound) / bound;
        worst = std::max(worst, err);
    }
    printf("  %s: %d elements slide, worst |p_t| / (f mu(s) p) - 1 = %.2g\n", what, contact,
           worst);
    assert_true(contact > 100 && t.n_adhesion == 0);
    assert_true(worst <= tol);
    return t.Fx;
}

// check_elements in both rolling directions ("what" and "what, -x").
void check_both_directions(cw::Solver& s, cw::ContactInput& in, const std::string& what)
{
    for (int d : {1, -1}) {
        in.rolling_direction = d;
        check_elements(s, in, 1e-12, (d > 0 ? what : what + ", -x").c_str());
    }
}

// The rational law of the slip speed: mu from 0.35 at rest to 0.2.
void set_rational_law(cw::ContactInput& in)
{
    in.friction_law = cw::FrictionLaw::rational;
    in.mu = 0.2;
    in.mu_e1 = 0.15;
    in.s_h1 = 3.0;
}

// After the factors, a solve without them equals a fresh solver's, bitwise.
void check_plain(cw::Solver& s, const cw::GridSpec& g, const cw::ContactInput& in)
{
    cw::Solver fresh(g);
    const double a = s.solve(in, cw::SolveMode::full).Fx;
    const double b = fresh.solve(in, cw::SolveMode::full).Fx;
    assert_true(a == b);
}

void fastsim_takes_factors(void**)
{
    cw::GridSpec g;
    g.kind = cw::GridKind::uniform;
    g.nx = kNx;
    g.ny = kNy;
    g.box_scale = 1.05;
    cw::Solver s(g);
    cw::ContactInput in = contact();
    check_both_directions(s, in, "FASTSIM, Coulomb");
    check_plain(s, g, in);
    set_rational_law(in);
    check_both_directions(s, in, "FASTSIM, rational law");
    check_plain(s, g, in);
}

// The gap grid: Hertz's gap of the semi-axes on 1.2 times them; h holds it.
cw::GridSpec hertz_gap_grid(cw::ContactInput& in, std::vector<double>& h)
{
    cw::GridSpec g;
    g.kind = cw::GridKind::gap;
    g.nx = kNx;
    g.ny = kNy;
    g.dx = 2.4 * in.a / kNx;
    g.dy = 2.4 * in.b / kNy;
    g.x0 = -1.2 * in.a + 0.5 * g.dx;
    g.y0 = -1.2 * in.b + 0.5 * g.dy;
    const cw::HertzCurvatures hz =
        cw::hertz_from_semi_axes(in.a, in.b, in.normal_force, in.G / (1.0 - in.nu));
    h.assign(static_cast<size_t>(kNx) * kNy, 0.0);
    for (int j = 0; j < kNy; ++j)
        for (int i = 0; i < kNx; ++i) {
            const double x = g.x0 + i * g.dx, y = g.y0 + j * g.dy;
            h[i + static_cast<size_t>(kNx) * j] = hz.A * x * x + hz.B * y * y;
        }
    in.gap = h.data();
    in.gap_len = h.size();
    return g;
}

// The Jacobian holds the factors: its N column in partial slip against
// central differences of solves with the same factors (steps 1e-5 N, no
// element entering or leaving contact or slip; agreement 1e-6, measured
// 5e-8 for the exact model: the differences' truncation and the solves'
// tolerance).
void check_jacobian_holds_factors(cw::Solver& s, cw::ContactInput in, const char* what)
{
    in.xi_x = 2e-3;
    in.rolling_direction = 1;
    const std::vector<double> f = factors();
    s.set_friction_factors(f.data());
    cw::Jacobian J;
    s.solve_jacobian(in, cw::SolveMode::forces_only, J);
    const double step = 1e-5 * in.normal_force;
    cw::ContactInput up = in, down = in;
    up.normal_force += step;
    down.normal_force -= step;
    const double fu = s.solve(up, cw::SolveMode::forces_only).Fx;
    const double fd = s.solve(down, cw::SolveMode::forces_only).Fx;
    s.set_friction_factors(nullptr);
    const double central = (fu - fd) / (2.0 * step);
    printf("  %s dFx/dN with factors: %.8g, central differences %.8g\n", what, J.d[0][3], central);
    assert_close(J.d[0][3], central, 1e-6, 0.0);
}

void gap_exact_takes_factors(void**)
{
    cw::ContactInput in = contact();
    in.model = cw::ModelKind::exact;
    std::vector<double> h;
    const cw::GridSpec g = hertz_gap_grid(in, h);
    cw::Solver s(g);
    check_both_directions(s, in, "exact, gap grid");
    in.warm_start = false;
    check_plain(s, g, in);
    check_jacobian_holds_factors(s, in, "gap exact");
}

// FASTSIM on the gap grid (its exact normal method): Coulomb's law and the
// rational law at each element's slip speed.
void gap_fastsim_takes_factors(void**)
{
    cw::ContactInput in = contact();
    in.model = cw::ModelKind::fastsim;
    std::vector<double> h;
    const cw::GridSpec g = hertz_gap_grid(in, h);
    cw::Solver s(g);
    check_both_directions(s, in, "FASTSIM, gap grid");
    check_plain(s, g, in);
    check_jacobian_holds_factors(s, in, "gap FASTSIM, Coulomb");
    set_rational_law(in);
    check_both_directions(s, in, "FASTSIM, gap grid, rational law");
    check_plain(s, g, in);
    check_jacobian_holds_factors(s, in, "gap FASTSIM, rational law");
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(fastsim_takes_factors),
        cmocka_unit_test(gap_exact_takes_factors),
        cmocka_unit_test(gap_fastsim_takes_factors),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
