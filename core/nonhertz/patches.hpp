// The separate contact patches of a solution on a grid: the 4-connected
// components of its contact elements (elements sharing an edge belong to one
// patch; touching corners do not join), as CONTACT counts them. Patches are
// numbered in the order of their first element in the layout [i + nx j]
// (lowest row first, then lowest x).
#pragma once

#include <vector>

namespace creepwork {

// What one patch carries, in the caller's frame (SI).
struct PatchTotals {
    int n_contact = 0, n_adhesion = 0, n_slip = 0; // elements
    double x_centroid = 0, y_centroid = 0;         // of the elements' area [m]
    double Fx = 0, Fy = 0;                         // on the wheel [N]
    double Mz = 0;                                 // about the grid's origin [N m]
    double Fn = 0;                                 // normal force [N]
    double p_max = 0;                              // [Pa]
    double W_macro = 0;                            // -(Fx xi_x + Fy xi_y + Mz phi) [J/m]
};

class PatchLabels {
public:
    PatchLabels(int nx, int ny); // all workspace

    // Labels the elements with in_contact[k] != 0; returns the number of
    // patches. Allocates nothing.
    int label(const signed char* in_contact);
    // Patch of element k (0-based), or -1 outside the contact.
    int of(int k) const { return label_[k]; }
    int count() const { return count_; }

private:
    int nx_, ny_, count_ = 0;
    std::vector<int> label_, queue_;
};

} // namespace creepwork
