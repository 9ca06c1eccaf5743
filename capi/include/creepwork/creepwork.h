/*
 * creepwork -- creep forces, creep moment and frictional-work distributions
 * of a wheel rolling on a rail, by Kalker's simplified theory (FASTSIM, 1982)
 * extended to the moment and an energy-consistent work map.
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
 *             Distribution in Rolling Contact With Slip; README.md, "How
 *             to cite") prints the force on the rail.
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
CW_API const char* cw_version_string(void); /* "1.2.0", static */

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
                                 uniform grid and G, nu needed */
#define CW_MODEL_CALIBRATED 2 /* simplified theory calibrated to the exact theory */

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
#define CW_WORK_NON_POSITIVE 2 /* W_macro <= 0 with dissipation (three-flexibility defect):
                                  energy-consistent map set to zero */

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
} cw_params;

/* Defaults: steel (G = 82e9 Pa, nu = 0.28), mu = 0.3, a = b = 6e-3 m,
 * N = 80e3 N, zero creepage, parabolic pressure, rolling towards +x.
 * Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_params_init(cw_params* params);

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
} cw_result;

/* Zeroes the result and sets struct_size. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_result_init(cw_result* result);

/* ----------------------------------------------------------------- solver */

typedef struct cw_solver cw_solver;

/* Creates a solver for one grid: all memory is allocated here, none in
 * solve. message (may be NULL) receives a NUL-terminated explanation of an
 * error, truncated to message_len bytes. A CW_GRID_GAP solver makes the
 * exact model's memory here (its only model).
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
 * from G, nu), no other model and no Jacobian (CW_ERR_INVALID_INPUT);
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
 * struct_size). len = 0 asks for the count only (out may then be NULL). Off a
 * gap grid a contact is one patch (centroid at the ellipse centre).
 * Allocates nothing. Errors: CW_ERR_NULL_POINTER (solver, count),
 * CW_ERR_NO_SOLUTION, CW_ERR_STRUCT_SIZE, CW_ERR_BUFFER_TOO_SMALL (len <
 * *count: *count is set, nothing else is written). */
CW_API int cw_solver_get_patches(const cw_solver* solver, cw_patch* out, size_t len,
                                 size_t* count);

/* Detailed message of the last error on this handle ("" after success);
 * owned by the handle, valid until its next call. NULL solver gives a
 * static message. */
CW_API const char* cw_solver_last_error(const cw_solver* solver);

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

CW_API const char* cw_accumulator_last_error(const cw_accumulator* accumulator);

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

CW_API const char* cw_batch_last_error(const cw_batch* batch);

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

/* ----------------------------------------------------------- model memory */

/* Makes one model's memory now, so that its solves allocate nothing
 * afterwards. CW_MODEL_FASTSIM: nothing to do (made by create).
 * CW_MODEL_EXACT: influence tables, FFT plans and spectra, Krylov basis and
 * every workspace of the grid and of its coarser levels (memory linear in
 * nx*ny, doc/theory/exact.md); without prepare the first exact solve
 * makes them. CW_MODEL_CALIBRATED: its FASTSIM march workspace (every
 * grid). Idempotent. Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_UNKNOWN_OPTION (model), CW_ERR_INVALID_INPUT (CW_MODEL_EXACT on
 * CW_GRID_KALKER_STRIPS; another model on CW_GRID_GAP),
 * CW_ERR_GRID_OUT_OF_RANGE (exact: nx or ny > CW_MAX_EXACT_CELLS),
 * CW_ERR_OUT_OF_MEMORY. */
CW_API int cw_solver_prepare(cw_solver* solver, int model);

/* cw_solver_prepare for the solver of every thread of a batch. */
CW_API int cw_batch_prepare(cw_batch* batch, int model);

/* -------------------------------------------------------------- Jacobians */

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
 * Where an element sits exactly on the traction bound the derivative is the
 * one of the state the solve found (doc/theory/jacobians.md). Needs
 * normal_force > 0 when mu > 0 (the forces are not differentiable in N at
 * N = 0): CW_ERR_INVALID_INPUT. Allocates nothing (FASTSIM, calibrated;
 * exact as cw_solver_solve). Errors: those of cw_solver_solve, and
 * CW_ERR_NULL_POINTER (jacobian), CW_ERR_BUFFER_TOO_SMALL (jacobian_len <
 * CW_JACOBIAN_LEN). On error nothing is written to jacobian or result. */
CW_API int cw_solver_solve_jacobian(cw_solver* solver, const cw_params* params, int mode,
                                    cw_result* result, double* jacobian, size_t jacobian_len);

/* ------------------------------------------------------------------- wear */

/* Wear of a solved contact (any model) by the USFD or Archard law applied
 * element by element to its frictional work, and its accumulation on the
 * host's wheel or rail profile over many passes (doc/theory/wear.md).
 *
 * A "pass" is one passage of the body's material through the contact: one
 * axle passage for the rail, one wheel revolution for the wheel. Depths per
 * pass are therefore the same numbers for both bodies; a wheel's depth per
 * rolled distance is its depth per pass / (2 pi R), and a wheel that rolls a
 * distance D makes D / (2 pi R) passes. Depth is measured normal to the
 * contact plane; the profile accumulator also gives it along the profile's
 * height axis (vertical on a rail, radial on a wheel) from the contact
 * angle. The per-element "rate" is the mass worn per unit contact area per
 * unit rolled distance [kg/m^3]; element (i, j), strip j of width dy_j,
 * loses rate * area / (rho * dy_j) of depth per pass. */

/* cw_wear_params.law */
#define CW_WEAR_USFD 0        /* USFD T_gamma/A law (Braghin et al., Wear 261 (2006) 1253) */
#define CW_WEAR_ARCHARD_KTH 1 /* Archard, k from the KTH map (Jendel, Wear 253 (2002) 89) */

/* cw_wear_params.source: the frictional work the law is fed with */
#define CW_WEAR_SOURCE_CONSISTENT 0 /* energy-consistent map (default): sums to W_macro */
#define CW_WEAR_SOURCE_PAPER 1      /* paper's eq. 36 map, negative values taken as 0 */
#define CW_WEAR_SOURCE_SLIP 2       /* the model's traction x micro-slip, -(px sx + py sy) area */

/* cw_wear_get_field: one value per element at [i + j*nx] */
#define CW_WEAR_FIELD_RATE 0         /* mass worn per area per rolled distance [kg/m^3] */
#define CW_WEAR_FIELD_DEPTH 1        /* depth per pass [m]: rate * area / (rho dy_j) */
#define CW_WEAR_FIELD_MASS 2         /* mass per pass [kg]: rate * area * pass_length */
#define CW_WEAR_FIELD_WORK_DENSITY 3 /* T_gamma/A: work per rolled distance / area [Pa] */
#define CW_WEAR_FIELD_SLIDING 4      /* sliding per rolled distance [-]: the slip that
                                        dissipates the work under the element's traction,
                                        work / (|p| area) (|s| with CW_WEAR_SOURCE_SLIP);
                                        sliding velocity = this * rolling_speed */

/* cw_wear_get_regimes: per element */
#define CW_WEAR_REGIME_NONE 0 /* no wear (exterior, adhesion, zero work) */
/* USFD: 1 mild (T_gamma/A < usfd_t1), 2 severe (usfd_t1..usfd_t2), 3 catastrophic.
 * KTH:  1 v < kth_v1, 2 kth_v1 <= v <= kth_v2, 3 v > kth_v2, 4 seizure
 *       (pressure > kth_seizure_ratio * hardness), v the sliding velocity. */

/* cw_wear_profile_get_depth kinds */
#define CW_WEAR_DEPTH_NORMAL 0 /* normal to the surface [m] */
#define CW_WEAR_DEPTH_HEIGHT 1 /* along the profile's height axis: normal / cos(gamma) [m] */

#define CW_WEAR_MAX_CONTACT_ANGLE 1.4835298641951802 /* 85 degrees [rad] */
#define CW_WEAR_MAX_PASSES 1e15                      /* per cw_wear_profile_add call */
#define CW_WEAR_MAX_PROFILE_NODES 10000000

typedef struct cw_wear_params {
    size_t struct_size;   /* set by cw_wear_params_init */
    int law;              /* CW_WEAR_USFD (default) or CW_WEAR_ARCHARD_KTH */
    int source;           /* CW_WEAR_SOURCE_CONSISTENT (default), _PAPER or _SLIP */
    double density;       /* rho [kg/m^3] in [1, 1e5]; default 7800 (steel) */
    double rolling_speed; /* V [m/s]: Archard only (sliding velocity = sliding * V),
                             in (0, 1e3] there; >= 0 and unused for USFD. Default 0 */
    double pass_length;   /* rolled distance of one pass [m] in (0, 1e6], for the mass
                             per pass only: 2 pi R for a wheel (kg per revolution);
                             default 1 (rail: kg per metre of rail per axle passage) */
    /* USFD, SI units (Braghin et al. 2006 print ug/(m mm^2) and N/mm^2:
     * 1 ug/(m mm^2) = 1e-3 kg/m^3, 1 N/mm^2 = 1e6 Pa). Defaults R8T/900A:
     *   rate = usfd_k1 * T_gamma/A               T_gamma/A <  usfd_t1
     *   rate = usfd_k2                           usfd_t1 <= T_gamma/A <= usfd_t2
     *   rate = max(0, usfd_k3 * T_gamma/A - usfd_c3)   above usfd_t2 */
    double usfd_k1;       /* [kg/(N m)] default 5.3e-9  (5.3 ug/(m mm^2) per N/mm^2) */
    double usfd_t1;       /* [Pa]       default 10.4e6  (10.4 N/mm^2) */
    double usfd_k2;       /* [kg/m^3]   default 55.0e-3 (55.0 ug/(m mm^2)) */
    double usfd_t2;       /* [Pa]       default 77.2e6  (77.2 N/mm^2), >= usfd_t1 */
    double usfd_k3;       /* [kg/(N m)] default 61.9e-9 */
    double usfd_c3;       /* [kg/m^3]   default 4.7787  (4778.7 ug/(m mm^2)) */
    /* Archard with the KTH map: volume = k N s / H per element (doc/theory/wear.md);
     * coefficients in [0, 1e6]. Defaults: Jendel's regime boundaries and the
     * middles of his k bands. */
    double hardness;      /* H [Pa] in [1e6, 1e12]; default 2.5e9 (about 255 HB) */
    double kth_v1;        /* [m/s] default 0.2 */
    double kth_v2;        /* [m/s] default 0.7, >= kth_v1 */
    double kth_seizure_ratio; /* seizure above pressure > ratio * H; default 0.8 */
    double kth_k_seizure; /* [-] default 350e-4 (Jendel: 300-400e-4) */
    double kth_k_slow;    /* [-] default 5.5e-4 (1-10e-4), v < kth_v1 */
    double kth_k_severe;  /* [-] default 35e-4  (30-40e-4), kth_v1 <= v <= kth_v2 */
    double kth_k_fast;    /* [-] default 5.5e-4 (1-10e-4), v > kth_v2 */
} cw_wear_params;

/* Fills the defaults above. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_wear_params_init(cw_wear_params* params);

typedef struct cw_wear_result {
    size_t struct_size;         /* set by cw_wear_result_init */
    double mass_per_distance;   /* [kg/m] sum of rate * area: per metre rolled */
    double mass_per_pass;       /* [kg] mass_per_distance * pass_length */
    double volume_per_distance; /* [m^3/m] mass_per_distance / rho */
    double max_depth;           /* [m] largest strip depth per pass */
    double work;                /* [J/m] frictional work the law was fed with */
    double regime_area[4];      /* [m^2] contact area in regime 1..4 (index regime-1) */
    int law, source;            /* as computed */
} cw_wear_result;

/* Zeroes the result and sets struct_size. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_wear_result_init(cw_wear_result* result);

/* Workspace and results of the wear of one contact, for one solver grid.
 * All memory is allocated here. Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_OUT_OF_MEMORY. */
typedef struct cw_wear cw_wear;
CW_API int cw_wear_create(const cw_solver* solver, cw_wear** wear);
CW_API int cw_wear_destroy(cw_wear* wear); /* NULL: no-op */

/* The wear of the last CW_SOLVE_FULL solve of solver (a pure function of it
 * and params; the solver is not changed). result may be NULL. Allocates
 * nothing on success. Errors: CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE,
 * CW_ERR_GRID_MISMATCH (solver's grid is not wear's), CW_ERR_NO_SOLUTION,
 * CW_ERR_NO_WORK (a CW_SOLVE_FORCES solve), CW_ERR_UNKNOWN_OPTION (law,
 * source), CW_ERR_INVALID_INPUT (a parameter, named in the message),
 * CW_ERR_NUMERIC. After an error the handle holds no wear. */
CW_API int cw_wear_compute(cw_wear* wear, const cw_solver* solver, const cw_wear_params* params,
                           cw_wear_result* result);

/* One CW_WEAR_FIELD_* of the last compute into out[i + j*nx], out_len >=
 * nx*ny. Errors: CW_ERR_NULL_POINTER, CW_ERR_UNKNOWN_OPTION,
 * CW_ERR_NO_SOLUTION (no compute yet), CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_wear_get_field(const cw_wear* wear, int field, double* out, size_t out_len);

/* CW_WEAR_REGIME_* (0..4) per element into out[i + j*nx], out_len >= nx*ny.
 * Errors: as cw_wear_get_field. */
CW_API int cw_wear_get_regimes(const cw_wear* wear, int* out, size_t out_len);

/* The lateral wear profile, per strip j < ny: strip centre y [m], width
 * [m], depth per pass [m] (sum over the strip), and the paper's assumption
 * for comparison: the same worn cross-section per pass spread as a parabola
 * (3V/4b)(1 - y^2/b^2) over [-b, b], averaged over the strip [m]. Each of
 * y, width, depth, parabola may be NULL; len >= ny. Errors:
 * CW_ERR_NULL_POINTER (wear), CW_ERR_NO_SOLUTION, CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_wear_get_strips(const cw_wear* wear, double* y, double* width, double* depth,
                              double* parabola, size_t len);

/* Copies the totals of the last compute. Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_STRUCT_SIZE, CW_ERR_NO_SOLUTION. */
CW_API int cw_wear_get_result(const cw_wear* wear, cw_wear_result* result);

CW_API const char* cw_wear_last_error(const cw_wear* wear);

/* ---------------------------------------------- wear on a profile grid */

/* Wear depth accumulated over many passes on a host's profile grid: nodes
 * s[k] [m] of the host's lateral profile coordinate, strictly increasing,
 * any spacing; node k owns the cell between the midpoints to its neighbours
 * (end cells extend half a spacing beyond the end nodes). A pass puts
 * strip j (centre y_j, width dy_j, depth d_j) on
 *   s = s0 + orientation * (y_j -+ dy_j/2) * cos(contact_angle),
 * and spreads its worn cross-section d_j dy_j uniformly over that interval
 * (doc/theory/wear.md). Sums are exact: the depths read do not depend on the
 * order of the calls, on how the same passes are split between calls (pass
 * counts that add up exactly, e.g. integers), or on merging: bitwise (only
 * products passes * depth below about 1e-120 m lose low bits). */
typedef struct cw_wear_profile cw_wear_profile;

typedef struct cw_wear_profile_totals {
    size_t struct_size;  /* set by cw_wear_profile_totals_init */
    double passes;       /* sum of the passes added */
    double volume;       /* worn cross-section added [m^2]: volume per metre of rail
                            (or of wheel circumference) */
    double volume_lost;  /* part of volume that fell outside the grid [m^2] */
    int64_t adds;        /* successful add calls (merged ones included) */
} cw_wear_profile_totals;

/* Zeroes the totals and sets struct_size. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_wear_profile_totals_init(cw_wear_profile_totals* totals);

/* n in 2..CW_WEAR_MAX_PROFILE_NODES finite nodes within +-1e6 m, strictly
 * increasing (copied). message as cw_solver_create. Errors:
 * CW_ERR_NULL_POINTER, CW_ERR_INVALID_INPUT, CW_ERR_OUT_OF_MEMORY. */
CW_API int cw_wear_profile_create(const double* s, size_t n, cw_wear_profile** profile,
                                  char* message, size_t message_len);
CW_API int cw_wear_profile_destroy(cw_wear_profile* profile); /* NULL: no-op */
/* Back to zero. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_wear_profile_reset(cw_wear_profile* profile);

/* Adds passes times the lateral profile of wear's last compute.
 *   s0            profile coordinate of the patch centre [m], within +-1e6
 *   orientation   +1: s grows with the contact's y; -1: s falls
 *   contact_angle angle between the contact plane and the s axis [rad],
 *                 |.| <= CW_WEAR_MAX_CONTACT_ANGLE; 0 when s runs along the
 *                 surface (then normal and height depth agree)
 *   passes        in [0, CW_WEAR_MAX_PASSES]: axle passages (rail) or wheel
 *                 revolutions (wheel: rolled distance / (2 pi R))
 * Allocates nothing. Errors: CW_ERR_NULL_POINTER, CW_ERR_NO_SOLUTION (no
 * compute on wear), CW_ERR_INVALID_INPUT, CW_ERR_NUMERIC (a depth would
 * exceed the exact range, 2^120 m). On error nothing changes. */
CW_API int cw_wear_profile_add(cw_wear_profile* profile, const cw_wear* wear, double s0,
                               int orientation, double contact_angle, double passes);

/* The same from the caller's strips (any lateral distribution, e.g. another
 * code's or the parabola of cw_wear_get_strips): count strips with centres
 * y [m] (finite), widths [m] (> 0) and depths per pass [m] (>= 0), each
 * array of length count >= 1. Errors: as cw_wear_profile_add (not
 * CW_ERR_NO_SOLUTION). */
CW_API int cw_wear_profile_add_strips(cw_wear_profile* profile, const double* y,
                                      const double* width, const double* depth, size_t count,
                                      double s0, int orientation, double contact_angle,
                                      double passes);

/* Accumulated depth per node [m], CW_WEAR_DEPTH_NORMAL or _HEIGHT, into
 * out[k], out_len >= n (correctly rounded from the exact sums). Errors:
 * CW_ERR_NULL_POINTER, CW_ERR_UNKNOWN_OPTION, CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_wear_profile_get_depth(const cw_wear_profile* profile, int kind, double* out,
                                     size_t out_len);
/* Errors: CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE. */
CW_API int cw_wear_profile_get_totals(const cw_wear_profile* profile,
                                      cw_wear_profile_totals* totals);

/* into += from (same nodes), exactly: e.g. the accumulators of parallel
 * workers. Errors: CW_ERR_NULL_POINTER, CW_ERR_GRID_MISMATCH, CW_ERR_NUMERIC.
 * On error into is unchanged. */
CW_API int cw_wear_profile_merge(cw_wear_profile* into, const cw_wear_profile* from);

/* The exact state as 64-bit words, to move it between processes (MPI):
 * cw_wear_profile_state_size gives the number of words (5 + 30 + 20 n);
 * cw_wear_profile_get_state copies it (len >= that), and
 * cw_wear_profile_add_state adds a state saved from an accumulator on the
 * same nodes (checked by a fingerprint of the nodes), as merge would.
 * Errors: CW_ERR_NULL_POINTER, CW_ERR_BUFFER_TOO_SMALL, CW_ERR_GRID_MISMATCH
 * (not a state of these nodes), CW_ERR_NUMERIC. */
CW_API int cw_wear_profile_state_size(const cw_wear_profile* profile, size_t* words);
CW_API int cw_wear_profile_get_state(const cw_wear_profile* profile, uint64_t* state,
                                     size_t len);
CW_API int cw_wear_profile_add_state(cw_wear_profile* profile, const uint64_t* state,
                                     size_t len);

CW_API const char* cw_wear_profile_last_error(const cw_wear_profile* profile);

/* The profile update, a helper the host calls when it chooses:
 *   new_profile[k] = old_profile[k] - smooth(depth)[k]
 * on n nodes s (as cw_wear_profile_create), with smooth a volume-conserving
 * Gaussian filter of standard deviation smoothing [m] (0: none; <= 1e6):
 * each cell's worn cross-section is spread over the cells within 5
 * smoothing lengths in proportion to exp(-(s_k - s_m)^2/(2 smoothing^2)) -
 * exp(-12.5) (cut continuously at 5 smoothing lengths) times their widths,
 * so sum (old - new) * width = sum depth * width to rounding. The
 * sign is the host's: pass heights that wear reduces (rail head height,
 * wheel radius) and the depth of the same direction. new_profile may be
 * old_profile or depth; new_len >= n. Allocates a workspace of up to 2n
 * doubles. Errors: CW_ERR_NULL_POINTER, CW_ERR_INVALID_INPUT,
 * CW_ERR_BUFFER_TOO_SMALL, CW_ERR_NUMERIC (a value overflows),
 * CW_ERR_OUT_OF_MEMORY; on error new_profile is untouched. */
CW_API int cw_wear_profile_update(const double* s, const double* old_profile,
                                  const double* depth, size_t n, double smoothing,
                                  double* new_profile, size_t new_len, char* message,
                                  size_t message_len);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* CREEPWORK_H */
