/* Golden outputs: one 64-bit hash per case over every number the public C
 * ABI gives back (totals, each field, states, profiles, patches, Jacobians,
 * batches, accumulators, wear, wheel/rail, transient steps and their saved
 * states), for every model, grid kind, solve mode, normal method and load
 * mode. Built against the public header only, so the same source builds
 * against any commit's library: a refactoring that must not change a result
 * bit is checked by running this before and after and comparing the lines
 * (tools/golden/compare.sh).
 * The kernel ISA is the machine's (the kernels' bitwise equality across
 * ISAs is test_core_kernels's job).
 *   golden_outputs <profile dir>   (tests/wheelrail/data)
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "creepwork/creepwork.h"

/* FNV-1a over bytes: the hash of a case. */
typedef struct hash {
    uint64_t h;
    long n; /* numbers hashed */
} hash;

static void hash_bytes(hash* s, const void* p, size_t len)
{
    const unsigned char* b = (const unsigned char*)p;
    for (size_t k = 0; k < len; ++k) s->h = (s->h ^ b[k]) * 1099511628211ull;
}
static void hd(hash* s, double v) { hash_bytes(s, &v, sizeof v), ++s->n; }
static void hi(hash* s, long v) { hash_bytes(s, &v, sizeof v), ++s->n; }
static void hds(hash* s, const double* v, size_t n) { for (size_t k = 0; k < n; ++k) hd(s, v[k]); }
static void his(hash* s, const int* v, size_t n) { for (size_t k = 0; k < n; ++k) hi(s, v[k]); }

static hash begin(void) { hash s = {1469598103934665603ull, 0}; return s; }
static void end(const char* name, const hash* s) { printf("%-48s %016llx %ld\n", name, (unsigned long long)s->h, s->n); }

static int fail(const char* what, const char* msg)
{
    fprintf(stderr, "golden_outputs: %s: %s\n", what, msg);
    exit(1);
}

static void hash_result(hash* s, const cw_result* r)
{
    const double d[] = {r->Fx, r->Fy, r->Mz, r->W_macro, r->W_micro_paper, r->K, r->W_consistent,
                        r->balance_factor, r->adhesion_fraction, r->a, r->b, r->L1, r->L2, r->L3,
                        r->C11, r->C22, r->C23, r->C33, r->profile_max_diff, r->profile_rms_diff,
                        r->p_max, r->approach, r->residual, r->normal_force};
    hds(s, d, sizeof d / sizeof d[0]);
    const int i[] = {r->n_contact, r->n_adhesion, r->n_slip, r->work_flags, r->model, r->iterations,
                     r->n_patches};
    his(s, i, sizeof i / sizeof i[0]);
}

/* Every field, the states, the profile and the patches of the last solve. */
static void hash_solution(hash* s, const cw_solver* solver, int mode)
{
    int nx, ny;
    cw_solver_grid_size(solver, &nx, &ny);
    const size_t n = (size_t)nx * (size_t)ny;
    double* f = malloc(n * sizeof *f);
    int* st = malloc(n * sizeof *st);
    const int last = mode == CW_SOLVE_FULL ? CW_FIELD_WORK_CONSISTENT : CW_FIELD_MZ;
    for (int field = CW_FIELD_X; field <= last; ++field) {
        if (mode != CW_SOLVE_FULL && (field == CW_FIELD_SX || field == CW_FIELD_SY)) continue;
        if (cw_solver_get_field(solver, field, f, n)) fail("get_field", cw_solver_last_error(solver));
        hds(s, f, n);
    }
    if (cw_solver_get_state(solver, st, n)) fail("get_state", cw_solver_last_error(solver));
    his(s, st, n);
    if (mode == CW_SOLVE_FULL) {
        double* y = malloc((size_t)ny * 3 * sizeof *y);
        if (cw_solver_get_profile(solver, y, y + ny, y + 2 * ny, (size_t)ny) == CW_OK)
            hds(s, y, (size_t)ny * 3);
        free(y);
    }
    size_t count = 0;
    cw_patch patches[16];
    for (int k = 0; k < 16; ++k) cw_patch_init(&patches[k]);
    if (cw_solver_get_patches(solver, patches, 16, &count) == CW_OK)
        for (size_t k = 0; k < count; ++k) {
            const cw_patch* p = &patches[k];
            const double d[] = {p->x_centroid, p->y_centroid, p->Fx, p->Fy, p->Mz, p->Fn, p->p_max, p->W_macro};
            hds(s, d, 8);
            const int i[] = {p->n_contact, p->n_adhesion, p->n_slip};
            his(s, i, 3);
        }
    free(f);
    free(st);
}

static cw_solver* make_solver(const cw_grid* g)
{
    cw_solver* s = NULL;
    char msg[512];
    if (cw_solver_create(g, &s, msg, sizeof msg)) fail("solver_create", msg);
    return s;
}

static cw_grid grid_of(int kind, int nx, int ny, double box)
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = kind, g.nx = nx, g.ny = ny, g.box_scale = box;
    return g;
}

/* One solve and one Jacobian solve of p on a fresh solver; name the case. */
static void solve_case(const char* name, const cw_grid* g, const cw_params* p)
{
    for (int mode = CW_SOLVE_FORCES; mode <= CW_SOLVE_FULL; ++mode) {
        cw_solver* s = make_solver(g);
        cw_result r;
        cw_result_init(&r);
        hash h = begin();
        const int status = cw_solver_solve(s, p, mode, &r);
        hi(&h, status);
        if (status == CW_OK) hash_result(&h, &r), hash_solution(&h, s, mode);
        char full[160];
        snprintf(full, sizeof full, "%s/%s", name, mode == CW_SOLVE_FULL ? "full" : "forces");
        end(full, &h);
        /* the Jacobian solve on the same handle (warm for the exact model) */
        double jac[CW_JACOBIAN_LEN];
        cw_result_init(&r);
        h = begin();
        const int js = cw_solver_solve_jacobian(s, p, mode, &r, jac, CW_JACOBIAN_LEN);
        hi(&h, js);
        if (js == CW_OK) hash_result(&h, &r), hds(&h, jac, CW_JACOBIAN_LEN), hash_solution(&h, s, mode);
        snprintf(full, sizeof full, "%s/%s/jacobian", name, mode == CW_SOLVE_FULL ? "full" : "forces");
        end(full, &h);
        cw_solver_destroy(s);
    }
}

typedef struct creepage { const char* name; double xi_x, xi_y, phi; } creepage;
static const creepage creepages[] = {
    {"partial", 6e-4, -4e-4, 0.2},
    {"spin", 1e-4, 2e-4, 3.0},
    {"sliding", 8e-3, 5e-3, -0.5},
    {"lateral", 0.0, -1.5e-3, 0.0},
};
#define N_CREEPAGES (sizeof creepages / sizeof creepages[0])

static cw_params base_params(const creepage* c)
{
    cw_params p;
    cw_params_init(&p);
    p.a = 7.2e-3, p.b = 5.4e-3, p.normal_force = 100e3, p.mu = 0.3;
    p.xi_x = c->xi_x, p.xi_y = c->xi_y, p.phi = c->phi;
    return p;
}

static void elliptic_cases(void)
{
    static const struct { const char* name; int kind, nx, ny; double box; } grids[] = {
        {"strips20", CW_GRID_KALKER_STRIPS, 20, 20, 1.0},
        {"strips7x31", CW_GRID_KALKER_STRIPS, 7, 31, 1.0},
        {"uniform24", CW_GRID_UNIFORM, 24, 24, 1.1},
        {"uniform17x23", CW_GRID_UNIFORM, 17, 23, 1.25},
    };
    static const struct { const char* name; int model; } models[] = {
        {"fastsim", CW_MODEL_FASTSIM}, {"calibrated", CW_MODEL_CALIBRATED}, {"exact", CW_MODEL_EXACT}};
    char name[160];
    for (size_t gi = 0; gi < sizeof grids / sizeof grids[0]; ++gi) {
        const cw_grid g = grid_of(grids[gi].kind, grids[gi].nx, grids[gi].ny, grids[gi].box);
        for (size_t mi = 0; mi < 3; ++mi) {
            if (models[mi].model == CW_MODEL_EXACT && grids[gi].kind != CW_GRID_UNIFORM) continue;
            for (size_t ci = 0; ci < N_CREEPAGES; ++ci) {
                cw_params p = base_params(&creepages[ci]);
                p.model = models[mi].model;
                snprintf(name, sizeof name, "%s/%s/%s", grids[gi].name, models[mi].name, creepages[ci].name);
                solve_case(name, &g, &p);
                p.rolling_direction = -1;
                snprintf(name, sizeof name, "%s/%s/%s/backwards", grids[gi].name, models[mi].name, creepages[ci].name);
                solve_case(name, &g, &p);
            }
            /* the options, on one creepage */
            cw_params p = base_params(&creepages[0]);
            p.model = models[mi].model;
            p.spin_offset = 0.5;
            snprintf(name, sizeof name, "%s/%s/spin_offset", grids[gi].name, models[mi].name);
            solve_case(name, &g, &p);
            if (models[mi].model == CW_MODEL_EXACT) {
                p = base_params(&creepages[2]);
                p.model = CW_MODEL_EXACT, p.tolerance = 1e-11, p.nu = 0.0, p.mu = 0.45;
                snprintf(name, sizeof name, "%s/exact/tolerance_nu0", grids[gi].name);
                solve_case(name, &g, &p);
                continue;
            }
            p = base_params(&creepages[1]);
            p.model = models[mi].model;
            p.pressure = CW_PRESSURE_ELLIPTIC, p.exact_load = 1;
            snprintf(name, sizeof name, "%s/%s/elliptic_exact_load", grids[gi].name, models[mi].name);
            solve_case(name, &g, &p);
            if (models[mi].model == CW_MODEL_FASTSIM) {
                p = base_params(&creepages[2]);
                p.flexibility_blending = 1, p.spin_offset = 1.0 / 6.0;
                snprintf(name, sizeof name, "%s/fastsim/blending", grids[gi].name);
                solve_case(name, &g, &p);
                p = base_params(&creepages[0]);
                p.flexibility = CW_FLEX_GIVEN, p.L1 = 3.1e-11, p.L2 = 2.9e-11, p.L3 = 4.4e-11;
                snprintf(name, sizeof name, "%s/fastsim/given_L", grids[gi].name);
                solve_case(name, &g, &p);
                p = base_params(&creepages[0]);
                p.a = 3e-3, p.b = 11e-3, p.normal_force = 0.0;
                snprintf(name, sizeof name, "%s/fastsim/no_load", grids[gi].name);
                solve_case(name, &g, &p);
                /* a law of the slip speed at every element, each form, two terms */
                static const int laws[] = {CW_FRICTION_LINEAR, CW_FRICTION_RATIONAL,
                                           CW_FRICTION_EXPONENTIAL};
                for (size_t li = 0; li < sizeof laws / sizeof laws[0]; ++li)
                    for (size_t ci = 0; ci < N_CREEPAGES; ++ci) {
                        p = base_params(&creepages[ci]);
                        p.friction_law = laws[li], p.V = 10.0, p.mu = 0.14;
                        p.mu_e1 = 0.12, p.s_h1 = 0.02, p.mu_e2 = 0.05, p.s_h2 = 0.005;
                        snprintf(name, sizeof name, "%s/fastsim/law%d/%s", grids[gi].name, laws[li],
                                 creepages[ci].name);
                        solve_case(name, &g, &p);
                    }
            }
        }
    }
}

/* A host's drifting creepages on one exact handle: warm starts. */
static void warm_sequence(void)
{
    const cw_grid g = grid_of(CW_GRID_UNIFORM, 20, 20, 1.1);
    cw_solver* s = make_solver(&g);
    hash h = begin();
    for (int step = 0; step < 12; ++step) {
        cw_params p = base_params(&creepages[0]);
        p.model = CW_MODEL_EXACT;
        p.xi_x *= 1.0 + 0.01 * step;
        p.phi *= 1.0 - 0.02 * step;
        p.normal_force *= 1.0 + 0.003 * step;
        cw_result r;
        cw_result_init(&r);
        hi(&h, cw_solver_solve(s, &p, step % 3 == 0 ? CW_SOLVE_FULL : CW_SOLVE_FORCES, &r));
        hash_result(&h, &r);
    }
    end("uniform20/exact/warm_sequence", &h);
    cw_solver_destroy(s);
}

static void batch_and_accumulator(void)
{
    const cw_grid g = grid_of(CW_GRID_UNIFORM, 16, 16, 1.0);
    cw_batch* b = NULL;
    char msg[512];
    if (cw_batch_create(&g, 2, &b, msg, sizeof msg)) fail("batch_create", msg);
    cw_params p[12];
    cw_result r[12];
    int st[12];
    for (int k = 0; k < 12; ++k) {
        p[k] = base_params(&creepages[k % N_CREEPAGES]);
        p[k].model = k % 3;
        p[k].normal_force *= 0.5 + 0.1 * k;
        cw_result_init(&r[k]);
    }
    hash h = begin();
    hi(&h, cw_batch_solve(b, 12, p, CW_SOLVE_FULL, r, st));
    for (int k = 0; k < 12; ++k) hi(&h, st[k]), hash_result(&h, &r[k]);
    end("uniform16/batch", &h);
    cw_batch_destroy(b);

    cw_solver* s = make_solver(&g);
    cw_accumulator* acc = NULL;
    if (cw_accumulator_create(s, &acc)) fail("accumulator", "create");
    h = begin();
    for (int k = 0; k < 6; ++k) {
        hi(&h, cw_solver_solve(s, &p[k], CW_SOLVE_FULL, NULL));
        hi(&h, cw_accumulator_add(acc, s, 0.01 * (k + 1)));
    }
    cw_accumulation t;
    cw_accumulation_init(&t);
    cw_accumulator_get_totals(acc, &t);
    const double d[] = {t.distance, t.W_macro, t.W_micro_paper, t.K, t.W_consistent};
    hds(&h, d, 5);
    double f[256];
    cw_accumulator_get_field(acc, CW_FIELD_WORK_PAPER, f, 256), hds(&h, f, 256);
    cw_accumulator_get_field(acc, CW_FIELD_WORK_CONSISTENT, f, 256), hds(&h, f, 256);
    cw_accumulator_get_strip_work(acc, f, 16), hds(&h, f, 16);
    end("uniform16/accumulator", &h);
    cw_accumulator_destroy(acc);
    cw_solver_destroy(s);
}

/* Wear of a FULL solve by each law and source, and on a profile grid. */
static void wear_case(const char* name, const cw_grid* g, const cw_params* p)
{
    cw_solver* s = make_solver(g);
    if (cw_solver_solve(s, p, CW_SOLVE_FULL, NULL)) fail("wear solve", cw_solver_last_error(s));
    cw_wear* w = NULL;
    if (cw_wear_create(s, &w)) fail("wear_create", "");
    int nx, ny;
    cw_solver_grid_size(s, &nx, &ny);
    const size_t n = (size_t)nx * (size_t)ny;
    double* f = malloc(n * sizeof *f);
    int* reg = malloc(n * sizeof *reg);
    double nodes[200];
    for (int k = 0; k < 200; ++k) nodes[k] = -0.02 + 2e-4 * k;
    char full[160];
    for (int law = CW_WEAR_USFD; law <= CW_WEAR_ARCHARD_KTH; ++law)
        for (int source = CW_WEAR_SOURCE_CONSISTENT; source <= CW_WEAR_SOURCE_SLIP; ++source) {
            cw_wear_params wp;
            cw_wear_params_init(&wp);
            wp.law = law, wp.source = source, wp.rolling_speed = 30.0;
            cw_wear_result r;
            cw_wear_result_init(&r);
            hash h = begin();
            const int status = cw_wear_compute(w, s, &wp, &r);
            hi(&h, status);
            if (status == CW_OK) {
                const double d[] = {r.mass_per_distance, r.mass_per_pass, r.volume_per_distance, r.max_depth,
                                    r.work, r.regime_area[0], r.regime_area[1], r.regime_area[2], r.regime_area[3]};
                hds(&h, d, 9);
                for (int field = CW_WEAR_FIELD_RATE; field <= CW_WEAR_FIELD_SLIDING; ++field)
                    if (cw_wear_get_field(w, field, f, n) == CW_OK) hds(&h, f, n);
                cw_wear_get_regimes(w, reg, n), his(&h, reg, n);
                double* strips = malloc((size_t)ny * 4 * sizeof *strips);
                cw_wear_get_strips(w, strips, strips + ny, strips + 2 * ny, strips + 3 * ny, (size_t)ny);
                hds(&h, strips, (size_t)ny * 4);
                free(strips);
                cw_wear_profile* prof = NULL;
                char msg[256];
                if (cw_wear_profile_create(nodes, 200, &prof, msg, sizeof msg)) fail("profile", msg);
                hi(&h, cw_wear_profile_add(prof, w, 1e-3, 1, 0.3, 1e4));
                hi(&h, cw_wear_profile_add(prof, w, -2e-3, -1, -0.1, 3.0));
                double depth[200];
                cw_wear_profile_get_depth(prof, CW_WEAR_DEPTH_NORMAL, depth, 200), hds(&h, depth, 200);
                cw_wear_profile_get_depth(prof, CW_WEAR_DEPTH_HEIGHT, depth, 200), hds(&h, depth, 200);
                cw_wear_profile_destroy(prof);
            }
            snprintf(full, sizeof full, "%s/wear/law%d/source%d", name, law, source);
            end(full, &h);
        }
    free(f);
    free(reg);
    cw_wear_destroy(w);
    cw_solver_destroy(s);
}

/* Gap grids: a Hertzian gap, two lobes, a flat top; both models, both
 * normal methods, force or approach prescribed. */
static void gap_cases(void)
{
    enum { NX = 30, NY = 26 };
    const double dx = 0.5e-3, dy = 0.5e-3, x0 = -7.25e-3, y0 = -6.25e-3;
    static double h[3][NX * NY];
    for (int j = 0; j < NY; ++j)
        for (int i = 0; i < NX; ++i) {
            const double x = x0 + i * dx, y = y0 + j * dy;
            h[0][i + NX * j] = x * x / (2 * 0.46) + y * y / (2 * 0.3);
            const double y1 = y - 2.5e-3, y2 = y + 3.0e-3;
            h[1][i + NX * j] = x * x / (2 * 0.46) + fmin(y1 * y1 / (2 * 0.08) + 2e-6, y2 * y2 / (2 * 0.05));
            const double r = fabs(y) > 2e-3 ? fabs(y) - 2e-3 : 0.0;
            h[2][i + NX * j] = x * x / (2 * 0.46) + r * r / (2 * 0.04) - 0.3e-6 * (i % 3 == 0);
        }
    static const char* shapes[] = {"hertz", "two_lobes", "flat_top"};
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_GAP, g.nx = NX, g.ny = NY, g.x0 = x0, g.y0 = y0, g.dx = dx, g.dy = dy;
    char name[160];
    for (int shape = 0; shape < 3; ++shape)
        for (int model = 0; model < 2; ++model)
            for (int method = CW_NORMAL_EXACT; method <= CW_NORMAL_SEMI_HERTZ; ++method)
                for (int load = CW_NORMAL_FORCE; load <= CW_NORMAL_APPROACH; ++load)
                    for (size_t ci = 0; ci < N_CREEPAGES; ci += 2) {
                        cw_params p = base_params(&creepages[ci]);
                        p.model = model ? CW_MODEL_EXACT : CW_MODEL_FASTSIM;
                        p.gap = h[shape], p.gap_len = NX * NY;
                        p.normal_method = method, p.normal_load = load;
                        p.normal_force = 60e3, p.approach = 40e-6;
                        p.rolling_direction = ci == 2 ? -1 : 1;
                        snprintf(name, sizeof name, "gap/%s/%s/%s/%s/%s", shapes[shape],
                                 model ? "exact" : "fastsim", method ? "semi_hertz" : "exact_normal",
                                 load ? "approach" : "force", creepages[ci].name);
                        solve_case(name, &g, &p);
                    }
    /* one handle through a sequence: warm starts and held normal state */
    cw_solver* s = make_solver(&g);
    hash hs = begin();
    for (int step = 0; step < 10; ++step) {
        cw_params p = base_params(&creepages[step % N_CREEPAGES]);
        p.model = step % 4 == 3 ? CW_MODEL_FASTSIM : CW_MODEL_EXACT;
        p.gap = h[step % 2], p.gap_len = NX * NY;
        p.normal_method = step % 5 == 2 ? CW_NORMAL_SEMI_HERTZ : CW_NORMAL_EXACT;
        p.normal_force = 50e3 + 1e3 * step;
        cw_result r;
        cw_result_init(&r);
        hi(&hs, cw_solver_solve(s, &p, CW_SOLVE_FULL, &r));
        hash_result(&hs, &r);
        hash_solution(&hs, s, CW_SOLVE_FULL);
    }
    end("gap/sequence", &hs);
    cw_solver_destroy(s);
    cw_params p = base_params(&creepages[0]);
    p.gap = h[1], p.gap_len = NX * NY, p.normal_force = 60e3;
    for (int model = 0; model < 2; ++model) {
        p.model = model ? CW_MODEL_EXACT : CW_MODEL_FASTSIM;
        wear_case(model ? "gap/two_lobes/exact" : "gap/two_lobes/fastsim", &g, &p);
    }
}

/* One transient step's (or steady start's) status, totals, fields and
 * states on n elements, and the step Jacobian's status and values (the
 * exact model's; FASTSIM's is an error, its status hashed). */
static void hash_transient(hash* h, cw_transient* t, int status, const cw_transient_result* r,
                           size_t n)
{
    hi(h, status);
    if (status != CW_OK) return;
    const double d[] = {r->xi_x, r->xi_y, r->phi, r->Fx, r->Fy, r->Mz, r->W_step, r->W_slip, r->residual};
    hds(h, d, sizeof d / sizeof d[0]);
    const int i[] = {r->n_contact, r->n_adhesion, r->n_slip, r->iterations, r->force_iterations};
    his(h, i, sizeof i / sizeof i[0]);
    hi(h, (long)r->steps_committed);
    static const int fields[] = {CW_FIELD_X, CW_FIELD_Y, CW_FIELD_PZ, CW_FIELD_PX, CW_FIELD_PY,
                                 CW_FIELD_SX, CW_FIELD_SY, CW_FIELD_WORK_CONSISTENT};
    double* f = malloc(n * sizeof *f);
    int* st = malloc(n * sizeof *st);
    for (size_t k = 0; k < sizeof fields / sizeof fields[0]; ++k) {
        hi(h, cw_transient_get_field(t, fields[k], f, n));
        hds(h, f, n);
    }
    hi(h, cw_transient_get_state(t, st, n));
    his(h, st, n);
    double J[CW_TRANSIENT_JACOBIAN_LEN] = {0};
    hi(h, cw_transient_jacobian(t, J, CW_TRANSIENT_JACOBIAN_LEN));
    hds(h, J, CW_TRANSIENT_JACOBIAN_LEN);
    free(f);
    free(st);
}

/* The saved state's words. */
static void hash_saved(hash* h, const cw_transient* t, uint64_t** words, size_t* len)
{
    hi(h, cw_transient_state_size(t, len));
    *words = malloc(*len * sizeof **words);
    hi(h, cw_transient_save(t, *words, *len));
    hash_bytes(h, *words, *len * sizeof **words), ++h->n;
}

/* One transient handle through a run: a steady start, rolling steps (whole
 * and part elements), prescribed Fx and both forces, a shift, a rewound
 * trial repeated, save, more steps, restore and a step again, wear over the
 * committed steps; world-fixed too where the model has it. */
static void transient_run(const char* name, const cw_grid* g, const cw_params* p, size_t n,
                          int coordinates)
{
    cw_transient* t = NULL;
    char msg[512];
    hash h = begin();
    const int created = cw_transient_create(g, p, &t, msg, sizeof msg);
    hi(&h, created);
    if (created != CW_OK) {
        end(name, &h);
        return;
    }
    hi(&h, cw_transient_set_coordinates(t, coordinates));
    double* x = malloc(n * sizeof *x);
    hi(&h, cw_transient_get_field(t, CW_FIELD_X, x, n)); /* none yet */
    cw_transient_input in;
    cw_transient_result r;
    cw_transient_input_init(&in);
    cw_transient_result_init(&r);
    in.xi_x = p->xi_x, in.xi_y = p->xi_y, in.phi = p->phi;
    int status = cw_transient_start_steady(t, &in, &r);
    hash_transient(&h, t, status, &r, n);
    if (status == CW_OK && cw_transient_get_field(t, CW_FIELD_X, x, n) == CW_OK) {
        const double dx = x[1] - x[0];
        const double fn = p->normal_force * p->mu;
        cw_wear_params wp;
        cw_wear_params_init(&wp);
        const struct { double dq, xi_x, xi_y, phi; int prescribe; double Fx, Fy; } steps[] = {
            {1.0, 1.2 * p->xi_x, p->xi_y, p->phi, CW_PRESCRIBE_CREEPAGES, 0, 0},
            {0.5, 1.5 * p->xi_x, 0.5 * p->xi_y, -p->phi, CW_PRESCRIBE_CREEPAGES, 0, 0},
            {1.0, 0.0, p->xi_y, p->phi, CW_PRESCRIBE_FX, 0.25 * fn, 0},
            {0.75, 0.0, 0.0, 0.5 * p->phi, CW_PRESCRIBE_FORCES, -0.3 * fn, 0.2 * fn},
            {0.0, 2e-7, -1e-7, 1e-5, CW_PRESCRIBE_CREEPAGES, 0, 0},
            {1.0, -p->xi_x, 2.0 * p->xi_y, p->phi, CW_PRESCRIBE_CREEPAGES, 0, 0},
        };
        uint64_t* saved = NULL;
        size_t len = 0;
        for (size_t k = 0; k < sizeof steps / sizeof steps[0]; ++k) {
            in.dq = steps[k].dq * dx, in.xi_x = steps[k].xi_x, in.xi_y = steps[k].xi_y;
            in.phi = steps[k].phi, in.prescribe = steps[k].prescribe;
            in.Fx = steps[k].Fx, in.Fy = steps[k].Fy;
            hash_transient(&h, t, cw_transient_step(t, &in, &r), &r, n);
            if (k == 1) { /* a trial dropped and repeated */
                hi(&h, cw_transient_rewind(t));
                hash_transient(&h, t, cw_transient_step(t, &in, &r), &r, n);
            }
            hi(&h, cw_transient_commit(t));
            double mass = 0.0;
            hi(&h, cw_transient_add_wear(t, &wp, &mass)), hd(&h, mass);
            if (k == 2) hash_saved(&h, t, &saved, &len);
        }
        hi(&h, cw_transient_restore(t, saved, len));
        in.dq = dx, in.xi_x = p->xi_x, in.xi_y = p->xi_y, in.phi = p->phi;
        in.prescribe = CW_PRESCRIBE_CREEPAGES;
        hash_transient(&h, t, cw_transient_step(t, &in, &r), &r, n);
        double mass = 0.0;
        hi(&h, cw_transient_get_wear(t, x, n, &mass)), hds(&h, x, n), hd(&h, mass);
        free(saved);
        hash_saved(&h, t, &saved, &len);
        free(saved);
    }
    free(x);
    cw_transient_destroy(t);
    end(name, &h);
}

/* Transient rolling: both models on an ellipse's uniform grid and on a gap
 * grid, the exact model world-fixed too. */
static void transient_cases(void)
{
    enum { NX = 24, NY = 20 };
    const double dx = 0.6e-3, dy = 0.6e-3, x0 = -6.9e-3, y0 = -5.7e-3;
    static double h[NX * NY];
    for (int j = 0; j < NY; ++j)
        for (int i = 0; i < NX; ++i) {
            const double x = x0 + i * dx, y = y0 + j * dy;
            h[i + NX * j] = x * x / (2 * 0.46) + y * y / (2 * 0.3);
        }
    cw_grid gap;
    cw_grid_init(&gap);
    gap.kind = CW_GRID_GAP, gap.nx = NX, gap.ny = NY, gap.x0 = x0, gap.y0 = y0, gap.dx = dx, gap.dy = dy;
    const cw_grid uniform = grid_of(CW_GRID_UNIFORM, 16, 14, 1.1);
    char name[160];
    for (int model = 0; model < 2; ++model)
        for (int coordinates = CW_COORDINATES_CONTACT; coordinates <= CW_COORDINATES_WORLD; ++coordinates) {
            if (!model && coordinates == CW_COORDINATES_WORLD) continue; /* the exact model's */
            cw_params p = base_params(&creepages[0]);
            p.model = model ? CW_MODEL_EXACT : CW_MODEL_FASTSIM;
            const char* m = model ? "exact" : "fastsim";
            const char* c = coordinates ? "world" : "contact";
            snprintf(name, sizeof name, "transient/uniform16x14/%s/%s", m, c);
            transient_run(name, &uniform, &p, 16 * 14, coordinates);
            p.gap = h, p.gap_len = NX * NY, p.normal_force = 60e3;
            snprintf(name, sizeof name, "transient/gap/%s/%s", m, c);
            transient_run(name, &gap, &p, NX * NY, coordinates);
            p.normal_method = CW_NORMAL_SEMI_HERTZ, p.spin_offset = 0.3;
            snprintf(name, sizeof name, "transient/gap/%s/%s/semi_hertz", m, c);
            transient_run(name, &gap, &p, NX * NY, coordinates);
        }
}

static void wheelrail_cases(const char* dir)
{
    char rail[512], wheel[512], msg[512];
    snprintf(rail, sizeof rail, "%s/MBench_UIC60_v3.prr", dir);
    snprintf(wheel, sizeof wheel, "%s/MBench_S1002_v3.prw", dir);
    for (int model = 0; model < 2; ++model)
        for (int side = CW_WHEELRAIL_RIGHT; side <= CW_WHEELRAIL_LEFT; ++side) {
            cw_wheelrail_params wp;
            cw_wheelrail_params_init(&wp);
            wp.side = side;
            if (!model) wp.model = CW_MODEL_FASTSIM, wp.normal_method = CW_NORMAL_SEMI_HERTZ;
            cw_wheelrail* w = NULL;
            if (cw_wheelrail_create(&wp, rail, wheel, &w, msg, sizeof msg)) fail("wheelrail_create", msg);
            cw_wear_profile* rp = NULL;
            cw_wear_profile* wpf = NULL;
            double nodes[400];
            for (int k = 0; k < 400; ++k) nodes[k] = -0.06 + 3e-4 * k;
            if (cw_wear_profile_create(nodes, 400, &rp, msg, sizeof msg)) fail("profile", msg);
            if (cw_wear_profile_create(nodes, 400, &wpf, msg, sizeof msg)) fail("profile", msg);
            static const double shifts[] = {0.0, 3e-3, 6e-3, -4e-3, 9e-3};
            for (size_t k = 0; k < sizeof shifts / sizeof shifts[0]; ++k) {
                double z_found = 0.0; /* the height case starts 5 um below the force case's */
                for (int load = CW_WHEELRAIL_FORCE; load <= CW_WHEELRAIL_HEIGHT; ++load) {
                    cw_wheelrail_motion mo;
                    cw_wheelrail_motion_init(&mo);
                    mo.y = side ? -shifts[k] : shifts[k];
                    mo.yaw = 2e-3 * (double)k, mo.roll = -1.8e-4;
                    mo.vs = 20.0, mo.vpitch = -20.0 / 0.46 * (1.0 + 1e-3 * (double)k);
                    mo.z = load == CW_WHEELRAIL_HEIGHT ? z_found + 5e-6 : 0.0;
                    cw_wheelrail_totals t;
                    cw_wheelrail_totals_init(&t);
                    hash h = begin();
                    const int status = cw_wheelrail_solve(w, &mo, load, 80e3, &t);
                    hi(&h, status);
                    if (status == CW_OK) {
                        z_found = t.z;
                        const double d[] = {t.z, t.Fx, t.Fy, t.Fz};
                        hds(&h, d, 4);
                        hi(&h, t.n_patches), hi(&h, t.evaluations);
                        for (int q = 0; q < t.n_patches; ++q) {
                            cw_wheelrail_patch pt;
                            cw_wheelrail_patch_init(&pt);
                            cw_wheelrail_get_patch(w, (size_t)q, &pt);
                            const double e[] = {pt.x_contact, pt.y_contact, pt.z_contact, pt.y_contact_rail,
                                                pt.z_contact_rail, pt.y_contact_wheel, pt.z_contact_wheel,
                                                pt.contact_angle, pt.cksi, pt.ceta, pt.cphi, pt.veloc, pt.Fn,
                                                pt.Fx, pt.Fs, pt.Mn, pt.p_max, pt.approach, pt.Fx_track,
                                                pt.Fy_track, pt.Fz_track, pt.rolling_radius, pt.field_x0,
                                                pt.field_s0, pt.field_dx, pt.field_ds, pt.rail_profile_y,
                                                pt.rail_s_cos, pt.wheel_profile_y, pt.wheel_s_cos};
                            hds(&h, e, sizeof e / sizeof e[0]);
                            const int i[] = {pt.n_contact, pt.n_adhesion, pt.n_slip, pt.nx, pt.ny, pt.field_nx, pt.field_ny};
                            his(&h, i, 7);
                            const size_t n = (size_t)pt.field_nx * (size_t)pt.field_ny;
                            double* f = malloc(n * sizeof *f);
                            int* st = malloc(n * sizeof *st);
                            for (int field = CW_FIELD_X; field <= CW_FIELD_WORK_CONSISTENT; ++field)
                                if (cw_wheelrail_get_patch_field(w, (size_t)q, field, f, n) == CW_OK) hds(&h, f, n);
                            if (cw_wheelrail_get_patch_state(w, (size_t)q, st, n) == CW_OK) his(&h, st, n);
                            free(f);
                            free(st);
                        }
                        cw_wear_params lw;
                        cw_wear_params_init(&lw);
                        cw_wear_result wr;
                        cw_wear_result_init(&wr);
                        hi(&h, cw_wheelrail_add_wear(w, &lw, 1e3, rp, wpf, &wr));
                        hd(&h, wr.max_depth), hd(&h, wr.mass_per_pass), hd(&h, wr.work);
                        size_t count = 0;
                        cw_wheelrail_get_profile(w, CW_WHEELRAIL_WHEEL, NULL, NULL, 0, &count);
                        double* py = malloc(2 * count * sizeof *py);
                        if (cw_wheelrail_get_profile(w, CW_WHEELRAIL_WHEEL, py, py + count, count, &count) == CW_OK)
                            hds(&h, py, 2 * count);
                        free(py);
                    }
                    char name[160];
                    snprintf(name, sizeof name, "wheelrail/%s/%s/y%+.0fmm/%s", model ? "exact" : "fast",
                             side ? "left" : "right", shifts[k] * 1e3, load ? "height" : "force");
                    end(name, &h);
                }
            }
            hash h = begin();
            double depth[400];
            cw_wear_profile_get_depth(rp, CW_WEAR_DEPTH_HEIGHT, depth, 400), hds(&h, depth, 400);
            cw_wear_profile_get_depth(wpf, CW_WEAR_DEPTH_HEIGHT, depth, 400), hds(&h, depth, 400);
            char name[160];
            snprintf(name, sizeof name, "wheelrail/%s/%s/wear", model ? "exact" : "fast", side ? "left" : "right");
            end(name, &h);
            cw_wear_profile_destroy(rp);
            cw_wear_profile_destroy(wpf);
            cw_wheelrail_destroy(w);
        }
}

static void helpers(void)
{
    hash h = begin();
    double c[4], l[3], hz[4], tx, ty;
    for (int k = 0; k < 30; ++k) {
        const double g = 0.05 + 0.35 * k;
        hi(&h, cw_kalker_coefficients(g, 0.28, c, NULL, 0)), hds(&h, c, 4);
        hi(&h, cw_kalker_flexibilities(6e-3 * g, 6e-3, 82e9, 0.25, l, NULL, 0)), hds(&h, l, 3);
        hi(&h, cw_hertz_solve(1.0 / (0.92 * g), 1.0 / 0.6, 1e3 * (k + 1), 82e9 / 0.72, hz, NULL, 0)), hds(&h, hz, 4);
        hi(&h, cw_fastsim_normalised(0.1 * k - 1.0, 0.3, 0.02 * k, -0.4, 5 + k, 5 + k % 7, 1e-3, &tx, &ty, NULL, 0));
        hd(&h, tx), hd(&h, ty);
    }
    end("helpers", &h);
}

int main(int argc, char** argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: golden_outputs <profile dir (tests/wheelrail/data)>\n");
        return 2;
    }
    printf("# creepwork %s\n", cw_version_string());
    helpers();
    elliptic_cases();
    warm_sequence();
    batch_and_accumulator();
    const creepage wear_c = {"wear", 2e-3, -1e-3, 0.4};
    cw_params p = base_params(&wear_c);
    for (int model = 0; model < 3; ++model) {
        const cw_grid g = grid_of(CW_GRID_UNIFORM, 22, 18, 1.05);
        p.model = model;
        char name[64];
        snprintf(name, sizeof name, "uniform22x18/model%d", model);
        wear_case(name, &g, &p);
    }
    gap_cases();
    transient_cases();
    wheelrail_cases(argv[1]);
    return 0;
}
