// The pictures of `creepwork wheelrail --out DIR`, in CONTACT's module-1
// conventions (wheelrail_data.hpp), lengths in mm, forces in kN:
//
//   profiles.png  the rail's and the wheel's profile in track coordinates
//                 (y across the track, z down drawn downwards, equal scales),
//                 each patch's contact point, its normal n (into the rail),
//                 its extent across s and its force on the rail; beside it the
//                 same zoomed onto the contacts; the total force on the rail
//                 in the title
//   patch_K.png   patch K's maps over x, s: pressure, slip/adhesion (separate
//                 lobes labelled), the traction on the rail along x and s, the
//                 energy-consistent work per unit area, and the zoom onto the
//                 contacts; titled with Fn, Fx, Fs, Mn, p_max and the creepages
//
// Scripts and data stay in DIR/gnuplot/ (wheelrail.gp re-draws them all).
#pragma once

#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "wheelrail_data.hpp"

namespace cwcli {

// model names the contact model in the captions ("exact", "fast").
void write_wheelrail_pictures(const std::string& dir, const ProfilePoints& rail,
                              const ProfilePoints& wheel, const std::vector<PatchView>& patches,
                              const cw_wheelrail_totals& totals, const std::string& model);

} // namespace cwcli
