#include "exact/local_friction.hpp"

#include <cmath>

namespace creepwork {

bool solve_local_friction(std::complex<double> c, double b1, double b2, double g,
                          std::complex<double>& q, LocalJacobian& J)
{
    const double cx = c.real(), cy = c.imag();
    const double ax = -cx / b1, ay = -cy / b2; // the adhesion solution
    if (ax * ax + ay * ay <= g * g) {
        q = {ax, ay};
        J = {-1.0 / b1, 0.0, 0.0, -1.0 / b2};
        return false;
    }
    if (!(g > 0.0)) { // no pressure: no traction, the element slips freely
        q = {0.0, 0.0};
        J = {};
        return true;
    }
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

} // namespace creepwork
