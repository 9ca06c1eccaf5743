#include "friction/friction_input.hpp"

namespace creepwork {

static_assert(static_cast<int>(FrictionLaw::linear) == static_cast<int>(SlipSpeedLawKind::linear) &&
                  static_cast<int>(FrictionLaw::rational) ==
                      static_cast<int>(SlipSpeedLawKind::rational) &&
                  static_cast<int>(FrictionLaw::exponential) ==
                      static_cast<int>(SlipSpeedLawKind::exponential),
              "the input's law and the friction layer's share CONTACT's numbering");

SlipSpeedLaw slip_speed_law(const ContactInput& in)
{
    SlipSpeedLaw law = coulomb_law(in.mu);
    if (in.friction_law == FrictionLaw::coulomb) return law;
    law.kind = static_cast<SlipSpeedLawKind>(static_cast<int>(in.friction_law));
    law.mu_e1 = in.mu_e1;
    law.s_h1 = in.s_h1;
    law.mu_e2 = in.mu_e2;
    law.s_h2 = in.s_h2;
    return law;
}

SlopeReduction slope_reduction(const ContactInput& in)
{
    return SlopeReduction{in.k0, in.alpha_inf, in.beta};
}

FrictionMemory friction_memory(const ContactInput& in)
{
    return FrictionMemory{in.memory_distance, in.memory_s0};
}

} // namespace creepwork
