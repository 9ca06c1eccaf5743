/* creepwork: transient rolling -- part of the C API, included by <creepwork/creepwork.h>
 * (include that header, not this one). The conventions of creepwork.h hold. */
#ifndef CREEPWORK_H
#error "include <creepwork/creepwork.h>, not <creepwork/creepwork_transient.h>"
#endif
#ifndef CREEPWORK_TRANSIENT_H
#define CREEPWORK_TRANSIENT_H

/* ------------------------------------------------------ transient rolling */

/* Kalker's exact half-space theory with memory (doc/theory/transient.md):
 * the tangential tractions of one time step depend on those of the last,
 * as in the start of rolling from a shifted contact, short-pitch
 * oscillations or an integrator's steps at the adhesion limit. Contact-fixed
 * coordinates (CONTACT's T = 2) on a gap grid (CW_GRID_GAP): the contact
 * stays on the grid and the material moves through it from +x (the leading
 * edge) to -x by dq per step; dq = 0 is a shift (Cattaneo's problem); or
 * an elliptic contact on the uniform grid (CW_GRID_UNIFORM). Or
 * world-fixed (T = 1, cw_transient_set_coordinates): the grid stays with
 * the material and the geometry moves over it.
 *
 * The handle holds a committed state (the tractions of the last committed
 * step). cw_transient_input computes one step from it without changing it
 * (a trial, as often as an integrator retries); cw_transient_commit makes
 * the last trial the state; cw_transient_rewind drops it. A trial depends
 * only on the committed state and its inputs: repeated, it gives the same
 * bits. cw_transient_save / cw_transient_restore give and take the
 * committed state as an array of 64-bit words (this library build's
 * layout), for a host's checkpoints. */

typedef struct cw_transient cw_transient;

/* cw_transient_input.prescribe */
#define CW_PRESCRIBE_CREEPAGES 0 /* xi_x, xi_y, phi given */
#define CW_PRESCRIBE_FX 1        /* Fx given: xi_x found; xi_y, phi given */
#define CW_PRESCRIBE_FORCES 2    /* Fx and Fy given: xi_x, xi_y found; phi given */

typedef struct cw_transient_input {
    size_t struct_size; /* set by cw_transient_input_init */
    double dq;          /* distance rolled in the step [m], 0 <= dq <= the grid's dx; 0 (the
                           default) is a shift */
    double xi_x, xi_y;  /* rolling (dq > 0): creepages [-]; a shift: the rigid shift along
                           x, y [m] */
    double phi;         /* rolling: spin creepage [1/m]; a shift: rotation [rad] */
    int prescribe;      /* CW_PRESCRIBE_* (default CW_PRESCRIBE_CREEPAGES) */
    double Fx, Fy;      /* prescribed forces on the wheel [N], |F| < mu N; met to within
                           params->tolerance (default 1e-8) times mu N */
} cw_transient_input;

typedef struct cw_transient_result {
    size_t struct_size;     /* set by cw_transient_result_init */
    double xi_x, xi_y, phi; /* the step's creepages (shift): as given, the prescribed
                               forces' found */
    double Fx, Fy;          /* creep force on the wheel [N] */
    double Mz;              /* creep moment about the grid's origin, on the wheel [N m] */
    int n_contact, n_adhesion, n_slip;
    double W_step;          /* frictional work of the step [J], energy-consistent: the work of
                               the step's rigid displacement under the mean of the old and
                               new tractions less the change of the elastic energy; in
                               steady rolling dq (W_macro - phi spin_offset dq Fy), W_macro
                               the steady model's */
    int iterations;         /* Newton steps of the tangential problem, all force iterations */
    int force_iterations;   /* Newton steps on the prescribed forces */
    double residual;        /* final relative residual of the tangential problem */
    int64_t steps_committed;/* committed steps since the last start or restore */
    double W_slip;          /* dissipation of the step's own slip [J]: |traction| |slip|
                               summed over the slipping elements times their area
                               (CONTACT's frictional work). It weighs the slip by the
                               new traction, W_step by the mean of the old and new: in
                               steady rolling W_slip is the paper's map, below W_step;
                               at a shift from rest it is 2 W_step. FASTSIM's step is
                               explicit: W_slip = W_step */
} cw_transient_result;

/* Fills defaults and struct_size. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_transient_input_init(cw_transient_input* step);
/* Zeroes the result and sets struct_size. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_transient_result_init(cw_transient_result* result);

/* Creates the transient contact of grid (CW_GRID_GAP) and params
 * (model CW_MODEL_EXACT, or CW_MODEL_FASTSIM for FASTSIM's transient form
 * (doc/theory/transient.md); the gap, normal load and method, mu > 0, G, nu,
 * tolerance, max_iterations and spin_offset are read, the creepages and
 * rolling_direction are not), or of an elliptic contact on the exact
 * model's uniform grid (CW_GRID_UNIFORM: the semi-axes a, b and
 * normal_force, as cw_solver's exact model reads them; it runs on that
 * grid's elements with Hertz's undeformed distance of the ellipse): solves
 * the normal problem and starts from zero tractions. All memory is allocated here. message (may be NULL)
 * receives an explanation of an error, truncated to message_len bytes.
 * Errors: CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE, CW_ERR_UNKNOWN_OPTION,
 * CW_ERR_GRID_OUT_OF_RANGE, CW_ERR_INVALID_INPUT (another grid kind or
 * model, mu = 0, no contact, a bad input), CW_ERR_NOT_CONVERGED,
 * CW_ERR_OUT_OF_MEMORY. On error *transient is set to NULL. */
CW_API int cw_transient_create(const cw_grid* grid, const cw_params* params,
                               cw_transient** transient, char* message, size_t message_len);

/* Frees everything; NULL is a no-op. Always CW_OK. */
CW_API int cw_transient_destroy(cw_transient* transient);

/* Starts from zero tractions (no committed step). Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_transient_start_zero(cw_transient* transient);

/* Starts from the steady-rolling solution of step's creepages or forces
 * (dq is not read) and writes it to result (may be NULL). Errors:
 * CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE, CW_ERR_UNKNOWN_OPTION
 * (prescribe), CW_ERR_INVALID_INPUT, CW_ERR_NOT_CONVERGED. On error the
 * committed state is unchanged. */
CW_API int cw_transient_start_steady(cw_transient* transient, const cw_transient_input* step,
                                     cw_transient_result* result);

/* Computes one step from the committed state (a trial) into result (may
 * be NULL) and the fields. Errors: CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE,
 * CW_ERR_UNKNOWN_OPTION (prescribe), CW_ERR_INVALID_INPUT (dq outside [0,
 * dx], a force at or beyond mu N, NaN), CW_ERR_NOT_CONVERGED. On error the
 * committed state is unchanged and there is no trial. */
CW_API int cw_transient_step(cw_transient* transient, const cw_transient_input* step,
                             cw_transient_result* result);

/* Makes the last trial the committed state. Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_NO_SOLUTION (no trial since the last commit, rewind or start). */
CW_API int cw_transient_commit(cw_transient* transient);

/* Drops the last trial; the committed state stays. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_transient_rewind(cw_transient* transient);

/* The length of a saved state in 64-bit words into *words. Errors:
 * CW_ERR_NULL_POINTER. */
CW_API int cw_transient_state_size(const cw_transient* transient, size_t* words);

/* Writes the committed state to out (len >= cw_transient_state_size
 * words). Errors: CW_ERR_NULL_POINTER, CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_transient_save(const cw_transient* transient, uint64_t* out, size_t len);

/* Makes a saved state (len words) the committed state and drops any trial.
 * Errors: CW_ERR_NULL_POINTER, CW_ERR_INVALID_INPUT (words not saved by a
 * handle of the same grid, load and friction). On error the handle is
 * unchanged. */
CW_API int cw_transient_restore(cw_transient* transient, const uint64_t* state, size_t len);

/* Copies a field of the last step (or steady start) at [i + j*nx]:
 * CW_FIELD_X, CW_FIELD_Y, CW_FIELD_PZ, CW_FIELD_PX, CW_FIELD_PY,
 * CW_FIELD_SX, CW_FIELD_SY as the slip of the step [m] (0 in adhesion and
 * outside the contact), and CW_FIELD_WORK_CONSISTENT as the frictional work
 * of each element over the step [J]: its slip's dissipation scaled to add up
 * to W_step (0 in adhesion, outside the contact, and everywhere when no
 * element slips; FASTSIM: its slip's dissipation, unscaled). Errors: CW_ERR_NULL_POINTER, CW_ERR_NO_SOLUTION,
 * CW_ERR_UNKNOWN_OPTION (another field), CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_transient_get_field(const cw_transient* transient, int field, double* out,
                                  size_t len);

/* Copies the element states of the last step (or steady start) at [i +
 * j*nx], as cw_solver_get_state. Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_NO_SOLUTION, CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_transient_get_state(const cw_transient* transient, int* out, size_t len);

/* The derivative of the last step (or steady start) by its inputs, for an
 * implicit integrator, row-major: jacobian[3*r + c] = d(output r)/d(input c)
 * (CW_TRANSIENT_JACOBIAN_LEN values). With CW_PRESCRIBE_CREEPAGES rows are
 * Fx, Fy, Mz [N, N, N m] and columns xi_x, xi_y, phi (rolling; a shift:
 * the shift along x, y [m] and the rotation [rad]). A prescribed force and
 * its found creepage trade places: with CW_PRESCRIBE_FX row 0 is xi_x and
 * column 0 is Fx; with CW_PRESCRIBE_FORCES also row 1 is xi_y and column 1
 * Fy. The derivative of the converged discrete step (no extra steps; the
 * state and the trial are unchanged). Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_NO_SOLUTION, CW_ERR_BUFFER_TOO_SMALL, CW_ERR_NOT_CONVERGED (a
 * prescribed force in full slip), CW_ERR_NUMERIC, CW_ERR_INVALID_INPUT
 * (CW_MODEL_FASTSIM: the step Jacobian is the exact model's). On error
 * nothing is written. */
#define CW_TRANSIENT_JACOBIAN_LEN 9
CW_API int cw_transient_jacobian(cw_transient* transient, double* jacobian, size_t len);

/* cw_transient_set_coordinates */
#define CW_COORDINATES_CONTACT 0 /* contact-fixed (CONTACT's T = 2): the default */
#define CW_COORDINATES_WORLD 1   /* world-fixed (T = 1): the grid stays with the material */

/* Chooses the coordinates and starts from zero tractions with the geometry
 * at its start. World-fixed (doc/theory/transient.md): the geometry (the
 * gap) moves over the grid by dq towards +x per step, interpolated between
 * the elements when dq is not a multiple of dx, and the normal problem is
 * solved per step; the problem runs on the whole grid, which must hold the
 * contact over the run; the spin's rigid slip turns about the geometry's
 * moved origin. With dq = dx the two coordinates give the same steps to the
 * solver's tolerance. Errors: CW_ERR_NULL_POINTER, CW_ERR_UNKNOWN_OPTION
 * (coordinates), CW_ERR_INVALID_INPUT (CW_COORDINATES_WORLD with
 * CW_MODEL_FASTSIM: FASTSIM's transient form is contact-fixed),
 * CW_ERR_NOT_CONVERGED (the normal problem). On error the handle is
 * unchanged. */
CW_API int cw_transient_set_coordinates(cw_transient* transient, int coordinates);

/* Wear over the steps (doc/theory/transient.md): adds the wear of the last
 * step (or steady start) to the handle's accumulated wear, by the law of
 * params (cw_wear_params; its pass_length is not read): each element's
 * frictional work of the step (CW_FIELD_WORK_CONSISTENT) per rolled
 * distance dq of the step, the mass it loses in the step its rate times
 * its area times dq. A shift (dq = 0) adds none. *step_mass (may be NULL)
 * receives the step's mass [kg]. Add each step once, after it is
 * committed. Errors: CW_ERR_NULL_POINTER (params), CW_ERR_STRUCT_SIZE,
 * CW_ERR_UNKNOWN_OPTION, CW_ERR_INVALID_INPUT (a bad law), CW_ERR_NO_SOLUTION.
 * On error nothing is added. */
CW_API int cw_transient_add_wear(cw_transient* transient, const cw_wear_params* params,
                                 double* step_mass);

/* The accumulated wear: the mass per element [kg] at [i + j*nx] into
 * mass_map (may be NULL; len >= nx*ny) and the total [kg] into *mass (may
 * be NULL). The grid holds contact-fixed or world-fixed (material) places as
 * the coordinates are. Errors: CW_ERR_NULL_POINTER, CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_transient_get_wear(const cw_transient* transient, double* mass_map, size_t len,
                                 double* mass);

/* Sets the accumulated wear to zero. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_transient_reset_wear(cw_transient* transient);

/* Detailed message of the last error on this handle, as cw_solver_last_error. */
CW_API const char* cw_transient_last_error(const cw_transient* transient);

#endif /* CREEPWORK_TRANSIENT_H */
