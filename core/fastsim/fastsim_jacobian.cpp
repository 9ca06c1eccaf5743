#include "fastsim/fastsim_jacobian.hpp"

#include "contact/flexibility_blending.hpp"
#include "contact/jacobian_load.hpp"

namespace creepwork {

Jacobian fastsim_jacobian(const ContactInput& in, const ModelSetup& s, const ContactGrid& grid,
                          const MarchState& march, const TangentState& tangents)
{
    Jacobian J;
    if (in.mu == 0.0) return J; // no traction whatever the inputs: all derivatives 0
    if (in.normal_force == 0.0)
        throw zero_load_jacobian_error();

    // Forces over the traction scale T in the rolling frame, Phi = F / T, and
    // their derivatives by the march parameters k = ux, uy, kappa.
    const double a = s.a, b = s.b, T = s.traction_scale;
    static_assert(kTangents == kStripTangents, "scaled_forces sums three tangents");
    double Phi[3], dPhi[3][kStripTangents];
    StripTangents sums;
    sums.sum_px = tangents.sum_px.data();
    sums.sum_py = tangents.sum_py.data();
    sums.sum_x_py = tangents.sum_x_py.data();
    sums.stride = tangents.stride;
    scaled_forces(grid, a, b, march, sums, Phi, dPhi);

    // dT/dc: only N moves T = mu p0, p0 proportional to N.
    const double dT[4] = {0.0, 0.0, 0.0, in.mu * s.pressure_per_force};

    // dL_i/dc: only blending moves the flexibilities.
    double dL[3][4] = {};
    if (in.flexibility_blending) {
        Flexibilities L0{in.L1, in.L2, in.L3};
        if (in.flexibility == FlexibilitySource::kalker_from_material)
            L0 = kalker_flexibilities(a, b, in.G, s.C);
        blend_flexibilities_derivatives(L0, a, b, in.mu, in.normal_force, in.xi_x, in.xi_y,
                                        in.phi, dL);
    }

    // March parameters kin_k = n_k / divisor, n = a (xi/L1, eta/L2, phi/L3)
    // in the rolling frame (xi = d xi_x, phi = d phi_caller).
    const double d = s.direction;
    const double L[3] = {s.L1, s.L2, s.L3};
    const double n[3] = {a * s.xi / L[0], a * s.eta / L[1], a * s.phi / L[2]};
    const double dn_own[3] = {a * d / L[0], a / L[1], a * d / L[2]}; // by xi_x, xi_y, phi
    const double divisor = s.kin_divisor;
    const bool divisor_is_T = divisor == T;
    double dkin[kTangents][4];
    for (int k = 0; k < kTangents; ++k)
        for (int c = 0; c < 4; ++c) {
            double dn = (c == k ? dn_own[k] : 0.0) - n[k] * dL[k][c] / L[k];
            if (divisor_is_T) dn -= (n[k] / T) * dT[c];
            dkin[k][c] = dn / divisor;
        }

    // Rolling-frame forces f_i = T Phi_i; the caller's Fx = d fx, Fy = fy,
    // Mz = d mz.
    const double frame[3] = {d, 1.0, d};
    for (int i = 0; i < 3; ++i)
        for (int c = 0; c < 4; ++c) {
            double chain = 0.0;
            for (int k = 0; k < kTangents; ++k) chain += dPhi[i][k] * dkin[k][c];
            J.d[i][c] = frame[i] * (dT[c] * Phi[i] + T * chain);
        }
    return J;
}

} // namespace creepwork
