// A fast normal method for any gap on a regular grid: each row of the grid
// (a strip along the rolling direction x) carries a Hertzian semi-ellipse of
// pressure, after the analytical method of Sichani, Enblom and Berg (Vehicle
// System Dynamics 52 (2014) 1752-1764; CONTACT's B = 6, "ANALYN"):
//  - the row's contact locus is its lowest element, g its height above the
//    lowest element of the whole gap;
//  - the row's curvatures are fitted there: A along x by least squares over
//    the deeply penetrating elements around the locus, B across by the
//    second difference of the neighbouring rows;
//  - Hertz's ellipse of curvatures A, B under the total depth d gives shape
//    factors alpha = d / (A a^2), beta = d / (B b^2), and the row's local
//    depth is d - beta g;
//  - the row is in contact over |x - x_locus| < sqrt(depth / (alpha A)),
//    with the semi-elliptic pressure of Hertz's ellipse under that depth.
// Curvatures below kMinCurvature count as kMinCurvature (a flat or concave
// row then gives a long, low patch). With the force prescribed, the depth is
// found by a safeguarded iteration on the total force (increasing in the
// depth; it jumps where a row's fit widens), started from the depth where the
// rows' continuous semi-ellipses carry N, and the pressures are scaled to N
// exactly.
//
// Cost: O(nx ny) once, then O(ny + contact elements) per force evaluation,
// about five evaluations with the force prescribed, one with the approach.
// Accuracy against the exact half-space solution:
// doc/validation/non-hertzian.md.
#pragma once

#include <vector>

#include "simd/kernel_isa.hpp"

namespace creepwork {

// Smallest curvature of a row [1/m] (a 5 m radius): CONTACT's 1e-4 1/mm.
constexpr double kMinCurvature = 0.1;
// The widest least-squares fit along x: this many elements on each side of
// the row's locus.
constexpr int kMaxFitHalfWidth = 10;

struct SemiHertzResult {
    double approach = 0;    // [m] from the gap's datum h = 0
    double normal_force = 0; // [N]
    int n_contact = 0;
    int iterations = 0;     // force evaluations (force prescribed)
};

class SemiHertz {
public:
    SemiHertz(int nx, int ny); // nx, ny >= 3; all workspace

    // h [i + nx j]: the gap [m] on cells of size dx x dy; E* = G / (1 - nu).
    // force = true: value = N [N] > 0; false: value = the approach [m] from
    // the datum. pressure [i + nx j] (nx ny values) receives the pressure
    // [Pa]; zero_outside_extents = true says it is zero outside the last
    // solve's row extents (row_extent) already, so that only those are
    // cleared. Allocates nothing.
    SemiHertzResult solve(const double* h, double dx, double dy, double E_star, bool force,
                          double value, double* pressure, bool zero_outside_extents = false);
    // The derivative of the last solve's pressure by the normal force,
    // dp/dN [1/m^2] per element [i + nx j] (semi_hertz_derivative.cpp),
    // from that solve's pressure [Pa].
    void load_derivative(const double* pressure, double* dp_dN) const;
    // dN/dd [N/m] of the last solve: the force's derivative by the depth (so
    // by the approach), from that solve's pressure [Pa]
    // (semi_hertz_derivative.cpp).
    double force_by_depth(const double* pressure) const;
    // The copy of the roots' kernel to run (every copy gives the same bits).
    void set_kernel_isa(KernelIsa isa) { isa_ = isa; }
    // The elements lo .. hi of row j outside which the last solve's
    // pressure is zero (hi < lo: the whole row).
    void row_extent(int j, int& lo, int& hi) const
    {
        lo = rows_[j].written_lo;
        hi = rows_[j].written_hi;
    }

private:
    struct Row {
        int locus = 0;        // i of the lowest element (kept one cell inside the row)
        double g = 0;         // its height above the lowest element of the gap [m]
        double B = 0;         // curvature across [1/m]
        double A[kMaxFitHalfWidth + 1] = {}; // curvature along x fitted over +-k elements, k >= 1
        int shape_k = -1;     // the k of the cached shape factors
        double beta = 0, p_factor = 0, c = 0, inv_c = 0; // at shape_k
        int written_lo = 0, written_hi = -1; // the elements the last solve's pressure has
        // force_at's: the elements in contact, the first of its roots in
        // roots_, the local depth [m].
        int lo = 0, hi = -1, packed = 0;
        double local = 0;
        // For k = 1..9: the least depth at which the fit is wider than k, from
        // the heights of the pairs of elements locus -+ (k' + 1), k' <= k
        // (nondecreasing in k; infinite from a pair past the row's ends on).
        double widen[kMaxFitHalfWidth] = {};
        // Per k, known once computed in this solve (bit k of known): the
        // shape factors, and the continuous semi-ellipse's force per unit
        // local depth [N/m].
        unsigned known = 0;
        double beta_k[kMaxFitHalfWidth + 1] = {}, p_factor_k[kMaxFitHalfWidth + 1] = {},
               slope_k[kMaxFitHalfWidth + 1] = {};
        // c = alpha A dx^2 [m] (the semi-ellipse's local - c m^2) and 1 / c.
        double c_k[kMaxFitHalfWidth + 1] = {}, inv_c_k[kMaxFitHalfWidth + 1] = {};
    };
    void fit_rows(const double* h);
    int depth_for_force(double N, double& d, double& F);
    // Total force [N] at depth d; the rows' contact elements and roots kept
    // for write_pressure.
    double force_at(double d);
    // The last force_at's pressures times scale into out (zero elsewhere
    // already); the number of elements with pressure > 0.
    int write_pressure(double scale, double* out);
    // The force of the rows' semi-ellipses over the continuous x, a
    // piecewise-linear function of d with the shape factors held: d where it
    // is N (the discrete iteration's first guess).
    double continuous_depth(double N);
    double continuous_slope_ = 0; // that force's slope at that depth [N/m]
    // The fit's half-width k of row j at depth d, and the row's shape factors
    // for it: inline where k stays the last depth's (the depths of an
    // iteration lie close together), else shape_change.
    int shape_at(int j, double d)
    {
        const Row& R = rows_[j];
        const int k = R.shape_k;
        const bool in = d > R.g;
        if (k >= 1 && (k == kMaxFitHalfWidth || !(in && d >= R.widen[k])) &&
            (k == 1 || (in && d >= R.widen[k - 1])))
            return k;
        return shape_change(j, d);
    }
    int shape_change(int j, double d);

    // The least-squares parabola over t = -k..k, per half-width k: the
    // moments m0 = sum 1, m2 = sum t^2 and 1 / (m0 m4 - m2^2) (m4 = sum t^4).
    struct FitMoments {
        double m0[kMaxFitHalfWidth + 1], m2[kMaxFitHalfWidth + 1], inv_den[kMaxFitHalfWidth + 1];
        FitMoments();
    };
    FitMoments fit_;

    int nx_, ny_;
    double dx_ = 0, dy_ = 0, E_star_ = 0, h_min_ = 0;
    std::vector<Row> rows_;
    // force_at's roots of all rows, packed (at most nx ny), and their weights.
    std::vector<double> roots_, weights_;
    // force_at's rows in contact, for the roots' kernel: local depth, c,
    // pressure factor, |m| on both sides, largest |m|, first packed value.
    std::vector<double> list_local_, list_c_, list_p_factor_;
    std::vector<int> list_both_, list_M_, list_offset_;
    KernelIsa isa_ = best_kernel_isa(); // the rows' semi-ellipses' copy
};

} // namespace creepwork
