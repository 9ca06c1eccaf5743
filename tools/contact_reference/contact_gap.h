/* A non-Hertzian contact solved by CONTACT's library (Vollebregt & Kalker,
 * github eve70a/CONTACT, Apache-2.0; module 3, steady rolling, exact
 * half-space normal and tangential problems, the gap given per element with
 * IBASE = 9), for the reference data of tests/nonhertz/data and for the
 * benchmark's side-by-side timing. Never built by CI: only when
 * CREEPWORK_CONTACT_DIR names a CONTACT build (tests/nonhertz/data/README.md).
 * SI units in and out; CONTACT is called in its own units (mm, N).
 */
#ifndef CREEPWORK_CONTACT_GAP_H
#define CREEPWORK_CONTACT_GAP_H

typedef struct contact_gap_case {
    int nx, ny;             /* cells */
    double x0, y0, dx, dy;  /* centre of cell (0, 0) and spacing [m] */
    const double* h;        /* gap [m] at [i + nx j], positive = separation */
    int approach_given;     /* 0: normal_force prescribed; 1: approach prescribed */
    double normal_force;    /* [N] */
    double approach;        /* [m] from the datum h = 0 */
    double G, nu, mu;       /* [Pa], [-], [-] */
    double xi_x, xi_y, phi; /* [-], [-], [1/m] */
    int rolling_direction;  /* +1 (CHI = 0) or -1 (CHI = 180 deg) */
    double eps;             /* CONTACT's solver tolerance EPS */
    int bound_digit;        /* B: 0 exact normal problem, 5 KPEC, 6 ANALYN */
    int tang_digit;         /* M: 0 exact tangential, 3 FASTSIM, 5 FaStrip */
} contact_gap_case;

typedef struct contact_gap_result {
    int ierror;
    double Fn, Fx, Fy, Mz;  /* [N], Mz about the origin [N m] */
    double p_max, approach; /* [Pa], [m] */
    int n_contact, n_adhesion, n_slip;
    double seconds;         /* wall time of the last cntc_calculate */
    /* per element [i + nx j] when not NULL: CONTACT's element division
     * (0 exterior, 1 adhesion, 2 slip, 3 plastic) and tractions [Pa] */
    int* eldiv;
    double *pn, *px, *py;
} contact_gap_result;

/* Once per process; 0 on success. */
int contact_gap_init(void);
/* Sets the case up on result element 1 (every call: the grid may change). */
int contact_gap_setup(const contact_gap_case* c);
/* cntc_calculate, repeated; the result of the last. */
int contact_gap_solve(const contact_gap_case* c, int repeats, contact_gap_result* r);
void contact_gap_finish(void);

#endif
