// The options that describe one contact (geometry, load, material or
// flexibilities, creepages, grid) and their translation into the C ABI's
// cw_params / cw_grid in SI. Validation happens here, in the user's units
// and with the option's name, before anything is solved or written; the
// library's own checks remain the backstop.
#pragma once

#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "options.hpp"
#include "units.hpp"

namespace cwcli {

struct ContactSetup {
    cw_grid grid;
    cw_params params; // SI
    Units units = Units::si();
};

// --a --b --N --mu --G --nu --L1 --L2 --L3 --pressure --rolling-direction --units
std::vector<OptionSpec> material_and_load_options();
// --xi-x --xi-y --spin
std::vector<OptionSpec> creepage_options();
// --grid --nx --ny --box-scale
std::vector<OptionSpec> grid_options();

// Reads the options present in opts over the given defaults (SI structs) and
// validates the result. Throws CliError(kExitUsage) naming the option.
ContactSetup read_contact(const ParsedOptions& opts, const cw_params& default_params,
                          const cw_grid& default_grid);

// Library defaults (cw_params_init, cw_grid_init).
cw_params library_default_params();
cw_grid library_default_grid();

const char* grid_kind_name(int kind);    // "strips" | "uniform"
const char* pressure_name(int pressure); // "parabolic" | "elliptic"

} // namespace cwcli
