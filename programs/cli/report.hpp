// Totals of one solve for people (text) and programs (JSON). Values are in
// the chosen unit system with the library's sign convention: Fx, Fy, Mz act
// on the wheel, opposite to the creepages (the paper prints the force on the
// rail, i.e. the opposite sign).
//
// JSON keys, stable (new keys are only ever added):
//   Fx Fy Mz W_macro W_micro_paper K W_consistent balance_factor work_flags
//   adhesion_fraction n_contact n_adhesion n_slip a b L1 L2 L3 C11 C22 C23 C33
//   profile_max_diff profile_rms_diff model p_max approach iterations residual
//   units sign_convention input{...} unit_of{...}
#pragma once

#include <ostream>

#include <creepwork/creepwork.h>

#include "json.hpp"
#include "units.hpp"

namespace cwcli {

JsonObject result_json(const cw_result& r, const cw_params& p, const cw_grid& g, const Units& u);

void print_result_text(std::ostream& os, const cw_result& r, const cw_params& p, const cw_grid& g,
                       const Units& u);

// "jacobian": {"Fx": {"xi_x": .., "xi_y": .., "phi": .., "N": ..}, ...} in SI,
// rows and columns of cw_solver_solve_jacobian (doc/theory/jacobians.md),
// and the same as a text table.
JsonObject jacobian_json(const double J[CW_JACOBIAN_LEN]);
void print_jacobian_text(std::ostream& os, const double J[CW_JACOBIAN_LEN]);

// "%.*g" of a double, for text output.
std::string fmt(double v, int digits = 7);

} // namespace cwcli
