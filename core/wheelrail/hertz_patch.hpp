// A simple estimate of a patch's normal force from its undeformed distance,
// for the vertical force balance until the non-Hertzian solvers take over:
// Hertz's solution (Johnson, Contact Mechanics, 1985, section 4.2) for the
// curvatures of h at its deepest element (second differences over one
// element) and the approach -min h. Tangential forces are zero.
#pragma once

#include "wheelrail/vertical_force.hpp"

namespace creepwork::wheelrail {

struct HertzPatchEstimate {
    double G = 82e9;  // [Pa] combined shear modulus
    double nu = 0.28; // [-] combined Poisson's ratio

    PatchForces operator()(const ContactPatch& p) const;
    // As a PatchSolver (the patch's index is not needed).
    PatchForces operator()(std::size_t, const ContactPatch& p) const { return (*this)(p); }
};

} // namespace creepwork::wheelrail
