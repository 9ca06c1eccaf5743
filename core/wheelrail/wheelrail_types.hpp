// Inputs of the wheel/rail geometry: track, wheelset, wheelset position and
// velocity, and the contact search options. SI units; the meaning and signs
// of every quantity are CONTACT's module 1 (user guide, chapter "Inputs and
// outputs for module 1"), with lengths in metres instead of millimetres.
//
// Track coordinates: x along the track (the direction of travel), y to the
// right seen in the direction of travel, z downwards; the origin midway
// between the rails in the plane on top of the (design) rails. One case is
// one wheel on one rail, the left or the right one; both use the same
// profiles in canonical form (profile.hpp), the left side mirrored.
#pragma once

namespace creepwork::wheelrail {

enum class Side { left, right };

// The track of one case: its values describe the rail of that case's side.
struct Track {
    // Rail placement by the gauge: the canted rail touches the plane z = 0
    // and its gauge face, at gauge_height below that plane, lies at
    // gauge_width / 2 from the track centre. gauge_height <= 0 places the
    // rail profile's origin at (rail_y0, rail_z0) instead (rail_y0 > 0 for
    // the right rail; mirrored for the left).
    double gauge_height = 14e-3; // [m]
    double gauge_width = 1.435;  // [m] between the gauge faces
    double cant = 0.0;           // [rad] rail inclination, > 0 towards the track centre
    double rail_y0 = 0.0;        // [m] absolute placement (gauge_height <= 0), track y
    double rail_z0 = 0.0;        // [m]
    // Deviations of the rail from its design position (CONTACT's DY, DZ,
    // ROLL), in track coordinates.
    double rail_dy = 0.0, rail_dz = 0.0, rail_roll = 0.0; // [m], [m], [rad]
    double curvature = 0.0; // [1/m] track curvature, > 0 for a right-hand curve
};

struct Wheelset {
    double flange_back_distance = 1.360; // [m] between the flange backs (FBDIST)
    double flange_back_position = -0.070; // [m] flange back in wheel profile y (FBPOS)
    double nominal_radius = 0.460;        // [m] axle to the wheel profile origin (NOMRADW)
};

// Position of the wheelset centre and its orientation in track coordinates:
// roll about x, then yaw about the rolled z, then pitch about the axle
// (irrelevant for round wheels). z = 0 puts the axle at z = -nominal_radius;
// z > 0 lowers the wheelset (CONTACT's Z_WS).
struct WheelsetPosition {
    double y = 0.0, z = 0.0;             // [m]
    double roll = 0.0, yaw = 0.0, pitch = 0.0; // [rad]
};

// Velocities: forward speed along the track, rates of the position
// coordinates, and the angular velocity about the axle (< 0 rolling forward).
struct WheelsetVelocity {
    double vs = 0.0;                        // [m/s]
    double vy = 0.0, vz = 0.0;              // [m/s]
    double vroll = 0.0, vyaw = 0.0, vpitch = 0.0; // [rad/s]
};

// Contact search and discretisation (CONTACT's DX, DS, A_SEP, D_SEP, D_COMB,
// D_TURN, G_MISS, NPOT_MAX).
struct SearchOptions {
    double dx = 0.2e-3; // [m] element size along x of the patch grids
    double ds = 0.2e-3; // [m] element size across, in the tangent plane
    // Interpenetration regions closer than d_comb are one patch; up to d_sep
    // one patch with sub-patches; farther, or with contact angles more than
    // a_sep apart, separate patches, whose angles turn towards each other up
    // to d_turn (< 0: 2 d_sep - d_comb).
    double a_sep = 1.5707963267948966; // [rad]
    double d_sep = 8e-3;               // [m]
    double d_comb = 4e-3;              // [m]
    double d_turn = -1.0;              // [m]
    double g_miss = -1.0; // [m] near misses with gap below g_miss widen nearby patches (< 0: off)
    // The lateral sampling of the vertical gap: lateral_step * ds (CONTACT: 0.3).
    double lateral_step = 0.3;
    // A patch grid with more elements is made coarser by doubling dx, ds.
    int max_elements = 20000;
};

} // namespace creepwork::wheelrail
