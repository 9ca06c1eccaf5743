/* creepwork: wheel/rail contact from profiles -- part of the C API, included by <creepwork/creepwork.h>
 * (include that header, not this one). The conventions of creepwork.h hold. */
#ifndef CREEPWORK_H
#error "include <creepwork/creepwork.h>, not <creepwork/creepwork_wheelrail.h>"
#endif
#ifndef CREEPWORK_WHEELRAIL_H
#define CREEPWORK_WHEELRAIL_H

/* ------------------------------------------------------------ wheel/rail */

/* One wheel on one rail, from the profiles to the forces (doc/wheelrail.md):
 * the contact search, per contact patch its reference point, undeformed
 * distance grid and creepages, and the contact problem on every patch's
 * grid -- Kalker's exact theory, or the fast model (FASTSIM with the
 * semi-Hertzian normal problem); with the vertical force prescribed, the
 * wheelset height is found. Every patch's fields and work maps, and its
 * wear on the rail and wheel profiles, follow from the solution.
 * Conventions are CONTACT's module-1 ones in SI units: track coordinates x
 * along the track, y to the right seen along x, z down; patch frame x, s
 * (lateral, in the tangent plane), n (normal, into the rail); creepages of
 * the rail relative to the wheel; forces on the rail. Made once per pair of
 * profiles, track, wheelset and side; solved for any wheelset position. */
typedef struct cw_wheelrail cw_wheelrail;

#define CW_WHEELRAIL_RIGHT 0 /* cw_wheelrail_params.side */
#define CW_WHEELRAIL_LEFT 1
#define CW_WHEELRAIL_RAIL 0   /* cw_wheelrail_get_profile */
#define CW_WHEELRAIL_WHEEL 1
#define CW_WHEELRAIL_FORCE 0  /* cw_wheelrail_solve: vertical force prescribed */
#define CW_WHEELRAIL_HEIGHT 1 /* cw_wheelrail_solve: wheelset height prescribed */

/* Set by cw_wheelrail_params_init to the Manchester benchmark's set-up
 * (UIC60 rails, S1002 wheels, 1435 mm gauge), dx = ds = 0.2 mm, steel.
 * Fields are only ever appended. */
typedef struct cw_wheelrail_params {
    size_t struct_size;          /* set by cw_wheelrail_params_init */
    int side;                    /* CW_WHEELRAIL_RIGHT (default) or CW_WHEELRAIL_LEFT */
    double gauge_height;         /* [m] gauge point below the rail top (14e-3); <= 0: the
                                    rail profile's origin at (rail_y0, rail_z0) */
    double gauge_width;          /* [m] between the gauge faces (1.435) */
    double cant;                 /* [rad] rail inclination towards the track centre (0) */
    double rail_y0, rail_z0;     /* [m] absolute rail placement (gauge_height <= 0) */
    double rail_dy, rail_dz, rail_roll; /* [m, m, rad] rail deviations (0), in track
                                    coordinates on either side and with either
                                    placement: rail_dy > 0 moves the rail to the
                                    right, so the left rail at -rail_dy under the
                                    mirrored position is the right one's mirror image */
    double curvature;            /* [1/m] track curvature, > 0 in a right-hand curve (0) */
    double flange_back_distance; /* [m] (1.360) */
    double flange_back_position; /* [m] flange back in wheel profile y (-0.070) */
    double nominal_radius;       /* [m] axle to the wheel profile's origin (0.460) */
    double dx, ds;               /* [m] patch grid element sizes (0.2e-3) */
    double a_sep, d_sep, d_comb; /* [rad, m, m] patch separation (pi/2, 8e-3, 4e-3) */
    double mu;                   /* [-] friction coefficient (0.3) */
    double G;                    /* [Pa] combined shear modulus (82e9) */
    double nu;                   /* [-] combined Poisson's ratio (0.28) */
    double tolerance;            /* exact solver's relative tolerance (0: its default) */
    double profile_unit;         /* [m] per length unit of the profiles; 0: a file's own
                                    (SIMPACK: its units; MiniProf, tables: mm), metres
                                    for cw_wheelrail_create_points */
    int model;                   /* CW_MODEL_EXACT (default) or CW_MODEL_FASTSIM */
    int normal_method;           /* CW_NORMAL_EXACT (default) or CW_NORMAL_SEMI_HERTZ; the
                                    fast model is CW_MODEL_FASTSIM with CW_NORMAL_SEMI_HERTZ */
    int solve_mode;              /* CW_SOLVE_FULL (default: every field and the work maps
                                    per patch) or CW_SOLVE_FORCES */
    /* Profiles whose origin or direction is not this module's (doc/wheelrail.md,
     * "Placement"): each point's y becomes (mirror ? -y : y) + offset, in metres
     * after the length unit. A wheel profile's origin lies on its tread, its
     * flange back at flange_back_position: a profile measured from the flange
     * back (MiniProf) takes wheel_y_offset = flange_back_position. */
    double rail_y_offset;        /* [m] added to the rail profile's y (0) */
    double wheel_y_offset;       /* [m] added to the wheel profile's y (0) */
    int mirror_wheel;            /* 1: the wheel profile's y is mirrored before the offset
                                    (measured with y towards the track centre); 0 (default) */
    /* A friction law of the slip speed in every patch (either model;
     * cw_params' fields of the same names): mu is then its mu_kin, and the
     * slip speed of an element its micro-slip times the patch's rolling
     * speed veloc. Polach's law: cw_friction_polach writes these fields of a
     * cw_params, copy them. */
    int friction_law;            /* CW_FRICTION_COULOMB (default), _LINEAR, _RATIONAL or
                                    _EXPONENTIAL */
    double mu_e1, s_h1;          /* [-], [m/s] the law's first term (0, 0) */
    double mu_e2, s_h2;          /* [-], [m/s] its second term (0, 0) */
    /* Friction memory and an interface layer in every patch (cw_params'
     * fields of the same names and meaning, doc/theory/friction.md and
     * doc/theory/interface-layer.md; the exact model only): the memory acts
     * with a friction law, over the time dx / veloc of one element rolled;
     * the layer's elastic compliance layer_h / layer_G is in series with the
     * bodies. A patch's grid is a gap grid: its yield (tau_c0, k_tau) is
     * refused with an error naming the field, as cw_solve refuses it there. */
    double memory_distance;      /* [m] characteristic slip distance d_c >= 0 (0: none) */
    double memory_s0;            /* [m/s] background slip speed s0 >= 0 (0) */
    double layer_h;              /* [m] the layer's thickness >= 0 (0: no layer) */
    double layer_G;              /* [Pa] its shear modulus G3, > 0 when layer_h > 0 (0) */
    double tau_c0;               /* [Pa] its yield stress >= 0 (0: no yield) */
    double k_tau;                /* [Pa/m] its hardening with the plastic displacement (0) */
} cw_wheelrail_params;

/* The wheelset's position (CONTACT's Z_WS etc.) and velocity. */
typedef struct cw_wheelrail_motion {
    size_t struct_size;          /* set by cw_wheelrail_motion_init (all zero) */
    double y, z;                 /* [m] lateral shift; height (> 0 lowers the wheelset; 0
                                    puts the axle at the nominal radius above z = 0) */
    double roll, yaw, pitch;     /* [rad] roll about x, then yaw, then pitch */
    double vs;                   /* [m/s] forward speed */
    double vy, vz;               /* [m/s] rates of y, z */
    double vroll, vyaw;          /* [rad/s] rates of roll, yaw */
    double vpitch;               /* [rad/s] about the axle, < 0 rolling forward */
} cw_wheelrail_motion;

/* The whole wheel. Fields are only ever appended. */
typedef struct cw_wheelrail_totals {
    size_t struct_size;          /* set by cw_wheelrail_totals_init */
    double z;                    /* [m] wheelset height, found or given */
    double Fx, Fy, Fz;           /* [N] on the rail, track coordinates */
    int n_patches;               /* contact patches (cw_wheelrail_get_patch) */
    int evaluations;             /* geometry evaluations (1 with the height given) */
} cw_wheelrail_totals;

/* One contact patch. Fields are only ever appended. */
typedef struct cw_wheelrail_patch {
    size_t struct_size;          /* set by cw_wheelrail_patch_init */
    double x_contact, y_contact, z_contact; /* [m] reference point, track coordinates */
    double y_contact_rail, z_contact_rail;   /* [m] on the rail profile */
    double y_contact_wheel, z_contact_wheel; /* [m] on the wheel profile */
    double contact_angle;        /* [rad] rotation about x from track z to n */
    double cksi, ceta;           /* [-] creepages, rail relative to wheel */
    double cphi;                 /* [1/m] spin creepage */
    double veloc;                /* [m/s] reference velocity of the creepages */
    double Fn;                   /* [N] normal force pressing the rail */
    double Fx, Fs;               /* [N] tangential forces on the rail along x and s */
    double Mn;                   /* [N m] moment about n through the reference point */
    double p_max;                /* [Pa] largest element pressure */
    double approach;             /* [m] rigid overlap of the surfaces (-min h) */
    double Fx_track, Fy_track, Fz_track; /* [N] this patch's force, track coordinates */
    double rolling_radius;       /* [m] depth of the wheel point below the axle */
    int n_contact, n_adhesion, n_slip; /* elements */
    int nx, ny;                  /* the patch's grid */
    /* The grid of the fields (cw_wheelrail_get_patch_field): element (i, j) at
     * x = field_x0 + i field_dx, s = field_s0 + j field_ds from the reference
     * point; the patch's grid, or every 2nd (4th ...) element of a grid longer
     * than 256 elements. */
    int field_nx, field_ny;
    double field_x0, field_s0, field_dx, field_ds; /* [m] */
    /* Where the patch lies on the profiles as their points are given (y
     * towards the field side on both sides, unlike y_contact_rail on the left
     * side): the reference point's y, and d y / d s along the patch's s. */
    double rail_profile_y, rail_s_cos;   /* [m], [-] */
    double wheel_profile_y, wheel_s_cos; /* [m], [-] */
} cw_wheelrail_patch;

/* Set the defaults above and struct_size. Errors: CW_ERR_NULL_POINTER. */
CW_API int cw_wheelrail_params_init(cw_wheelrail_params* params);
CW_API int cw_wheelrail_motion_init(cw_wheelrail_motion* motion);
CW_API int cw_wheelrail_totals_init(cw_wheelrail_totals* totals);
CW_API int cw_wheelrail_patch_init(cw_wheelrail_patch* patch);

/* From profile files: SIMPACK (.prr rail, .prw wheel), MiniProf (.ban,
 * .whl) or a table of "y z" lines (any other name); paths NUL-terminated.
 * params may be NULL (the defaults). message as cw_solver_create; errors
 * name the file and line or the field. Errors: CW_ERR_NULL_POINTER,
 * CW_ERR_INVALID_INPUT, CW_ERR_STRUCT_SIZE, CW_ERR_OUT_OF_MEMORY. On error
 * *wheelrail is set to NULL. */
CW_API int cw_wheelrail_create(const cw_wheelrail_params* params, const char* rail_file,
                               const char* wheel_file, cw_wheelrail** wheelrail, char* message,
                               size_t message_len);

/* From points: rail_y[k], rail_z[k], k < rail_n, and the wheel's likewise,
 * in units of params->profile_unit (0: metres), y towards the field side, z
 * down, as the files' points. Errors: as cw_wheelrail_create. */
CW_API int cw_wheelrail_create_points(const cw_wheelrail_params* params, const double* rail_y,
                                      const double* rail_z, size_t rail_n,
                                      const double* wheel_y, const double* wheel_z,
                                      size_t wheel_n, cw_wheelrail** wheelrail, char* message,
                                      size_t message_len);

CW_API int cw_wheelrail_destroy(cw_wheelrail* wheelrail); /* NULL: no-op */

/* Solves one wheelset position: load CW_WHEELRAIL_FORCE finds the height z
 * at which the vertical force on the rail is Fz [N] in (0, 1e7), starting
 * from motion->z (when motion->z is the height the last call found and
 * the calls since the last CW_WHEELRAIL_HEIGHT were at least two force
 * balances, from the height extrapolated linearly from the last two: a
 * host passing the height back drifts); CW_WHEELRAIL_HEIGHT takes
 * motion->z (Fz unused). Every
 * patch is solved with its approach the rigid overlap at that height.
 * Errors: CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE, CW_ERR_UNKNOWN_OPTION
 * (load), CW_ERR_INVALID_INPUT, CW_ERR_NOT_CONVERGED, CW_ERR_NUMERIC; on
 * error the handle has no solution. */
CW_API int cw_wheelrail_solve(cw_wheelrail* wheelrail, const cw_wheelrail_motion* motion,
                              int load, double Fz, cw_wheelrail_totals* totals);

/* Patch k < totals.n_patches of the last solve, from the field side to the
 * track centre. Errors: CW_ERR_NULL_POINTER, CW_ERR_NO_SOLUTION,
 * CW_ERR_INVALID_INPUT (k), CW_ERR_STRUCT_SIZE. */
CW_API int cw_wheelrail_get_patch(const cw_wheelrail* wheelrail, size_t k,
                                  cw_wheelrail_patch* patch);

/* Field CW_FIELD_* of patch k of the last solve (with CW_SOLVE_FULL for the
 * slips and work maps) into out[i + j*field_nx], out_len >= field_nx *
 * field_ny, on the grid cw_wheelrail_get_patch describes, in the patch frame
 * of the wheel/rail conventions: CW_FIELD_X, CW_FIELD_Y the element centre's
 * x and s from the reference point; CW_FIELD_PX, CW_FIELD_PY the traction
 * on the rail along x and s; CW_FIELD_SX, CW_FIELD_SY the micro-slip of the
 * rail relative to the wheel; CW_FIELD_MZ the moment about n through the
 * reference point, on the rail; CW_FIELD_AREA, CW_FIELD_PZ and the work maps
 * as their names say. Errors: CW_ERR_NULL_POINTER, CW_ERR_NO_SOLUTION,
 * CW_ERR_NO_WORK (a slip or work map after CW_SOLVE_FORCES),
 * CW_ERR_INVALID_INPUT (k), CW_ERR_UNKNOWN_OPTION (field),
 * CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_wheelrail_get_patch_field(const cw_wheelrail* wheelrail, size_t k, int field,
                                        double* out, size_t out_len);

/* CW_STATE_* per element of patch k, as cw_wheelrail_get_patch_field.
 * Errors: as cw_wheelrail_get_patch_field. */
CW_API int cw_wheelrail_get_patch_state(const cw_wheelrail* wheelrail, size_t k, int* out,
                                        size_t out_len);

/* The solver holding patch k of the last solve, for the solver's getters
 * and cw_wear_create / cw_wear_compute: its fields are in creepwork's own
 * conventions (doc/wheelrail.md: y = -s, forces on the wheel) on a grid
 * whose element (0, 0) is at (field_x0, -(field_s0 + (field_ny - 1)
 * field_ds)) from the reference point. It carries the patch's rolling
 * direction: cw_temperature_compute with rolling_direction 0 takes it (its
 * rolling_speed: the patch's veloc). Owned by the handle: never destroy
 * or solve it; valid until the next cw_wheelrail_solve. NULL on error
 * (wheelrail NULL, no solution, k out of range). */
CW_API const cw_solver* cw_wheelrail_patch_solver(const cw_wheelrail* wheelrail, size_t k);

/* Adds the wear of every patch of the last solve (CW_SOLVE_FULL), by the law
 * in params, passes times, to the rail's and the wheel's profile
 * accumulators (cw_wear_profile; either may be NULL): nodes in the
 * profile's y as its points are given [m], the strips placed through
 * rail_profile_y, rail_s_cos (wheel_...) with the contact angle between
 * the patch and the profile, so that CW_WEAR_DEPTH_HEIGHT is vertical on
 * the rail and radial on the wheel. result (may be NULL) sums the patches'
 * mass, volume and work per pass; max_depth is the largest patch's. Checks
 * every patch before adding: on error nothing is added. Allocates a wear
 * workspace per patch and call. Errors:
 * CW_ERR_NULL_POINTER, CW_ERR_NO_SOLUTION, CW_ERR_NO_WORK, CW_ERR_STRUCT_SIZE,
 * CW_ERR_UNKNOWN_OPTION and CW_ERR_INVALID_INPUT (params, passes), and those
 * of cw_wear_profile_add. */
CW_API int cw_wheelrail_add_wear(const cw_wheelrail* wheelrail, const cw_wear_params* params,
                                 double passes, cw_wear_profile* rail, cw_wear_profile* wheel,
                                 cw_wear_result* result);

/* The points of the rail's or the wheel's profile (which: CW_WHEELRAIL_RAIL
 * or CW_WHEELRAIL_WHEEL) in track coordinates at the last solve's position,
 * y[k], z[k] [m] (z down), k < *count: the rail as placed, the wheel in the
 * wheelset's plane through the axle; for pictures and checks. len is the
 * room in y and z; *count is set to the number of points also when it
 * exceeds len (then CW_ERR_BUFFER_TOO_SMALL). y or z may be NULL with len 0
 * to ask for the count. Errors: CW_ERR_NULL_POINTER, CW_ERR_NO_SOLUTION,
 * CW_ERR_UNKNOWN_OPTION (which), CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_wheelrail_get_profile(const cw_wheelrail* wheelrail, int which, double* y, double* z,
                                    size_t len, size_t* count);

/* Message of the last error on this handle ("" after success); owned by
 * the handle, valid until its next call; "" for NULL. */
CW_API const char* cw_wheelrail_last_error(const cw_wheelrail* wheelrail);

/* Checks the handle's inputs and the last solve (cw_params_check's cw_check
 * entries, one per rule broken, contacts = 1): params (G, mu, dx, ds as
 * implausible units), the last cw_wheelrail_solve's motion and Fz (also
 * when that solve failed: y beyond 20 mm, roll or yaw beyond 0.05 rad,
 * vs, vpitch against vs / nominal_radius, Fz), and its solution: a patch on
 * the wheel's flange tip, or a wheelset height |z| beyond 5 mm with no
 * patch on the flange, each with its likely cause (a profile origin off,
 * a lateral shift in mm typed as m); and, from the profiles alone, a wheel
 * whose flange tip lies on the field side of its origin. Before any solve
 * only params and the profiles are checked. Fills out as cw_params_check;
 * leaves cw_wheelrail_last_error as the last solve left it unless this call
 * fails. Errors: CW_ERR_NULL_POINTER (wheelrail, found), CW_ERR_STRUCT_SIZE,
 * CW_ERR_BUFFER_TOO_SMALL. */
CW_API int cw_wheelrail_check(const cw_wheelrail* wheelrail, cw_check* out, size_t len,
                              size_t* found);

#endif /* CREEPWORK_WHEELRAIL_H */
