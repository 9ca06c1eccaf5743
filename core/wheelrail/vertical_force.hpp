// The wheelset height for a prescribed vertical force (CONTACT's N = 1):
// z_ws is raised or lowered until the vertical force of all patches on the
// rail equals the target. The contact problem of a patch is a plug-in: any
// function of the patch's geometry (its undeformed distance grid, its frame,
// its creepages) that returns the patch's forces -- a simple estimate
// (hertz_patch.hpp), or the non-Hertzian normal and tangential solvers.
//
// Forces are CONTACT's module-1 ones: on the rail, in the patch frame (x,
// s, n); in track coordinates F = fx e_x + fs e_s + fn e_n with e_s = (0,
// cos delta, sin delta), e_n = (0, -sin delta, cos delta).
#pragma once

#include <functional>

#include "wheelrail/wheelrail_geometry.hpp"

namespace creepwork::wheelrail {

struct PatchForces {
    double fn = 0.0; // [N] normal force on the rail (> 0 pressing it)
    double fx = 0.0; // [N] longitudinal, on the rail
    double fs = 0.0; // [N] lateral in the tangent plane, on the rail
    // [N/m] d fn / d(approach) at the patch's geometry, the normal method's
    // own derivative (0: not known; the balance then takes secant steps)
    double fn_by_approach = 0.0;
};

// Solves patch k of the geometry's current state (k: its index there).
using PatchSolver = std::function<PatchForces(std::size_t k, const ContactPatch&)>;

struct TrackForces {
    double fx = 0.0, fy = 0.0, fz = 0.0; // [N] on the rail, track coordinates
};
TrackForces track_forces(const ContactPatch& patch, const PatchForces& f);

struct VerticalForceOptions {
    double tolerance = 1e-6; // relative to the target force
    int max_iterations = 60;
};

struct VerticalForceSolution {
    double z = 0.0;     // [m] the wheelset height found
    double fz = 0.0;    // [N] the vertical force there
    int evaluations = 0; // geometry evaluations used
    int final_solves = 0; // heights the final solver solved (with a trial solver)
};

// Solves for z (the start position gives y, roll, yaw and the first guess
// of z); leaves `geometry` evaluated at the solution. fz > 0 [N]. Throws
// creepwork::Error (not_converged) if the force is not reached.
VerticalForceSolution solve_vertical_position(WheelRailGeometry& geometry, double fz,
                                              const WheelsetPosition& start,
                                              const WheelsetVelocity& velocity, const PatchSolver& solver,
                                              const VerticalForceOptions& options = {});

// The same with a cheaper solver at the heights tried: `trial` solves the
// patches at every height (e.g. to a looser tolerance); once its vertical
// force meets the tolerance (or at the fifth trial height in a row),
// `final` solves the same patches again (the geometry is not evaluated
// again) and the balance ends only if that force meets the tolerance too;
// otherwise it goes on from the final force, the later trial forces
// corrected by the final's difference to the trial's at that height, and
// after two such misses with `final` at every height. The force returned
// is always that of a final solve at the height returned, the last solves
// `final` made.
VerticalForceSolution solve_vertical_position(WheelRailGeometry& geometry, double fz,
                                              const WheelsetPosition& start,
                                              const WheelsetVelocity& velocity, const PatchSolver& trial,
                                              const PatchSolver& final,
                                              const VerticalForceOptions& options = {});

} // namespace creepwork::wheelrail
