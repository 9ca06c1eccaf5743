/* Helpers shared by the robustness tests (C, cmocka): sentinels that prove
 * an output was left untouched, "message names the input" checks, and the
 * physical invariants every successful solve must satisfy. */
#ifndef CREEPWORK_ROBUSTNESS_SUPPORT_H
#define CREEPWORK_ROBUSTNESS_SUPPORT_H

#include "test_support.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "creepwork/creepwork.h"

/* A byte pattern no result of the library can have as a whole. */
#define ROB_SENTINEL_BYTE 0xA5

static inline void rob_fill(void* p, size_t bytes) { memset(p, ROB_SENTINEL_BYTE, bytes); }

static inline int rob_untouched(const void* p, size_t bytes)
{
    const unsigned char* c = (const unsigned char*)p;
    for (size_t k = 0; k < bytes; ++k)
        if (c[k] != ROB_SENTINEL_BYTE) return 0;
    return 1;
}

/* A result struct full of sentinels except a valid struct_size. */
static inline void rob_sentinel_result(cw_result* r)
{
    rob_fill(r, sizeof *r);
    r->struct_size = sizeof *r;
}

static inline int rob_result_untouched(const cw_result* r)
{
    return r->struct_size == sizeof *r &&
           rob_untouched((const unsigned char*)r + sizeof r->struct_size,
                         sizeof *r - sizeof r->struct_size);
}

/* name occurs in message as a whole word (not inside a longer identifier). */
static inline int rob_names(const char* message, const char* name)
{
    const size_t n = strlen(name);
    for (const char* p = strstr(message, name); p; p = strstr(p + 1, name)) {
        const int before_ok = p == message || !(isalnum((unsigned char)p[-1]) || p[-1] == '_');
        const char after = p[n];
        const int after_ok = !(isalnum((unsigned char)after) || after == '_');
        if (before_ok && after_ok) return 1;
    }
    return 0;
}

#define assert_names(message, name)                                                       \
    do {                                                                                  \
        const char* rob_msg_ = (message);                                                 \
        if (!rob_names(rob_msg_, (name))) {                                               \
            print_error("message \"%s\" does not name \"%s\"\n", rob_msg_, (name));       \
            _fail(__FILE__, __LINE__);                                                    \
        }                                                                                 \
    } while (0)

#define assert_status(call, expected)                                                     \
    do {                                                                                  \
        const int rob_st_ = (call);                                                       \
        if (rob_st_ != (expected)) {                                                      \
            print_error("%s returned %d (%s), expected %d (%s)\n", #call, rob_st_,       \
                        cw_status_string(rob_st_), (int)(expected),                       \
                        cw_status_string(expected));                                      \
            _fail(__FILE__, __LINE__);                                                    \
        }                                                                                 \
    } while (0)

static inline int rob_all_finite(const double* v, size_t n)
{
    for (size_t k = 0; k < n; ++k)
        if (!isfinite(v[k])) return 0;
    return 1;
}

/* Every double of a result struct. */
static inline int rob_result_finite(const cw_result* r)
{
    const double v[] = {r->Fx,  r->Fy,  r->Mz,  r->W_macro, r->W_micro_paper, r->K,
                        r->W_consistent, r->balance_factor, r->adhesion_fraction, r->a,
                        r->b,   r->L1,  r->L2,  r->L3,  r->C11, r->C22, r->C23, r->C33,
                        r->profile_max_diff, r->profile_rms_diff};
    return rob_all_finite(v, sizeof v / sizeof v[0]);
}

static inline cw_solver* rob_solver(int kind, int nx, int ny, double box_scale)
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = kind;
    g.nx = nx;
    g.ny = ny;
    g.box_scale = box_scale;
    cw_solver* s = NULL;
    char message[256];
    const int st = cw_solver_create(&g, &s, message, sizeof message);
    if (st != CW_OK) {
        print_error("cw_solver_create(%d, %d, %d, %g): %s\n", kind, nx, ny, box_scale, message);
        _fail(__FILE__, __LINE__);
    }
    return s;
}

static inline size_t rob_cells(const cw_solver* s)
{
    int nx = 0, ny = 0;
    cw_solver_grid_size(s, &nx, &ny);
    return (size_t)nx * (size_t)ny;
}

/* Fetches one field into a fresh malloc'd buffer (caller frees). */
static inline double* rob_field(const cw_solver* s, int field)
{
    const size_t n = rob_cells(s);
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
static inline void rob_check_solution(const cw_solver* s, const cw_params* p, int mode,
                                      const cw_result* r)
{
    const size_t n = rob_cells(s);
    assert_true(rob_result_finite(r));
    const int fields_forces[] = {CW_FIELD_X,  CW_FIELD_Y,  CW_FIELD_AREA, CW_FIELD_PZ,
                                 CW_FIELD_PX, CW_FIELD_PY, CW_FIELD_MZ};
    for (size_t f = 0; f < sizeof fields_forces / sizeof fields_forces[0]; ++f) {
        double* v = rob_field(s, fields_forces[f]);
        if (!rob_all_finite(v, n)) {
            print_error("field %d has a non-finite value\n", fields_forces[f]);
            _fail(__FILE__, __LINE__);
        }
        free(v);
    }
    double* area = rob_field(s, CW_FIELD_AREA);
    double* pz = rob_field(s, CW_FIELD_PZ);
    double* px = rob_field(s, CW_FIELD_PX);
    double* py = rob_field(s, CW_FIELD_PY);
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
        double* v = rob_field(s, fields_full[f]);
        if (!rob_all_finite(v, n)) {
            print_error("field %d has a non-finite value\n", fields_full[f]);
            _fail(__FILE__, __LINE__);
        }
        free(v);
    }
    double* w = rob_field(s, CW_FIELD_WORK_CONSISTENT);
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
    assert_true(rob_all_finite(prof, 3 * (size_t)ny));
    free(prof);
}

#endif
