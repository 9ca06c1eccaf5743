#include "wheelrail/profile.hpp"

#include <algorithm>
#include <cmath>

#include "contact/error.hpp"
#include "contact/fp_safe.hpp"
#include "wheelrail/profile_checks.hpp"

namespace creepwork::wheelrail {

Profile::Profile(ProfileKind kind, std::vector<ProfilePoint> points, const std::string& source,
                 const ProfileChecks& checks)
    : kind_(kind), source_(source)
{
    const std::vector<int> breaks = check_profile_points(kind, points, source, checks);
    const size_t n = points.size();
    s_.resize(n);
    y_.resize(n);
    z_.resize(n);
    for (size_t i = 0; i < n; ++i) {
        y_[i] = points[i].y;
        z_[i] = points[i].z;
    }
    // Summed chord length, shifted to s = 0 at y = 0 (monotone y) or at the
    // point closest to the origin (CONTACT's grid_make_arclength).
    s_[0] = 0.0;
    for (size_t i = 1; i < n; ++i) s_[i] = s_[i - 1] + std::hypot(y_[i] - y_[i - 1], z_[i] - z_[i - 1]);
    bool increasing = true, decreasing = true;
    for (size_t i = 1; i < n; ++i) {
        increasing = increasing && y_[i] > y_[i - 1];
        decreasing = decreasing && y_[i] < y_[i - 1];
    }
    double s0 = 0.0;
    if ((increasing || decreasing) && (y_.front() - 0.0) * (y_.back() - 0.0) <= 0.0) {
        size_t i = 1;
        while (i + 1 < n && (y_[i] - 0.0) * (y_.front() - 0.0) > 0.0) ++i;
        const double t = (0.0 - y_[i - 1]) / (y_[i] - y_[i - 1]);
        s0 = s_[i - 1] + t * (s_[i] - s_[i - 1]);
    } else if (increasing || decreasing) {
        s0 = std::abs(y_.front()) < std::abs(y_.back()) ? s_.front() : s_.back(); // nearer end
    } else {
        size_t best = 0;
        for (size_t i = 0; i < n; ++i)
            if (y_[i] * y_[i] + z_[i] * z_[i] <= y_[best] * y_[best] + z_[best] * z_[best]) best = i;
        s0 = s_[best];
    }
    for (double& s : s_) s -= s0;
    build_spline(breaks);
    build_pieces();
}

// Natural cubic spline per section between breaks (first and last point
// included): second derivatives from the tridiagonal system with zero end
// curvature, then the coefficients of each segment.
void Profile::build_spline(const std::vector<int>& breaks)
{
    const int nseg = size() - 1;
    cy_.assign(3 * static_cast<size_t>(nseg), 0.0);
    cz_.assign(3 * static_cast<size_t>(nseg), 0.0);
    std::vector<double> m(static_cast<size_t>(size())), diag, rhs;
    for (int coord = 0; coord < 2; ++coord) {
        const std::vector<double>& f = coord == 0 ? y_ : z_;
        std::vector<double>& c = coord == 0 ? cy_ : cz_;
        for (size_t b = 0; b + 1 < breaks.size(); ++b) {
            const int k0 = breaks[b], k1 = breaks[b + 1];
            const int ni = k1 - k0 - 1; // interior knots
            m[k0] = 0.0;
            m[k1] = 0.0;
            if (ni > 0) {
                diag.assign(ni, 0.0);
                rhs.assign(ni, 0.0);
                for (int j = 0; j < ni; ++j) {
                    const int i = k0 + 1 + j;
                    const double h0 = s_[i] - s_[i - 1], h1 = s_[i + 1] - s_[i];
                    diag[j] = 2.0 * (h0 + h1);
                    rhs[j] = 6.0 * ((f[i + 1] - f[i]) / h1 - (f[i] - f[i - 1]) / h0);
                }
                // Thomas algorithm: off-diagonals h_i (symmetric)
                for (int j = 1; j < ni; ++j) {
                    const int i = k0 + 1 + j;
                    const double h = s_[i] - s_[i - 1];
                    const double w = h / diag[j - 1];
                    diag[j] -= w * h;
                    rhs[j] -= w * rhs[j - 1];
                }
                m[k0 + ni] = rhs[ni - 1] / diag[ni - 1];
                for (int j = ni - 2; j >= 0; --j) {
                    const int i = k0 + 1 + j;
                    const double h = s_[i + 1] - s_[i];
                    m[i] = (rhs[j] - h * m[i + 1]) / diag[j];
                }
            }
            for (int i = k0; i < k1; ++i) {
                const double h = s_[i + 1] - s_[i];
                c[3 * i] = (f[i + 1] - f[i]) / h - h * (2.0 * m[i] + m[i + 1]) / 6.0;
                c[3 * i + 1] = 0.5 * m[i];
                c[3 * i + 2] = (m[i + 1] - m[i]) / (6.0 * h);
            }
        }
    }
}

// Split the curve where dy/ds changes sign: each piece has monotone y(s),
// so a lateral position has at most one point per piece.
void Profile::build_pieces()
{
    std::vector<double> cuts{s_.front()};
    for (int i = 0; i + 1 < size(); ++i) {
        const double h = s_[i + 1] - s_[i];
        const double b = cy_[3 * i], c = 2.0 * cy_[3 * i + 1], d = 3.0 * cy_[3 * i + 2];
        double roots[2];
        int nr = 0;
        if (std::abs(d) > 0.0) {
            const double disc = c * c - 4.0 * d * b;
            if (disc > 0.0) {
                const double q = -0.5 * (c + std::copysign(std::sqrt(disc), c));
                roots[nr++] = q / d;
                if (q != 0.0) roots[nr++] = b / q;
            }
        } else if (c != 0.0) {
            roots[nr++] = -b / c;
        }
        std::sort(roots, roots + nr);
        for (int k = 0; k < nr; ++k)
            if (roots[k] > 1e-12 * h && roots[k] < h * (1.0 - 1e-12)) cuts.push_back(s_[i] + roots[k]);
        // a knot where the slope changes sign (a corner between sections)
        if (i + 1 < size() - 1) {
            const double left = b + c * h + d * h * h, right = cy_[3 * (i + 1)];
            if (left * right < 0.0) cuts.push_back(s_[i + 1]);
        }
    }
    cuts.push_back(s_.back());
    pieces_.clear();
    y_lo_ = y_hi_ = y_.front();
    for (size_t k = 0; k + 1 < cuts.size(); ++k) {
        if (cuts[k + 1] <= cuts[k]) continue;
        const Piece p{cuts[k], cuts[k + 1], at(cuts[k]).y, at(cuts[k + 1]).y};
        if (p.y_a == p.y_b) continue; // vertical piece: no lateral extent
        pieces_.push_back(p);
        y_lo_ = std::min({y_lo_, p.y_a, p.y_b});
        y_hi_ = std::max({y_hi_, p.y_a, p.y_b});
    }
}

Profile Profile::placed(const Frame& f) const
{
    Profile q(*this);
    const double ryy = f.r(1, 1), ryz = f.r(1, 2), rzy = f.r(2, 1), rzz = f.r(2, 2);
    for (int i = 0; i < size(); ++i) {
        q.y_[i] = f.o(1) + ryy * y_[i] + ryz * z_[i];
        q.z_[i] = f.o(2) + rzy * y_[i] + rzz * z_[i];
    }
    for (size_t k = 0; k < cy_.size(); ++k) { // derivatives rotate, no shift
        q.cy_[k] = ryy * cy_[k] + ryz * cz_[k];
        q.cz_[k] = rzy * cy_[k] + rzz * cz_[k];
    }
    q.build_pieces();
    return q;
}

int Profile::segment_of(double s, int hint) const
{
    const int nseg = size() - 1;
    if (hint >= 0 && hint < nseg && s >= s_[hint] && s <= s_[hint + 1]) return hint;
    if (hint >= 0 && hint + 1 < nseg && s >= s_[hint + 1] && s <= s_[hint + 2]) return hint + 1;
    if (hint >= 1 && hint - 1 < nseg && s >= s_[hint - 1] && s <= s_[hint]) return hint - 1;
    const auto it = std::upper_bound(s_.begin(), s_.end(), s);
    return std::clamp(static_cast<int>(it - s_.begin()) - 1, 0, nseg - 1);
}

Profile::Point Profile::at(double s, int* segment) const
{
    s = std::clamp(s, s_.front(), s_.back());
    const int i = segment_of(s, segment ? *segment : -1);
    if (segment) *segment = i;
    const double t = s - s_[i];
    const double* a = &cy_[3 * static_cast<size_t>(i)];
    const double* b = &cz_[3 * static_cast<size_t>(i)];
    Point p;
    p.y = y_[i] + t * (a[0] + t * (a[1] + t * a[2]));
    p.z = z_[i] + t * (b[0] + t * (b[1] + t * b[2]));
    p.dy = a[0] + t * (2.0 * a[1] + 3.0 * t * a[2]);
    p.dz = b[0] + t * (2.0 * b[1] + 3.0 * t * b[2]);
    p.d2y = 2.0 * a[1] + 6.0 * t * a[2];
    p.d2z = 2.0 * b[1] + 6.0 * t * b[2];
    return p;
}

double Profile::inclination(double s) const
{
    const Point p = at(s);
    return std::atan2(p.dz, p.dy);
}

double Profile::solve_y(double y, double s_a, double s_b) const
{
    double ya = at(s_a).y, yb = at(s_b).y;
    if ((y - ya) * (y - yb) > 0.0) return std::abs(y - ya) < std::abs(y - yb) ? s_a : s_b;
    double lo = s_a, hi = s_b;
    const bool rising = yb > ya;
    double s = s_a + (s_b - s_a) * quotient_or_zero(y - ya, yb - ya);
    int seg = -1;
    for (int it = 0; it < 100; ++it) {
        const Point p = at(s, &seg);
        const double f = p.y - y;
        if ((f > 0.0) == rising) hi = s; else lo = s;
        if (f == 0.0) return s;
        // Newton, or bisection where it would leave the bracket (no division
        // by a zero slope, even speculated: contact/fp_safe.hpp)
        double next = s - quotient_or_zero(f, p.dy);
        if (!(next > lo && next < hi) || p.dy == 0.0) next = 0.5 * (lo + hi);
        if (std::abs(next - s) <= 1e-15 * (1.0 + std::abs(s)) || hi - lo <= 1e-15 * (1.0 + std::abs(s)))
            return next;
        s = next;
    }
    return s;
}

bool Profile::visible_s_at_y(double y, double& s) const
{
    bool found = false;
    double best_z = 0.0;
    for (const Piece& p : pieces_) {
        if ((y - p.y_a) * (y - p.y_b) > 0.0) continue;
        const double sp = solve_y(y, p.s_a, p.s_b);
        const double z = at(sp).z;
        const bool better = kind_ == ProfileKind::rail ? z < best_z : z > best_z;
        if (!found || better) {
            s = sp;
            best_z = z;
            found = true;
        }
    }
    return found;
}

} // namespace creepwork::wheelrail
