#include "calibrated/calibration_table.hpp"

#include <algorithm>
#include <cmath>

#include "contact/kalker_coefficients.hpp"

namespace creepwork {

NormalisedCreepage normalised_creepage(const ContactInput& in)
{
    NormalisedCreepage s;
    const double muN = in.mu * in.normal_force;
    if (!(muN > 0.0)) return s;
    const CreepCoefficients C = kalker_coefficients(in.a / in.b, in.nu);
    const double c2 = in.a * in.b, c = std::sqrt(c2);
    // Divided step by step: extreme but valid inputs must not overflow.
    s.s_long = in.xi_x * (in.G / muN) * c2 * C.C11;
    s.s_lat = in.xi_y * (in.G / muN) * c2 * C.C22;
    s.s_spin = in.phi * (in.G / muN) * c2 * c * C.C23;
    return s;
}

CalibrationParams calibration_params(const CalibrationNode& n, const NormalisedCreepage& s)
{
    const double size = std::hypot(std::hypot(s.s_long, s.s_lat), s.s_spin);
    // s/(1+s), 1 for huge or non-finite s (sliding: the factors' full effect).
    const double g = std::isfinite(size) ? size / (1.0 + size) : 1.0;
    CalibrationParams p;
    p.pressure = PressureKind::parabolic;
    p.k_long = 1.0 + n.alpha_long * g;
    p.k_lat = 1.0 + n.alpha_lat * g;
    p.k_spin_x = 1.0 + n.alpha_spin_x * g;
    p.k_spin_y = 1.0 + n.alpha_spin_y * g;
    const double fs = std::isfinite(size) ? n.fade * size : 1e300;
    const double fade = fs < 1e75 ? 1.0 / (1.0 + fs * fs) : 0.0;
    p.lateral_moment = fade * fade;
    // Linear in s, not g(s) = s/(1+s): e g(s) stays below e < 1, so the
    // direction error of unequal flexibilities stayed near full sliding
    // (a/b 0.2, xi_x + xi_y at 276 % of saturation: 7.0 % of mu N in Fx).
    p.equalise = std::isfinite(size) ? std::min(1.0, n.equalise * size) : 1.0;
    p.edge_gain = n.edge * g;
    // s^2/(h^2 + s^2): 1 for huge or non-finite s, 0 at s = 0 (the bound
    // does not matter in the linear limit: no element slips).
    const double s2 = std::isfinite(size) && size < 1e150 ? size * size : 1e300;
    const double h2 = n.blend_half * n.blend_half;
    p.bound_blend = s2 > 0.0 ? n.blend * (s2 / (h2 + s2)) : 0.0;
    return p;
}

CalibrationNode calibration_node(const CalibrationNode* t, double a_over_b)
{
    const int last = kCalibrationNodes - 1;
    if (!(a_over_b > t[0].a_over_b)) return t[0];
    if (!(a_over_b < t[last].a_over_b)) return t[last];
    int k = 0;
    while (a_over_b > t[k + 1].a_over_b) ++k;
    const double w = std::log(a_over_b / t[k].a_over_b) / std::log(t[k + 1].a_over_b / t[k].a_over_b);
    static constexpr double CalibrationNode::*kMembers[] = {
        &CalibrationNode::alpha_long, &CalibrationNode::alpha_lat, &CalibrationNode::alpha_spin_x,
        &CalibrationNode::alpha_spin_y, &CalibrationNode::fade,    &CalibrationNode::equalise,
        &CalibrationNode::edge,       &CalibrationNode::blend,     &CalibrationNode::blend_half};
    CalibrationNode n = t[k];
    n.a_over_b = a_over_b;
    for (auto m : kMembers) n.*m = (1 - w) * (t[k].*m) + w * (t[k + 1].*m);
    return n;
}

CalibrationParams calibration_for(const ContactInput& in)
{
    return calibration_params(calibration_node(in.a / in.b), normalised_creepage(in));
}

} // namespace creepwork
