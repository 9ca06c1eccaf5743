#include "wheelrail/patch_combination.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace creepwork::wheelrail {
namespace {

// Distance between the bounding boxes of two regions (CONTACT's
// cpatch_distance): along x, and in (y, z) between the facing lateral ends.
double box_distance(const double* a, const double* b)
{
    double dx = 0.0, dy = 0.0, dz = 0.0;
    if (a[0] > b[1]) dx = a[0] - b[1];
    else if (b[0] > a[1]) dx = b[0] - a[1];
    if (a[2] > b[3]) {
        dy = a[2] - b[3];
        dz = a[4] - b[5];
    } else if (b[2] > a[3]) {
        dy = b[2] - a[3];
        dz = b[4] - a[5];
    }
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

void box(const Region& r, double* b)
{
    b[0] = r.x_lo;
    b[1] = r.x_hi;
    b[2] = r.y_lo;
    b[3] = r.y_hi;
    b[4] = r.z_lo;
    b[5] = r.z_hi;
}

double distance(const Region& a, const Region& b)
{
    double ba[6], bb[6];
    box(a, ba);
    box(b, bb);
    return box_distance(ba, bb);
}

// True contacts from the field side (largest y) to the track centre, then
// near misses from the smallest gap.
void sort_regions(std::vector<Region>& r)
{
    for (bool changed = true; changed;) {
        changed = false;
        for (size_t i = 0; i + 1 < r.size(); ++i) {
            const double g0 = r[i].gap_min, g1 = r[i + 1].gap_min;
            if ((g0 >= 0.0 && g1 < 0.0) || (g0 < 0.0 && g1 < 0.0 && r[i].wgt_y < r[i + 1].wgt_y) ||
                (g0 >= 0.0 && g1 >= 0.0 && g0 > g1)) {
                std::swap(r[i], r[i + 1]);
                changed = true;
            }
        }
    }
}

void merge(Region& tot, const Region& add, bool as_sub)
{
    if (add.gap_min < tot.gap_min) {
        tot.deepest = add.deepest;
        tot.gap_min = add.gap_min;
    }
    tot.x_lo = std::min(tot.x_lo, add.x_lo);
    tot.x_hi = std::max(tot.x_hi, add.x_hi);
    if (add.y_lo < tot.y_lo) {
        tot.y_lo = add.y_lo;
        tot.z_lo = add.z_lo;
    }
    if (add.y_hi > tot.y_hi) {
        tot.y_hi = add.y_hi;
        tot.z_hi = add.z_hi;
    }
    const double w = tot.weight + add.weight;
    tot.wgt_x = (tot.wgt_x * tot.weight + add.wgt_x * add.weight) / w;
    tot.wgt_y = (tot.wgt_y * tot.weight + add.wgt_y * add.weight) / w;
    tot.wgt_z = (tot.wgt_z * tot.weight + add.wgt_z * add.weight) / w;
    tot.wgt_angle = (tot.wgt_angle * tot.weight + add.wgt_angle * add.weight) / w;
    tot.weight = w;
    if (as_sub) {
        double b[6];
        box(add, b);
        tot.sub_extent.insert(tot.sub_extent.end(), b, b + 6);
    }
}

void turn_angles(std::vector<Region>& r, const SearchOptions& opt, double d_turn)
{
    if (d_turn <= opt.d_sep + 1e-15) return;
    std::vector<Region> before(r); // the turns use the angles before turning
    for (size_t i = 0; i + 1 < r.size(); ++i) {
        const Region &a = before[i], &b = before[i + 1];
        const double dist = std::hypot(a.y_lo - b.y_hi, a.z_lo - b.z_hi);
        const double dangle = a.wgt_angle - b.wgt_angle;
        if (b.gap_min >= 0.0 || std::abs(dangle) > opt.a_sep || dist < opt.d_sep || dist > d_turn) continue;
        const double mean = (a.wgt_angle * a.weight + b.wgt_angle * b.weight) / (a.weight + b.weight);
        const double fac = (d_turn - dist) / (d_turn - opt.d_sep);
        r[i].wgt_angle += fac * (mean - a.wgt_angle);
        r[i + 1].wgt_angle += fac * (mean - b.wgt_angle);
    }
}

} // namespace

void combine_regions(std::vector<Region>& r, const SearchOptions& opt)
{
    sort_regions(r);
    // true patches reach out to near misses closer than d_comb with a gap
    // below g_miss, in proportion 1 - gap / g_miss
    size_t n_true = 0;
    while (n_true < r.size() && r[n_true].gap_min < 0.0) ++n_true;
    for (size_t i = 0; i < n_true; ++i)
        for (size_t j = n_true; j < r.size(); ++j) {
            Region &a = r[i], &b = r[j];
            if (!(b.gap_min < opt.g_miss && distance(a, b) <= opt.d_comb)) continue;
            const double th = std::max(0.0, 1.0 - b.gap_min / opt.g_miss);
            if (b.x_lo < a.x_lo) a.x_lo = th * b.x_lo + (1.0 - th) * a.x_lo;
            else if (b.x_lo > a.x_hi) a.x_hi = (1.0 - th) * a.x_hi + th * b.x_lo;
            if (b.y_lo < a.y_lo) {
                a.y_lo = th * b.y_lo + (1.0 - th) * a.y_lo;
                a.z_lo = th * b.z_lo + (1.0 - th) * a.z_lo;
            } else if (b.y_lo > a.y_hi) {
                a.y_hi = (1.0 - th) * a.y_hi + th * b.y_lo;
                a.z_hi = (1.0 - th) * a.z_hi + th * b.z_lo;
            }
        }
    // pass 1 merges within d_comb, pass 2 within d_sep as sub-patches
    for (int pass = 1; pass <= 2; ++pass) {
        if (pass == 2)
            for (Region& reg : r) {
                reg.sub_extent.resize(6);
                box(reg, reg.sub_extent.data());
            }
        for (size_t i = 0; i + 1 < r.size(); ++i) {
            for (size_t j = i + 1; j < r.size();) {
                const double dist = distance(r[i], r[j]);
                const double dangle = r[i].wgt_angle - r[j].wgt_angle;
                if (r[i].gap_min >= 0.0 || r[j].gap_min >= 0.0 || std::abs(dangle) > opt.a_sep ||
                    dist > opt.d_sep || (pass == 1 && dist > opt.d_comb)) {
                    ++j;
                    continue;
                }
                merge(r[i], r[j], pass == 2);
                r.erase(r.begin() + static_cast<std::ptrdiff_t>(j));
            }
        }
    }
    const double d_turn = opt.d_turn < 0.0 ? 2.0 * opt.d_sep - opt.d_comb : opt.d_turn;
    turn_angles(r, opt, d_turn);
    r.erase(std::remove_if(r.begin(), r.end(), [](const Region& x) { return x.gap_min >= 0.0; }), r.end());
    for (Region& reg : r) {
        const int n = reg.n_sub();
        reg.sub_factor.assign(static_cast<size_t>(n) * n, 1.0);
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b)
                if (a != b) {
                    const double d = box_distance(&reg.sub_extent[6 * a], &reg.sub_extent[6 * b]);
                    reg.sub_factor[a * n + b] =
                        std::pow(std::max(0.0, opt.d_sep - d) / (opt.d_sep - opt.d_comb), 0.8);
                }
    }
}

} // namespace creepwork::wheelrail
