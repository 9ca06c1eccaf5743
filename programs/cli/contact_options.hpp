// The options that describe one contact (geometry, load, material or
// flexibilities, creepages, grid) and their translation into the C ABI's
// cw_params / cw_grid in SI, through the rules every door shares
// (contact_inputs.hpp). Validation happens here, in the user's units and
// with the option's name, before anything is solved or written; the
// library's own checks remain the backstop.
#pragma once

#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "contact_inputs.hpp"
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
// --spin-offset --flexibility-blending --exact-load
std::vector<OptionSpec> material_and_load_options();
// A friction law of the slip speed: --friction-law and its terms, --polach
// MU0,A,B, --friction-speed, Spiryagin's --k0 --alpha-inf --beta, the memory.
std::vector<OptionSpec> friction_options();
// --xi-x --xi-y --spin
std::vector<OptionSpec> creepage_options();
// --grid --nx --ny --box-scale
std::vector<OptionSpec> grid_options();
// --model fastsim|exact|calibrated --tolerance --max-iterations
std::vector<OptionSpec> model_options();

// The contact's inputs as a command line gives them: "--a" in messages,
// values in --units.
class OptionSource : public ContactSource {
public:
    explicit OptionSource(const ParsedOptions& opts);
    std::string name(Input in) const override;
    std::string label(Input in) const override { return name(in); }
    const Units& units() const override { return units_; }
    bool has(Input in) const override;
    double number(Input in) const override;
    int integer(Input in) const override;
    std::string choice(Input in, const std::vector<std::string>& choices) const override;
    bool flag(Input in) const override { return has(in); }

protected:
    void raise(const std::string& names, const std::string& problem, Refusal why) const override;

private:
    const ParsedOptions& opts_;
    Units units_;
};

// What read_contact insists on. solve has no sensible default for the size
// and load of a contact, so it requires --a, --b and --N; sweep and fit-fig6
// default to the paper's contact (their --help says which).
// gap: solve --gap, where a gap file replaces the semi-axes and the grid
// (gap_input.hpp): the model defaults to exact, the grid options are not read.
enum class SizeAndLoad { required, defaulted, gap };

// Reads the options present in opts over the given defaults (SI structs) and
// validates the result (read_contact_inputs: the rules of every door).
// Throws CliError(kExitUsage) naming the option. Inputs that are valid but
// implausible for a wheel-rail contact (plausibility_warnings) get a
// warning each in notes; with SizeAndLoad::required, the library defaults
// taken for mu, G and nu are named in a note.
ContactSetup read_contact(const ParsedOptions& opts, const cw_params& default_params,
                          const cw_grid& default_grid,
                          SizeAndLoad size_and_load = SizeAndLoad::defaulted);

} // namespace cwcli
