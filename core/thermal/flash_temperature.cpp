#include "thermal/flash_temperature.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/contact_input.hpp"
#include "contact/error.hpp"

namespace creepwork::thermal {

namespace {

constexpr double kPi = 3.141592653589793238462643383279502884;
constexpr double kAbsoluteZero = -273.15; // [deg C]

void require_in(const char* name, double v, double lo, double hi, const char* rule)
{
    require_finite(name, v);
    if (!(v >= lo && v <= hi)) reject_input(name, v, rule);
}

void validate_body(const Body& b, int index)
{
    const std::string s = "_" + std::to_string(index);
    require_in(("T0" + s).c_str(), b.T0, kAbsoluteZero, 1e4,
               "must lie in [-273.15, 1e4] deg C");
    require_in(("heat_capacity" + s).c_str(), b.heat_capacity, 1.0, 1e5,
               "must lie in [1, 1e5] J/(kg K) (steel: 450)");
    require_in(("conductivity" + s).c_str(), b.conductivity, 1e-3, 1e4,
               "must lie in [1e-3, 1e4] W/(m K) (steel: 50)");
    require_in(("density" + s).c_str(), b.density, 1.0, 1e5,
               "must lie in [1, 1e5] kg/m^3 (steel: 7850)");
}

// Which elements of a row heat, and what T_c and flash factors apply.
struct Partition {
    double Tc;          // bulk contact temperature
    double f1, f2;      // flash factor of body 1 and 2 [K m^2 / (W m^1/2)]
    double self_weight; // the element's own term, in units of 2 sqrt(dx)
    int heat_state;     // lowest element state that heats
    double relax_shift; // extra distance behind the span, in elements
};

Partition partition(const ThermalParams& p, int rolling_direction)
{
    const double b1 = effusivity(p.rail), b2 = effusivity(p.wheel);
    const double shared = 2.0 / ((b1 + b2) * std::sqrt(kPi * p.rolling_speed));
    Partition r{};
    if (p.discretisation == Discretisation::consistent) {
        r.Tc = (b1 * p.rail.T0 + b2 * p.wheel.T0) / (b1 + b2);
        r.f1 = r.f2 = shared;
        r.self_weight = std::sqrt(0.5);
        r.heat_state = 1;
        r.relax_shift = 0.0;
    } else {
        // CONTACT: eps = beta1/(beta1 + beta2), T_c = T0_1 + eps (T0_2 - T0_1),
        // body 1 gets (1 - eps) (2/beta1)/sqrt(pi V), body 2 eps (2/beta1)/sqrt(pi V).
        r.Tc = p.rail.T0 + b1 / (b1 + b2) * (p.wheel.T0 - p.rail.T0);
        r.f2 = shared;
        r.f1 = shared * b2 / b1;
        r.self_weight = std::sqrt(2.0);
        r.heat_state = 2;
        r.relax_shift = rolling_direction > 0 ? 1.0 : 0.0;
    }
    return r;
}

void validate_contact(const HeatedContact& in, int nx, int ny)
{
    if (in.nx != nx || in.ny != ny)
        throw Error(ErrorKind::invalid_input,
                    "grid " + std::to_string(in.nx) + " x " + std::to_string(in.ny) +
                        " differs from the temperature workspace's " + std::to_string(nx) +
                        " x " + std::to_string(ny));
    if (!in.x || !in.y || !in.row_dx || !in.state || !in.q)
        throw Error(ErrorKind::invalid_input, "a field of the heated contact is missing");
    if (in.rolling_direction != 1 && in.rolling_direction != -1)
        reject_input("rolling_direction", in.rolling_direction, "must be +1 or -1");
    for (int j = 0; j < ny; ++j)
        if (!(std::isfinite(in.row_dx[j]) && in.row_dx[j] > 0.0))
            reject_input("row_dx", in.row_dx[j], "must be a finite length > 0");
    const long n = static_cast<long>(nx) * ny;
    for (long e = 0; e < n; ++e)
        if (!(std::isfinite(in.q[e]) && in.q[e] >= 0.0))
            reject_input("q (frictional power density)", in.q[e], "must be finite and >= 0");
}

void track(TemperatureMaximum& m, double T, long e, const HeatedContact& in)
{
    const bool better = m.element < 0 || T > m.T || (T == m.T && e < m.element);
    if (!better) return;
    m.T = T;
    m.element = e;
    m.x = in.x[e];
    m.y = in.y[e];
}

} // namespace

double effusivity(const Body& body)
{
    return std::sqrt(body.conductivity * body.density * body.heat_capacity);
}

void validate(const ThermalParams& p)
{
    validate_body(p.rail, 1);
    validate_body(p.wheel, 2);
    require_in("rolling_speed", p.rolling_speed, 1e-3, 1e3, "must lie in [1e-3, 1e3] m/s");
    if (p.discretisation != Discretisation::consistent &&
        p.discretisation != Discretisation::contact)
        reject_input("discretisation", static_cast<double>(p.discretisation),
                     "must be consistent (0) or contact (1)");
}

FlashTemperature::FlashTemperature(int nx, int ny) : nx_(nx), ny_(ny), kernel_(nx)
{
    if (ny < 1)
        throw Error(ErrorKind::invalid_input, "ny = " + std::to_string(ny) + " must be >= 1");
    for (int r = 0; r < 2; ++r) {
        q_[r].assign(nx, 0.0);
        flash_[r].assign(nx, 0.0);
    }
}

TemperatureTotals FlashTemperature::compute(const HeatedContact& in, const ThermalParams& p,
                                            double* T1, double* T2)
{
    validate(p);
    validate_contact(in, nx_, ny_);
    const Partition part = partition(p, in.rolling_direction);
    const int nx = nx_;
    // Time order: t = 0 is the element a material point meets first.
    auto element = [&](int t, int j) {
        const int i = in.rolling_direction > 0 ? nx - 1 - t : t;
        return i + static_cast<long>(j) * nx;
    };
    TemperatureTotals totals;
    totals.contact_temperature = part.Tc;
    totals.rail.T = p.rail.T0;
    totals.wheel.T = p.wheel.T0;
    for (int j0 = 0; j0 < ny_; j0 += 2) {
        const int rows = std::min(2, ny_ - j0);
        for (int r = 0; r < rows; ++r)
            for (int t = 0; t < nx; ++t) {
                const long e = element(t, j0 + r);
                q_[r][t] = in.state[e] >= part.heat_state ? in.q[e] : 0.0;
            }
        kernel_.apply(q_[0].data(), rows > 1 ? q_[1].data() : nullptr, flash_[0].data(),
                      rows > 1 ? flash_[1].data() : nullptr, part.self_weight);
        for (int r = 0; r < rows; ++r) {
            const int j = j0 + r;
            int first = -1, last = -1; // the row's contact span, time order
            for (int t = 0; t < nx; ++t)
                if (in.state[element(t, j)] >= 1) {
                    if (first < 0) first = t;
                    last = t;
                }
            const double dx = in.row_dx[j];
            const double flash_scale = std::sqrt(dx);
            const double half_span = 0.5 * (last - first + 1) * dx;
            for (int t = 0; t < nx; ++t) {
                const long e = element(t, j);
                const bool contact = in.state[e] >= 1;
                double g = 0.0; // share of T_c - T0 in the bulk part behind the span
                if (!contact && first >= 0 && t > last) {
                    const double from_centre =
                        (t - 0.5 * (first + last) + part.relax_shift) * dx;
                    const double ratio = std::min(1.0, 2.0 * half_span / (half_span + from_centre));
                    g = 2.0 / kPi * std::asin(std::sqrt(ratio));
                }
                const double flash = flash_scale * flash_[r][t];
                const double base1 = contact ? part.Tc : p.rail.T0 + g * (part.Tc - p.rail.T0);
                const double base2 = contact ? part.Tc : p.wheel.T0 + g * (part.Tc - p.wheel.T0);
                T1[e] = base1 + part.f1 * flash;
                T2[e] = base2 + part.f2 * flash;
                if (contact) {
                    track(totals.rail, T1[e], e, in);
                    track(totals.wheel, T2[e], e, in);
                }
            }
        }
    }
    return totals;
}

} // namespace creepwork::thermal
