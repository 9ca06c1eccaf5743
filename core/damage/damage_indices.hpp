// Surface damage indices of one solved contact: a pure function of the
// per-element fields every model exports and the contact's totals.
//
// Per element [i + j*nx]:
//  - RCF index, CONTACT's definition (its user guide, cntc_getrcfindex):
//        -0.5 outside the contact; max(-0.5, (|p_t| - k)/p_n) in it,
//    k the surface shear yield stress. Positive where the traction exceeds
//    the shear strength: surface-initiated fatigue (ratchetting) is likely;
//    -0.5 marks no risk (and elements of small pressure).
//  - T_gamma density: the element's frictional work per rolled distance
//    per area, W_e / A_e [Pa = J/m per m^2], from the energy-consistent
//    map: the sum of density x area is W_macro.
// Per contact:
//  - FI_surf = mu_eff - 2 A k / (3 F_z), mu_eff = |F_t| / F_z (Ekberg,
//    Kabo & Andersson, Fatigue Fract. Engng Mater. Struct. 25 (2002)
//    899-909), A the contact area: pi a b for an ellipse, where it is
//    mu_eff - k/p0 with the Hertzian peak pressure p0 = 3 F_z/(2 pi a b);
//    on a gap grid the area of the contact elements. > 0: beyond the
//    surface shakedown limit.
//  - T_gamma = W_macro [N] and the WLRM damage per pass from it (wlrm.hpp).
#pragma once

#include "damage/wlrm.hpp"

namespace creepwork::damage {

constexpr double kRcfNoRisk = -0.5; // CONTACT's floor and exterior value

struct DamageParams {
    double k_yield = 0.0; // surface shear yield stress k [Pa], > 0
    WlrmFunction wlrm;
};

// Throws Error(invalid_input) naming the parameter.
void validate(const DamageParams& p);

// The element's RCF index (contact: state >= 1).
double rcf_index(double px, double py, double pz, bool contact, double k_yield);

struct DamageInput {
    int nx = 0, ny = 0;
    const double* area = nullptr; // [m^2]
    const double* pz = nullptr;   // [Pa]
    const double* px = nullptr;   // [Pa]
    const double* py = nullptr;   // [Pa]
    const int* state = nullptr;   // 0 exterior, 1 adhesion, 2 slip
    const double* work = nullptr; // energy-consistent work per element [J/m]
    double Fx = 0, Fy = 0;        // tangential force [N]
    double normal_force = 0;      // F_z [N]
    double W_macro = 0;           // [J/m = N]
    double contact_area = 0;      // A [m^2] for FI_surf
};

// Outputs per element; each may be null.
struct DamageFields {
    double* rcf_index = nullptr;
    double* t_gamma_density = nullptr; // [Pa]
};

struct DamageTotals {
    double rcf_index_max = kRcfNoRisk; // over every element
    long rcf_element = -1;             // where (first in storage order); -1 without contact
    double mu_eff = 0;                 // |F_t| / F_z (0 without load)
    double FI_surf = 0;                // 0 without load
    double T_gamma = 0;                // W_macro [N]
    double wlrm_damage = 0;            // per pass [-]
};

DamageTotals damage_indices(const DamageInput& in, const DamageParams& p,
                            const DamageFields& out);

} // namespace creepwork::damage
