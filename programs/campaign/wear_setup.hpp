// What a wear campaign (--wear) needs on every rank: the wear law
// and its parameters, the wheel radius, the orientation of the profile
// coordinate and the profile grid the rows' wear is accumulated on. Every
// rank reads the same options; only rank 0 reads the input, so it makes the
// grid (from the options, else from the rows, as `creepwork wear` does) and
// sends it to the others.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "campaign_types.hpp"

namespace cwcampaign {

struct WearSetup {
    cw_wear_params params; // law, source, density, hardness, --speed (0: none)
    double wheel_radius = 0.0; // --wheel-radius [m]; 0: not given
    int orientation = 1;       // --orientation: +1, s grows with the contact's y
    int default_body = kRail;  // --body: rows without a body cell
    // --profile-from/-to/-step; NaN: from the rows.
    double profile_from = std::numeric_limits<double>::quiet_NaN();
    double profile_to = std::numeric_limits<double>::quiet_NaN();
    double profile_step = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> nodes; // the profile grid (the same on every rank)
};

// The wear parameters of one row: the options', with the row's rolling
// speed, and a wheel's mass per pass per revolution (2 pi R) when R is given.
cw_wear_params row_wear_params(const WearSetup& setup, const RowWear& row);

// The grid: --profile-from/-to/-step, each defaulting as `creepwork wear`'s
// do, from the readable rows: every patch (s0 -+ b x box scale) with a
// margin of 20 %, spacing a quarter of the narrowest strip (at most 20000
// nodes). Throws cwcli::CliError (usage) naming the option.
std::vector<double> profile_nodes(const WearSetup& setup, const std::vector<ContactCase>& rows);

// The grid as bytes for mpi::broadcast_string, and back.
std::string nodes_to_bytes(const std::vector<double>& nodes);
std::vector<double> nodes_from_bytes(const std::string& bytes);

// A hash of everything that shapes the wear results, mixed into the
// checkpoint's identity: resuming with other wear options is refused.
uint64_t wear_identity(const WearSetup& setup, uint64_t seed);

} // namespace cwcampaign
