// The wear law of a caller's cw_wear_params (defaults for a short struct,
// every value checked), shared by the wear handle and transient rolling.
#pragma once

#include <creepwork/creepwork.h>

#include "wear/wear_law.hpp"

// Throws the C API's failure (capi_internal.hpp) naming a bad parameter.
// solve_V: the V of the solve the wear follows (cw_params.V), Archard's
// rolling speed when its own is 0; negative: none (its own is needed).
creepwork::wear::WearLaw to_wear_law(const cw_wear_params* caller, double solve_V);
