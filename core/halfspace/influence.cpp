#include "halfspace/influence.hpp"

#include <cmath>

namespace creepwork {
namespace {

// asinh(a) - asinh(b) without cancellation when a and b are close and of one
// sign: asinh(a) - asinh(b) = asinh((a^2 - b^2) / (a sqrt(1 + b^2) + b sqrt(1 + a^2))).
double asinh_diff(double a, double b)
{
    if (a > 0.0 && b > 0.0)
        return std::asinh((a - b) * (a + b) /
                          (a * std::sqrt(1.0 + b * b) + b * std::sqrt(1.0 + a * a)));
    if (a < 0.0 && b < 0.0) return -asinh_diff(-a, -b);
    return std::asinh(a) - std::asinh(b);
}

// Corner coordinates of the loaded element seen from the observation point
// at offset (k, l): x_k = k - 1/2, y_l = (l - 1/2) rho (never 0 for k, l >= 0).
double corner_x(int k) { return k - 0.5; }
double corner_y(int l, double rho) { return (l - 0.5) * rho; }

// x log((y2 + r2) / (y1 + r1)) along the edge x = x_k from y_l to y_(l+1).
double x_log_y(int k, int l, double rho)
{
    const double x = corner_x(k), ax = std::fabs(x);
    return x * asinh_diff(corner_y(l + 1, rho) / ax, corner_y(l, rho) / ax);
}

// y log((x2 + r2) / (x1 + r1)) along the edge y = y_l from x_k to x_(k+1).
double y_log_x(int k, int l, double rho)
{
    const double y = corner_y(l, rho), ay = std::fabs(y);
    return y * asinh_diff(corner_x(k + 1) / ay, corner_x(k) / ay);
}

double corner_r(int k, int l, double rho) { return std::hypot(corner_x(k), corner_y(l, rho)); }

// Offsets of either sign through the symmetries (X, Y even, R odd in k and l).
InfluenceParts quadrant_parts(int k, int l, double rho)
{
    InfluenceParts p;
    p.X = x_log_y(k + 1, l, rho) - x_log_y(k, l, rho);
    p.Y = y_log_x(k, l + 1, rho) - y_log_x(k, l, rho);
    p.R = -corner_r(k, l, rho) + corner_r(k, l + 1, rho) + corner_r(k + 1, l, rho) -
          corner_r(k + 1, l + 1, rho);
    return p;
}

} // namespace

InfluenceParts influence_parts(int k, int l, double rho)
{
    InfluenceParts p = quadrant_parts(k < 0 ? -k : k, l < 0 ? -l : l, rho);
    if ((k < 0) != (l < 0)) p.R = -p.R;
    return p;
}

void influence_quadrant(int kmax, int lmax, double rho, double* X, double* Y, double* R,
                        double* work)
{
    const int nk = kmax + 2, nl = lmax + 2; // corner index ranges 0..kmax+1, 0..lmax+1
    double* xly = work;                     // [k + nk * l], k <= kmax + 1, l <= lmax
    double* ylx = work + nk * nl;           // [k + nk * l], k <= kmax, l <= lmax + 1
    double* r = work + 2 * nk * nl;         // [k + nk * l]
    for (int l = 0; l < nl; ++l)
        for (int k = 0; k < nk; ++k) {
            const int c = k + nk * l;
            if (l <= lmax) xly[c] = x_log_y(k, l, rho);
            if (k <= kmax) ylx[c] = y_log_x(k, l, rho);
            r[c] = corner_r(k, l, rho);
        }
    for (int l = 0; l <= lmax; ++l)
        for (int k = 0; k <= kmax; ++k) {
            const int c = k + nk * l, o = k + (kmax + 1) * l;
            X[o] = xly[c + 1] - xly[c];
            Y[o] = ylx[c + nk] - ylx[c];
            R[o] = -r[c] + r[c + nk] + r[c + 1] - r[c + 1 + nk];
        }
}

} // namespace creepwork
