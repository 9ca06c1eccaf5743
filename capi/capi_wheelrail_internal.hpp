// The wheel/rail handle's state, shared by capi_wheelrail.cpp (profiles,
// geometry, solve) and capi_wheelrail_patch.cpp (fields, solver views, wear).
#pragma once

#include <map>
#include <memory>
#include <string>

#include "capi_internal.hpp"
#include "wheelrail/patch_contact.hpp"
#include "wheelrail/placement_checks.hpp"

namespace wr = creepwork::wheelrail;

struct cw_wheelrail {
    explicit cw_wheelrail(wr::WheelRailContact c) : contact(std::move(c)) {}
    wr::WheelRailContact contact;
    bool solved = false;
    // What cw_wheelrail_check reads besides the geometry: the parameters and
    // the last solve's motion, load and height.
    wr::WheelRailInputs inputs;
    // Views of the patch solvers handed out by cw_wheelrail_patch_solver,
    // one per solver (the solvers live as long as the handle); made on
    // first request, also through a const handle.
    mutable std::map<const cw::Solver*, std::unique_ptr<cw_solver>> views;
    mutable std::string last_error;
};

namespace creepwork::capi {

// Patch k of the last solve, checked (CW_ERR_NO_SOLUTION, CW_ERR_INVALID_INPUT).
const wr::PatchSolution& solved_patch(const cw_wheelrail& w, size_t k);

} // namespace creepwork::capi
