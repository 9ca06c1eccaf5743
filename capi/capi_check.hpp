// What the plausibility checks of the contact (capi_check.cpp) and of the
// wheel/rail handle (capi_wheelrail_check.cpp) share: a finding as a
// cw_check, and the caller's array of them filled as cw_solver_get_patches
// fills its patches.
#pragma once

#include <string>
#include <vector>

#include "capi_internal.hpp"
#include "contact/plausibility.hpp"

namespace creepwork::capi {

// One finding of contacts contacts, the first at index first; where is
// said after the value in the message (e.g. " (2 of 10 contacts)").
void fill_check(const cw::Implausible& w, size_t contacts, size_t first, const std::string& where,
                cw_check& out);

// *found = checks.size(); with len > 0, checks into out (len structs of
// out[0].struct_size): CW_ERR_STRUCT_SIZE, CW_ERR_BUFFER_TOO_SMALL.
void write_checks(const std::vector<cw_check>& checks, cw_check* out, size_t len, size_t* found);

} // namespace creepwork::capi
