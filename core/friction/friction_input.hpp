// The friction inputs of a ContactInput (contact/params.hpp: the law's
// kind and terms with mu as mu_kin, the slope reduction, the memory) as the
// friction layer's types. The input is checked already
// (validate_friction_input).
#pragma once

#include "contact/params.hpp"
#include "friction/friction_memory.hpp"
#include "friction/global_slip.hpp"
#include "friction/slip_speed_law.hpp"

namespace creepwork {

SlipSpeedLaw slip_speed_law(const ContactInput& in);
SlopeReduction slope_reduction(const ContactInput& in);
FrictionMemory friction_memory(const ContactInput& in);

} // namespace creepwork
