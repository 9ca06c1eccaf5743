// The outputs of creepwork transient --out DIR: history.csv (every step's
// totals), and pictures drawn by gnuplot -- per step the slip/adhesion
// state, both tractions and the longitudinal traction along the centre row
// beside its bound mu p_z (step_NNN.png), and the history of the creepages
// and forces over the steps (history.png). The maps are gap_plots.hpp's,
// over the gap grid's extent, tractions on the wheel.
#pragma once

#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "contact_solver.hpp"

namespace cwcli {

// One step as the outputs need it: its input, result and line in the steps
// file, and (for a drawn step) its fields as a Solution.
struct TransientRecord {
    long line = 0;
    cw_transient_input input;
    cw_transient_result result;
    bool drawn = false;
    Solution fields; // set when drawn
};

// At most this many steps get a picture of their own (spread evenly, the
// first and the last always among them): each is one PNG.
constexpr size_t kMaxTransientStepPictures = 100;

// True when step k (0-based) of n gets a picture.
bool transient_step_drawn(size_t k, size_t n);

// The fields and states of the last step of t (a gap grid g, contact p)
// as a Solution for the maps.
Solution transient_fields(const cw_transient* t, const cw_grid& g, const cw_params& p,
                          const cw_transient_result& r);

// Writes dir/history.csv (one row per step, SI: step line dq_m xi_x xi_y phi
// Fx_N Fy_N Mz_N_m n_contact n_adhesion n_slip W_step_J).
void write_transient_history(const std::string& dir, const std::vector<TransientRecord>& steps);

// Writes the data files and scripts into dir/gnuplot and runs gnuplot in
// dir: step_NNN.png for each drawn step (NNN its 1-based number) and
// history.png. gap_file names the contact in the captions.
void write_transient_pictures(const std::string& dir, const std::vector<TransientRecord>& steps,
                              const cw_params& p, const std::string& gap_file);

} // namespace cwcli
