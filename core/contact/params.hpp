// Plain parameter and result types of the core. Units are consistent
// (SI recommended: m, N, Pa, 1/m); see doc/reference/conventions.md.
#pragma once

#include <cstddef>

namespace creepwork {

enum class GridKind {
    kalker_strips, // Kalker 1982: ny equal strips, nx equal elements per chord
    uniform,       // CONTACT: nx*ny box [-S a, S a] x [-S b, S b], centre-in-ellipse
    gap,           // the caller's gap function on nx*ny cells of given origin and spacing
};

enum class PressureKind {
    parabolic, // pz = 2N/(pi a b) (1 - x^2/a^2 - y^2/b^2), simplified theory (paper eq. 16)
    elliptic,  // pz = 3N/(2 pi a b) sqrt(1 - x^2/a^2 - y^2/b^2), Hertz
};

// The models of the contact: how the tangential tractions are found.
enum class ModelKind {
    fastsim = 0,    // Kalker's simplified theory, FASTSIM (fastsim/)
    exact = 1,      // Kalker's exact half-space theory on CONTACT's uniform grid (exact/)
    calibrated = 2, // simplified theory calibrated to the exact one (calibrated/)
    // The solver's own routes, never an input: FASTSIM under a law of the
    // slip speed at every element (fastsim/fastsim_law_model.hpp) and at the
    // contact's global slip speed (fastsim/fastsim_global_slip_model.hpp).
    fastsim_law = 16,
    fastsim_global_slip = 17,
};

// The friction law, in CONTACT's L-digit numbering (friction/slip_speed_law.hpp).
enum class FrictionLaw {
    coulomb = 0,     // mu at every slip speed
    linear = 2,      // mu + sum mu_ek max(0, 1 - s / (2 s_hk))
    rational = 3,    // mu + mu_e1 / (1 + s/s_h1) + mu_e2 / (1 + (s/s_h2)^2)
    exponential = 4, // mu + sum mu_ek exp(-ln2 s / s_hk)
};

// Where FASTSIM takes the slip speed of a law.
enum class FrictionSpeed {
    local = 0,  // each element's own slip speed
    global = 1, // the contact's rigid slip speed V |(xi_x, xi_y)| (CONTACT's FASTSIM), with
                // Spiryagin's slope reduction k0, alpha_inf, beta
};

enum class FlexibilitySource {
    kalker_from_material, // L1, L2, L3 from G, nu and Kalker's C11, C22, C23
    given,                // L1, L2, L3 supplied by the caller
};

// Grid limits, enforced when a solver is created.
constexpr int kMaxGridCells = 1000;    // per direction
constexpr double kMaxBoxScale = 100.0; // uniform grid box scale S in [1, 100]

struct GridSpec {
    GridKind kind = GridKind::kalker_strips;
    int nx = 20;             // elements along x (rolling direction)
    int ny = 20;             // strips across y
    double box_scale = 1.0;  // S, uniform grid only
    // Gap grid only: centre of element (0, 0) and the spacing [m]; element
    // (i, j) is centred at (x0 + i dx, y0 + j dy).
    double x0 = 0.0, y0 = 0.0, dx = 0.0, dy = 0.0;
};

// What the normal problem is given on a gap grid.
enum class NormalLoad {
    force,    // ContactInput::normal_force; the approach is found
    approach, // ContactInput::approach; the normal force is found
};

// How the normal problem is solved on a gap grid.
enum class NormalMethod {
    exact,      // Kalker's half-space problem on the grid (CONTACT's NormCG problem)
    semi_hertz, // per row of the grid a Hertzian semi-ellipse (after Sichani et al. 2014)
};

// a/b range accepted (Kalker's table + asymptotes are used up to here).
constexpr double kMinAspect = 1e-3;
constexpr double kMaxAspect = 1e3;

struct ContactInput {
    double a = 0.0;            // semi-axis along x (rolling direction) [m]
    double b = 0.0;            // semi-axis along y (lateral) [m]
    double normal_force = 0.0; // N >= 0 [N]
    double mu = 0.0;           // friction coefficient >= 0 [-]
    // The rolling speed V >= 0 [m/s]; 0: not given. A law of the slip speed
    // (slip speed = |micro-slip| V) needs it; Coulomb's law does not use it.
    double V = 0.0;
    FlexibilitySource flexibility = FlexibilitySource::kalker_from_material;
    double G = 0.0;            // combined shear modulus [Pa] (kalker_from_material)
    double nu = 0.0;           // combined Poisson ratio, 0..0.5 (kalker_from_material)
    double L1 = 0.0, L2 = 0.0, L3 = 0.0; // flexibilities [m/Pa] (given)
    double xi_x = 0.0;         // longitudinal creepage [-]
    double xi_y = 0.0;         // lateral creepage [-]
    double phi = 0.0;          // spin creepage [1/m]
    PressureKind pressure = PressureKind::parabolic;
    int rolling_direction = 1; // +1: leading edge at x = +a; -1: at x = -a
    ModelKind model = ModelKind::fastsim;
    // Iterative models (exact): relative tolerance and iteration bound (0:
    // the model's default), and whether to start from the last solution.
    double tolerance = 0.0;
    int max_iterations = 0;
    bool warm_start = true;
    // The exact normal problem on a gap grid (gap_normal.hpp): its relative
    // tolerance, 0 for its own (1e-10). Set by the wheel/rail force
    // balance's trial heights only; the C ABI leaves it 0.
    double normal_tolerance = 0.0;
    // CONTACT's facphi: the spin centre of the rigid slip shifted by
    // spin_offset * dx along x (uniform grid). Negative: the model's default
    // (0 for FASTSIM as Kalker 1982, 1/6 for exact as CONTACT).
    double spin_offset = -1.0;
    // FASTSIM: CONTACT's blending of L1, L2, L3 for combined creepages.
    bool flexibility_blending = false;
    // FASTSIM, calibrated: the pressure scale set so that the discrete load
    // sum pz dA equals normal_force exactly (false: the analytic scale of the
    // pressure law, which the grid integrates to within a few tenths of a per
    // cent). The exact model's discrete normal problem carries N exactly
    // either way.
    bool exact_load = false;
    // Gap grid only: the undeformed distance per element [i + nx j] [m]
    // (positive = separation), gap_len >= nx ny values, and the normal load.
    const double* gap = nullptr;
    std::size_t gap_len = 0;
    NormalLoad normal_load = NormalLoad::force;
    double approach = 0.0;     // [m] from the gap's datum h = 0, when prescribed
    NormalMethod normal_method = NormalMethod::exact;
    // The friction law of the slip speed s = |micro-slip| V. mu is its
    // kinetic coefficient mu_kin (the value at large s); the static one is
    // mu + mu_e1 + mu_e2. A term with mu_ek = 0 is absent.
    FrictionLaw friction_law = FrictionLaw::coulomb;
    double mu_e1 = 0.0, s_h1 = 0.0; // [-] >= 0, [m/s] > 0 when mu_e1 > 0
    double mu_e2 = 0.0, s_h2 = 0.0; // [-] >= 0, [m/s] > 0 when mu_e2 > 0
    FrictionSpeed friction_speed = FrictionSpeed::local;
    // Spiryagin's slope reduction (friction_speed global): k0 > 0, alpha_inf
    // in [0, 1], beta >= 0; k0 = alpha_inf = 1 is none.
    double k0 = 1.0, alpha_inf = 1.0, beta = 0.0;
    // Friction memory (friction_speed local): the distance d_c [m] >= 0 (0:
    // none) and the background slip speed s0 [m/s] >= 0.
    double memory_distance = 0.0, memory_s0 = 0.0;
    // The interface (third-body) layer, CONTACT's M = 4: an elastic shear
    // compliance layer_h / layer_G [m/Pa] in series with the bodies (h >= 0
    // [m], G3 > 0 [Pa] when h > 0) and the yield stress tau_c = tau_c0 +
    // k_tau u_pl (tau_c0 >= 0 [Pa], 0: no yield; k_tau [Pa/m], > 0 hardens,
    // < 0 softens, u_pl the plastic displacement accumulated along a row).
    // All 0: none.
    // The exact models take it (exact/exact_model.hpp, gap/gap_exact_model.hpp).
    double layer_h = 0.0, layer_G = 0.0, tau_c0 = 0.0, k_tau = 0.0;
};

// Whether the input asks for an interface layer (elastic or yielding).
inline bool has_interface_layer(const ContactInput& in)
{
    return in.layer_h != 0.0 || in.tau_c0 != 0.0 || in.k_tau != 0.0;
}

// Whether the input asks for more than Coulomb's law at every element (a
// law of the slip speed, the global slip speed, friction memory).
inline bool beyond_coulomb(const ContactInput& in)
{
    return in.friction_law != FrictionLaw::coulomb || in.friction_speed != FrictionSpeed::local;
}

// Flags in SolveTotals::work_flags.
constexpr int kWorkUnresolved = 1;   // no slip element: released energy put on trailing elements
constexpr int kWorkNonPositive = 2;  // map cannot add up to W_macro: consistent map set to zero

struct SolveTotals {
    double Fx = 0, Fy = 0, Mz = 0;        // on the wheel (body 1) [N, N, N m]
    double W_macro = 0;                   // -(Fx xi_x + Fy xi_y + Mz phi) [J/m]
    double W_micro_paper = 0;             // sum of the paper's local work [J/m]
    double K = 0;                         // W_macro / W_micro_paper (0 if undefined)
    double W_consistent = 0;              // sum of the energy-consistent map [J/m]
    double balance_factor = 1;            // W_macro / model energy terms (work.hpp); 1 on the
                                          // uniform grid without spin or with L1=L2=L3
    double adhesion_fraction = 0;         // n_adhesion / n_contact
    int n_contact = 0, n_adhesion = 0, n_slip = 0;
    int work_flags = 0;
    double a = 0, b = 0;
    double L1 = 0, L2 = 0, L3 = 0;
    double C11 = 0, C22 = 0, C23 = 0, C33 = 0; // 0 when the flexibilities were given
    double profile_max_diff = 0;          // lateral work vs equal-area parabola, / peak
    double profile_rms_diff = 0;
    ModelKind model = ModelKind::fastsim;
    double p_max = 0;                     // largest element pressure [Pa]
    double approach = 0;                  // normal approach [m] (exact: of the grid solution)
    int iterations = 0;                   // iterative models: iterations of the last solve
    int n_patches = 0;                    // separate contact patches (4-connected elements)
    double residual = 0;                  // iterative models: final relative residual
    double normal_force = 0;              // total normal force [N] (gap grid: found
                                          // when the approach is prescribed)
    // (n_patches fills the gap after iterations: tests compare the bytes.)
    // The friction coefficient: at rest (mu + mu_e1 + mu_e2; Coulomb's mu),
    // and the smallest and largest over the slipping elements (the static
    // one when none slips; the contact's mu(w) at its global slip speed).
    double mu_static = 0, mu_min = 0, mu_max = 0;
};

// What one separate patch of a contact carries (normal/patches.hpp finds
// them on a gap grid), in the caller's frame (SI).
struct PatchTotals {
    int n_contact = 0, n_adhesion = 0, n_slip = 0; // elements
    double x_centroid = 0, y_centroid = 0;         // of the elements' area [m]
    double Fx = 0, Fy = 0;                         // on the wheel [N]
    double Mz = 0;                                 // about the grid's origin [N m]
    double Fn = 0;                                 // normal force [N]
    double p_max = 0;                              // [Pa]
    double W_macro = 0;                            // -(Fx xi_x + Fy xi_y + Mz phi) [J/m]
};

} // namespace creepwork
