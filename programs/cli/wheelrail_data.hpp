// What `creepwork wheelrail --out` reads from a solved cw_wheelrail handle,
// and its data files. Everything is in CONTACT's module-1 conventions (SI):
// track coordinates x along the track, y to the right, z down; a patch's
// frame x, s (lateral, in the tangent plane), n (into the rail); tractions
// and moments on the rail, micro-slips of the rail relative to the wheel.
//
//   profiles.csv          body,y_m,z_m: the rail's, then the wheel's profile
//                         points in track coordinates at the solved position
//   patch_K_fields.csv    x_m,s_m,area_m2,pz_Pa,px_Pa,ps_Pa,sx,ss,state,
//                         work_J_per_m: one row per element of patch K's field
//                         grid, i (x) fastest; state 0 exterior, 1 adhesion,
//                         2 slip; work the energy-consistent work per rolled
//                         distance
#pragma once

#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "contact_solver.hpp"

namespace cwcli {

// A profile's points in track coordinates [m] (cw_wheelrail_get_profile).
struct ProfilePoints {
    std::vector<double> y, z;
};

// which: CW_WHEELRAIL_RAIL or CW_WHEELRAIL_WHEEL.
ProfilePoints read_profile(const cw_wheelrail* w, int which);

void write_profiles_csv(const std::string& path, const ProfilePoints& rail,
                        const ProfilePoints& wheel);

void write_patch_fields_csv(const std::string& path, const cw_wheelrail* w, size_t k,
                            const cw_wheelrail_patch& patch);

// Patch k of the last solve as the pictures draw it: its solver's solution
// (cw_wheelrail_patch_solver: creepwork's frame, y = -s, on the wheel)
// mirrored about x, so that y is the patch's s and creepwork's sign of the
// rail (ForceSign::rail) gives CONTACT's module-1 quantities: px, ps, mn on
// the rail, sx, ss of the rail; the grid is the field grid (CW_GRID_GAP,
// x0 = field_x0, y0 = field_s0). `lobes` receives the patch's separate
// regions (cw_solver_get_patches, mirrored alike).
struct PatchView {
    cw_wheelrail_patch patch;
    Solution solution;
    std::vector<cw_patch> lobes;
};
PatchView read_patch_view(const cw_wheelrail* w, size_t k, const cw_wheelrail_params& params);

} // namespace cwcli
