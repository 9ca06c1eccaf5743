#include "thermal/flash_temperature.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "contact/contact_input.hpp"
#include "contact/error.hpp"

namespace creepwork::thermal {

namespace {

constexpr double kPi = 3.141592653589793238462643383279502884;
constexpr double kAbsoluteZero = -273.15; // [deg C]
constexpr double kMaxHeat = 1e300;        // [W/m^2]: finite, with room for the sums

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
}

// The heat q of the elements that heat is checked as the rows are read;
// this names the first offender.
[[noreturn]] void reject_heat(const HeatedContact& in)
{
    const long n = static_cast<long>(in.nx) * in.ny;
    long e = 0;
    while (e + 1 < n && in.q[e] >= 0.0 && in.q[e] <= kMaxHeat) ++e;
    reject_input("q (frictional power density)", in.q[e], "must be finite and >= 0");
}

// The first contact element (state >= 1) of T[lo..hi] holding the largest
// value; the span holds at least one. Four running maxima, so that no
// comparison waits for the one before (max is exact in any order).
int hottest(const double* T, const int* state, int lo, int hi)
{
    const double none = -std::numeric_limits<double>::infinity();
    double m[4] = {none, none, none, none};
    int i = lo;
    for (; i + 3 <= hi; i += 4)
        for (int k = 0; k < 4; ++k) {
            const double v = state[i + k] >= 1 ? T[i + k] : none;
            m[k] = v > m[k] ? v : m[k];
        }
    for (; i <= hi; ++i) {
        const double v = state[i] >= 1 ? T[i] : none;
        m[0] = v > m[0] ? v : m[0];
    }
    const double top = std::max(std::max(m[0], m[1]), std::max(m[2], m[3]));
    for (i = lo; i < hi; ++i)
        if (state[i] >= 1 && T[i] == top) break;
    return i;
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

FlashTemperature::FlashTemperature(int nx, int ny, MovingSourceKernel::Method method)
    : nx_(nx), ny_(ny), kernel_(nx, method)
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
    // Time order: t = 0 is the element a material point meets first; with
    // rolling_direction +1 that is the last element of the row in storage.
    const bool reversed = in.rolling_direction > 0;
    const double T0[2] = {p.rail.T0, p.wheel.T0}, f[2] = {part.f1, part.f2};
    double* T[2] = {T1, T2};
    TemperatureMaximum* best[2] = {nullptr, nullptr};
    TemperatureTotals totals;
    totals.contact_temperature = part.Tc;
    totals.rail.T = p.rail.T0;
    totals.wheel.T = p.wheel.T0;
    best[0] = &totals.rail;
    best[1] = &totals.wheel;
    for (int j0 = 0; j0 < ny_; j0 += 2) {
        const int rows = std::min(2, ny_ - j0);
        for (int r = 0; r < rows; ++r) {
            const long base = static_cast<long>(j0 + r) * nx;
            const int* st = in.state + base;
            const double* q = in.q + base;
            double* qt = q_[r].data();
            bool bad = false;
            for (int t = 0; t < nx; ++t) {
                const int i = reversed ? nx - 1 - t : t;
                qt[t] = st[i] >= part.heat_state ? q[i] : 0.0;
                bad |= !(qt[t] >= 0.0 && qt[t] <= kMaxHeat);
            }
            if (bad) reject_heat(in);
        }
        kernel_.apply(q_[0].data(), rows > 1 ? q_[1].data() : nullptr, flash_[0].data(),
                      rows > 1 ? flash_[1].data() : nullptr, part.self_weight);
        for (int r = 0; r < rows; ++r) {
            const long base = static_cast<long>(j0 + r) * nx;
            const int* st = in.state + base;
            int lo = nx, hi = -1; // the row's contact span, storage order
            for (int i = 0; i < nx; ++i)
                if (st[i] >= 1) {
                    lo = std::min(lo, i);
                    hi = i;
                }
            const double dx = in.row_dx[j0 + r];
            const double scale = std::sqrt(dx);
            const double* flash = flash_[r].data();
            for (int b = 0; b < 2; ++b) {
                double* Tb = T[b] + base;
                const double fb = f[b] * scale;
                for (int i = 0; i < nx; ++i) {
                    const double Fi = flash[reversed ? nx - 1 - i : i];
                    Tb[i] = (st[i] >= 1 ? part.Tc : T0[b]) + fb * Fi;
                }
            }
            if (hi < 0) continue;
            // Behind the span each surface relaxes from T_c towards its own T0.
            const int first = reversed ? nx - 1 - hi : lo, last = reversed ? nx - 1 - lo : hi;
            const double half_span = 0.5 * (last - first + 1) * dx;
            for (int t = last + 1; t < nx; ++t) {
                const int i = reversed ? nx - 1 - t : t;
                if (st[i] >= 1) continue;
                const double from_centre = (t - 0.5 * (first + last) + part.relax_shift) * dx;
                const double ratio = std::min(1.0, 2.0 * half_span / (half_span + from_centre));
                const double g = 2.0 / kPi * std::asin(std::sqrt(ratio));
                const double Fi = flash[t];
                for (int b = 0; b < 2; ++b)
                    T[b][base + i] = T0[b] + g * (part.Tc - T0[b]) + f[b] * scale * Fi;
            }
            // The hottest contact element of each body (the first in storage
            // order on a tie: rows in order, strict comparison).
            for (int b = 0; b < 2; ++b) {
                const long at = base + hottest(T[b] + base, st, lo, hi);
                if (best[b]->element < 0 || T[b][at] > best[b]->T) {
                    best[b]->T = T[b][at];
                    best[b]->element = at;
                    best[b]->x = in.x[at];
                    best[b]->y = in.y[at];
                }
            }
        }
    }
    return totals;
}

double bulk_contact_temperature(const ThermalParams& p) { return partition(p, 1).Tc; }

} // namespace creepwork::thermal
