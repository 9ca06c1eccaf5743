/* contact_gap.h, over CONTACT's cntc_* library (prototypes as in CONTACT's
 * matlab_intfc/contact_addon.h; every argument by reference; the magic
 * numbers of its src/caddon_flags.inc). */
#define _POSIX_C_SOURCE 199309L
#include "contact_gap.h"

#include <stdlib.h>
#include <time.h>

void cntc_initializefirst(int* ifcver, int* ierror, int* ioutput, const char* c_wrkdir,
                          const char* c_outdir, const char* c_expnam, int* len_wrkdir,
                          int* len_outdir, int* len_expnam);
void cntc_initialize(int* ire, int* imodul, int* ifcver, int* ierror, const char* c_outdir,
                     int* len_outdir);
void cntc_setglobalflags(int* lenflg, int* params, int* values);
void cntc_setflags(int* ire, int* icp, int* lenflg, int* params, int* values);
void cntc_setsolverflags(int* ire, int* icp, int* gdigit, int* nints, int* iparam, int* nreals,
                         double* rparam);
void cntc_setmaterialparameters(int* ire, int* icp, int* mdigit, int* nparam, double* rparam);
void cntc_setreferencevelocity(int* ire, int* icp, double* veloc);
void cntc_setrollingstepsize(int* ire, int* icp, double* chi, double* dq);
void cntc_setfrictionmethod(int* ire, int* icp, int* imeth, int* nparam, double* params);
void cntc_setpotcontact(int* ire, int* icp, int* ipotcn, int* nparam, double* rparam);
void cntc_setundeformeddistc(int* ire, int* icp, int* ibase, int* nparam, double* prmudf);
void cntc_setnormalforce(int* ire, int* icp, double* fn);
void cntc_setpenetration(int* ire, int* icp, double* pen);
void cntc_setcreepages(int* ire, int* icp, double* vx, double* vy, double* phi);
void cntc_calculate(int* ire, int* icp, int* ierror);
void cntc_getcontactforces(int* ire, int* icp, double* fn, double* tx, double* ty, double* mz);
void cntc_getpenetration(int* ire, int* icp, double* pen);
void cntc_getmaximumpressure(int* ire, int* icp, double* pnmax);
void cntc_getnumelements(int* ire, int* icp, int* mx, int* my);
void cntc_getelementdivision(int* ire, int* icp, int* lenarr, int* eldiv);
void cntc_gettractions(int* ire, int* icp, int* lenarr, double* pn, double* px, double* py);
void cntc_finalizelast(void);

enum {
    CNTC_if_units = 1933, CNTC_un_cntc = 1934, CNTC_ic_pvtime = 1970, CNTC_ic_bound = 1971,
    CNTC_ic_tang = 1972, CNTC_ic_norm = 1973, CNTC_ic_force = 1974, CNTC_ic_iestim = 1983,
    CNTC_ic_output = 1984, CNTC_ic_flow = 1985, CNTC_ic_matfil = 1987, CNTC_ic_sens = 1988,
    CNTC_if_idebug = 2000, CNTC_if_wrtinp = 2002, CNTC_if_openmp = 2003, CNTC_if_timers = 2004
};

static const double kPi = 3.14159265358979323846;

int contact_gap_init(void)
{
    int ierror = 0, ifcver = 0, ioutput = 0, one = 1, ire = 1, imodul = 3;
    const char* empty = " ";
    cntc_initializefirst(&ifcver, &ierror, &ioutput, empty, empty, empty, &one, &one, &one);
    int gflg[3] = {CNTC_if_idebug, CNTC_if_openmp, CNTC_if_timers}, gval[3] = {0, 0, 0}, ng = 3;
    cntc_setglobalflags(&ng, gflg, gval);
    cntc_initialize(&ire, &imodul, &ifcver, &ierror, empty, &one);
    return ierror;
}

int contact_gap_setup(const contact_gap_case* c)
{
    int ire = 1, icp = 1;
    /* P=2 (initiation), B, T=3 (steady rolling), N=1/0, F=0, I=0, no output */
    int flg[12] = {CNTC_if_units, CNTC_ic_pvtime, CNTC_ic_bound, CNTC_ic_tang, CNTC_ic_norm,
                   CNTC_ic_force, CNTC_ic_iestim, CNTC_ic_output, CNTC_ic_flow, CNTC_ic_matfil,
                   CNTC_if_wrtinp, CNTC_ic_sens};
    int val[12] = {CNTC_un_cntc, 2, c->bound_digit, 3, c->approach_given ? 0 : 1, 0, 0, 0, 0, 0,
                   0, 0};
    int nflg = 12;
    cntc_setflags(&ire, &icp, &nflg, flg, val);

    int gdig = 0, nints = 4, nreals = 1, ipar[4] = {999, 100, 30, 1};
    double eps = c->eps;
    cntc_setsolverflags(&ire, &icp, &gdig, &nints, ipar, &nreals, &eps);

    /* M digit 0: [nu1 nu2 g1 g2]; 3 (FASTSIM): also k0_mf, alfamf, betamf = 1 */
    int mdig = c->tang_digit, nmat = c->tang_digit == 3 ? 7 : 4;
    double mat[7] = {c->nu, c->nu, 1e-6 * c->G, 1e-6 * c->G, 1.0, 1.0, 1.0};
    cntc_setmaterialparameters(&ire, &icp, &mdig, &nmat, mat);

    int lmeth = 0, nfric = 2;
    double fric[2] = {c->mu, c->mu};
    cntc_setfrictionmethod(&ire, &icp, &lmeth, &nfric, fric);

    double veloc = 1000.0, chi = c->rolling_direction < 0 ? kPi : 0.0, dq = 1e3 * c->dx;
    cntc_setreferencevelocity(&ire, &icp, &veloc);
    cntc_setrollingstepsize(&ire, &icp, &chi, &dq);

    int ipotcn = 3, npot = 6;
    double pot[6] = {c->nx, c->ny, 1e3 * c->x0, 1e3 * c->y0, 1e3 * c->dx, 1e3 * c->dy};
    cntc_setpotcontact(&ire, &icp, &ipotcn, &npot, pot);

    const int n = c->nx * c->ny;
    double* h = malloc(sizeof(double) * (size_t)n);
    if (!h) return -1;
    for (int k = 0; k < n; ++k) h[k] = 1e3 * c->h[k];
    int ibase = 9, nh = n;
    cntc_setundeformeddistc(&ire, &icp, &ibase, &nh, h);
    free(h);

    if (c->approach_given) {
        double pen = 1e3 * c->approach;
        cntc_setpenetration(&ire, &icp, &pen);
    } else {
        double fn = c->normal_force;
        cntc_setnormalforce(&ire, &icp, &fn);
    }
    /* CONTACT's spin is in rad/mm */
    double cksi = c->xi_x, ceta = c->xi_y, cphi = 1e-3 * c->phi;
    cntc_setcreepages(&ire, &icp, &cksi, &ceta, &cphi);
    return 0;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int contact_gap_solve(const contact_gap_case* c, int repeats, contact_gap_result* r)
{
    int ire = 1, icp = 1, ierror = 0;
    for (int k = 0; k < (repeats > 0 ? repeats : 1); ++k) {
        const double t0 = now();
        cntc_calculate(&ire, &icp, &ierror);
        r->seconds = now() - t0;
    }
    r->ierror = ierror;
    double fn, fx, fy, mz, pen, pmax;
    cntc_getcontactforces(&ire, &icp, &fn, &fx, &fy, &mz);
    cntc_getpenetration(&ire, &icp, &pen);
    cntc_getmaximumpressure(&ire, &icp, &pmax);
    r->Fn = fn;
    r->Fx = fx;
    r->Fy = fy;
    r->Mz = 1e-3 * mz;
    r->approach = 1e-3 * pen;
    r->p_max = 1e6 * pmax;
    int mx = 0, my = 0;
    cntc_getnumelements(&ire, &icp, &mx, &my);
    int n = mx * my;
    if (mx != c->nx || my != c->ny) return -2;
    int* el = malloc(sizeof(int) * (size_t)n);
    double* f = malloc(sizeof(double) * 3 * (size_t)n);
    if (!el || !f) {
        free(el);
        free(f);
        return -1;
    }
    cntc_getelementdivision(&ire, &icp, &n, el);
    cntc_gettractions(&ire, &icp, &n, f, f + n, f + 2 * n);
    r->n_contact = r->n_adhesion = r->n_slip = 0;
    for (int k = 0; k < n; ++k) {
        r->n_adhesion += el[k] == 1;
        r->n_slip += el[k] >= 2;
        if (r->eldiv) r->eldiv[k] = el[k];
        if (r->pn) r->pn[k] = 1e6 * f[k];
        if (r->px) r->px[k] = 1e6 * f[n + k];
        if (r->py) r->py[k] = 1e6 * f[2 * n + k];
    }
    r->n_contact = r->n_adhesion + r->n_slip;
    free(el);
    free(f);
    return ierror;
}

void contact_gap_finish(void) { cntc_finalizelast(); }
