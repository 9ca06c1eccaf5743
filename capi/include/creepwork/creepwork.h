/*
 * creepwork -- creep forces, creep moment, frictional-work distributions and
 * wear of a wheel rolling on a rail: Kalker's simplified theory (FASTSIM,
 * 1982) extended to the moment and an energy-consistent work map, a
 * simplified theory calibrated to the exact one, Kalker's exact half-space
 * theory, contacts of any shape, and wheel/rail contact from the profiles.
 *
 * This header is the whole public contract of libcreepwork. It is C99 and
 * C++ compatible and includes only <stddef.h> and <stdint.h>.
 *
 * Conventions
 *   Units     Consistent units; SI recommended: m, N, Pa, 1/m (spin), J/m
 *             (work per unit rolling distance). The library never converts.
 *   Frame     x along the rolling direction, y lateral, z into the rail;
 *             the contact ellipse has semi-axis a along x and b along y.
 *             rolling_direction = +1: material enters at x = +a (leading
 *             edge) and leaves at x = -a; -1 mirrors this.
 *   Kinematics Kalker's: rigid slip w = (xi_x - phi*y, xi_y + phi*x).
 *   Forces    Fx, Fy, Mz act on the wheel (body 1), as in Kalker's and
 *             CONTACT's conventions: opposite in sign to the creepages.
 *             The paper (Determination of Creep Force, Moment, and Work
 *             Distribution in Rolling Contact With Slip;
 *             doc/reference/conventions.md) prints the force on the rail.
 *   Work      Positive when dissipated; per unit rolling distance [J/m].
 *             Multiply by V*dt for the work of a time step.
 *   Grids     Element (i, j), i = 0..nx-1 along x (increasing x),
 *             j = 0..ny-1 along y (increasing y), is stored at
 *             [i + j*nx]: column-major with i fastest, so a Fortran array
 *             real(c_double) :: f(nx, ny) maps directly.
 *   Buffers   Caller-owned; each pointer is followed by its length in
 *             elements. Too short is an error: nothing is written.
 *   Errors    Every function that can fail returns an int status (CW_OK =
 *             0); the others return what they name: cw_version_number and
 *             cw_abi_version an int version, cw_version_string,
 *             cw_status_string and the cw_*_last_error functions a string.
 *             Codes are never renumbered, only appended. cw_status_string()
 *             gives a static message; a handle keeps a detailed message
 *             naming the offending input (cw_solver_last_error). On any
 *             error nothing is written to the outputs and the handle stays
 *             usable.
 *   Floating point  No call raises a floating-point exception in the
 *             caller: each runs with exceptions masked and subnormals
 *             flushed to zero, and restores the caller's control and status
 *             word (masks, rounding, flags) on return, so hosts that trap
 *             invalid, zero, overflow or denormal are safe
 *             (doc/reference/guarantees.md).
 *   Threads   Distinct handles may be used concurrently from different
 *             threads; one handle must be used by one thread at a time.
 *             The library has no global mutable state.
 *   Structs   Parameter and result structs start with size_t struct_size,
 *             set by the matching _init function. Fields are only ever
 *             appended; the library reads and writes min(struct_size,
 *             sizeof) bytes, so a program built against an older, smaller
 *             struct keeps working.
 */
#ifndef CREEPWORK_H
#define CREEPWORK_H

#include <stddef.h>
#include <stdint.h>

#include "creepwork/creepwork_export.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- version */

#define CW_VERSION_MAJOR 1
#define CW_VERSION_MINOR 2
#define CW_VERSION_PATCH 0
/* 10000*major + 100*minor + patch */
#define CW_VERSION_NUMBER (CW_VERSION_MAJOR * 10000 + CW_VERSION_MINOR * 100 + CW_VERSION_PATCH)
/* Incremented only when a binary built against an older header could break. */
#define CW_ABI_VERSION 1

/* Run-time versions: compare with CW_VERSION_NUMBER / CW_ABI_VERSION to check
 * that the loaded library is the one the program was built against. */
CW_API int cw_version_number(void);
CW_API int cw_abi_version(void);
CW_API const char* cw_version_string(void); /* The release as text, "1.2.0"; static. */

/* ------------------------------------------------------------ status codes */

/* One list generates the codes (here) and their messages (in the library).
 * X(name, value, message) */
#define CW_STATUS_LIST(X)                                                              \
    X(CW_OK, 0, "success")                                                             \
    X(CW_ERR_NULL_POINTER, 1, "a required pointer argument is NULL")                   \
    X(CW_ERR_INVALID_INPUT, 2, "an input value is invalid (NaN, Inf, out of range)")   \
    X(CW_ERR_GRID_OUT_OF_RANGE, 3, "grid size or box scale outside the limits")        \
    X(CW_ERR_BUFFER_TOO_SMALL, 4, "an output buffer is shorter than required")         \
    X(CW_ERR_NO_SOLUTION, 5, "no successful solve yet on this handle")                 \
    X(CW_ERR_NO_WORK, 6, "field needs a solve with CW_SOLVE_FULL")                     \
    X(CW_ERR_STRUCT_SIZE, 7, "struct_size is too small or not set")                    \
    X(CW_ERR_OUT_OF_MEMORY, 8, "memory allocation failed")                             \
    X(CW_ERR_NUMERIC, 9, "a result is not finite: inputs too extreme")                 \
    X(CW_ERR_UNKNOWN_OPTION, 10, "unknown field, mode or enumeration value")           \
    X(CW_ERR_GRID_MISMATCH, 11, "accumulator and solver grids differ")                 \
    X(CW_ERR_INTERNAL, 12, "internal error (please report)")                           \
    X(CW_ERR_NOT_CONVERGED, 13, "the iterative solver reached its iteration bound")

#define CW_STATUS_ENUMERATOR_(name, value, message) name = value,
enum cw_status { CW_STATUS_LIST(CW_STATUS_ENUMERATOR_) CW_STATUS_END_ };
#undef CW_STATUS_ENUMERATOR_

/* Static, never NULL; "unknown status code" for values not in the list. */
CW_API const char* cw_status_string(int status);

/* ------------------------------------------------------------------ limits */

#define CW_MAX_GRID_CELLS 1000  /* nx, ny in 1..1000 */
#define CW_MAX_BOX_SCALE 100.0  /* uniform grid box scale S in [1, 100] */
#define CW_MAX_BATCH_THREADS 256 /* cw_batch_create */
#define CW_MAX_EXACT_CELLS 256  /* exact model: nx, ny <= 256 (memory grows as nx*ny) */
#define CW_MIN_ASPECT 1e-3      /* a/b in [1e-3, 1e3]: Kalker's table + asymptotes */
#define CW_MAX_ASPECT 1e3
/* What the exact model takes when params->tolerance, max_iterations are 0 */
#define CW_DEFAULT_TOLERANCE 1e-8   /* relative residual of the tangential solve */
#define CW_DEFAULT_MAX_ITERATIONS 50 /* Newton steps per grid */

/* ------------------------------------------------------------ enumerations */

/* cw_grid.kind */
#define CW_GRID_KALKER_STRIPS 0 /* ny equal strips, nx equal elements per chord (Kalker 1982) */
#define CW_GRID_UNIFORM 1       /* nx*ny box [-S a, S a] x [-S b, S b] (CONTACT) */
#define CW_GRID_GAP 2           /* a contact of any shape: nx*ny cells of dx*dy from (x0, y0),
                                   the gap given per solve (cw_params.gap; CW_MODEL_EXACT or
                                   CW_MODEL_FASTSIM) */

/* cw_params.normal_load (gap grid) */
#define CW_NORMAL_FORCE 0    /* normal_force prescribed, the approach found (default) */
#define CW_NORMAL_APPROACH 1 /* approach prescribed, the normal force found */

/* cw_params.normal_method (gap grid) */
#define CW_NORMAL_EXACT 0      /* the half-space normal problem on the grid (default) */
#define CW_NORMAL_SEMI_HERTZ 1 /* per row a Hertzian semi-ellipse (Sichani et al. 2014): fast */

#define CW_MIN_GAP_CELLS 3 /* gap grid: nx, ny in 3..CW_MAX_EXACT_CELLS */

/* cw_params.pressure: normal pressure and traction bound mu*pz */
#define CW_PRESSURE_PARABOLIC 0 /* 2N/(pi a b) (1 - x^2/a^2 - y^2/b^2), paper eq. 16 */
#define CW_PRESSURE_ELLIPTIC 1  /* 3N/(2 pi a b) sqrt(1 - x^2/a^2 - y^2/b^2), Hertz */

/* cw_params.model: how the tangential tractions are found */
#define CW_MODEL_FASTSIM 0    /* Kalker's simplified theory, FASTSIM (default) */
#define CW_MODEL_EXACT 1      /* Kalker's exact half-space theory (CONTACT's method),
                                 on a uniform or gap grid, G, nu needed */
#define CW_MODEL_CALIBRATED 2 /* simplified theory calibrated to the exact theory */

/* cw_params.friction_law: the friction coefficient as a function of the slip
 * speed s = |micro-slip| * V [m/s], in CONTACT's numbering (its L digit).
 * mu is the kinetic coefficient mu_kin (what is left at large s); each term
 * k = 1, 2 falls from mu_ek at s = 0 to mu_ek/2 at s = s_hk; the static
 * coefficient (s = 0) is mu + mu_e1 + mu_e2 (cw_result.mu_static). */
#define CW_FRICTION_COULOMB 0     /* mu at every slip speed (default) */
#define CW_FRICTION_LINEAR 2      /* mu + sum mu_ek max(0, 1 - s/(2 s_hk)) */
#define CW_FRICTION_RATIONAL 3    /* mu + mu_e1/(1 + s/s_h1) + mu_e2/(1 + (s/s_h2)^2) */
#define CW_FRICTION_EXPONENTIAL 4 /* mu + sum mu_ek exp(-ln2 s/s_hk); Polach's law:
                                     cw_friction_polach */

/* cw_params.friction_speed: where FASTSIM takes the slip speed of a law */
#define CW_FRICTION_SPEED_LOCAL 0  /* each element's own slip speed (default) */
#define CW_FRICTION_SPEED_GLOBAL 1 /* the contact's rigid slip speed V |(xi_x, xi_y)|, one mu
                                      for the contact (CONTACT's FASTSIM), with Spiryagin's
                                      slope reduction k0, alpha_inf, beta */

/* cw_params.spin_offset: the model's own default (0 FASTSIM, 1/6 exact) */
#define CW_SPIN_OFFSET_DEFAULT -1.0

/* cw_params.flexibility */
#define CW_FLEX_FROM_MATERIAL 0 /* L1, L2, L3 from G, nu and Kalker's C11, C22, C23 */
#define CW_FLEX_GIVEN 1         /* L1, L2, L3 as given (legacy codes) */

/* cw_solver_solve mode */
#define CW_SOLVE_FORCES 0 /* totals, px, py, pz, mz, state: fastest */
#define CW_SOLVE_FULL 1   /* also micro-slip, both work maps and the profile */

/* Field identifiers for cw_solver_get_field (one value per element). */
#define CW_FIELD_X 0               /* element centre x [m] */
#define CW_FIELD_Y 1               /* element centre y [m] */
#define CW_FIELD_AREA 2            /* element area, 0 outside contact [m^2] */
#define CW_FIELD_PZ 3              /* normal pressure [Pa] */
#define CW_FIELD_PX 4              /* traction on the wheel, x [Pa] */
#define CW_FIELD_PY 5              /* traction on the wheel, y [Pa] */
#define CW_FIELD_SX 6              /* micro-slip W_x/V [-], 0 in adhesion (FULL) */
#define CW_FIELD_SY 7              /* micro-slip W_y/V [-], 0 in adhesion (FULL) */
#define CW_FIELD_MZ 8              /* moment contribution (x*py - y*px)*area [N m] */
#define CW_FIELD_WORK_PAPER 9      /* paper's local work, eq. 36: F.s_transl + M phi [J/m] (FULL) */
#define CW_FIELD_WORK_CONSISTENT 10 /* energy-consistent local work [J/m] (FULL) */

/* Element states (cw_solver_get_state), paper eqs. 32-33 */
#define CW_STATE_EXTERIOR 0
#define CW_STATE_ADHESION 1
#define CW_STATE_SLIP 2

/* cw_result.work_flags bits */
#define CW_WORK_UNRESOLVED 1  /* no element slips: released elastic energy put on each
                                 strip's trailing contact element (an adhesion element) */
#define CW_WORK_NON_POSITIVE 2 /* the map cannot add up to W_macro: W_macro <= 0 with
                                  dissipation (three-flexibility defect), or W_macro > 0
                                  with no dissipation left after rounding (extreme
                                  inputs); energy-consistent map set to zero */

/* ------------------------------------------------------------------ grid */

typedef struct cw_grid {
    size_t struct_size; /* set by cw_grid_init */
    int kind;           /* CW_GRID_KALKER_STRIPS (default), CW_GRID_UNIFORM or CW_GRID_GAP */
    int nx;             /* elements along x, 1..CW_MAX_GRID_CELLS (default 20) */
    int ny;             /* strips along y, 1..CW_MAX_GRID_CELLS (default 20) */
    double box_scale;   /* uniform grid: S in [1, CW_MAX_BOX_SCALE] (default 1) */
    /* ---- appended in 1.2 ---- */
    /* CW_GRID_GAP only: element (i, j) is the cell of dx*dy centred at
     * (x0 + i*dx, y0 + j*dy) [m], in the frame of the caller's gap (x along
     * the rolling direction); the cells are the potential contact area.
     * nx, ny in CW_MIN_GAP_CELLS..CW_MAX_EXACT_CELLS, |x0|, |y0| <= 1e6,
     * dx, dy in (0, 1e3] with dy/dx in [0.05, 20]. Defaults 0. */
    double x0, y0;
    double dx, dy;
} cw_grid;

/* Fills defaults and struct_size. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_grid_init(cw_grid* grid);

/* The grid a model gets when none is given, and struct_size: for
 * CW_MODEL_FASTSIM and CW_MODEL_CALIBRATED cw_grid_init's (Kalker's strips,
 * 20 x 20); for CW_MODEL_EXACT CONTACT's layout, the uniform grid over 1.2
 * times the semi-axes with 24 x 24 elements (20 across the ellipse, two
 * guard cells on each side; doc/theory/exact.md). Every door's default.
 * Errors: CW_ERR_NULL_POINTER, CW_ERR_UNKNOWN_OPTION (model). */
CW_API int cw_grid_init_model(cw_grid* grid, int model);

/* -------------------------------------------------------------- parameters */

typedef struct cw_params {
    size_t struct_size;    /* set by cw_params_init */
    double a;              /* semi-axis along x (rolling) [m], > 0 */
    double b;              /* semi-axis along y (lateral) [m], > 0; a/b in [1e-3, 1e3] */
    double normal_force;   /* N [N], >= 0 */
    double mu;             /* friction coefficient [-], >= 0 */
    int flexibility;       /* CW_FLEX_FROM_MATERIAL (default) or CW_FLEX_GIVEN */
    int pressure;          /* CW_PRESSURE_PARABOLIC (default) or CW_PRESSURE_ELLIPTIC */
    double G;              /* combined shear modulus [Pa], > 0 (FROM_MATERIAL) */
    double nu;             /* combined Poisson's ratio [-], 0..0.5 (FROM_MATERIAL) */
    double L1, L2, L3;     /* flexibilities [m/Pa], > 0 (GIVEN) */
    double xi_x;           /* longitudinal creepage [-] */
    double xi_y;           /* lateral creepage [-] */
    double phi;            /* spin creepage [1/m] */
    int rolling_direction; /* +1 (default): leading edge at x = +a; -1: at x = -a */
    /* ---- appended in 1.1 ---- */
    int model;             /* CW_MODEL_FASTSIM (default), CW_MODEL_EXACT, CW_MODEL_CALIBRATED
                              (doc/theory/calibrated.md: needs CW_FLEX_FROM_MATERIAL; uses
                              its own fitted pressure law and flexibilities, so pressure and
                              flexibility_blending are not used) */
    double tolerance;      /* exact model: relative tolerance of the tangential solve;
                              0 (default) = 1e-8; else in [1e-13, 1) (doc/theory/exact.md) */
    int max_iterations;    /* exact model: bound on Newton steps per grid; 0 (default) =
                              50; reaching it is CW_ERR_NOT_CONVERGED */
    int warm_start;        /* exact model: 1 (default) starts from the handle's last
                              solution, 0 from scratch (coarser grids); the same answer to
                              the tolerance. Ignored by cw_batch_solve (always 0) */
    double spin_offset;    /* CONTACT's facphi, in [0, 1]: the spin term of the lateral
                              rigid slip is taken spin_offset element lengths ahead of
                              the slip point, towards the leading edge (x' + s dx in the
                              rolling frame, either rolling_direction; on Kalker's strip
                              grid dx is the strip's own element length);
                              CW_SPIN_OFFSET_DEFAULT (default): 0 for FASTSIM (Kalker
                              1982), 1/6 for the exact model (CONTACT) */
    int flexibility_blending; /* FASTSIM: 1 = CONTACT's blending of L1..L3 towards one
                                 flexibility as the creepage grows (CONTACT's default;
                                 with spin_offset = 1/6 on the uniform grid it reproduces
                                 CONTACT's FASTSIM), 0 (default) = Kalker's L1, L2, L3 */
    /* ---- appended in 1.2 ---- */
    int exact_load;        /* FASTSIM, calibrated: 1 = pressure scaled so that the discrete
                              load sum(pz * area) equals normal_force exactly, so that
                              |F| <= mu * normal_force to rounding on every grid; 0 (default)
                              = the pressure law's analytic scale (2N/(pi a b) parabolic,
                              3N/(2 pi a b) elliptic), whose sum over the grid differs from
                              N by up to a few tenths of a per cent (the original algorithm:
                              FASTSIM and CONTACT comparisons use it). The exact model's
                              discrete normal problem carries N exactly either way. */
    /* A contact of any shape (CW_GRID_GAP, CW_MODEL_EXACT or CW_MODEL_FASTSIM;
     * doc/theory/non-hertzian.md). a, b, pressure and flexibility_blending
     * are not used; spin_offset is as for the model; Mz is about the grid's
     * origin. Off a gap grid gap must be NULL and the next two their defaults. */
    const double* gap;     /* undeformed distance between the surfaces at each element
                              centre [m] at [i + j*nx], positive = separation; the
                              approach is measured from its datum h = 0. Read during
                              the solve only. Default NULL */
    size_t gap_len;        /* values at gap, >= nx*ny */
    int normal_load;       /* CW_NORMAL_FORCE (default) or CW_NORMAL_APPROACH */
    int normal_method;     /* CW_NORMAL_EXACT (default) or CW_NORMAL_SEMI_HERTZ; the
                              tangential problem is the model's either way */
    double approach;       /* [m] from the gap's datum, with CW_NORMAL_APPROACH (default 0) */
    /* ---- appended in 1.3 ---- */
    double V;              /* rolling speed [m/s], >= 0; 0 (default) = not given. A
                              friction law of the slip speed (|micro-slip| * V) needs it;
                              Coulomb's law (every model's) does not use it */
    /* A friction law of the slip speed (doc/theory/friction.md). Beyond Coulomb's
     * law CW_MODEL_EXACT runs on the uniform and gap grids (friction_speed
     * LOCAL, every mode); CW_MODEL_FASTSIM on the ellipse's grids, in
     * CW_SOLVE_FORCES with friction_speed LOCAL or every mode with GLOBAL; the
     * calibrated model and FASTSIM on a gap grid refuse a law by name. */
    int friction_law;      /* CW_FRICTION_COULOMB (default), _LINEAR, _RATIONAL or
                              _EXPONENTIAL; beyond Coulomb's V > 0 is needed */
    double mu_e1, s_h1;    /* first falling term: [-] >= 0, half speed [m/s] > 0 when
                              mu_e1 > 0 (default 0: absent) */
    double mu_e2, s_h2;    /* second falling term, the same (default 0: absent) */
    int friction_speed;    /* CW_FRICTION_SPEED_LOCAL (default) or _GLOBAL */
    double k0;             /* Spiryagin's initial slope reduction (GLOBAL), > 0; default 1 */
    double alpha_inf;      /* its share left at large creepage, in [0, 1]; default 1
                              (k0 = alpha_inf = 1: no reduction) */
    double beta;           /* how fast the reduction goes, >= 0; default 0 */
    double memory_distance;/* friction memory (LOCAL): CONTACT's characteristic slip
                              distance d_c [m] >= 0; 0 (default) = none */
    double memory_s0;      /* its background slip speed s0 [m/s] >= 0 (default 0) */
    /* An interface (third-body) layer between the bodies (doc/theory/interface-layer.md):
     * an elastic shear compliance layer_h / layer_G in series with the bodies and a yield
     * stress tau_c = tau_c0 + k_tau u_pl (u_pl the plastic displacement accumulated along
     * the contact). CW_MODEL_EXACT takes the elastic layer on the uniform and gap grids and
     * the yield on the uniform grid (CW_FRICTION_COULOMB); every other model and the
     * transient handle refuse a layer with an error naming layer_h (or tau_c0, k_tau).
     * Defaults 0: no layer. */
    double layer_h;        /* the layer's thickness h [m] >= 0; 0 (default) = no elastic layer */
    double layer_G;        /* its shear modulus G3 [Pa], > 0 when layer_h > 0 (only
                              layer_h / layer_G matters) */
    double tau_c0;         /* its yield stress in shear [Pa] >= 0; 0 (default) = no yield */
    double k_tau;          /* its hardening (> 0) or softening (< 0) with the plastic
                              displacement [Pa/m], finite, with tau_c0 > 0; 0 (default) =
                              perfectly plastic; softening stops at 0.1 tau_c0 */
} cw_params;

/* Defaults: steel (G = 82e9 Pa, nu = 0.28), mu = 0.3, a = b = 6e-3 m,
 * N = 80e3 N, zero creepage, parabolic pressure, rolling towards +x.
 * The semi-axes and the load are placeholders: a contact's size and load
 * have no sensible default, and cw_params_check reports params whose a, b
 * and normal_force all still hold these values (CW_CHECK_DEFAULT_GEOMETRY).
 * Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_params_init(cw_params* params);

/* ----------------------------------------------------------- plausibility */

/* cw_check.rule: what an input's value suggests (cw_params_check,
 * cw_wheelrail_check, cw_temperature_params_check, cw_damage_params_check) */
#define CW_CHECK_SEMI_AXIS 1        /* a, b outside 0.1 mm .. 0.1 m */
#define CW_CHECK_NORMAL_FORCE 2     /* a load outside 1 kN .. 10 MN (kN typed as N?) */
#define CW_CHECK_FRICTION 3         /* mu above 1.5 */
#define CW_CHECK_MODULUS 4          /* G, layer_G outside 1e6 .. 1e12 Pa (MPa typed as Pa?) */
#define CW_CHECK_FLEXIBILITY 5      /* L1..L3 outside 1e-18 .. 1e-10 m/Pa */
#define CW_CHECK_CREEPAGE 6         /* |xi_x|, |xi_y| above 0.5 (a per cent typed?) */
#define CW_CHECK_SPIN 7             /* |phi| above 50 1/m (1/mm typed as 1/m?) */
#define CW_CHECK_GAP_SPACING 8      /* a gap grid's dx, dy outside 1 um .. 5 mm */
#define CW_CHECK_GAP_HEIGHTS 9      /* gap heights spanning more than 10 mm */
#define CW_CHECK_APPROACH 10        /* |approach| above 1 mm (CW_NORMAL_APPROACH) */
#define CW_CHECK_DEFAULT_GEOMETRY 11 /* a, b, normal_force all at cw_params_init's values */
#define CW_CHECK_HALF_SPEED 12      /* a friction law's s_h1, s_h2 above 50 m/s (mm/s typed?) */
#define CW_CHECK_LAYER_THICKNESS 13 /* an interface layer's layer_h above 10 mm (mm typed as m?) */
#define CW_CHECK_WHEELSET_SHIFT 20  /* |y| of the wheelset above 20 mm */
#define CW_CHECK_WHEELSET_ANGLE 21  /* |roll|, |yaw| above 0.05 rad (degrees typed?) */
#define CW_CHECK_PATCH_ELEMENT 22   /* wheel/rail dx, ds above 5 mm */
#define CW_CHECK_SPEED 23           /* V, a forward or rolling speed above 150 m/s (km/h typed?) */
#define CW_CHECK_PITCH_RATE 24      /* vpitch far from -vs / nominal_radius */
#define CW_CHECK_WHEELSET_HEIGHT 25 /* |z| beyond 5 mm with no patch on the flange */
#define CW_CHECK_FLANGE_TIP 26      /* a patch on the wheel's flange tip */
#define CW_CHECK_PROFILE_ORIGIN 27  /* the wheel's flange tip on the field side of its origin */
#define CW_CHECK_CONDUCTIVITY 30    /* lambda outside 1 .. 1000 W/(m K) (W/(mm K) typed?) */
#define CW_CHECK_HEAT_CAPACITY 31   /* c outside 100 .. 5000 J/kg/K (kJ/kg/K typed?) */
#define CW_CHECK_DENSITY 32         /* rho outside 1000 .. 25000 kg/m^3 (g/cm^3 typed?) */
#define CW_CHECK_YIELD_STRESS 33    /* k_yield, tau_c0 > 0 below 1e6 Pa (MPa typed as Pa?) */
#define CW_CHECK_WLRM_THRESHOLD 34  /* a WLRM threshold in (0, 1) N (kN typed as N?) */

/* One input whose value a solve accepts but no wheel-rail contact has: the
 * signature of a unit mistake (millimetres typed as metres, kN as N, MPa
 * as Pa, a per cent as a ratio) or of an input left out. Fields are only
 * ever appended. */
typedef struct cw_check {
    size_t struct_size;   /* set by cw_check_init */
    int rule;             /* CW_CHECK_* */
    char input[32];       /* the input, NUL-terminated: a field of cw_params, cw_grid,
                             cw_wheelrail_params, cw_wheelrail_motion,
                             cw_temperature_params or cw_damage_params ("a",
                             "normal_force", "gap", "dx", "y", "Fz", "z") */
    double value;         /* its value in SI (the first contact's that breaks the rule;
                             for "gap" the heights' spread max - min) */
    char unit[8];         /* the value's unit ("m", "N", "Pa", "1/m", "m/Pa", "rad",
                             "m/s", "rad/s", "W/(m K)", "J/kg/K", "kg/m^3") or "" */
    size_t contacts;      /* how many of the contacts checked break the rule */
    size_t first;         /* the index of the first */
    char reason[256];     /* what is plausible and the likely mistake */
    char message[384];    /* "<input> = <value> <unit> is implausible for a wheel-rail
                             contact: <reason>" (truncated to fit) */
} cw_check;

/* Zeroes the check and sets struct_size. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_check_init(cw_check* check);

/* Checks count contacts (params[k], k < count, elements of size
 * params[0].struct_size, each carrying the same struct_size) solved on grid
 * for values that are valid but implausible for a wheel-rail contact, one
 * rule at a time (doc/input-schema.md, "Plausibility warnings"): *found
 * receives the number of rules broken, out[k], k < *found, one entry each, in a fixed
 * order, with the number of contacts that break it and the first's index
 * and value. out is an array of len structs of size out[0].struct_size
 * (each initialised by cw_check_init); len = 0 asks for the number only
 * (out may then be NULL). On a gap grid (CW_GRID_GAP) a and b are not
 * used; the grid's spacing and params->gap's heights (when given, nx*ny
 * values) are checked instead. Values a solve refuses (negative, NaN) are
 * left to the solve's errors. Prints nothing, and the library never calls
 * it by itself: a solve in other consistent units stays silent. Cost:
 * linear in count (and in nx*ny with a gap); it allocates its findings. Errors: CW_ERR_NULL_POINTER (grid, params with count > 0,
 * found), CW_ERR_STRUCT_SIZE, CW_ERR_BUFFER_TOO_SMALL (len < *found:
 * *found is set, nothing else is written). */
CW_API int cw_params_check(const cw_grid* grid, const cw_params* params, size_t count,
                           cw_check* out, size_t len, size_t* found);

/* The name every door documents for an input or an enumeration value typed
 * another way: writes to name (NUL-terminated, name_len bytes) the
 * canonical spelling of typed. Inputs: "N" -> "normal_force", "spin" ->
 * "phi". Enumeration values (of cw_grid.kind, cw_params.model, pressure,
 * flexibility, normal_load, normal_method: the names of their CW_
 * constants without the prefix, in lower case) in any case and with "-"
 * for "_" ("Semi-Hertz" -> "semi_hertz"), and the short forms "strips" ->
 * "kalker_strips", "fast" -> "fastsim". Any other name is copied
 * unchanged. Errors: CW_ERR_NULL_POINTER, CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_input_name(const char* typed, char* name, size_t name_len);

/* ----------------------------------------------------------------- result */

typedef struct cw_result {
    size_t struct_size;       /* set by cw_result_init */
    double Fx, Fy;            /* creep force on the wheel [N] */
    double Mz;                /* creep moment about the ellipse centre (a gap grid: about
                                 its origin x = y = 0), on the wheel [N m] */
    double W_macro;           /* -(Fx xi_x + Fy xi_y + Mz phi) [J/m], paper eq. 34 */
    double W_micro_paper;     /* sum of the paper's local work [J/m] (FULL) */
    double K;                 /* W_macro / W_micro_paper, paper eq. 39; 0 if undefined (FULL) */
    double W_consistent;      /* sum of the energy-consistent map = W_macro [J/m] (FULL) */
    double balance_factor;    /* W_macro / model energy terms; 1 without spin on the
                                 uniform grid (see doc/theory/work.md) (FULL) */
    double adhesion_fraction; /* n_adhesion / n_contact */
    int n_contact, n_adhesion, n_slip;
    int work_flags;           /* CW_WORK_* bits (FULL) */
    double a, b;              /* semi-axes used [m] (a gap grid: half the contact's extent
                                 along x and y) */
    double L1, L2, L3;        /* flexibilities used [m/Pa]; 0 on a gap grid */
    double C11, C22, C23, C33;/* Kalker coefficients used; 0 when L's were given and on a
                                 gap grid */
    double profile_max_diff;  /* lateral work profile vs equal-area parabola, max |diff| / peak */
    double profile_rms_diff;  /* ... RMS difference / peak (FULL) */
    /* ---- appended in 1.1 ---- */
    int model;                /* the CW_MODEL_* that produced this result */
    double p_max;             /* largest element pressure [Pa] */
    double approach;          /* normal approach [m]: exact model, of the discrete normal
                                 problem; FASTSIM, Hertz's value (0 with given L1..L3) */
    int iterations;           /* exact model: iterations of the tangential solve; else 0 */
    double residual;          /* exact model: final relative residual; else 0 */
    /* ---- appended in 1.2 ---- */
    double normal_force;      /* total normal force [N]: found with CW_NORMAL_APPROACH,
                                 else params->normal_force */
    int n_patches;            /* separate contact patches (4-connected elements;
                                 cw_solver_get_patches); 1 for an ellipse, 0 without contact */
    /* ---- appended in 1.3 ---- */
    double mu_static;         /* the friction coefficient at rest: mu + mu_e1 + mu_e2
                                 under a law of the slip speed, mu under Coulomb's */
    double mu_min, mu_max;    /* the smallest and largest coefficient over the slipping
                                 elements (mu_static when none slips; the contact's one
                                 mu with CW_FRICTION_SPEED_GLOBAL) */
} cw_result;

/* Zeroes the result and sets struct_size. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_result_init(cw_result* result);

/* ----------------------------------------------------------------- solver */

typedef struct cw_solver cw_solver;

/* Creates a solver for one grid: all memory is allocated here, none in
 * solve. message (may be NULL) receives a NUL-terminated explanation of an
 * error, truncated to message_len bytes. A CW_GRID_GAP solver makes the
 * exact model's memory here (FASTSIM's on that grid comes with its first
 * solve or cw_solver_prepare).
 * Errors: CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE, CW_ERR_UNKNOWN_OPTION
 * (kind), CW_ERR_GRID_OUT_OF_RANGE, CW_ERR_INVALID_INPUT (a gap grid's
 * origin or spacing), CW_ERR_OUT_OF_MEMORY. On error *solver is set to
 * NULL. */
CW_API int cw_solver_create(const cw_grid* grid, cw_solver** solver, char* message,
                            size_t message_len);

/* Frees everything; NULL is a no-op. Always CW_OK. */
CW_API int cw_solver_destroy(cw_solver* solver);

/* Grid dimensions of the solver. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_solver_grid_size(const cw_solver* solver, int* nx, int* ny);

/* Makes one model's memory now, so that its solves allocate nothing
 * afterwards. CW_MODEL_FASTSIM: nothing to do (made by create), but on
 * CW_GRID_GAP its march and normal-method workspace.
 * CW_MODEL_EXACT: influence tables, FFT plans and spectra, Krylov basis and
 * every workspace of the grid and of its coarser levels (memory linear in
 * nx*ny, doc/theory/exact.md); without prepare the first exact solve
 * makes them. CW_MODEL_CALIBRATED: its FASTSIM march workspace (every
 * grid). Idempotent. Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_UNKNOWN_OPTION (model), CW_ERR_INVALID_INPUT (CW_MODEL_EXACT on
 * CW_GRID_KALKER_STRIPS; CW_MODEL_CALIBRATED on CW_GRID_GAP),
 * CW_ERR_GRID_OUT_OF_RANGE (exact: nx or ny > CW_MAX_EXACT_CELLS),
 * CW_ERR_OUT_OF_MEMORY. */
CW_API int cw_solver_prepare(cw_solver* solver, int model);

/* Solves one steady-rolling contact. mode: CW_SOLVE_FORCES or CW_SOLVE_FULL.
 * result may be NULL (read fields afterwards). Allocates nothing on success
 * (an error may allocate its message; the first CW_MODEL_EXACT solve makes
 * that model's memory unless cw_solver_prepare did), prints nothing.
 * CW_MODEL_EXACT (doc/theory/exact.md): needs CW_GRID_UNIFORM or
 * CW_GRID_GAP and CW_FLEX_FROM_MATERIAL (G, nu); solves its own normal
 * problem (from a, b, normal_force on the uniform grid; on a gap grid from
 * params->gap with the force or the approach prescribed), so
 * params->pressure is ignored; a gap grid takes CW_MODEL_EXACT or
 * CW_MODEL_FASTSIM (each patch with the flexibilities of its own ellipse
 * from G, nu), no other model (CW_ERR_INVALID_INPUT);
 * with warm_start = 1 the exact model starts from this handle's last
 * successful exact solution (the answer equals a cold start's to the
 * tolerance); it stops when the relative
 * residual is <= tolerance (default 1e-8) and reports CW_ERR_NOT_CONVERGED
 * after max_iterations Newton steps (default 50) otherwise -- never an
 * unconverged answer. Errors: CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE,
 * CW_ERR_UNKNOWN_OPTION, CW_ERR_INVALID_INPUT, CW_ERR_GRID_OUT_OF_RANGE
 * (exact model beyond CW_MAX_EXACT_CELLS), CW_ERR_NOT_CONVERGED,
 * CW_ERR_NUMERIC, CW_ERR_OUT_OF_MEMORY (first exact solve). After an
 * error the handle holds no solution (fields give CW_ERR_NO_SOLUTION) and
 * the next exact solve starts cold. */
CW_API int cw_solver_solve(cw_solver* solver, const cw_params* params, int mode,
                           cw_result* result);

/* The 4 x 4 Jacobian of a solve for implicit integrators
 * (doc/theory/jacobians.md; its cost: doc/performance.md), row-major:
 * jacobian[4*r + c] = d(row r)/d(column c). */
#define CW_JACOBIAN_LEN 16
#define CW_JAC_FX 0      /* rows: Fx [N], Fy [N], Mz [N m], W_macro [J/m] */
#define CW_JAC_FY 1
#define CW_JAC_MZ 2
#define CW_JAC_W_MACRO 3
#define CW_JAC_XI_X 0    /* columns: xi_x [-], xi_y [-], phi [1/m], normal_force [N] */
#define CW_JAC_XI_Y 1
#define CW_JAC_PHI 2
#define CW_JAC_N 3

/* Solves as cw_solver_solve (same result, fields and errors; the totals are
 * bitwise those of cw_solver_solve) and writes the derivatives of exactly
 * the Fx, Fy, Mz, W_macro it reports, in the caller's frame and sign
 * convention (any rolling_direction), with respect to the params fields
 * xi_x, xi_y, phi and normal_force, in SI units: e.g. jacobian[4*CW_JAC_FX
 * + CW_JAC_XI_X] = dFx/dxi_x [N], [4*CW_JAC_MZ + CW_JAC_PHI] = dMz/dphi
 * [N m^2]. Held fixed: a, b, mu, G, nu, L1..L3 as given; N moves the
 * pressure scale and so the traction bound (and, with
 * flexibility_blending, the blended L1..L3).
 *   CW_MODEL_FASTSIM  exact derivatives of the discrete march by forward
 *                     mode in the same pass: a small constant times a
 *                     CW_SOLVE_FORCES solve, linear in the elements (with
 *                     CW_SOLVE_FULL the work pass comes on top).
 *                     Every grid, pressure, spin_offset and
 *                     flexibility_blending.
 *   CW_MODEL_EXACT    derivatives of the converged discrete system (implicit
 *                     function theorem, states fixed at the solution), three
 *                     extra linear solves with the Newton-GMRES machinery,
 *                     each to the solve's tolerance.
 *   CW_MODEL_CALIBRATED  derivatives of its march by forward mode along the
 *                     directions in which each input moves its setup (the
 *                     table's knobs depend on the saturation level: those
 *                     closed forms are differenced centrally, the march
 *                     exactly; N by homogeneity): a small constant times a
 *                     CW_SOLVE_FORCES solve, linear in the elements.
 *                     Needs CW_FLEX_FROM_MATERIAL, as its solves.
 * On CW_GRID_GAP (CW_MODEL_EXACT and CW_MODEL_FASTSIM) the gap is held
 * and the normal_force column is d/dN along the solution, with the force
 * or the approach prescribed: the normal method's exact dp/dN carried
 * through the tangential problem (implicit function theorem, four linear
 * solves; or forward mode through the march), the contact set, the
 * patches and their flexibilities held as the solve found them
 * (doc/theory/non-hertzian.md); an approach that gives no contact is
 * CW_ERR_INVALID_INPUT naming approach.
 * Where an element sits exactly on the traction bound the derivative is the
 * one of the state the solve found (doc/theory/jacobians.md). Needs
 * normal_force > 0 when mu > 0 (the forces are not differentiable in N at
 * N = 0): CW_ERR_INVALID_INPUT. Allocates nothing (FASTSIM, calibrated;
 * exact as cw_solver_solve). Errors: those of cw_solver_solve, and
 * CW_ERR_NULL_POINTER (jacobian), CW_ERR_BUFFER_TOO_SMALL (jacobian_len <
 * CW_JACOBIAN_LEN). On error nothing is written to jacobian or result. */
CW_API int cw_solver_solve_jacobian(cw_solver* solver, const cw_params* params, int mode,
                                    cw_result* result, double* jacobian, size_t jacobian_len);

/* Copies the totals of the last successful solve. Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_STRUCT_SIZE, CW_ERR_NO_SOLUTION. */
CW_API int cw_solver_get_result(const cw_solver* solver, cw_result* result);

/* One field of the last solve into out[i + j*nx], out_len >= nx*ny.
 * Units in the CW_FIELD_* list. Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_UNKNOWN_OPTION, CW_ERR_NO_SOLUTION, CW_ERR_NO_WORK,
 * CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_solver_get_field(const cw_solver* solver, int field, double* out,
                               size_t out_len);

/* Element states CW_STATE_* into out[i + j*nx], out_len >= nx*ny.
 * Errors: as cw_solver_get_field. */
CW_API int cw_solver_get_state(const cw_solver* solver, int* out, size_t out_len);

/* Lateral work profile (paper Figs. 8-9), per strip j < ny: strip centre y
 * [m], energy-consistent work per unit width w(y) [J/m per m], and the
 * parabola over [-b, b] with the same area, (3W/4b)(1 - y^2/b^2). Each of y,
 * w, parabola may be NULL; len >= ny. Needs a CW_SOLVE_FULL solve.
 * Errors: CW_ERR_NO_SOLUTION, CW_ERR_NO_WORK, CW_ERR_BUFFER_TOO_SMALL,
 * CW_ERR_NULL_POINTER (solver). */
CW_API int cw_solver_get_profile(const cw_solver* solver, double* y, double* w,
                                 double* parabola, size_t len);

/* One contact patch of the last solve (cw_solver_get_patches), on the wheel,
 * in the grid's frame. Fields are only ever appended. */
typedef struct cw_patch {
    size_t struct_size;        /* set by cw_patch_init */
    int n_contact, n_adhesion, n_slip; /* elements */
    double x_centroid, y_centroid; /* centre of the patch's element area [m] */
    double Fx, Fy;             /* creep force [N] */
    double Mz;                 /* creep moment [N m]: about the grid's origin on a gap grid,
                                  about the ellipse centre otherwise */
    double Fn;                 /* normal force [N] */
    double p_max;              /* largest element pressure [Pa] */
    double W_macro;            /* -(Fx xi_x + Fy xi_y + Mz phi) [J/m]; the patches' sum is
                                  the result's W_macro */
} cw_patch;

/* Zeroes the patch and sets struct_size. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_patch_init(cw_patch* patch);

/* The separate contact patches of the last solve, in the order of their
 * first element at [i + j*nx] (lowest y row first): *count receives their
 * number (cw_result.n_patches) and out[k], k < *count, the patch totals
 * (the result's totals are their sums, to rounding). out is an array of len
 * structs of size out[0].struct_size (every element must carry the same
 * struct_size): patch k is written at byte k * out[0].struct_size, so a
 * program built against an older or newer cw_patch gets every patch. len =
 * 0 asks for the count only (out may then be NULL). Off a gap grid a
 * contact is one patch (centroid at the ellipse centre). Allocates nothing. Errors: CW_ERR_NULL_POINTER (solver, count),
 * CW_ERR_NO_SOLUTION, CW_ERR_STRUCT_SIZE, CW_ERR_BUFFER_TOO_SMALL (len <
 * *count: *count is set, nothing else is written). */
CW_API int cw_solver_get_patches(const cw_solver* solver, cw_patch* out, size_t len,
                                 size_t* count);

/* Detailed message of the last error on this handle ("" after success);
 * owned by the handle, valid until its next call. NULL solver gives a
 * static message. */
CW_API const char* cw_solver_last_error(const cw_solver* solver);

/* ------------------------------------------------------------------ batch */

/* Many independent contacts on one grid (e.g. every wheel of a vehicle),
 * in parallel with OpenMP when available. Results are bitwise identical to
 * one-by-one cw_solver_solve calls, whatever the number of threads.
 * CW_MODEL_EXACT contacts are solved cold (warm_start is ignored: which
 * thread solved what before must not matter), so they equal one-by-one
 * solves with warm_start = 0. */
typedef struct cw_batch cw_batch;

/* threads <= 0: use all available cores; at most CW_MAX_BATCH_THREADS (each
 * thread owns a solver of the grid's size). All memory is allocated here.
 * Errors: as cw_solver_create, and CW_ERR_INVALID_INPUT (threads). */
CW_API int cw_batch_create(const cw_grid* grid, int threads, cw_batch** batch, char* message,
                           size_t message_len);
CW_API int cw_batch_destroy(cw_batch* batch); /* NULL: no-op */

/* cw_solver_prepare for the solver of every thread of a batch. Errors: those
 * of cw_solver_prepare. */
CW_API int cw_batch_prepare(cw_batch* batch, int model);

/* Solves count contacts. params and results are arrays whose element size is
 * params[0].struct_size and results[0].struct_size (every element must carry
 * the same struct_size), so older, smaller structs work. statuses (may be
 * NULL) receives each contact's status. Returns CW_OK when all succeeded,
 * otherwise the status of the first failing contact (its message names the
 * index); results of failed contacts are left untouched.
 * Errors: CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE, CW_ERR_UNKNOWN_OPTION, and
 * per contact those of cw_solver_solve. */
CW_API int cw_batch_solve(cw_batch* batch, size_t count, const cw_params* params, int mode,
                          cw_result* results, int* statuses);

/* Detailed message of the last error on this handle, as cw_solver_last_error. */
CW_API const char* cw_batch_last_error(const cw_batch* batch);

/* ------------------------------------------------------ work accumulator */

/* Running totals for simulation loops (paper eqs. 35 and 37). The per-element
 * totals live on the patch grid in normalised coordinates (x/a, y/b), so
 * contacts whose a, b change from step to step accumulate element by
 * element. */
typedef struct cw_accumulator cw_accumulator;

typedef struct cw_accumulation {
    size_t struct_size;   /* set by cw_accumulation_init */
    double distance;      /* total rolled distance sum(V dt) [m] */
    double W_macro;       /* sum W_macro V dt, paper eq. 35 [J] */
    double W_micro_paper; /* sum W_micro_paper V dt, paper eq. 37 [J] */
    double K;             /* W_macro / W_micro_paper over the run (eq. 39), 0 if undefined */
    double W_consistent;  /* sum of the energy-consistent map over the run [J] */
    int64_t steps;        /* number of cw_accumulator_add calls that succeeded */
} cw_accumulation;

/* Zeroes the totals and sets struct_size. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_accumulation_init(cw_accumulation* totals);

/* Accumulator on the grid of solver (same nx, ny, kind needed when adding).
 * Errors: CW_ERR_NULL_POINTER, CW_ERR_OUT_OF_MEMORY. */
CW_API int cw_accumulator_create(const cw_solver* solver, cw_accumulator** accumulator);
CW_API int cw_accumulator_destroy(cw_accumulator* accumulator); /* NULL: no-op */
/* Back to zero totals and maps. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_accumulator_reset(cw_accumulator* accumulator);

/* Adds the last CW_SOLVE_FULL solve of solver for a step of length
 * distance = V*dt [m] >= 0 (finite). Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_NO_SOLUTION, CW_ERR_NO_WORK, CW_ERR_GRID_MISMATCH,
 * CW_ERR_INVALID_INPUT (distance), CW_ERR_NUMERIC (a running total would
 * overflow). On error the accumulator is unchanged. */
CW_API int cw_accumulator_add(cw_accumulator* accumulator, const cw_solver* solver,
                              double distance);

/* Copies the running totals. Errors: CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE. */
CW_API int cw_accumulator_get_totals(const cw_accumulator* accumulator,
                                     cw_accumulation* totals);

/* Accumulated per-element work [J] into out[i + j*nx]: field is
 * CW_FIELD_WORK_PAPER or CW_FIELD_WORK_CONSISTENT. Errors:
 * CW_ERR_NULL_POINTER, CW_ERR_UNKNOWN_OPTION, CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_accumulator_get_field(const cw_accumulator* accumulator, int field,
                                    double* out, size_t out_len);

/* Accumulated energy-consistent work per strip j < ny [J] (sum over i).
 * Errors: CW_ERR_NULL_POINTER, CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_accumulator_get_strip_work(const cw_accumulator* accumulator, double* out,
                                         size_t len);

/* Detailed message of the last error on this handle, as cw_solver_last_error. */
CW_API const char* cw_accumulator_last_error(const cw_accumulator* accumulator);

/* ------------------------------------------- linear theory and Hertz helpers */

/* Kalker's coefficients (Kalker 1990, Table E.3; interpolated as CONTACT
 * does; asymptotes below min(a/b, b/a) = 0.1, where C33, for which no
 * published asymptote is confirmed, continues the table's 0.1 row).
 * coefficients[4] = C11, C22, C23, C33.
 * Errors: CW_ERR_NULL_POINTER, CW_ERR_INVALID_INPUT. */
CW_API int cw_kalker_coefficients(double a_over_b, double nu, double coefficients[4],
                                  char* message, size_t message_len);

/* Flexibilities of the simplified theory, flexibilities[3] = L1, L2, L3 [m/Pa]:
 * L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G), L3 = pi a sqrt(a/b)/(4 C23 G).
 * Errors: CW_ERR_NULL_POINTER, CW_ERR_INVALID_INPUT. */
CW_API int cw_kalker_flexibilities(double a, double b, double G, double nu,
                                   double flexibilities[3], char* message,
                                   size_t message_len);

/* Hertz contact of elastically similar bodies. A, B > 0 [1/m] are the
 * coefficients of the undeformed gap z = A x^2 + B y^2, i.e. HALF the
 * relative curvatures: A = (1/R1x + 1/R2x)/2 along x (the rolling
 * direction), B = (1/R1y + 1/R2y)/2 across (convex radii positive, a flat
 * profile 0). Passing the curvatures 1/R themselves gives a patch 20 %
 * smaller and p0 59 % higher. Load N >= 0 [N], contact modulus E* > 0 [Pa]
 * (E* = G/(1-nu) for identical materials). Example: wheel radius 0.457 m on
 * a rail crown of 0.3 m, A = 1/(2*0.457), B = 1/(2*0.3), N = 100 kN,
 * G = 82 GPa, nu = 0.28: a = 7.170 mm, b = 5.417 mm, p0 = 1229 MPa.
 * hertz[4] = a [m] (along x), b [m], maximum pressure p0 [Pa], approach [m].
 * Errors: CW_ERR_NULL_POINTER, CW_ERR_INVALID_INPUT, CW_ERR_NUMERIC. */
CW_API int cw_hertz_solve(double A, double B, double normal_force, double E_star,
                          double hertz[4], char* message, size_t message_len);

/* Polach's friction law mu = mu0 [(1 - A) exp(-B s) + A] (Polach, Wear 258
 * (2005) 992-1000) written into params as CONTACT's exponential law:
 * friction_law = CW_FRICTION_EXPONENTIAL, mu = A mu0, mu_e1 = (1 - A) mu0,
 * s_h1 = ln2 / B, mu_e2 = s_h2 = 0; nothing else is touched. mu0 >= 0,
 * A in [0, 1], B > 0 [s/m]. Errors: CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE
 * (params cut before s_h2), CW_ERR_INVALID_INPUT (naming mu0, A or B). */
CW_API int cw_friction_polach(double mu0, double A, double B, cw_params* params, char* message,
                              size_t message_len);

/* Kalker's original normalised FASTSIM (1982): a drop-in for its SIM routine.
 * Unit disk, parabolic bound 1 - x^2 - y^2, rigid slip (ux - y fx, uy + x fy):
 *   ux, uy   normalised creepages pi a^2 b xi/(2 mu N L), pi a^2 b eta/(2 mu N L)
 *   fx, fy   normalised spin terms pi a^2 b^2 phi/(2 mu N L), pi a^3 b phi/(2 mu N L)
 *   mx       elements per strip (1..CW_MAX_GRID_CELLS)
 *   my, tol  Kalker's strip layout: the strips are cut at the y of the spin
 *            pole (-uy/fy, ux/fx) when it lies in the disk (else at y = 0),
 *            each side gets ceil(my (1 -+ ys)/2) equal strips, and the strip
 *            beside the cut is halved until its centre is within tol of it
 * Outputs tx, ty with the signs of Kalker's published check values (so old
 * callers get the numbers they always got): tx = rail's x-force / (mu N),
 * sign of ux; ty = wheel's y-force / (mu N), opposite sign to uy. In
 * cw_solver_solve's convention: tx = -Fx/(mu N), ty = +Fy/(mu N).
 * Errors: CW_ERR_NULL_POINTER, CW_ERR_INVALID_INPUT, CW_ERR_GRID_OUT_OF_RANGE,
 * CW_ERR_NUMERIC. */
CW_API int cw_fastsim_normalised(double ux, double uy, double fx, double fy, int mx, int my,
                                 double tol, double* tx, double* ty, char* message,
                                 size_t message_len);

/* Wear laws and wear on a profile grid; surface temperature and damage
 * indices; one wheel on one rail from the profiles; transient rolling: in
 * these parts, included here. */
#include "creepwork/creepwork_wear.h"
#include "creepwork/creepwork_surface.h"
#include "creepwork/creepwork_wheelrail.h"
#include "creepwork/creepwork_transient.h"

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* CREEPWORK_H */
