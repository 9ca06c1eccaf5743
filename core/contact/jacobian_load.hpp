// The load errors every model's Jacobian raises, one text for every model and
// every door: at zero load the forces grow as mu N from N = 0, so they have
// a derivative in N from above only.
#pragma once

#include <string>

#include "contact/error.hpp"
#include "contact/jacobian.hpp"
#include "contact/number_text.hpp"
#include "contact/params.hpp"

namespace creepwork {

inline Error zero_load_jacobian_error()
{
    return Error(ErrorKind::invalid_input,
                 "normal_force = 0: the forces are not differentiable in N there (they "
                 "grow as mu N from N = 0); the Jacobian needs normal_force > 0");
}

// A gap grid's approach that leaves no element in contact.
inline Error unloaded_approach_jacobian_error(double approach)
{
    return Error(ErrorKind::invalid_input,
                 "approach = " + number_text(approach) +
                     " m gives no contact: the forces are not differentiable in N there; "
                     "the Jacobian needs a loaded contact");
}

// The start of a gap grid's Jacobian, after its solve: true with J zeroed
// when mu = 0 (no traction whatever the inputs); the errors above for a
// zero prescribed force or an approach that leaves no element in contact.
inline bool gap_jacobian_is_zero(const ContactInput& in, int n_contact, Jacobian& J)
{
    if (in.mu == 0.0) {
        J = Jacobian{};
        return true;
    }
    if (in.normal_load == NormalLoad::force && in.normal_force == 0.0)
        throw zero_load_jacobian_error();
    if (!(n_contact > 0)) throw unloaded_approach_jacobian_error(in.approach);
    return false;
}

} // namespace creepwork
