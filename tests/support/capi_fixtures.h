/* Fixtures of the C ABI tests (C and C++; tests/capi, tests/robustness,
 * tests/compat): a grid, solver or batch on grid X; sentinels that prove an
 * output was left untouched; message and status checks; a list of contacts
 * that together reach every branch of a solve (pressure laws, flexibility
 * sources, spin, rolling direction, adhesion to full slip); and the
 * invariants every successful solve must satisfy. Always goes through the
 * public header. */
#ifndef CREEPWORK_CAPI_FIXTURES_H
#define CREEPWORK_CAPI_FIXTURES_H

#include "test_support.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "creepwork/creepwork.h"

/* ------------------------------------------------------------- grid X */

/* cw_grid_init's grid with the given kind (CW_GRID_*), size and box scale. */
static inline cw_grid cw_test_grid(int kind, int nx, int ny, double box_scale)
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = kind;
    g.nx = nx;
    g.ny = ny;
    g.box_scale = box_scale;
    return g;
}

/* A solver on that grid; fails the test (naming the grid) if it cannot be
 * made. */
static inline cw_solver* cw_test_solver(int kind, int nx, int ny, double box_scale)
{
    const cw_grid g = cw_test_grid(kind, nx, ny, box_scale);
    cw_solver* s = NULL;
    char message[256];
    if (cw_solver_create(&g, &s, message, sizeof message) != CW_OK || !s ||
        message[0] != '\0') {
        print_error("cw_solver_create(%d, %d, %d, %g): %s\n", kind, nx, ny, box_scale, message);
        _fail(__FILE__, __LINE__);
    }
    return s;
}

/* A batch on that grid with threads threads (0: one per core). */
static inline cw_batch* cw_test_batch(int kind, int nx, int ny, double box_scale, int threads)
{
    const cw_grid g = cw_test_grid(kind, nx, ny, box_scale);
    cw_batch* b = NULL;
    char message[256];
    if (cw_batch_create(&g, threads, &b, message, sizeof message) != CW_OK || !b) {
        print_error("cw_batch_create(%d, %d, %d, %g, %d): %s\n", kind, nx, ny, box_scale,
                    threads, message);
        _fail(__FILE__, __LINE__);
    }
    return b;
}

/* A gap grid (30 x 56 cells of 0.35 x 0.45 mm) holding two paraboloid
 * lobes 12 mm apart across, the upper one 2 um higher: under a load two
 * separate contact patches, lower y first. h receives its 30 * 56 values. */
enum { CW_LOBES_NX = 30, CW_LOBES_NY = 56 };
static inline cw_grid cw_test_two_lobes(double* h)
{
    cw_grid g = cw_test_grid(CW_GRID_GAP, CW_LOBES_NX, CW_LOBES_NY, 1.0);
    g.dx = 0.35e-3;
    g.dy = 0.45e-3;
    g.x0 = -5e-3;
    g.y0 = -12e-3;
    for (int j = 0; j < CW_LOBES_NY; ++j)
        for (int i = 0; i < CW_LOBES_NX; ++i) {
            const double x = g.x0 + i * g.dx, y = g.y0 + j * g.dy;
            const double lower = x * x / 0.9 + (y + 6e-3) * (y + 6e-3) / 0.5;
            const double upper = x * x / 0.9 + (y - 6e-3) * (y - 6e-3) / 0.5 + 2e-6;
            h[i + CW_LOBES_NX * j] = lower < upper ? lower : upper;
        }
    return g;
}

/* CONTACT's example catt_to_cart (examples/catt_to_cart.inp, in SI): a
 * sphere, h = 2.963 (x^2 + y^2) [m], on 34 x 33 cells of 0.25 mm from
 * (-4.125, -4.125) mm; N = 0.4705 N, G = 1e6 Pa, nu = 0.28, mu = 0.4013;
 * the exact model. h receives its 34 * 33 values; params the contact. */
enum { CW_CATT_NX = 34, CW_CATT_NY = 33 };
static inline cw_grid cw_test_catt_to_cart(double* h, cw_params* params)
{
    cw_grid g = cw_test_grid(CW_GRID_GAP, CW_CATT_NX, CW_CATT_NY, 1.0);
    g.dx = g.dy = 0.25e-3;
    g.x0 = g.y0 = -4.0e-3;
    for (int j = 0; j < CW_CATT_NY; ++j)
        for (int i = 0; i < CW_CATT_NX; ++i) {
            const double x = g.x0 + i * g.dx, y = g.y0 + j * g.dy;
            h[i + CW_CATT_NX * j] = 2.963 * (x * x + y * y);
        }
    cw_params_init(params);
    params->model = CW_MODEL_EXACT;
    params->normal_force = 0.4705;
    params->G = 1e6;
    params->nu = 0.28;
    params->mu = 0.4013;
    params->gap = h;
    params->gap_len = (size_t)CW_CATT_NX * CW_CATT_NY;
    return g;
}

/* An elliptic contact on the exact model's uniform grid (32 x 24, box
 * scale 1.1): a = 4 mm, b = 2.5 mm and catt_to_cart's load and material. */
static inline cw_grid cw_test_transient_ellipse(cw_params* params)
{
    cw_grid g = cw_test_grid(CW_GRID_UNIFORM, 32, 24, 1.1);
    cw_params_init(params);
    params->model = CW_MODEL_EXACT;
    params->a = 4e-3;
    params->b = 2.5e-3;
    params->normal_force = 0.4705;
    params->G = 1e6;
    params->nu = 0.28;
    params->mu = 0.4013;
    return g;
}

/* Elements of the solver's grid. */
static inline size_t cw_cells(const cw_solver* s)
{
    int nx = 0, ny = 0;
    cw_solver_grid_size(s, &nx, &ny);
    return (size_t)nx * (size_t)ny;
}

/* ---------------------------------------------------------- sentinels */

/* Written into output buffers before a call that must not touch them. */
#define CW_SENTINEL (-12345.0)
#define CW_INT_SENTINEL (-777)
/* Byte pattern for structs and buffers that must come back unchanged: no
 * result of the library has it as a whole. */
#define CW_POISON 0xA5

static inline void cw_poison(void* p, size_t bytes) { memset(p, CW_POISON, bytes); }

static inline int cw_poisoned(const void* p, size_t bytes)
{
    const unsigned char* c = (const unsigned char*)p;
    for (size_t k = 0; k < bytes; ++k)
        if (c[k] != CW_POISON) return 0;
    return 1;
}

/* A result struct full of CW_POISON, with a valid struct_size. */
static inline void cw_poison_result(cw_result* r)
{
    cw_poison(r, sizeof *r);
    r->struct_size = sizeof *r;
}

/* Still as cw_poison_result left it. */
static inline int cw_result_poisoned(const cw_result* r)
{
    return r->struct_size == sizeof *r &&
           cw_poisoned((const unsigned char*)r + sizeof r->struct_size,
                       sizeof *r - sizeof r->struct_size);
}

static inline void cw_fill(double* v, size_t n, double value)
{
    for (size_t k = 0; k < n; ++k) v[k] = value;
}

static inline void cw_fill_int(int* v, size_t n, int value)
{
    for (size_t k = 0; k < n; ++k) v[k] = value;
}

/* Number of entries that differ from value (bitwise, so NaN counts as changed). */
static inline size_t cw_count_changed(const double* v, size_t n, double value)
{
    size_t changed = 0;
    for (size_t k = 0; k < n; ++k) changed += memcmp(&v[k], &value, sizeof value) != 0;
    return changed;
}

static inline size_t cw_count_changed_int(const int* v, size_t n, int value)
{
    size_t changed = 0;
    for (size_t k = 0; k < n; ++k) changed += v[k] != value;
    return changed;
}

#define assert_untouched(v, n) assert_int_equal(cw_count_changed((v), (n), CW_SENTINEL), 0)
#define assert_untouched_int(v, n) \
    assert_int_equal(cw_count_changed_int((v), (n), CW_INT_SENTINEL), 0)

/* Bitwise equality of two doubles (0.0 and -0.0 differ, NaN equals itself). */
static inline int cw_same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* The solver's last patches read into an older cw_patch (cut before Fn)
 * and a newer one (three doubles appended), each array with room for one
 * patch more: patch k lands at k times the caller's struct_size holding
 * expected[k]'s fields up to that size, and nothing is written past the
 * fields the library knows or past the last patch. */
typedef struct {
    cw_patch p;
    double future[3];
} cw_patch_next;

static inline void cw_check_patch_strides(const cw_solver* s, const cw_patch* expected,
                                          size_t count)
{
    enum { OLD = offsetof(cw_patch, Fn) };
    const size_t room = count + 1, head = sizeof(size_t);
    unsigned char* old = (unsigned char*)malloc(room * OLD);
    cw_patch_next* next = (cw_patch_next*)malloc(room * sizeof *next);
    assert_non_null(old);
    assert_non_null(next);
    cw_poison(old, room * OLD);
    cw_poison(next, room * sizeof *next);
    for (size_t k = 0; k < room; ++k) {
        const size_t size = OLD;
        memcpy(old + k * OLD, &size, sizeof size);
        next[k].p.struct_size = sizeof next[k];
    }
    size_t n = 0;
    assert_int_equal(cw_solver_get_patches(s, (cw_patch*)(void*)old, room, &n), CW_OK);
    assert_int_equal(n, count);
    assert_int_equal(cw_solver_get_patches(s, &next[0].p, room, &n), CW_OK);
    for (size_t k = 0; k < count; ++k) {
        const unsigned char* today = (const unsigned char*)&expected[k];
        assert_memory_equal(old + k * OLD + head, today + head, OLD - head);
        assert_int_equal(next[k].p.struct_size, sizeof next[k]);
        assert_memory_equal((const unsigned char*)&next[k].p + head, today + head,
                            sizeof(cw_patch) - head);
        assert_true(cw_poisoned(next[k].future, sizeof next[k].future));
    }
    assert_true(cw_poisoned(old + count * OLD + head, OLD - head));
    assert_true(cw_poisoned((const unsigned char*)&next[count] + head, sizeof next[count] - head));
    free(old);
    free(next);
}

/* ------------------------------------------------- messages, statuses */

static inline int cw_identifier_char(char c) { return isalnum((unsigned char)c) || c == '_'; }

/* name occurs in message, not inside a longer identifier: "a" is named by
 * "a = 0" but not by "area"; a name that ends in punctuation ("a = ") is
 * checked at its start only. */
static inline int cw_names(const char* message, const char* name)
{
    if (!message || !*name) return 0;
    const size_t n = strlen(name);
    for (const char* p = strstr(message, name); p; p = strstr(p + 1, name)) {
        const int before_ok =
            p == message || !cw_identifier_char(name[0]) || !cw_identifier_char(p[-1]);
        const int after_ok = !cw_identifier_char(name[n - 1]) || !cw_identifier_char(p[n]);
        if (before_ok && after_ok) return 1;
    }
    return 0;
}

/* The detailed message must name the offending input. */
#define assert_names(message, name)                                                     \
    do {                                                                                \
        const char* cw_msg_ = (message);                                                \
        if (!cw_names(cw_msg_, (name))) {                                               \
            print_error("message \"%s\" does not name \"%s\"\n",                         \
                        cw_msg_ ? cw_msg_ : "(null)", (name));                          \
            _fail(__FILE__, __LINE__);                                                  \
        }                                                                               \
    } while (0)

#define assert_status(call, expected)                                                   \
    do {                                                                                \
        const int cw_st_ = (call);                                                      \
        if (cw_st_ != (expected)) {                                                     \
            print_error("%s returned %d (%s), expected %d (%s)\n", #call, cw_st_,      \
                        cw_status_string(cw_st_), (int)(expected),                      \
                        cw_status_string(expected));                                    \
            _fail(__FILE__, __LINE__);                                                  \
        }                                                                               \
    } while (0)

/* ----------------------------------------------------------- contacts */

enum { CW_TEST_CASES = 10 };

/* Contact k of the list, in SI units, from cw_params_init's defaults
 * (steel, a = b = 6 mm, N = 80 kN, mu = 0.3). */
static inline void cw_test_case(int k, cw_params* p)
{
    cw_params_init(p);
    switch (k) {
    case 0: /* longitudinal, partial slip */
        p->xi_x = 1e-3;
        break;
    case 1: /* lateral + spin, Hertz pressure */
        p->pressure = CW_PRESSURE_ELLIPTIC;
        p->xi_y = -5e-4;
        p->phi = 0.3;
        break;
    case 2: /* combined, rolling towards -x */
        p->a = 7e-3;
        p->b = 4e-3;
        p->xi_x = 1.9e-3;
        p->xi_y = 1.1e-3;
        p->phi = 0.47;
        p->rolling_direction = -1;
        break;
    case 3: /* combined, rolling towards -x, Hertz pressure, high friction */
        p->pressure = CW_PRESSURE_ELLIPTIC;
        p->a = 4e-3;
        p->b = 8e-3;
        p->mu = 0.6;
        p->xi_x = -8e-4;
        p->xi_y = 4e-4;
        p->phi = -1.2;
        p->rolling_direction = -1;
        break;
    case 4: /* large creepage: full slip */
        p->xi_x = 0.05;
        p->xi_y = 0.02;
        break;
    case 5: /* tiny creepage: (almost) full adhesion */
        p->xi_x = 1e-7;
        break;
    case 6: /* no creepage at all */
        break;
    case 7: /* flexibilities given (legacy codes), narrow ellipse */
        p->flexibility = CW_FLEX_GIVEN;
        p->a = 3e-3;
        p->b = 10e-3;
        p->L1 = 4.6e-14;
        p->L2 = 5.3e-14;
        p->L3 = 3.9e-14;
        p->xi_x = 6e-4;
        p->phi = 0.9;
        break;
    case 8: /* pure spin, long ellipse, rolling towards -x */
        p->pressure = CW_PRESSURE_ELLIPTIC;
        p->a = 12e-3;
        p->b = 3e-3;
        p->phi = 2.0;
        p->rolling_direction = -1;
        break;
    default: /* frictionless: no tangential traction */
        p->mu = 0.0;
        p->xi_x = 1e-3;
        p->xi_y = -1e-3;
        break;
    }
}

/* --------------------------------------------- invariants of a solve */

static inline int cw_all_finite(const double* v, size_t n)
{
    for (size_t k = 0; k < n; ++k)
        if (!isfinite(v[k])) return 0;
    return 1;
}

/* Every double of a result struct. */
static inline int cw_result_finite(const cw_result* r)
{
    const double v[] = {r->Fx,  r->Fy,  r->Mz,  r->W_macro, r->W_micro_paper, r->K,
                        r->W_consistent, r->balance_factor, r->adhesion_fraction, r->a,
                        r->b,   r->L1,  r->L2,  r->L3,  r->C11, r->C22, r->C23, r->C33,
                        r->profile_max_diff, r->profile_rms_diff};
    return cw_all_finite(v, sizeof v / sizeof v[0]);
}

/* Fetches one field into a fresh malloc'd buffer (caller frees). */
static inline double* cw_field(const cw_solver* s, int field)
{
    const size_t n = cw_cells(s);
    double* out = (double*)malloc(n * sizeof *out);
    assert_non_null(out);
    assert_status(cw_solver_get_field(s, field, out, n), CW_OK);
    return out;
}

/* The invariants of a successful solve, whatever its inputs:
 *  - every total and every field finite;
 *  - pointwise Coulomb bound |p| <= mu pz on every element;
 *  - |F| <= sum_k mu pz_k area_k (the discrete bound, exact up to rounding);
 *  - element counts agree with the state map;
 *  - FULL: energy-consistent map >= 0; with work_flags == 0 it sums to
 *    W_macro (1e-9 relative) and W_consistent equals that sum. */
static inline void cw_check_solution(const cw_solver* s, const cw_params* p, int mode,
                                     const cw_result* r)
{
    const size_t n = cw_cells(s);
    assert_true(cw_result_finite(r));
    const int fields_forces[] = {CW_FIELD_X,  CW_FIELD_Y,  CW_FIELD_AREA, CW_FIELD_PZ,
                                 CW_FIELD_PX, CW_FIELD_PY, CW_FIELD_MZ};
    for (size_t f = 0; f < sizeof fields_forces / sizeof fields_forces[0]; ++f) {
        double* v = cw_field(s, fields_forces[f]);
        if (!cw_all_finite(v, n)) {
            print_error("field %d has a non-finite value\n", fields_forces[f]);
            _fail(__FILE__, __LINE__);
        }
        free(v);
    }
    double* area = cw_field(s, CW_FIELD_AREA);
    double* pz = cw_field(s, CW_FIELD_PZ);
    double* px = cw_field(s, CW_FIELD_PX);
    double* py = cw_field(s, CW_FIELD_PY);
    double bound = 0.0;
    for (size_t k = 0; k < n; ++k) {
        const double local = p->mu * pz[k];
        assert_true(pz[k] >= 0.0 && area[k] >= 0.0);
        /* |p| <= mu pz: the march scales onto the bound, so rounding only. */
        if (!(hypot(px[k], py[k]) <= local * (1.0 + 1e-12) + 1e-300)) {
            print_error("element %zu: |p| = %.17g > mu pz = %.17g\n", k, hypot(px[k], py[k]),
                        local);
            _fail(__FILE__, __LINE__);
        }
        bound += local * area[k];
    }
    const double F = hypot(r->Fx, r->Fy);
    if (!(F <= bound * (1.0 + 1e-12) + 1e-300)) {
        print_error("|F| = %.17g exceeds sum mu pz area = %.17g\n", F, bound);
        _fail(__FILE__, __LINE__);
    }
    free(area);
    free(pz);
    free(px);
    free(py);

    int* state = (int*)malloc(n * sizeof *state);
    assert_non_null(state);
    assert_status(cw_solver_get_state(s, state, n), CW_OK);
    int contact = 0, slip = 0;
    for (size_t k = 0; k < n; ++k) {
        assert_true(state[k] == CW_STATE_EXTERIOR || state[k] == CW_STATE_ADHESION ||
                    state[k] == CW_STATE_SLIP);
        contact += state[k] != CW_STATE_EXTERIOR;
        slip += state[k] == CW_STATE_SLIP;
    }
    free(state);
    assert_int_equal(contact, r->n_contact);
    assert_int_equal(slip, r->n_slip);
    assert_int_equal(r->n_adhesion + r->n_slip, r->n_contact);

    if (mode != CW_SOLVE_FULL) return;
    const int fields_full[] = {CW_FIELD_SX, CW_FIELD_SY, CW_FIELD_WORK_PAPER,
                               CW_FIELD_WORK_CONSISTENT};
    for (size_t f = 0; f < sizeof fields_full / sizeof fields_full[0]; ++f) {
        double* v = cw_field(s, fields_full[f]);
        if (!cw_all_finite(v, n)) {
            print_error("field %d has a non-finite value\n", fields_full[f]);
            _fail(__FILE__, __LINE__);
        }
        free(v);
    }
    double* w = cw_field(s, CW_FIELD_WORK_CONSISTENT);
    double sum = 0.0;
    for (size_t k = 0; k < n; ++k) {
        assert_true(w[k] >= 0.0);
        sum += w[k];
    }
    free(w);
    assert_close(r->W_consistent, sum, 1e-12, 1e-300);
    if (r->work_flags == 0) assert_close(sum, r->W_macro, 1e-9, 1e-300);

    int nx = 0, ny = 0;
    cw_solver_grid_size(s, &nx, &ny);
    double* prof = (double*)malloc(3 * (size_t)ny * sizeof *prof);
    assert_non_null(prof);
    assert_status(cw_solver_get_profile(s, prof, prof + ny, prof + 2 * ny, (size_t)ny), CW_OK);
    assert_true(cw_all_finite(prof, 3 * (size_t)ny));
    free(prof);
}

#endif
