/* creepwork: surface temperature and damage indices of a solved contact -- part of the C API,
 * included by <creepwork/creepwork.h> (include that header, not this one). The conventions of
 * creepwork.h hold. */
#ifndef CREEPWORK_H
#error "include <creepwork/creepwork.h>, not <creepwork/creepwork_surface.h>"
#endif
#ifndef CREEPWORK_SURFACE_H
#define CREEPWORK_SURFACE_H

/* ------------------------------------------------------------ temperature */

/* The steady flash temperatures of both bodies of a solved contact (any
 * model, any grid) from its frictional power (doc/theory/temperature.md).
 * Body 1 is the rail, body 2 the wheel (CONTACT's TEMP1, TEMP2). Each grid
 * row along the rolling direction is a moving heat source over two
 * half-spaces; in contact both surfaces share one temperature. Temperatures
 * in deg C (any scale with kelvin-sized degrees: the model is linear in
 * T0). */

/* cw_temperature_params.discretisation */
#define CW_TEMPERATURE_CONSISTENT 0 /* exact integral of the element-wise heat from the
                                       energy-consistent work map; one surface temperature
                                       in contact (default) */
#define CW_TEMPERATURE_CONTACT 1    /* CONTACT's calc_temp_steady: its self-element term
                                       (O(sqrt dx) too hot), heat |p_t| |s| V on slip
                                       elements, its partition between the bodies */

/* cw_temperature_get_field: one value per element at [i + j*nx] */
#define CW_TEMPERATURE_FIELD_RAIL 0  /* surface temperature of body 1, the rail [deg C] */
#define CW_TEMPERATURE_FIELD_WHEEL 1 /* surface temperature of body 2, the wheel [deg C] */
#define CW_TEMPERATURE_FIELD_HEAT 2  /* frictional power density q the bodies share [W/m^2] */

typedef struct cw_temperature_params {
    size_t struct_size;      /* set by cw_temperature_params_init */
    /* Body 1, the rail; defaults steel at 20 deg C. */
    double T0_1;             /* bulk temperature [deg C] in [-273.15, 1e4]; default 20 */
    double heat_capacity_1;  /* c [J/(kg K)] in [1, 1e5]; default 450 */
    double conductivity_1;   /* lambda [W/(m K)] in [1e-3, 1e4]; default 50 */
    double density_1;        /* rho [kg/m^3] in [1, 1e5]; default 7850 */
    /* Body 2, the wheel; the same ranges and defaults. */
    double T0_2, heat_capacity_2, conductivity_2, density_2;
    double rolling_speed;    /* V [m/s] in [1e-3, 1e3]; 0 (default): the V the solve was
                                given (cw_params.V), which must then be > 0. Both given:
                                they must agree (to 1e-9), else CW_ERR_INVALID_INPUT
                                naming both */
    int rolling_direction;   /* the solve's cw_params.rolling_direction (+1 default, -1);
                                0: the solve's (a wheel/rail patch: its own). Another
                                than the solve's: CW_ERR_INVALID_INPUT */
    int discretisation;      /* CW_TEMPERATURE_CONSISTENT (default) or _CONTACT */
} cw_temperature_params;

/* Fills the defaults above. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_temperature_params_init(cw_temperature_params* params);

typedef struct cw_temperature_result {
    size_t struct_size;        /* set by cw_temperature_result_init */
    /* Each body's hottest contact element (the maximum over the contact, as
     * CONTACT prints it; the first in storage order on a tie): temperature
     * [deg C] and centre [m]. Without contact: T0 at (0, 0). */
    double T_max_1, x_max_1, y_max_1;
    double T_max_2, x_max_2, y_max_2;
    double contact_temperature; /* bulk part in contact [deg C]: (b1 T0_1 + b2 T0_2)/(b1 + b2),
                                   b = sqrt(lambda rho c) (CONTACT's with b1, b2 swapped) */
    double power;               /* total frictional power, sum of q area [W] */
    int iterations;             /* passes of solve and temperature: 1 for
                                   cw_temperature_compute; cw_temperature_solve's count */
    int discretisation;         /* as computed */
} cw_temperature_result;

/* Zeroes the result and sets struct_size. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_temperature_result_init(cw_temperature_result* result);

/* Workspace and results of the temperature of one contact, for one solver
 * grid. All memory is allocated here. Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_OUT_OF_MEMORY. */
typedef struct cw_temperature cw_temperature;
CW_API int cw_temperature_create(const cw_solver* solver, cw_temperature** temperature);
/* Frees the handle; NULL is a no-op. Errors: none (always CW_OK). */
CW_API int cw_temperature_destroy(cw_temperature* temperature);

/* The temperatures of the last CW_SOLVE_FULL solve of solver (a pure
 * function of it and params; the solver is not changed). result may be
 * NULL. Allocates nothing. Errors: CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE,
 * CW_ERR_GRID_MISMATCH (solver's grid is not the handle's),
 * CW_ERR_NO_SOLUTION, CW_ERR_NO_WORK (a CW_SOLVE_FORCES solve),
 * CW_ERR_UNKNOWN_OPTION (discretisation), CW_ERR_INVALID_INPUT (a
 * parameter, named in the message). After an error the handle holds no
 * temperatures. */
CW_API int cw_temperature_compute(cw_temperature* temperature, const cw_solver* solver,
                                  const cw_temperature_params* params,
                                  cw_temperature_result* result);

/* One CW_TEMPERATURE_FIELD_* of the last compute into out[i + j*nx],
 * out_len >= nx*ny. Errors: CW_ERR_NULL_POINTER, CW_ERR_UNKNOWN_OPTION,
 * CW_ERR_NO_SOLUTION (no compute yet), CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_temperature_get_field(const cw_temperature* temperature, int field, double* out,
                                    size_t out_len);

/* Copies the result of the last compute. Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_STRUCT_SIZE, CW_ERR_NO_SOLUTION. */
CW_API int cw_temperature_get_result(const cw_temperature* temperature,
                                     cw_temperature_result* result);

/* Detailed message of the last error on this handle, as cw_solver_last_error. */
CW_API const char* cw_temperature_last_error(const cw_temperature* temperature);

/* Friction that depends on the surface temperature: mu(T) piecewise linear
 * through count points (temperature[k], mu[k]), constant beyond the first
 * and the last. CONTACT's L=6 (FREF, TREF, DFHEAT, DTHEAT) is the table
 * of two points (TREF, FREF), (TREF + DTHEAT, FREF + DFHEAT). Element e's
 * coefficient is mu(T_e) under Coulomb's law (cw_params.mu is not read),
 * and mu_law(s) mu(T_e) / mu_law(0) under a law of the slip speed (the
 * table gives the static coefficient, the law its fall with s); T_e is the
 * rail's (body 1's) surface temperature at the element, as CONTACT's
 * TEMP1 (in contact both bodies share it under the consistent
 * discretisation). The arrays are the caller's, read during the call.
 * Under Coulomb's law cw_result.mu_static is the table's largest mu and
 * mu_min, mu_max the range over the slipping elements. */
typedef struct cw_mu_temperature {
    size_t struct_size;        /* set by cw_mu_temperature_init */
    size_t count;              /* points, >= 2; default 0: must be set */
    const double* temperature; /* [deg C], count values, finite, strictly increasing */
    const double* mu;          /* [-], count values, finite, > 0 */
    double tolerance;          /* the loop stops when Fx and Fy change by at most
                                  tolerance N from one pass to the next; in [1e-12, 0.1],
                                  default 1e-6 */
    int max_iterations;        /* passes of solve and temperature, in [1, 1000]; default
                                  100; reaching it is CW_ERR_NOT_CONVERGED */
} cw_mu_temperature;

/* Fills the defaults above. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_mu_temperature_init(cw_mu_temperature* mu_T);

/* Solves params (CW_SOLVE_FULL) with friction mu(T) in a fixed-point loop:
 * the first pass with every element at mu of the bulk contact temperature,
 * then temperatures -> each element's mu from its temperature -> solve
 * again, until the forces change by at most mu_T->tolerance N. The solver
 * keeps the last solve (its fields and totals, as after cw_solver_solve;
 * later solves have no mu(T)), the handle its temperatures (as after
 * cw_temperature_compute, with iterations the passes taken). result and
 * temperature_result may be NULL. The exact model (CW_MODEL_EXACT) and
 * FASTSIM (CW_MODEL_FASTSIM) on the ellipse's and gap grids, under
 * Coulomb's law or a law with CW_FRICTION_SPEED_LOCAL, take mu(T); the
 * calibrated model and FASTSIM with CW_FRICTION_SPEED_GLOBAL refuse it
 * naming mu_T. Errors: those of cw_solver_solve and cw_temperature_compute,
 * CW_ERR_INVALID_INPUT naming a bad mu_T entry (mu_T.count,
 * mu_T.temperature[k], mu_T.mu[k], mu_T.tolerance, mu_T.max_iterations) or
 * a model without mu(T), CW_ERR_NOT_CONVERGED (max_iterations reached).
 * After an error neither handle holds a solution. */
CW_API int cw_temperature_solve(cw_temperature* temperature, cw_solver* solver,
                                const cw_params* params,
                                const cw_temperature_params* temperature_params,
                                const cw_mu_temperature* mu_T, cw_result* result,
                                cw_temperature_result* temperature_result);

/* Checks params for values that are valid but implausible for steel wheels
 * and rails, as cw_params_check does a contact's (doc/input-schema.md,
 * "Plausibility warnings"): conductivity_1/_2, heat_capacity_1/_2,
 * density_1/_2 far from steel's (CW_CHECK_CONDUCTIVITY, _HEAT_CAPACITY,
 * _DENSITY: W/(mm K), kJ/(kg K), g/cm^3 typed?) and rolling_speed above 150
 * m/s (CW_CHECK_SPEED: km/h typed?). *found receives the number of
 * findings, out[k], k < *found, one per rule and input in a fixed order
 * (cw_check.contacts = 1, first = 0). out is an array of len structs of
 * size out[0].struct_size (each initialised by cw_check_init); len = 0
 * asks for the number only (out may then be NULL). Values a compute
 * refuses (NaN, out of range) are left to its errors. Prints nothing;
 * cw_temperature_compute never calls it. Errors: CW_ERR_NULL_POINTER
 * (params, found), CW_ERR_STRUCT_SIZE, CW_ERR_BUFFER_TOO_SMALL (len <
 * *found: *found is set, nothing else is written). */
CW_API int cw_temperature_params_check(const cw_temperature_params* params, cw_check* out,
                                       size_t len, size_t* found);

/* ------------------------------------------------------------------ damage */

/* Surface damage indices of a solved contact (any model, any grid;
 * doc/theory/damage.md): per element CONTACT's RCF index and the T_gamma
 * density, per contact FI_surf (Ekberg, Kabo & Andersson 2002), T_gamma =
 * W_macro and the Whole Life Rail Model's damage per pass (Burstow 2004). */

/* cw_damage_get_field: one value per element at [i + j*nx] */
#define CW_DAMAGE_FIELD_RCF_INDEX 0       /* -0.5 outside the contact; in it
                                             max(-0.5, (|p_t| - k_yield)/p_n) [-] */
#define CW_DAMAGE_FIELD_T_GAMMA_DENSITY 1 /* frictional work per rolled distance per area,
                                             work_consistent / area [Pa]; sums (x area)
                                             to W_macro */

typedef struct cw_damage_params {
    size_t struct_size;      /* set by cw_damage_params_init */
    double k_yield;          /* surface shear yield stress k [Pa] in (0, 1e12]; default 0:
                                must be set */
    /* Burstow's damage per pass against T_gamma [N]: 0 up to wlrm_onset,
     * rising linearly to wlrm_peak_damage at wlrm_peak, falling linearly to 0
     * at wlrm_zero, 0 beyond. Defaults 20 N, 65 N, 175 N, 1e-5: a published
     * form of Burstow's function (its source and the 15 N onset also quoted:
     * doc/theory/damage.md). 0 <= onset < peak < zero <= 1e6 N, peak damage
     * in [0, 1]. */
    double wlrm_onset, wlrm_peak, wlrm_zero, wlrm_peak_damage;
} cw_damage_params;

/* Fills the defaults above. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_damage_params_init(cw_damage_params* params);

typedef struct cw_damage_result {
    size_t struct_size;     /* set by cw_damage_result_init */
    double rcf_index_max;   /* largest RCF index of the contact [-]; -0.5 without contact */
    double x_rcf_max, y_rcf_max; /* its element's centre [m] (first in storage order) */
    double mu_eff;          /* sqrt(Fx^2 + Fy^2) / N [-] (0 without load) */
    double FI_surf;         /* mu_eff - 2 A k_yield / (3 N), A = pi a b, on a gap grid the
                               contact elements' area [-] (0 without load) */
    double contact_area;    /* A [m^2] */
    double T_gamma;         /* W_macro [N = J/m] */
    double wlrm_damage;     /* damage per pass from T_gamma [-] */
} cw_damage_result;

/* Zeroes the result and sets struct_size. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_damage_result_init(cw_damage_result* result);

/* Workspace and results of the damage indices of one contact, for one
 * solver grid. All memory is allocated here. Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_OUT_OF_MEMORY. */
typedef struct cw_damage cw_damage;
CW_API int cw_damage_create(const cw_solver* solver, cw_damage** damage);
/* Frees the handle; NULL is a no-op. Errors: none (always CW_OK). */
CW_API int cw_damage_destroy(cw_damage* damage);

/* The indices of the last CW_SOLVE_FULL solve of solver (a pure function of
 * it and params). result may be NULL. Allocates nothing. Errors:
 * CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE, CW_ERR_GRID_MISMATCH,
 * CW_ERR_NO_SOLUTION, CW_ERR_NO_WORK, CW_ERR_INVALID_INPUT (a parameter,
 * named in the message). After an error the handle holds no indices. */
CW_API int cw_damage_compute(cw_damage* damage, const cw_solver* solver,
                             const cw_damage_params* params, cw_damage_result* result);

/* One CW_DAMAGE_FIELD_* of the last compute into out[i + j*nx], out_len >=
 * nx*ny. Errors: CW_ERR_NULL_POINTER, CW_ERR_UNKNOWN_OPTION,
 * CW_ERR_NO_SOLUTION (no compute yet), CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_damage_get_field(const cw_damage* damage, int field, double* out, size_t out_len);

/* Copies the result of the last compute. Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_STRUCT_SIZE, CW_ERR_NO_SOLUTION. */
CW_API int cw_damage_get_result(const cw_damage* damage, cw_damage_result* result);

/* Detailed message of the last error on this handle, as cw_solver_last_error. */
CW_API const char* cw_damage_last_error(const cw_damage* damage);

/* Checks params as cw_temperature_params_check does (the same out, len and
 * found): k_yield below 1e6 Pa (CW_CHECK_YIELD_STRESS: MPa typed as Pa?)
 * and wlrm_onset, wlrm_peak, wlrm_zero in (0, 1) N
 * (CW_CHECK_WLRM_THRESHOLD: kN typed as N?). k_yield = 0 (not set) is left
 * to cw_damage_compute's error. Prints nothing; cw_damage_compute never
 * calls it. Errors: CW_ERR_NULL_POINTER (params, found),
 * CW_ERR_STRUCT_SIZE, CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_damage_params_check(const cw_damage_params* params, cw_check* out, size_t len,
                                  size_t* found);

#endif /* CREEPWORK_SURFACE_H */
