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
    // Warnings about implausible inputs and a note naming the defaults used:
    // print_notes() writes them to stderr once the contact has been solved
    // (an error's single stderr line stays alone).
    std::vector<std::string> notes;
};

void print_notes(const ContactSetup& c);

// --a --b --N --mu --G --nu --L1 --L2 --L3 --pressure --rolling-direction --units
std::vector<OptionSpec> material_and_load_options();
// --xi-x --xi-y --spin
std::vector<OptionSpec> creepage_options();
// --grid --nx --ny --box-scale
std::vector<OptionSpec> grid_options();
// --model fastsim|exact|calibrated --tolerance --max-iterations
std::vector<OptionSpec> model_options();

// The grid the exact model gets when --grid is not given: CONTACT's layout,
// the uniform grid over kExactBoxScale times the semi-axes with
// kExactBoxScale times the command's default element count (solve: 24 x 24,
// 20 elements across the ellipse and two guard cells on each side).
constexpr double kExactBoxScale = 1.2;

// What read_contact insists on. solve has no sensible default for the size
// and load of a contact, so it requires --a, --b and --N; sweep and fit-fig6
// default to the paper's contact (their --help says which).
enum class SizeAndLoad { required, defaulted };

// Reads the options present in opts over the given defaults (SI structs) and
// validates the result. With --model exact the grid defaults to the uniform
// one (kExactBoxScale above), and the options the exact model cannot use
// (--grid strips, --L1..--L3, --pressure, --flexibility-blending) are errors;
// --tolerance and --max-iterations need --model exact. Throws CliError(kExitUsage) naming the option.
// Inputs that are valid but implausible for a wheel-rail contact (semi-axes
// above 0.1 m, G below 1e6 Pa, creepage above 0.5, ...: plausibility_warnings)
// get a warning each in notes; with SizeAndLoad::required, the library
// defaults taken for mu, G and nu are named in a note.
ContactSetup read_contact(const ParsedOptions& opts, const cw_params& default_params,
                          const cw_grid& default_grid,
                          SizeAndLoad size_and_load = SizeAndLoad::defaulted);

// The warnings for p (SI), each naming the option in the user's units.
std::vector<std::string> plausibility_warnings(const cw_params& p, const Units& u);

// Library defaults (cw_params_init, cw_grid_init).
cw_params library_default_params();
cw_grid library_default_grid();

const char* grid_kind_name(int kind);    // "strips" | "uniform"
const char* model_name(int model);       // "fastsim" | "exact" | "calibrated"
const char* pressure_name(int pressure); // "parabolic" | "elliptic"

} // namespace cwcli
