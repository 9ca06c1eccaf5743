// Flash temperature (thermal/): the moving-source kernel against its
// closed forms and a direct sum, the consistent quadrature against the
// analytic moving-source solution (uniform band, dissimilar bodies) and
// the continuous integral of the Ertz case, and the CONTACT discretisation
// against CONTACT's own example ertz_temperature (tests/data/temperature).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "contact/error.hpp"
#include "core_test_support.hpp"
#include "test_support.h"
#include "thermal/flash_temperature.hpp"
#include "thermal/heat_source.hpp"
#include "thermal/moving_source.hpp"

namespace cw = creepwork;
namespace th = creepwork::thermal;

namespace {

constexpr double kPi = 3.141592653589793238462643383279502884;

// Steel as in the Ertz case (CONTACT's example): c = 450 J/(kg K),
// lambda = 50 W/(m K), rho = 7850 kg/m^3.
th::Body steel(double T0)
{
    th::Body b;
    b.T0 = T0;
    b.heat_capacity = 450.0;
    b.conductivity = 50.0;
    b.density = 7850.0;
    return b;
}

th::ThermalParams ertz_params(th::Discretisation d, double T0_rail = 0.0, double T0_wheel = 0.0)
{
    th::ThermalParams p;
    p.rail = steel(T0_rail);
    p.wheel = steel(T0_wheel);
    p.rolling_speed = 30.0;
    p.discretisation = d;
    return p;
}

// A regular grid of nx x ny elements with its heat, fields and result.
struct Grid {
    int nx = 0, ny = 0;
    std::vector<double> x, y, row_dx, q, T1, T2;
    std::vector<int> state;
    int rolling_direction = -1;

    Grid(int nx_, int ny_, double x0, double y0, double dx, double dy)
        : nx(nx_), ny(ny_), row_dx(ny_, dx)
    {
        const size_t n = static_cast<size_t>(nx) * ny;
        x.resize(n);
        y.resize(n);
        q.assign(n, 0.0);
        T1.assign(n, -1.0);
        T2.assign(n, -1.0);
        state.assign(n, 0);
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                x[i + j * nx] = x0 + i * dx;
                y[i + j * nx] = y0 + j * dy;
            }
    }
    th::HeatedContact contact() const
    {
        th::HeatedContact c;
        c.nx = nx;
        c.ny = ny;
        c.x = x.data();
        c.y = y.data();
        c.row_dx = row_dx.data();
        c.state = state.data();
        c.q = q.data();
        c.rolling_direction = rolling_direction;
        return c;
    }
    th::TemperatureTotals solve(const th::ThermalParams& p,
                                th::MovingSourceKernel::Method method =
                                    th::MovingSourceKernel::Method::automatic)
    {
        th::FlashTemperature f(nx, ny, method);
        return f.compute(contact(), p, T1.data(), T2.data());
    }
};

// --------------------------------------------------------------- kernel

void weights_closed_form(void** state)
{
    (void)state;
    // w_k = sqrt(k + 1/2) - sqrt(k - 1/2), in long double; and the
    // telescoping sum sum_{k=1..m} w_k = sqrt(m + 1/2) - sqrt(1/2).
    long double sum = 0.0L;
    for (int k = 1; k <= 1000; ++k) {
        const long double exact = std::sqrt(k + 0.5L) - std::sqrt(k - 0.5L);
        assert_close(th::MovingSourceKernel::weight(k), static_cast<double>(exact), 1e-15, 0.0);
        sum += th::MovingSourceKernel::weight(k);
    }
    assert_close(static_cast<double>(sum), std::sqrt(1000.5) - std::sqrt(0.5), 1e-13, 0.0);
}

// Every path against a direct sum in long double, on random rows with
// leading zeros and gaps: the direct sum and the FFT to rounding, the
// recursion (exponential sum of the far weights) to 1e-9 relative in every
// element (its weights are checked to 3e-10 at construction; all weights
// and heats are >= 0, so no cancellation can amplify that).
void kernel_matches_long_double_sum(void** state)
{
    (void)state;
    using Method = th::MovingSourceKernel::Method;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int longest = th::MovingSourceKernel::kDirectMaxLength;
    for (int n : {1, 2, 3, 4, 16, 40, longest, longest + 1, 216, 640, 1000, 2500}) {
        std::vector<double> qa(n), qb(n);
        for (int t = 0; t < n; ++t) {
            qa[t] = t < n / 5 ? 0.0 : u(rng);
            qb[t] = t < n / 3 || u(rng) < 0.3 ? 0.0 : 100.0 * u(rng);
        }
        for (Method method : {Method::automatic, Method::direct, Method::recursive, Method::fft}) {
            th::MovingSourceKernel k(n, method);
            const Method used = k.method();
            if (method == Method::automatic)
                assert_true(used == (n <= longest ? Method::direct : Method::recursive));
            else
                assert_true(used == method);
            if (used == Method::recursive && n > th::MovingSourceKernel::kNearTerms) {
                assert_true(k.exponentials() >= 10 && k.exponentials() <= 60);
                assert_true(k.recursion_error() <= 3e-10);
            }
            std::vector<double> oa(n, -1.0), ob(n, -1.0);
            k.apply(qa.data(), qb.data(), oa.data(), ob.data(), std::sqrt(0.5));
            for (const auto& [q, o] : {std::pair{&qa, &oa}, std::pair{&qb, &ob}}) {
                double peak = 0.0;
                std::vector<long double> ref(n);
                for (int t = 0; t < n; ++t) {
                    long double s = std::sqrt(0.5L) * (*q)[t];
                    for (int m = 0; m < t; ++m)
                        s += (*q)[m] * (std::sqrt(t - m + 0.5L) - std::sqrt(t - m - 0.5L));
                    ref[t] = s;
                    peak = std::max(peak, static_cast<double>(s));
                }
                for (int t = 0; t < n; ++t) {
                    const double r = static_cast<double>(ref[t]);
                    if (used == Method::recursive)
                        assert_close((*o)[t], r, 1e-9, 1e-15 * peak);
                    else
                        assert_close((*o)[t], r, 0.0, 1e-13 * peak);
                    if (ref[t] == 0.0L) assert_true((*o)[t] == 0.0); // ahead of the heat: 0
                }
            }
        }
    }
}

// ----------------------------------------------------- analytic solutions

// A band of uniform heat q0 over the whole contact [-a, a] of every row:
// for q constant per element the quadrature is exact, so the analytic
// moving-source solution holds to rounding. Dissimilar bodies, beta1 =
// 2 beta2 (the rail's conductivity four times the wheel's), different bulk
// temperatures: both surfaces take T_c = (beta1 T0_1 + beta2 T0_2)/(beta1 +
// beta2) plus the flash 2 q0 sqrt(s)/((beta1 + beta2) sqrt(pi V)) in
// contact, s the distance from the leading edge; behind, each relaxes to
// its own T0 while the flash decays as sqrt(s) - sqrt(s - 2a).
void uniform_band_dissimilar_bodies(void** state)
{
    (void)state;
    const double a = 4e-3, q0 = 3e8, V = 20.0;
    const int in_contact = 40, behind = 60;
    const double dx = 2 * a / in_contact;
    th::ThermalParams p;
    p.rail = steel(20.0);
    p.rail.conductivity = 4 * 50.0;
    p.wheel = steel(80.0);
    p.rolling_speed = V;
    const double b1 = th::effusivity(p.rail), b2 = th::effusivity(p.wheel);
    assert_close(b1, 2 * b2, 1e-15, 0.0);
    const double Tc = (b1 * 20.0 + b2 * 80.0) / (b1 + b2); // = 40
    assert_close(Tc, 40.0, 1e-14, 0.0);
    const double flash_unit = 2 * q0 / ((b1 + b2) * std::sqrt(kPi * V));
    for (int rd : {-1, 1}) {
        Grid g(in_contact + behind + 5, 3, -a - 5 * dx + dx / 2, -1e-3, dx, 1e-3);
        g.rolling_direction = rd;
        // rolling_direction -1: material enters at low x; +1 mirrors the row.
        auto elem = [&](int t, int j) {
            const int i = rd < 0 ? 5 + t : g.nx - 6 - t;
            return i + j * g.nx;
        };
        for (int j = 0; j < g.ny; ++j)
            for (int t = 0; t < in_contact; ++t) {
                g.state[elem(t, j)] = 2;
                g.q[elem(t, j)] = q0;
            }
        const th::TemperatureTotals tot = g.solve(p);
        assert_close(tot.contact_temperature, Tc, 1e-14, 0.0);
        for (int j = 0; j < g.ny; ++j) {
            for (int t = -5; t < in_contact + behind; ++t) {
                const int e = elem(t, j);
                const double s = (t + 0.5) * dx; // from the leading edge
                double T1, T2;
                if (t < 0) {
                    T1 = 20.0;
                    T2 = 80.0;
                } else if (t < in_contact) {
                    T1 = T2 = Tc + flash_unit * std::sqrt(s);
                } else {
                    const double g_relax = 2 / kPi * std::asin(std::sqrt(2 * a / s));
                    const double flash = flash_unit * (std::sqrt(s) - std::sqrt(s - 2 * a));
                    T1 = 20.0 + (Tc - 20.0) * g_relax + flash;
                    T2 = 80.0 + (Tc - 80.0) * g_relax + flash;
                }
                // 105 elements a row: the recursion, 1e-9 (kernel test above)
                assert_close(g.T1[e], T1, 1e-9, 1e-12);
                assert_close(g.T2[e], T2, 1e-9, 1e-12);
                if (t >= 0 && t < in_contact) assert_true(g.T1[e] == g.T2[e]); // one surface
            }
        }
        // The hottest contact element: the trailing one, of the first row.
        assert_int_equal(tot.rail.element, elem(in_contact - 1, 0));
        assert_close(tot.rail.T, Tc + flash_unit * std::sqrt(2 * a - dx / 2), 1e-9, 0.0);
        assert_close(tot.wheel.x, g.x[elem(in_contact - 1, 0)], 0.0, 0.0);
        assert_close(tot.wheel.y, -1e-3, 0.0, 1e-18);
    }
}

// CONTACT's discretisation on the same band: its partition gives body 2
// the shared flash and body 1 beta2/beta1 of it, T_c with beta1 and beta2
// swapped, and the self-element term twice the consistent one.
void contact_partition_and_self_term(void** state)
{
    (void)state;
    const double a = 4e-3, q0 = 3e8, V = 20.0;
    const int n = 40;
    const double dx = 2 * a / n;
    th::ThermalParams p;
    p.rail = steel(20.0);
    p.rail.conductivity = 4 * 50.0;
    p.wheel = steel(80.0);
    p.rolling_speed = V;
    p.discretisation = th::Discretisation::contact;
    const double b1 = th::effusivity(p.rail), b2 = th::effusivity(p.wheel);
    Grid g(n, 1, -a + dx / 2, 0.0, dx, 1e-3);
    for (int i = 0; i < n; ++i) {
        g.state[i] = 2;
        g.q[i] = q0;
    }
    const th::TemperatureTotals tot = g.solve(p);
    const double Tc = 20.0 + b1 / (b1 + b2) * (80.0 - 20.0); // CONTACT's: 60, not 40
    assert_close(tot.contact_temperature, Tc, 1e-14, 0.0);
    const double unit = 2 * q0 / ((b1 + b2) * std::sqrt(kPi * V));
    for (int i = 0; i < n; ++i) {
        const double s = (i + 0.5) * dx;
        // consistent sqrt(s), plus the extra half element sqrt(dx/2)
        const double flash = unit * (std::sqrt(s) + std::sqrt(dx / 2));
        assert_close(g.T2[i], Tc + flash, 1e-12, 0.0);
        assert_close(g.T1[i], Tc + b2 / b1 * flash, 1e-12, 0.0);
    }
}

// Rolling the other way mirrors the fields along x, bitwise.
void rolling_direction_mirrors(void** state)
{
    (void)state;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1e8);
    for (int nx : {30, 150}) {
        Grid g(nx, 4, -1e-2, -1e-3, 2e-2 / (nx - 1), 1e-3), m = g;
        m.rolling_direction = 1;
        for (int j = 0; j < g.ny; ++j)
            for (int i = nx / 4; i < 3 * nx / 4; ++i) {
                const int e = i + j * nx, f = nx - 1 - i + j * nx;
                g.state[e] = m.state[f] = i % 3 ? 2 : 1;
                g.q[e] = m.q[f] = u(rng);
            }
        // Different bulk temperatures for the consistent scheme; equal ones for
        // CONTACT's, which relaxes one element later when rolling to -x.
        for (th::Discretisation d : {th::Discretisation::consistent, th::Discretisation::contact}) {
            const th::ThermalParams p = d == th::Discretisation::consistent
                                            ? ertz_params(d, 10.0, 50.0)
                                            : ertz_params(d, 20.0, 20.0);
            g.solve(p);
            m.solve(p);
            for (int j = 0; j < g.ny; ++j)
                for (int i = 0; i < nx; ++i) {
                    const int e = i + j * nx, f = nx - 1 - i + j * nx;
                    assert_true(g.T1[e] == m.T1[f]);
                    assert_true(g.T2[e] == m.T2[f]);
                }
        }
    }
}

// ---------------------------------------------------------- the Ertz case

// Ertz & Knothe's case: a = 5.88 mm, b = 10.54 mm, 100 kN (Hertz: p0 =
// 3N/(2 pi a b)), full sliding at 1 m/s with mu = 0.3, V = 30 m/s rolling
// towards -x, steel. The heat along y = 0 is q0 sqrt(1 - x^2/a^2).
constexpr double kErtzA = 5.88e-3, kErtzB = 10.54e-3;
double ertz_q0() { return 0.3 * 1.0 * 3 * 1e5 / (2 * kPi * kErtzA * kErtzB); }

// The continuous moving-source integral on y = 0 at x, by substitution
// (xi = x - U^2 sin^2 th, U = sqrt(x + a): smooth integrand) and Simpson's
// rule: an implementation independent of thermal/.
double ertz_continuous(double x)
{
    const double a = kErtzA, beta = th::effusivity(steel(0.0));
    const double U = std::sqrt(x + a);
    const int m = 4000;
    const double h = kPi / 2 / m;
    double s = 0.0;
    for (int k = 0; k <= m; ++k) {
        const double t = k * h, xi = x - U * U * std::sin(t) * std::sin(t);
        const double f = 2 * ertz_q0() / a * std::sqrt(std::max(0.0, a - xi)) * U * U *
                         std::cos(t) * std::cos(t);
        s += f * (k == 0 || k == m ? 1 : k % 2 ? 4 : 2);
    }
    return s * h / 3 / (2 * beta * std::sqrt(kPi * 30.0));
}

double ertz_continuous_max()
{
    double lo = 0.0, hi = kErtzA; // golden section: T is unimodal on [0, a]
    const double r = (std::sqrt(5.0) - 1) / 2;
    for (int k = 0; k < 80; ++k) {
        const double m1 = hi - r * (hi - lo), m2 = lo + r * (hi - lo);
        if (ertz_continuous(m1) < ertz_continuous(m2))
            lo = m1;
        else
            hi = m2;
    }
    return ertz_continuous(0.5 * (lo + hi));
}

// The Ertz heat on a grid of spacing dx over [-7.9, 7.9 + ...] mm (element
// edges at -7.9 mm as CONTACT's example), three rows around y = 0.
Grid ertz_grid(double dx)
{
    const int nx = static_cast<int>(std::lround(15.8e-3 / dx));
    Grid g(nx, 3, -7.9e-3 + dx / 2, -0.5e-3, dx, 0.5e-3);
    for (size_t e = 0; e < g.q.size(); ++e) {
        const double r = 1 - std::pow(g.x[e] / kErtzA, 2) - std::pow(g.y[e] / kErtzB, 2);
        if (r > 0.0) {
            g.state[e] = 2;
            g.q[e] = ertz_q0() * std::sqrt(r);
        }
    }
    return g;
}

// The maximum temperature of the Ertz heat at spacing dx.
double ertz_max(double dx, th::Discretisation d)
{
    Grid g = ertz_grid(dx);
    const th::TemperatureTotals t = g.solve(ertz_params(d));
    assert_true(t.rail.T == t.wheel.T);
    assert_close(t.rail.y, 0.0, 0.0, 1e-15); // the hottest row is y = 0
    return t.rail.T;
}

// The consistent maximum within 0.5 deg C of 150.3 (the continuous
// integral; Blok's estimate 150.1) at dx = 0.2 and 0.025 mm, and within
// 0.05 of this file's own continuous integral.
void ertz_consistent_converges(void** state)
{
    (void)state;
    const double exact = ertz_continuous_max();
    assert_close(exact, 150.3, 0.0, 0.01);
    for (double dx : {0.2e-3, 0.025e-3}) {
        const double T = ertz_max(dx, th::Discretisation::consistent);
        assert_close(T, 150.3, 0.0, 0.5);
        assert_close(T, exact, 0.0, 0.05);
    }
}

// The recursion against the direct sum on the Ertz heat at dx = 0.1 and
// 0.025 mm (158 and 632 elements a row, both above the direct sum's
// length): every element of both bodies to 1e-9 relative, both
// discretisations, and the maximum the same to 1e-9 (the digits of the
// table in doc/validation/temperature.md).
void ertz_recursion_matches_direct_sum(void** state)
{
    (void)state;
    using Method = th::MovingSourceKernel::Method;
    for (double dx : {0.1e-3, 0.025e-3}) {
        Grid g = ertz_grid(dx);
        assert_true(g.nx > th::MovingSourceKernel::kDirectMaxLength);
        for (th::Discretisation d : {th::Discretisation::consistent, th::Discretisation::contact}) {
            Grid direct = g;
            const th::TemperatureTotals a = direct.solve(ertz_params(d, 0.0, 150.0), Method::direct);
            const th::TemperatureTotals b = g.solve(ertz_params(d, 0.0, 150.0), Method::recursive);
            const th::TemperatureTotals c = g.solve(ertz_params(d, 0.0, 150.0));
            for (size_t e = 0; e < g.q.size(); ++e) {
                assert_close(g.T1[e], direct.T1[e], 1e-9, 0.0);
                assert_close(g.T2[e], direct.T2[e], 1e-9, 0.0);
            }
            assert_close(b.rail.T, a.rail.T, 1e-9, 0.0);
            assert_close(b.wheel.T, a.wheel.T, 1e-9, 0.0);
            assert_true(c.rail.T == b.rail.T); // automatic: the recursion
        }
    }
}

// CONTACT's discretisation of the same heat runs hot by its self-element
// term, O(sqrt dx): 170.4 at dx = 0.4 mm, 155.2 at 0.025 mm (the numbers
// of this analysis with CONTACT's scheme, frontier research W3 sec. 5.2).
void ertz_contact_discretisation_runs_hot(void** state)
{
    (void)state;
    assert_close(ertz_max(0.4e-3, th::Discretisation::contact), 170.4, 0.0, 0.05);
    assert_close(ertz_max(0.025e-3, th::Discretisation::contact), 155.2, 0.0, 0.05);
}

// CONTACT's example ertz_temperature: its grid (216 x 45, dx = 0.2 mm, dy
// = 0.5 mm, the gap 1.015 x^2 + 0.4215 y^2 [m]), solved by creepwork's exact
// model (its tractions and slips agree with CONTACT's to 1e-4), heated as
// CONTACT heats it (|p_t| |s| V on slip elements), against CONTACT's printed
// MAX(T1, T2) over the contact and its temperature fields, to 0.1 deg C.
struct ErtzCase {
    double xi_x, xi_y, phi; // phi [1/m]
    double T0_rail, T0_wheel;
    double printed_max; // CONTACT's examples/ertz_temperature.ref_out
};
const ErtzCase kErtzCases[] = {{-0.03333, 0, 0, 0, 0, 166.8},
                               {0, 0, 0, 0, 150, 75.00},
                               {-0.03333, 0, 0, 0, 150, 241.8},
                               {-0.002, 0.001, 0.2, 0, 150, 90.85}};

// One case of the example: the maximum over the contact with CONTACT's
// discretisation and with the consistent one, and the largest difference
// from CONTACT's fields (both bodies, every element of the data file).
struct ErtzResult {
    double contact_max = 0, consistent_max = 0, field_difference = 0;
    size_t compared = 0;
};

std::vector<ErtzResult> ertz_contact_example()
{
    const int nx = 216, ny = 45;
    cw::GridSpec gs;
    gs.kind = cw::GridKind::gap;
    gs.nx = nx;
    gs.ny = ny;
    gs.x0 = -7.8e-3;
    gs.y0 = -11.0e-3;
    gs.dx = 0.2e-3;
    gs.dy = 0.5e-3;
    cw::Solver solver(gs);
    std::vector<double> gap(nx * ny);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double x = gs.x0 + i * gs.dx, y = gs.y0 + j * gs.dy;
            gap[i + j * nx] = 1.015 * x * x + 0.4215 * y * y;
        }
    const cwtest::CsvTable ref =
        cwtest::read_csv(cwtest::test_data_path("temperature/ertz_fields.csv"));
    Grid g(nx, ny, gs.x0, gs.y0, gs.dx, gs.dy);
    std::vector<ErtzResult> results;
    for (int c = 0; c < 4; ++c) {
        const ErtzCase& k = kErtzCases[c];
        cw::ContactInput in;
        in.model = cw::ModelKind::exact;
        in.gap = gap.data();
        in.gap_len = gap.size();
        in.normal_force = 1e5;
        in.mu = 0.3;
        in.G = 82e9;
        in.nu = 0.28;
        in.rolling_direction = -1;
        in.xi_x = k.xi_x;
        in.xi_y = k.xi_y;
        in.phi = k.phi;
        solver.solve(in, cw::SolveMode::full);
        using F = cw::Field;
        const auto px = cwtest::field(solver, F::px), py = cwtest::field(solver, F::py);
        const auto sx = cwtest::field(solver, F::sx), sy = cwtest::field(solver, F::sy);
        g.state = cwtest::states(solver);
        th::heat_from_slip(nx * ny, px.data(), py.data(), sx.data(), sy.data(), 30.0, g.q.data());
        ErtzResult r;
        th::TemperatureTotals t =
            g.solve(ertz_params(th::Discretisation::consistent, k.T0_rail, k.T0_wheel));
        r.consistent_max = std::max(t.rail.T, t.wheel.T);
        t = g.solve(ertz_params(th::Discretisation::contact, k.T0_rail, k.T0_wheel));
        r.contact_max = std::max(t.rail.T, t.wheel.T);
        const std::string col = std::to_string(c + 1);
        for (size_t row = 0; row < ref.rows.size(); ++row) {
            const int e = static_cast<int>(ref.number(row, "ix")) - 1 +
                          (static_cast<int>(ref.number(row, "iy")) - 1) * nx;
            r.field_difference =
                std::max({r.field_difference, std::fabs(g.T1[e] - ref.number(row, "T1_case" + col)),
                          std::fabs(g.T2[e] - ref.number(row, "T2_case" + col))});
            ++r.compared;
        }
        results.push_back(r);
    }
    return results;
}

// CONTACT's example ertz_temperature: its grid (216 x 45, dx = 0.2 mm, dy
// = 0.5 mm, the gap 1.015 x^2 + 0.4215 y^2 [m]), solved by creepwork's exact
// model (its tractions and slips agree with CONTACT's to 1e-4), heated as
// CONTACT heats it (|p_t| |s| V on slip elements), against CONTACT's printed
// MAX(T1, T2) over the contact and its temperature fields, to 0.1 deg C.
void ertz_contact_reference(void** state)
{
    (void)state;
    const std::vector<ErtzResult> r = ertz_contact_example();
    for (int c = 0; c < 4; ++c) {
        assert_int_equal(r[c].compared, 2326);
        assert_close(r[c].contact_max, kErtzCases[c].printed_max, 0.0, 0.1);
        assert_close(r[c].field_difference, 0.0, 0.0, 0.1);
    }
}

// The tables of doc/validation/temperature.md.
int print_markdown()
{
    std::printf("The Ertz heat on y = 0 (continuous integral: maximum %.3f deg C)\n\n",
                ertz_continuous_max());
    std::printf("| dx [mm] | elements along x | consistent [deg C] | CONTACT's discretisation "
                "[deg C] |\n|---:|---:|---:|---:|\n");
    for (double dx : {0.4e-3, 0.2e-3, 0.1e-3, 0.05e-3, 0.025e-3})
        std::printf("| %.3f | %ld | %.3f | %.3f |\n", dx * 1e3, std::lround(15.8e-3 / dx),
                    ertz_max(dx, th::Discretisation::consistent),
                    ertz_max(dx, th::Discretisation::contact));
    std::printf("\nCONTACT's example ertz_temperature, maximum over the contact (deg C)\n\n");
    std::printf("| case | T0 rail, wheel [deg C] | creepages | CONTACT | creepwork, CONTACT's "
                "discretisation | largest field difference | creepwork, consistent |\n"
                "|---|---|---|---:|---:|---:|---:|\n");
    const char* names[] = {"1 full sliding", "2 rolling", "3 full sliding", "4 partial slip"};
    const std::vector<ErtzResult> r = ertz_contact_example();
    for (int c = 0; c < 4; ++c) {
        const ErtzCase& k = kErtzCases[c];
        std::printf("| %s | %g, %g | %g, %g, %g/m | %.2f | %.3f | %.4f | %.3f |\n", names[c],
                    k.T0_rail, k.T0_wheel, k.xi_x, k.xi_y, k.phi, k.printed_max, r[c].contact_max,
                    r[c].field_difference, r[c].consistent_max);
    }
    return 0;
}

// ------------------------------------------------------------- edge cases

void no_contact_is_bulk(void** state)
{
    (void)state;
    Grid g(20, 3, 0.0, 0.0, 1e-3, 1e-3);
    const th::TemperatureTotals t = g.solve(ertz_params(th::Discretisation::consistent, 15, 35));
    for (size_t e = 0; e < g.T1.size(); ++e) {
        assert_true(g.T1[e] == 15.0);
        assert_true(g.T2[e] == 35.0);
    }
    assert_int_equal(t.rail.element, -1);
    assert_int_equal(t.wheel.element, -1);
    assert_true(t.rail.T == 15.0 && t.wheel.T == 35.0);
}

void heat_sources(void** state)
{
    (void)state;
    const double work[] = {2.0, -1.0, 3.0, 0.5}, area[] = {1e-6, 1e-6, 0.0, 2e-6};
    double q[4];
    th::heat_from_work(4, work, area, 30.0, q);
    assert_close(q[0], 30.0 * 2.0 / 1e-6, 1e-15, 0.0);
    assert_true(q[1] == 0.0 && q[2] == 0.0); // negative work, exterior
    assert_close(q[3], 30.0 * 0.5 / 2e-6, 1e-15, 0.0);
    const double px[] = {3e8, 0}, py[] = {4e8, 0}, sx[] = {-0.006, 0}, sy[] = {-0.008, 0};
    th::heat_from_slip(2, px, py, sx, sy, 10.0, q);
    assert_close(q[0], 5e8 * 0.01 * 10.0, 1e-15, 0.0);
    assert_true(q[1] == 0.0);
}

void expect_invalid(const th::ThermalParams& p, const std::string& name)
{
    Grid g(5, 1, 0.0, 0.0, 1e-3, 1e-3);
    try {
        g.solve(p);
        fail_msg("no error for %s", name.c_str());
    } catch (const cw::Error& e) {
        assert_int_equal(static_cast<int>(e.kind()), static_cast<int>(cw::ErrorKind::invalid_input));
        if (std::string(e.what()).rfind(name + " = ", 0) != 0)
            fail_msg("message '%s' does not start with '%s = '", e.what(), name.c_str());
    }
}

void invalid_inputs_named(void** state)
{
    (void)state;
    const th::ThermalParams ok = ertz_params(th::Discretisation::consistent);
    th::ThermalParams p = ok;
    p.rail.T0 = -300;
    expect_invalid(p, "T0_1");
    p = ok;
    p.wheel.T0 = NAN;
    expect_invalid(p, "T0_2");
    p = ok;
    p.rail.heat_capacity = 0;
    expect_invalid(p, "heat_capacity_1");
    p = ok;
    p.wheel.conductivity = -1;
    expect_invalid(p, "conductivity_2");
    p = ok;
    p.rail.density = 7.85e-6; // kg/mm^3 given as kg/m^3
    expect_invalid(p, "density_1");
    p = ok;
    p.rolling_speed = 0;
    expect_invalid(p, "rolling_speed");
    p = ok;
    p.discretisation = static_cast<th::Discretisation>(5);
    expect_invalid(p, "discretisation");
    Grid g(5, 1, 0.0, 0.0, 1e-3, 1e-3);
    g.q[2] = -1.0;
    g.state[2] = 2;
    try {
        g.solve(ok);
        fail_msg("negative heat accepted");
    } catch (const cw::Error& e) {
        assert_non_null(std::strstr(e.what(), "q (frictional power density)"));
    }
}

} // namespace

int main(int argc, char** argv)
{
    if (argc > 1 && std::string(argv[1]) == "--markdown") return print_markdown();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(weights_closed_form),
        cmocka_unit_test(kernel_matches_long_double_sum),
        cmocka_unit_test(uniform_band_dissimilar_bodies),
        cmocka_unit_test(contact_partition_and_self_term),
        cmocka_unit_test(rolling_direction_mirrors),
        cmocka_unit_test(ertz_consistent_converges),
        cmocka_unit_test(ertz_recursion_matches_direct_sum),
        cmocka_unit_test(ertz_contact_discretisation_runs_hot),
        cmocka_unit_test(ertz_contact_reference),
        cmocka_unit_test(no_contact_is_bulk),
        cmocka_unit_test(heat_sources),
        cmocka_unit_test(invalid_inputs_named),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
