// The inputs that describe one contact, read the same way from a command
// line (creepwork solve, sweep, compare, wear's defaults) and from a row of
// a CSV file (creepwork campaign, creepwork wear): one list of inputs with
// their option and column names, one set of rules (what the exact model
// takes, which inputs go together, the defaults), one set of range checks,
// one set of plausibility warnings. A ContactSource says where the values
// come from and how a message names them ("--a" on a command line, "a" in a
// file). doc/input-schema.md describes the inputs for users.
#pragma once

#include <exception>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "units.hpp"

namespace cwcli {

// Every input of the row schema (doc/input-schema.md), the contact's first.
enum class Input {
    a, b, N, mu, G, nu, L1, L2, L3, xi_x, xi_y, phi,
    model, grid, nx, ny, box_scale, pressure, rolling_direction, spin_offset,
    flexibility_blending, exact_load, tolerance, max_iterations,
    // Not part of a contact: the row's name (campaign) and the wear columns.
    id, s0, distance, body, contact_angle, passes, speed,
    // A campaign row's contact of any shape (the gap file's grid, solve --gap).
    gap_file, approach, normal_method,
    // The rolling speed [m/s] (a friction law of the slip speed needs it).
    V,
    // A friction law of the slip speed (doc/theory/friction.md): CONTACT's
    // terms (speeds in m/s in every unit system), Polach's A and B [s/m]
    // with mu as mu0, where FASTSIM takes the slip speed, Spiryagin's slope
    // reduction, friction memory.
    friction_law, mu_e1, s_h1, mu_e2, s_h2, polach_A, polach_B, friction_speed, k0, alpha_inf,
    beta, memory_distance, memory_s0,
    // The interface layer (doc/theory/interface-layer.md): thickness, shear
    // modulus, yield stress and its slope (Pa/m in every unit system).
    layer_h, layer_G, tau_c0, k_tau
};

struct InputInfo {
    Input input;
    const char* option; // command-line option without "--" ("" when none)
    const char* column; // CSV column
    Quantity quantity;  // dimensionless also for choices and integers
};

// All inputs, in the order of Input.
const std::vector<InputInfo>& all_inputs();
const InputInfo& info(Input in);

// How messages name inputs and show their values.
class InputNames {
public:
    virtual ~InputNames() = default;
    // "--a" (command line) or "a" (a file's column), for errors.
    virtual std::string name(Input in) const = 0;
    // "--a" or "column a", to start a warning.
    virtual std::string label(Input in) const = 0;
    // The units the values are given in (files: SI).
    virtual const Units& units() const = 0;
};

// Where the values come from. has/number/... are asked only about inputs
// the source can hold; a value that cannot be read is the source's own
// failure (naming the input).
class ContactSource : public InputNames {
public:
    // Why a value or a combination is refused: the status a campaign row
    // gets (kept with the message; the command line's status is always 2).
    enum class Refusal { unreadable, invalid_input, grid_out_of_range };

    virtual bool has(Input in) const = 0;
    virtual double number(Input in) const = 0; // in units()
    virtual int integer(Input in) const = 0;
    // One of choices (their spelling), not case sensitive.
    virtual std::string choice(Input in, const std::vector<std::string>& choices) const = 0;
    // An on/off input: a command-line flag, or a column holding 0 or 1.
    virtual bool flag(Input in) const = 0;
    // Refuses the input: names "--a", or "--a/--b" for a pair.
    [[noreturn]] void fail(const std::string& names, const std::string& problem,
                           Refusal why) const
    {
        raise(names, problem, why);
        std::terminate(); // raise always throws
    }

protected:
    // Throws the source's error (the command line's CliError, a row's RowError).
    virtual void raise(const std::string& names, const std::string& problem,
                       Refusal why) const = 0;
};

struct ContactInputs {
    cw_params params; // SI
    cw_grid grid;
};

// Reads the inputs the source has over the defaults (SI) and checks them:
// with model exact the grid defaults to the library's
// (cw_grid_init_model: CONTACT's layout, the uniform grid over 1.2 times
// the semi-axes with 1.2 times the default grid's element count; solve:
// 24 x 24), and the
// inputs the exact model cannot use (strips, L1..L3, pressure,
// flexibility_blending) are refused; tolerance and max_iterations need the
// exact model; L1, L2, L3 go together and replace G and nu; every value in
// its range (a, b > 0 with a/b in [1e-3, 1e3], N >= 0, nu in [0, 0.5], nx
// in 1..1000, ...). A refusal goes through source.fail naming the input.
ContactInputs read_contact_inputs(const ContactSource& source, const cw_params& defaults,
                                  const cw_grid& default_grid);

// The library's plausibility checks of one contact on grid (cw_params_check:
// semi-axes above 0.1 m, N below 1000 N, G below 1e6 Pa, creepage above
// 0.5, a gap grid's spacing and heights that look like millimetres, ...),
// one warning each: "<label> = <value in names' units> is implausible for a
// wheel-rail contact: <why, with the likely mistake>"; a gap's spacing and
// heights are named after the gap file at gap_path. The one check behind
// every door: solve, sweep, compare, wear and campaign rows.
std::vector<std::string> plausibility_warnings(const cw_grid& grid, const cw_params& p,
                                               const InputNames& names,
                                               const std::string& gap_path = "");

// cw_params_check of count contacts on grid: every rule broken, once.
std::vector<cw_check> library_checks(const cw_grid& grid, const cw_params* params, size_t count);

// The same for a wear row's placement: s0 [m], contact angle [rad] and
// passes.
std::vector<std::string> wear_row_warnings(double s0, double contact_angle, double passes,
                                           const InputNames& names);

// The same for the wear options of creepwork wear and creepwork campaign
// --wear: --speed, --density, --hardness (when set, else 0 in p) and
// --wheel-radius (0: not given).
std::vector<std::string> wear_option_warnings(const cw_wear_params& p, double wheel_radius);

// "7.2 m", "0.6": an SI value in the names' units, as the user wrote it
// (round_trip_text), with its unit unless dimensionless.
std::string value_text(const InputNames& names, Input in, double value_si);

// Library defaults (cw_params_init, cw_grid_init).
cw_params library_default_params();
cw_grid library_default_grid();
cw_grid model_default_grid(int model); // cw_grid_init_model

// The exact model's tolerance and bound on Newton steps as solved: the
// library's defaults where params give 0.
double effective_tolerance(const cw_params& p);
int effective_max_iterations(const cw_params& p);

const char* grid_kind_name(int kind);    // "kalker_strips" | "uniform"
const char* model_name(int model);       // "fastsim" | "exact" | "calibrated"
const char* pressure_name(int pressure); // "parabolic" | "elliptic"

} // namespace cwcli
