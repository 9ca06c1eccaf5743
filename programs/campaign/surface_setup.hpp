// What a campaign with --temperature, --mu-T or --k-yield needs on every
// rank: the options of `creepwork solve` for the flash temperature of both
// bodies (body 1 the rail, body 2 the wheel), friction mu(T) and the damage
// indices. Every rank parses the same options to the same setup; a row's
// rolling speed comes from the row (V, or speed with --wear), else --speed.
#pragma once

#include <cstdint>
#include <string>

#include <creepwork/creepwork.h>

#include "../cli/surface_outputs.hpp"
#include "campaign_types.hpp"

namespace cwcampaign {

// The request of `creepwork solve` (its bodies, discretisation, mu(T) and
// damage), with the rolling speed of rows without V.
struct SurfaceSetup : cwcli::SurfaceRequest {
    double speed = 0.0; // --speed [m/s]: rows without V; 0: not given
    bool any() const { return temperature || damage; }
};

// The temperature parameters of one row: the setup's, with the rolling
// speed 0 (the solve's V) when the row has V, else the row's speed (--wear)
// or --speed; the direction is the solve's.
cw_temperature_params row_temperature_params(const SurfaceSetup& setup, const ContactCase& row);

// Why a readable row cannot have its temperature ("" when it can): no
// rolling speed at all, or a V that differs from --speed. The message
// names the row's line and column, as the reader's do.
std::string surface_row_problem(const SurfaceSetup& setup, const ContactCase& row, long line);

// A hash of everything that shapes the surface results, mixed into the
// checkpoint's identity: resuming with other options is refused.
uint64_t surface_identity(const SurfaceSetup& setup, uint64_t seed);

} // namespace cwcampaign
