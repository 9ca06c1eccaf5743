// Wear depth accumulated on a host's profile grid (wheel or rail) over many
// passes, and the profile update helper.
//
// The grid: nodes s_0 < s_1 < ... < s_(n-1) [m] of the host's lateral
// profile coordinate, any spacing. Node k owns the cell between the
// midpoints to its neighbours (the end cells extend half a spacing beyond
// the end nodes), of width w_k.
//
// A pass places the contact's strips on the grid: strip j (centre y_j,
// width dy_j, depth per pass d_j, measured in the contact plane) covers
//     s = s0 + orientation (y_j +- dy_j/2) cos(gamma)
// where s0 is the profile coordinate of the patch centre, orientation +1 if
// s grows with the contact's y and -1 if it falls, and gamma the contact
// angle between the contact plane and the grid's s axis (0: s runs along
// the surface, e.g. an arc length). Its worn cross-section d_j dy_j is spread
// uniformly over that interval: cell k, overlapped over a length o_jk,
// receives
//     normal depth  d_j o_jk / w_k                 (normal to the surface)
//     height depth  d_j o_jk / (w_k cos(gamma))     (along the grid's height
//                                                   axis: vertical on a
//                                                   rail, radial on a wheel)
// times the number of passes. Both conserve the worn volume; what falls
// outside the grid is counted as lost. Sums are exact (exact_sum.hpp): the
// result does not depend on the order of the passes, on how passes are split
// between calls, or on how accumulators are merged.
#pragma once

#include <vector>

#include "wear/exact_sum.hpp"

namespace creepwork::wear {

constexpr double kMaxContactAngle = 1.4835298641951802; // 85 degrees
constexpr double kMaxPasses = 1e15;
constexpr long kMaxProfileNodes = 10000000;

// One contact's lateral wear, per strip (the caller's arrays).
struct StripWear {
    const double* y = nullptr;     // strip centres [m]
    const double* width = nullptr; // strip widths [m], > 0
    const double* depth = nullptr; // depth per pass [m], >= 0
    long count = 0;
};

struct Placement {
    double s0 = 0.0;           // profile coordinate of the patch centre [m]
    int orientation = 1;       // +1: s grows with y; -1: s falls
    double contact_angle = 0;  // gamma [rad], |gamma| <= 85 degrees
    double passes = 1.0;       // >= 0: axle passages (rail), revolutions (wheel)
};

struct ProfileTotals {
    double passes = 0;         // sum of the passes added
    double volume = 0;         // worn cross-section added [m^2] (volume per metre
                               // of rail, or per metre of wheel circumference)
    double volume_lost = 0;    // part of it that fell outside the grid [m^2]
    long long adds = 0;        // successful add calls
};

enum class DepthKind { normal = 0, height = 1 };

class ProfileAccumulator {
public:
    // Throws Error(invalid_input) unless n >= 2 finite, strictly increasing
    // nodes with n <= kMaxProfileNodes.
    ProfileAccumulator(const double* s, long n);

    long size() const { return static_cast<long>(nodes_.size()); }
    const std::vector<double>& nodes() const { return nodes_; }
    const std::vector<double>& cell_widths() const { return widths_; }

    // Adds one contact's strips, placement.passes times. Checks everything
    // first (Error(invalid_input) naming the input, Error(numeric_failure)
    // if a sum would leave the exact range): on error nothing changes.
    // Allocates nothing.
    void add(const StripWear& strips, const Placement& placement);
    // Adds another accumulator on the same nodes (bitwise the same as having
    // added its passes here). Throws Error(invalid_input) if the nodes differ.
    void merge(const ProfileAccumulator& other);
    void reset();

    void depth(DepthKind kind, double* out) const; // n values [m]
    ProfileTotals totals() const;

    // The exact state, for transfer between processes: words() values.
    long state_words() const;
    void save(uint64_t* out) const;
    // Adds a state saved from an accumulator on the same nodes (checked by
    // a fingerprint of the nodes stored in the state).
    void add_saved(const uint64_t* in, long len);

private:
    void check_strips(const StripWear& strips, const Placement& p) const;
    uint64_t fingerprint() const;

    std::vector<double> nodes_, edges_, widths_;
    std::vector<ExactSum> normal_, height_;
    ExactSum passes_, volume_, lost_;
    long long adds_ = 0;
};

// new_profile = old_profile - smooth(depth) on the nodes s (n values each),
// where smooth is a volume-conserving Gaussian filter of standard deviation
// smoothing [m] (0: none): each cell's worn cross-section d_m w_m is spread
// over the cells k within 5 smoothing lengths in proportion to
// (exp(-(s_k - s_m)^2 / (2 smoothing^2)) - exp(-12.5)) w_k (a Gaussian cut
// continuously at 5 smoothing lengths), so sum_k (old - new)_k w_k =
// sum_m d_m w_m to rounding. out may alias old_profile or depth. Throws
// Error(invalid_input) naming the input, Error(numeric_failure) if a value
// overflows; on error out is untouched. Allocates a workspace.
void update_profile(const double* s, const double* old_profile, const double* depth, long n,
                    double smoothing, double* out);

} // namespace creepwork::wear
