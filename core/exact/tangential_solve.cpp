#include "exact/tangential_solve.hpp"

#include <cmath>

#include "contact/error.hpp"

namespace creepwork {
namespace {

// Normalised creepages beyond this slide everywhere; they are scaled down
// together (as FASTSIM does, march/march_setup.hpp) so nothing can overflow.
constexpr double kMaxNormalisedCreepage = 1e100;

} // namespace

void limit_rigid_slip(double& xi, double& eta, double& phi, double reach, double& slip_scale)
{
    const double largest = std::max({std::fabs(xi), std::fabs(eta), std::fabs(phi) * reach});
    if (!std::isfinite(largest))
        throw Error(ErrorKind::invalid_input,
                    "xi_x, xi_y or phi is so large that the rigid slip overflows");
    if (largest > kMaxNormalisedCreepage) {
        const double f = kMaxNormalisedCreepage / largest;
        xi *= f;
        eta *= f;
        phi *= f;
        slip_scale /= f;
    }
}

} // namespace creepwork
