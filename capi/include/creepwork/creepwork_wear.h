/* creepwork: wear laws and wear on profile grids -- part of the C API, included by <creepwork/creepwork.h>
 * (include that header, not this one). The conventions of creepwork.h hold. */
#ifndef CREEPWORK_H
#error "include <creepwork/creepwork.h>, not <creepwork/creepwork_wear.h>"
#endif
#ifndef CREEPWORK_WEAR_H
#define CREEPWORK_WEAR_H

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
                             in (0, 1e3] there; >= 0 and unused for USFD. Default 0:
                             Archard takes the V the solve was given (cw_params.V);
                             both given must agree (to 1e-9), else
                             CW_ERR_INVALID_INPUT naming both */
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

/* Detailed message of the last error on this handle, as cw_solver_last_error. */
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
/* Copies the totals. Errors: CW_ERR_NULL_POINTER, CW_ERR_STRUCT_SIZE. */
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

/* Detailed message of the last error on this handle, as cw_solver_last_error. */
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

#endif /* CREEPWORK_WEAR_H */
