#include "wheelrail/contact_search.hpp"

#include <algorithm>
#include <cmath>

#include "contact/error.hpp"
#include "contact/fp_safe.hpp"

namespace creepwork::wheelrail {
namespace {

constexpr double kNoGap = 1e3;      // [m] marks samples without wheel or rail
constexpr double kValidGap = 1e2;   // [m] samples below this are real
constexpr double kPlateau = 1e-9;   // [m] equal gaps on a plateau (CONTACT: 1e-6 mm)
constexpr double kSteep = 1e-3;     // [m] no parabola through steps this large (CONTACT: 1 mm)
constexpr double kMinWeight = 1e-19; // [m^3] CONTACT's floor of 1e-10 mm^3 per sample
constexpr int kMaxNearMisses = 2;
constexpr double kReachSlack = 1e-9; // [m] beyond the rounding of a knot's track y

// The interpenetration weight of one lateral sample: the squared
// interpenetration pen - a x^2 integrated over |x| < t0 = sqrt(pen / a),
// 2 pen^2 t0 - 4/3 a pen t0^3 + 2/5 a^2 t0^5 (CONTACT, compute_wgt_center_1d).
double sample_weight(double pen, double a)
{
    const double t0 = std::sqrt(pen / a);
    return std::max(kMinWeight, 2.0 * pen * pen * t0 - 4.0 / 3.0 * pen * a * t0 * t0 * t0 +
                                    0.4 * a * a * t0 * t0 * t0 * t0 * t0);
}

} // namespace

ContactSearch::ContactSearch(const Profile& rail, const Profile& wheel, const SearchOptions& opt,
                             double nominal_radius)
    : radius_(nominal_radius)
{
    int seg = 0;
    for (double s : wheel.knots_s()) knot_.push_back(wheel.at(s, &seg));
    const auto& ky = rail.knots_y();
    const double ymin = *std::min_element(ky.begin(), ky.end());
    const double ymax = *std::max_element(ky.begin(), ky.end());
    dy_ = opt.lateral_step * opt.ds;
    n_ = static_cast<int>(std::ceil((ymax - ymin) / dy_)) + 1;
    y0_ = ymin;
    zr_.resize(n_);
    alpha_.resize(n_);
    for (int i = 0; i < n_; ++i) {
        const double y = y0_ + i * dy_;
        double s = 0.0;
        if (!rail.visible_s_at_y(y, s)) s = y < rail.y_min() ? rail.s_first() : rail.s_last();
        const Profile::Point p = rail.at(s);
        zr_[i] = p.z;
        alpha_[i] = std::atan2(p.dz, p.dy);
    }
    zw_.resize(n_);
    xw_.resize(n_);
    gap_.resize(n_);
    mask_.resize(n_);
}

// The contact locus at every wheel knot of the part seen from below (the
// fold-back at the flange back cut off, CONTACT's prw_determine_foldback),
// then interpolated to the lateral samples: cubic Hermite in track y with the
// exact slopes of the locus.
void ContactSearch::sample_wheel(const Frame& f)
{
    const int nk = static_cast<int>(knot_.size());
    ky_.resize(nk);
    kx_.resize(nk);
    kz_.resize(nk);
    kdx_.resize(nk);
    kdz_.resize(nk);
    const Mat3& r = f.r;
    // profile in track y, for the fold-back trimming
    double ylo = 1e300, yhi = -1e300;
    for (int k = 0; k < nk; ++k) {
        const Profile::Point& p = knot_[k];
        ky_[k] = f.o(1) + r(1, 1) * p.y + r(1, 2) * p.z;
        kdx_[k] = r(1, 1) * p.dy + r(1, 2) * p.dz; // dy_track/ds
        ylo = std::min(ylo, ky_[k]);
        yhi = std::max(yhi, ky_[k]);
    }
    const double ymid = 0.5 * (ylo + yhi);
    int mid = 0;
    for (int k = 1; k < nk; ++k)
        if (std::abs(ky_[k] - ymid) < std::abs(ky_[mid] - ymid)) mid = k;
    int k_end = mid, k_sta = mid;
    while (k_end + 1 < nk && ky_[k_end + 1] < ky_[k_end] && kdx_[k_end + 1] < 0.0) ++k_end;
    while (k_sta > 0 && ky_[k_sta - 1] > ky_[k_sta] && kdx_[k_sta - 1] < 0.0) --k_sta;

    // locus: x = r (dz/dy) R01 / R00 on each circle (R02 = 0 without pitch)
    const double R = radius_, a = r(0, 1) / r(0, 0), b = R * r(0, 2) / r(0, 0);
    // Only the knots whose locus can reach the rail's samples: the locus's
    // track y differs from the profile point's (ky_ above) by r10 x + r12
    // (z_w - z), |x| <= R / 2 and |z_w - z| <= R + |z|; an interval of the
    // locus wholly above the last sample or below the first adds none.
    const double y_last = y0_ + (n_ - 1) * dy_;
    auto reach = [&](int k) {
        return std::abs(r(1, 0)) * 0.5 * R + std::abs(r(1, 2)) * (R + std::abs(knot_[k].z)) + kReachSlack;
    };
    while (k_sta < k_end && ky_[k_sta + 1] - reach(k_sta + 1) > y_last) ++k_sta;
    while (k_end > k_sta && ky_[k_end - 1] + reach(k_end - 1) < y0_) --k_end;
    for (int k = k_sta; k <= k_end; ++k) {
        const Profile::Point& p = knot_[k];
        const double dyc = std::min(-1e-6, p.dy);
        const double q = p.dz / dyc;
        const double dq = p.dy < -1e-6 ? (p.d2z * dyc - p.dz * p.d2y) / (dyc * dyc) : p.d2z / dyc;
        const double rr = R + p.z, drr = p.dz;
        double x = rr * q * a - b, dx = (drr * q + rr * dq) * a;
        if (std::abs(x) > 0.5 * R) {
            x = std::copysign(0.5 * R, x);
            dx = 0.0;
        }
        const double w2 = rr * rr - x * x;
        const double root = std::sqrt(std::max(w2, 1e-300));
        const double zw = root - R, dzw = (rr * drr - x * dx) / root;
        const Vec3 pos = f.o + r * Vec3(x, p.y, zw);
        const Vec3 der = r * Vec3(dx, p.dy, dzw);
        ky_[k] = pos(1);
        kx_[k] = pos(0);
        kz_[k] = w2 > 0.0 ? pos(2) : -kNoGap;
        const double dyt = der(1) < -1e-12 ? der(1) : -1e-12;
        kdx_[k] = der(0) / dyt;
        kdz_[k] = der(2) / dyt;
    }
    // samples: y ascending, the locus runs with y descending; per locus
    // interval the Hermite cubics of z and x in u = y - y_k
    std::fill(zw_.begin(), zw_.end(), -kNoGap);
    std::fill(xw_.begin(), xw_.end(), -kNoGap);
    std::fill(gap_.begin(), gap_.end(), kNoGap);
    for (int k = k_end - 1; k >= k_sta; --k) {
        const double ya = ky_[k + 1], yb = ky_[k]; // ya < yb
        if (!(yb > ya)) continue;
        int i = std::max(0, static_cast<int>(std::ceil((ya - y0_) / dy_)));
        const int i_end = std::min(n_ - 1, static_cast<int>(std::floor((yb - y0_) / dy_)));
        if (i > i_end || kz_[k] <= -kValidGap || kz_[k + 1] <= -kValidGap) continue;
        const double h = ya - yb;
        auto cubic = [&](double fa, double da, double fb, double db, double* c) {
            // f(u), u = y - ya in [0, -h]: values and slopes at both ends
            const double w = -h, m = quotient_if_positive(fb - fa, w);
            c[0] = fa;
            c[1] = da;
            c[2] = quotient_if_positive(3.0 * m - 2.0 * da - db, w);
            c[3] = quotient_if_positive(da + db - 2.0 * m, w * w);
        };
        double cz[4], cx[4];
        cubic(kz_[k + 1], kdz_[k + 1], kz_[k], kdz_[k], cz);
        cubic(kx_[k + 1], kdx_[k + 1], kx_[k], kdx_[k], cx);
        for (; i <= i_end; ++i) {
            const double u = y0_ + i * dy_ - ya;
            const double z = cz[0] + u * (cz[1] + u * (cz[2] + u * cz[3]));
            zw_[i] = z;
            xw_[i] = cx[0] + u * (cx[1] + u * (cx[2] + u * cx[3]));
            gap_[i] = zr_[i] - z;
        }
    }
}

double ContactSearch::find(const Frame& f, std::vector<Region>& regions, bool shift_height)
{
    regions.clear();
    if (shift_height && has_sampled_ && f.r == sampled_.r && f.o(0) == sampled_.o(0) && f.o(1) == sampled_.o(1)) {
        const double dz = f.o(2) - sampled_.o(2);
        for (int i = 0; i < n_; ++i)
            if (zw_sampled_[i] > -kValidGap) {
                zw_[i] = zw_sampled_[i] + dz;
                gap_[i] = zr_[i] - zw_[i];
            }
    } else {
        sample_wheel(f);
        sampled_ = f;
        has_sampled_ = true;
        zw_sampled_ = zw_;
    }
    const int i_min = static_cast<int>(std::min_element(gap_.begin(), gap_.end()) - gap_.begin());
    const double gap_min = gap_[i_min];
    // local minima, a plateau (equal gaps within kPlateau) counted once
    minima_.clear();
    std::fill(mask_.begin(), mask_.end(), 0);
    for (int i = 0; i < n_; ++i) {
        bool is_min = gap_[i] < kValidGap;
        if (is_min && i > 0) {
            if (mask_[i - 1] && std::abs(gap_[i - 1] - gap_[i]) < kPlateau) {
                mask_[i] = 1;
                is_min = false;
            } else if (gap_[i - 1] <= gap_[i]) {
                is_min = false;
            }
        }
        if (is_min && i + 1 < n_ && gap_[i + 1] < gap_[i]) is_min = false;
        if (is_min) {
            mask_[i] = 1;
            minima_.push_back(i);
        }
    }
    // take the deepest remaining minimum, open its region, drop the minima it
    // contains; stop after the true contacts and two near misses
    auto deepest = [&]() {
        int best = -1;
        for (size_t m = 0; m < minima_.size(); ++m)
            if (minima_[m] >= 0 && (best < 0 || gap_[minima_[m]] < gap_[minima_[best]])) best = static_cast<int>(m);
        return best;
    };
    int n_miss = 0;
    for (int m = deepest(); m >= 0; m = deepest()) {
        const int i = minima_[m];
        const double g = gap_[i];
        if (g >= 0.0 && n_miss >= kMaxNearMisses) break;
        if (g < 0.0 && (i == 0 || i == n_ - 1))
            throw Error(ErrorKind::invalid_input,
                        "wheel/rail contact search: the wheel penetrates the rail at the end of the "
                        "rail profile (is the rail profile wide enough, and upright?)");
        if (g >= 0.0) ++n_miss;
        const auto [sta, end] = add_region(i, g, regions);
        for (int& mm : minima_)
            if (mm >= sta && mm <= end) mm = -1;
    }
    return gap_min;
}

// One region from the local minimum at sample i (CONTACT's
// locate_interpen_1d, steps 5.c to 5.j); returns its sample range.
std::pair<int, int> ContactSearch::add_region(int i, double gap_locmin, std::vector<Region>& regions)
{
    Region r;
    // the minimum between the samples: parabolas through three samples
    double x = xw_[i], y = y_at(i), g = gap_[i], z = zr_[i];
    if (i > 0 && i + 1 < n_ && gap_[i - 1] < kValidGap && gap_[i + 1] < kValidGap &&
        std::abs(gap_[i - 1] - gap_[i]) < kSteep && std::abs(gap_[i + 1] - gap_[i]) < kSteep) {
        auto fit = [&](const std::vector<double>& f, double& a, double& b) {
            a = (f[i + 1] - 2.0 * f[i] + f[i - 1]) / (2.0 * dy_ * dy_);
            b = (f[i + 1] - f[i - 1]) / (2.0 * dy_);
        };
        double a = 0.0, b = 0.0;
        fit(gap_, a, b);
        const double t = -b / (2.0 * a);
        g = a * t * t + b * t + gap_[i];
        fit(zr_, a, b);
        z = a * t * t + b * t + zr_[i];
        fit(xw_, a, b);
        x = a * t * t + b * t + xw_[i];
        y += t;
    }
    r.deepest = Vec3(x, y, z);
    r.gap_min = g < 0.0 && gap_locmin >= 0.0 ? 1e-13 : g; // a near miss stays one
    int sta = i, end = i;
    if (r.gap_min < 0.0) {
        while (sta > 0 && gap_[sta - 1] < 0.0) --sta;
        while (end + 1 < n_ && gap_[end + 1] < 0.0) ++end;
        if (sta > 0) --sta;
        if (end + 1 < n_) ++end;
    }
    const double curv = 0.5 / radius_; // the wheel's curvature along the track
    if (r.gap_min >= 0.0) {
        r.wgt_x = x;
        r.wgt_y = y;
        r.wgt_z = z;
        r.wgt_angle = alpha_[i];
        r.x_lo = r.x_hi = xw_[i];
        r.y_lo = r.y_hi = y_at(i);
        r.z_lo = r.z_hi = zr_[i];
    } else {
        double sw = 0.0, sx = 0.0, sy = 0.0, sz = 0.0, sa = 0.0;
        r.x_lo = 1e300;
        r.x_hi = -1e300;
        for (int k = sta; k <= end; ++k) {
            if (gap_[k] > 0.0) continue;
            const double pen = -gap_[k];
            const double w = sample_weight(pen, curv);
            sw += dy_ * w;
            sx += dy_ * w * xw_[k];
            sy += dy_ * w * y_at(k);
            sz += dy_ * w * zr_[k];
            sa += dy_ * w * alpha_[k];
            const double t0 = std::sqrt(pen / curv);
            r.x_lo = std::min(r.x_lo, xw_[k] - t0);
            r.x_hi = std::max(r.x_hi, xw_[k] + t0);
        }
        r.weight = sw;
        r.wgt_x = sx / sw;
        r.wgt_y = sy / sw;
        r.wgt_z = sz / sw;
        r.wgt_angle = sa / sw;
        // where the gap changes sign, by linear interpolation
        auto crossing = [&](int k, int k_in, double& yc, double& zc) {
            const double dg = gap_[k_in] - gap_[k];
            if (gap_[k] * gap_[k_in] <= -1e-18 && std::abs(dg) >= 1e-12) {
                yc = y_at(k) - quotient_or_zero(gap_[k] * (y_at(k_in) - y_at(k)), dg);
                zc = zr_[k] - quotient_or_zero(gap_[k] * (zr_[k_in] - zr_[k]), dg);
            } else {
                yc = y_at(k);
                zc = zr_[k];
            }
        };
        crossing(sta, sta + 1, r.y_lo, r.z_lo);
        crossing(end, end - 1, r.y_hi, r.z_hi);
        // a region running off the sampled rail: mirror its far side
        if (sta == 0) r.y_lo = std::min(r.y_lo, r.wgt_y - (y_at(end) - r.wgt_y));
        if (end == n_ - 1) r.y_hi = std::max(r.y_hi, r.wgt_y + (r.wgt_y - y_at(sta)));
    }
    regions.push_back(r);
    return {sta, end};
}

} // namespace creepwork::wheelrail
