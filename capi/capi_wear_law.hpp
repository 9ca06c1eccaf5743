// The wear law of a caller's cw_wear_params (defaults for a short struct,
// every value checked), shared by the wear handle and transient rolling.
#pragma once

#include <creepwork/creepwork.h>

#include "wear/wear_law.hpp"

// Throws the C API's failure (capi_internal.hpp) naming a bad parameter.
creepwork::wear::WearLaw to_wear_law(const cw_wear_params* caller);
