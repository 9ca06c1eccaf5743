#include "exact/local_friction.hpp"

#include <cmath>

namespace creepwork {

namespace {

// J = -M K^-1 with K = I + diag(b1, b2) M for the symmetric M of dq = -M ds.
LocalJacobian local_jacobian(double m11, double m12, double m22, double b1, double b2)
{
    const double k11 = 1.0 + b1 * m11, k12 = b1 * m12;
    const double k21 = b2 * m12, k22 = 1.0 + b2 * m22;
    const double det = k11 * k22 - k12 * k21;
    const double i11 = k22 / det, i12 = -k12 / det, i21 = -k21 / det, i22 = k11 / det;
    LocalJacobian J;
    J.j11 = -(m11 * i11 + m12 * i21);
    J.j12 = -(m11 * i12 + m12 * i22);
    J.j21 = -(m12 * i11 + m22 * i21);
    J.j22 = -(m12 * i12 + m22 * i22);
    return J;
}

// The flow of one element whose bound h(sigma) depends on its own flow sigma
// (bound(sigma, h, dh) gives h and dh/dsigma): the root of
//   f(sigma) = (cx/(sigma + h b1))^2 + (cy/(sigma + h b2))^2 - 1,
// q = -h e, J and u = -(I + J B0) e (local_friction.hpp). h <= g_hi, so
// f(lo) >= 0 at lo = |c| - g_hi max(b); f(|c|) <= 0 (h >= 0). Newton's steps
// inside the bracket, bisection otherwise; the bracket shrinks with each sign.
struct Flow {
    double sigma = 0.0, h = 0.0, dh = 0.0, ex = 0.0, ey = 0.0;
    int iterations = 0;
    std::complex<double> u{0.0, 0.0};
};

template <class Bound>
Flow solve_flow(const Bound& bound, double cx, double cy, double b1, double b2, double g_hi,
                std::complex<double>& q, LocalJacobian& J)
{
    int iterations = 0;
    const double norm_c = std::sqrt(cx * cx + cy * cy);
    double lo = norm_c - g_hi * (b1 > b2 ? b1 : b2), hi = norm_c;
    if (lo < 0.0) lo = 0.0;
    double sigma = lo, h = 0.0, dh = 0.0;
    for (int it = 0; it < 200; ++it) {
        bound(sigma, h, dh);
        iterations = it + 1;
        const double dx = sigma + h * b1, dy = sigma + h * b2;
        const double tx = cx / dx, ty = cy / dy;
        const double f = tx * tx + ty * ty - 1.0;
        if (f == 0.0) break;
        (f > 0.0 ? lo : hi) = sigma;
        const double df = -2.0 * (tx * tx * (1.0 + dh * b1) / dx + ty * ty * (1.0 + dh * b2) / dy);
        double next = df < 0.0 ? sigma - f / df : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const bool stalled = !(std::fabs(next - sigma) > 1e-15 * (sigma + h * (b1 + b2)));
        sigma = next;
        if (stalled || !(hi > lo)) break;
    }
    bound(sigma, h, dh);
    double ex = cx / (sigma + h * b1), ey = cy / (sigma + h * b2);
    const double ne = std::sqrt(ex * ex + ey * ey);
    ex /= ne;
    ey /= ne;
    q = {-h * ex, -h * ey};
    // Derivative: q = -h(sigma) e, s = sigma e: dq = -M ds with
    // M = (h/sigma)(I - e e^T) + h' e e^T, and ds = dc + B0 dq.
    const double f = h / (sigma > 1e-300 ? sigma : 1e-300);
    const double m11 = f * (1.0 - ex * ex) + dh * ex * ex;
    const double m12 = (dh - f) * ex * ey;
    const double m22 = f * (1.0 - ey * ey) + dh * ey * ey;
    J = local_jacobian(m11, m12, m22, b1, b2);
    // u = -(I + J B0) e: the response to the bound's own change.
    const double bx = b1 * ex, by = b2 * ey;
    const std::complex<double> u{-(ex + J.j11 * bx + J.j12 * by), -(ey + J.j21 * bx + J.j22 * by)};
    return Flow{sigma, h, dh, ex, ey, iterations, u};
}

// The adhesion solution when it is within the bound g0 (returns true), else
// q = 0 and J = 0 when g0 = 0 (no pressure: the element slips freely).
bool adheres(double cx, double cy, double b1, double b2, double g0, std::complex<double>& q,
             LocalJacobian& J)
{
    const double ax = -cx / b1, ay = -cy / b2;
    if (ax * ax + ay * ay <= g0 * g0) {
        q = {ax, ay};
        J = {-1.0 / b1, 0.0, 0.0, -1.0 / b2};
        return true;
    }
    q = {0.0, 0.0};
    J = {};
    return false;
}

} // namespace

bool solve_local_friction(const CoulombLaw& law, std::complex<double> c, double b1, double b2,
                          double pressure, std::complex<double>& q, LocalJacobian& J)
{
    const double g = traction_bound(law, pressure);
    const double cx = c.real(), cy = c.imag();
    if (adheres(cx, cy, b1, b2, g, q, J)) return false;
    if (!(g > 0.0)) return true; // no pressure: no traction, the element slips freely
    // f(sigma) = (cx/(sigma+gx))^2 + (cy/(sigma+gy))^2 - 1 decreases and is
    // convex on sigma >= 0, with f(0) > 0 here (no adhesion). Newton's method
    // from a point left of the root converges monotonically; |c| - g max(b)
    // is one (f there is >= 0).
    const double gx = g * b1, gy = g * b2;
    // (sqrt, not hypot: the normalised values here are far from overflow,
    // ExactModel scales creepages beyond 1e100, and hypot is slow.)
    const double norm_c = std::sqrt(cx * cx + cy * cy);
    double sigma = norm_c - (gx > gy ? gx : gy);
    if (sigma < 0.0) sigma = 0.0;
    for (int it = 0; it < 100; ++it) {
        const double tx = cx / (sigma + gx), ty = cy / (sigma + gy);
        const double f = tx * tx + ty * ty - 1.0;
        const double df = -2.0 * (tx * tx / (sigma + gx) + ty * ty / (sigma + gy));
        if (!(df < 0.0)) break;
        const double step = -f / df;
        sigma += step;
        if (!(step > 1e-15 * (sigma + gx + gy))) break; // monotone: stops when it stalls
    }
    double ex = cx / (sigma + gx), ey = cy / (sigma + gy);
    const double ne = std::sqrt(ex * ex + ey * ey);
    ex /= ne;
    ey /= ne;
    q = {-g * ex, -g * ey};
    // Derivative: s = c - g B0 e with e = s/|s| gives
    // (I + (g/sigma) B0 (I - e e^T)) ds = dc and dq = -(g/sigma) (I - e e^T) ds.
    // sigma -> 0 is the adhesion limit; the floor keeps the matrix finite.
    const double f = g / (sigma > 1e-300 ? sigma : 1e-300);
    const double p11 = 1.0 - ex * ex, p12 = -ex * ey, p22 = 1.0 - ey * ey;
    const double k11 = 1.0 + f * b1 * p11, k12 = f * b1 * p12;
    const double k21 = f * b2 * p12, k22 = 1.0 + f * b2 * p22;
    const double det = k11 * k22 - k12 * k21;
    const double i11 = k22 / det, i12 = -k12 / det, i21 = -k21 / det, i22 = k11 / det;
    J.j11 = -f * (p11 * i11 + p12 * i21);
    J.j12 = -f * (p11 * i12 + p12 * i22);
    J.j21 = -f * (p12 * i11 + p22 * i21);
    J.j22 = -f * (p12 * i12 + p22 * i22);
    return true;
}

bool solve_local_friction(const LocalLaw& law, std::complex<double> c, double b1, double b2,
                          double pressure, std::complex<double>& q, LocalJacobian& J,
                          ElementSlip& out)
{
    out = ElementSlip{};
    const double cx = c.real(), cy = c.imag();
    const double g0 = traction_bound(law, pressure, 0.0);
    if (adheres(cx, cy, b1, b2, g0, q, J)) return false; // the static bound decides
    if (!(g0 > 0.0)) return true;
    // A law falls from m(0) = 1 (g_hi = g0); under memory m can rise above
    // m(0) (an element behind a slipping one), never above the static
    // coefficient, m = 1.
    const double g_hi = law.memory.distance > 0.0 ? pressure : g0;
    const Flow r = solve_flow(
        [&](double sigma, double& h, double& dh) {
            const FrictionValue m = law.value(sigma);
            h = pressure * m.mu;
            dh = pressure * m.dmu_ds;
            out.m = m.mu;
        },
        cx, cy, b1, b2, g_hi, q, J);
    out.iterations = r.iterations;
    out.u = r.u;
    out.speed_source = r.sigma * r.dh;
    return true;
}

bool solve_local_yield(const YieldBound& bound, std::complex<double> c, double b1, double b2,
                       std::complex<double>& q, LocalJacobian& J, YieldElement& out)
{
    out = YieldElement{};
    out.tau = bound.tau_ahead;
    const double cx = c.real(), cy = c.imag();
    const double g0 = bound.at(0.0).h;
    if (adheres(cx, cy, b1, b2, g0, q, J)) return false;
    if (!(g0 > 0.0)) return true;
    // Hardening rises to the friction bound g; softening falls from h(0).
    const double g_hi = bound.k > 0.0 ? bound.g : g0;
    const Flow r = solve_flow(
        [&](double phi, double& h, double& dh) {
            const YieldValue v = bound.at(phi);
            h = v.h;
            dh = v.h_phi;
        },
        cx, cy, b1, b2, g_hi, q, J);
    const YieldValue v = bound.at(r.sigma);
    out.u = r.u;
    out.e = {r.ex, r.ey};
    out.h_phi = v.h_phi;
    out.h_t = v.h_t;
    out.h_f = v.h_f;
    out.follows = bound.tau_ahead < bound.g;
    if (out.follows) out.tau = r.h;
    out.iterations = r.iterations;
    return true;
}

} // namespace creepwork
