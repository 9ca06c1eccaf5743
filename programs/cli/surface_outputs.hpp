// The surface post-processors of one solved contact on the command line:
// the flash temperature of both bodies (--temperature, body 1 the rail,
// body 2 the wheel) and the damage indices (--k-yield), through the C ABI's
// cw_temperature and cw_damage handles; their JSON keys and text lines.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "contact_solver.hpp"
#include "json.hpp"
#include "options.hpp"

namespace cwcli {

// --temperature, --T0-1, --T0-2, --heat-capacity-1/-2, --conductivity-1/-2,
// --density-1/-2, --temperature-discretisation, --mu-T, --speed, --k-yield.
std::vector<OptionSpec> surface_options();

// The temperature's part of them, without --speed (creepwork wheelrail: each
// patch rolls at its own speed).
std::vector<OptionSpec> temperature_options();

// The bodies and the discretisation of those options; rolling speed and
// direction 0 (the solve's). Throws CliError(kExitUsage) for a temperature
// option without --temperature.
cw_temperature_params read_temperature_params(const ParsedOptions& opts);

struct SurfaceRequest {
    bool temperature = false, damage = false;
    cw_temperature_params temperature_params{};
    cw_damage_params damage_params{};
    // --mu-T "T1:mu1,T2:mu2,...": friction mu(T) [deg C, -] (empty: none).
    std::vector<double> mu_T_temperature, mu_T_mu;
    bool mu_T() const { return !mu_T_temperature.empty(); }
    // "warning: ..." for values valid but implausible for steel wheels and
    // rails (W/(mm K) typed as W/(m K), km/h as m/s, MPa as Pa).
    std::vector<std::string> warnings;
};

// The options of the request that do not depend on the contact: the
// bodies, the discretisation, --mu-T, --k-yield and their warnings, with
// the temperature's rolling speed `speed` (0: the solve's V) and direction
// 0 (the solve's). Throws CliError(kExitUsage) naming the option: a
// temperature option or --mu-T without --temperature. (creepwork campaign
// reads its rows' speeds and directions itself.)
SurfaceRequest read_surface_options(const ParsedOptions& opts, double speed);

// read_surface_options for one contact. Throws CliError(kExitUsage) naming
// the option, as it does, and for --temperature without a rolling speed
// (--speed or the solve's V), --speed and V that differ, --speed without
// --temperature. V: the solve's cw_params.V (0: not given); without --speed
// the temperature takes it.
SurfaceRequest read_surface_request(const ParsedOptions& opts, int rolling_direction, double V);

struct SurfaceOutput {
    bool temperature = false, damage = false;
    cw_temperature_result temperature_result{};
    cw_damage_result damage_result{};
    std::vector<double> rail, wheel, rcf_index; // per element [i + j*nx]
};

// Computes what was requested on solver's last CW_SOLVE_FULL solve. Throws
// CliError(kExitUsage) with the library's message and the options it names.
SurfaceOutput compute_surface(const cw_solver* solver, const SurfaceRequest& request);

// Solves params in full mode into s and computes the request on that
// solve: with friction mu(T) (request.mu_T()) through cw_temperature_solve,
// the solve and its temperatures in one loop. Throws as compute_surface,
// and as ContactSolver::solve_full.
SurfaceOutput solve_with_surface(ContactSolver& solver, const cw_params& params,
                                 const SurfaceRequest& request, Solution& s);

// T_max_x, T_max_y [m]: the hotter body's hottest contact element (the
// rail's on a tie).
void hottest_point(const cw_temperature_result& t, double& x, double& y);

// T_max_1, T_max_2 [deg C], T_max_x, T_max_y [m] (the hotter body's hottest
// contact element), temperature_iterations; rcf_index_max, FI_surf,
// T_gamma [N], wlrm_damage. SI whatever --units.
void add_surface_json(JsonObject& json, const SurfaceOutput& o);
void print_surface_text(std::ostream& out, const SurfaceOutput& o);

} // namespace cwcli
