// The warm start of the half-space problem on a gap grid (gap_normal.hpp)
// along the gap's drift. On a fixed contact set the pressure is linear in
// the gap less the approach (normal_problem.hpp): from the last solutions,
// (h_0, p_0) the latest, (h_1, p_1) and (h_2, p_2), the start for the gap h
// is the secant step
//   p_0 + sum_i g_i (p_i - p_0),  g = argmin |h - h_0 - sum_i g_i (h_i - h_0)|
// over the elements in contact in any of them, each gap difference taken
// less its mean there when the force is prescribed (a constant in the gap
// moves only the approach) and less the approach's change when the approach
// is. A vehicle loop's gap drifts smoothly from call to call, so the start's
// error is of the drift's next order and of the elements that enter or
// leave contact, instead of the drift itself (measured: the conjugate
// gradients' products a warm step, doc/dev/decisions.md). Two differences
// follow a drift in two shapes (the gap's shape and its height, say); when
// they are parallel (one shape drifting) the newest alone; a difference
// below kRoundingFloor of the gap (rounding) is left out. The step is taken
// however long it is: a leap along the drift is still linear on the contact
// set away from the elements that enter or leave it (measured: a gap 5 %
// deeper at once, half the products of a start from p_0). A gap that has
// not moved gives p_0. The caller keeps one problem (rolling direction,
// material, kind of load) per history and clears it when that changes.
// Made once; nothing allocates.
#pragma once

#include <cstddef>
#include <vector>

namespace creepwork {

class PressureDrift {
public:
    // |d_i| <= kRoundingFloor |h_0| on the contact: rounding, no drift.
    static constexpr double kRoundingFloor = 1e-12;
    static constexpr int kSolutions = 3;

    explicit PressureDrift(std::size_t n); // n elements per field
    void clear() { count_ = 0; }
    // The solutions remembered (0 ... kSolutions).
    int count() const { return count_; }
    // With at least one solution: the start for the gap h (n values) and,
    // with the approach prescribed (force = false), the approach [the gap's
    // units] into start (n values, the pressures' units; the solve clips it
    // at 0). g: the steps taken (kSolutions - 1 values, 0 for those left
    // out), or null.
    void predict(const double* h, bool force, double approach, double* start,
                 double* g = nullptr) const;
    // The same steps g (predict's) on the solutions' products A p: A start
    // (n values) while start is not clipped, at no FFT product; false when
    // a solution used came without its product.
    bool predict_product(const double* g, double* product) const;
    // Adds the solution p (n values) of the gap h and the approach, with
    // its product A p times scale (n values) or none (null).
    void remember(const double* h, double approach, const std::vector<double>& p,
                  const double* product = nullptr, double scale = 1.0);

private:
    // Slot of the i-th newest solution.
    int slot(int i) const { return (newest_ + kSolutions - i) % kSolutions; }

    std::vector<double> h_[kSolutions], p_[kSolutions], u_[kSolutions];
    double approach_[kSolutions] = {};
    bool u_valid_[kSolutions] = {};
    int newest_ = 0;
    int count_ = 0;
};

} // namespace creepwork
