/* Shared by the C ABI tests (C and C++): sentinel buffers, message checks and
 * a list of contacts that together reach every branch of a solve (pressure
 * laws, flexibility sources, spin, rolling direction, adhesion to full
 * slip). Always goes through the public header. */
#ifndef CW_CAPI_TEST_H
#define CW_CAPI_TEST_H

#include "test_support.h"

#include <string.h>

#include "creepwork/creepwork.h"

/* Written into output buffers before a call that must not touch them. */
#define CW_SENTINEL (-12345.0)
#define CW_INT_SENTINEL (-777)
/* Byte pattern for structs that must come back unchanged. */
#define CW_POISON 0xA5

/* A result struct full of CW_POISON, with a valid struct_size. */
static inline void cw_poison_result(cw_result* r)
{
    memset(r, CW_POISON, sizeof *r);
    r->struct_size = sizeof *r;
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

/* The detailed message must name the offending input. */
#define assert_names(message, needle) \
    cw_test_assert_names((message), (needle), __FILE__, __LINE__)

static inline void cw_test_assert_names(const char* message, const char* needle,
                                        const char* file, int line)
{
    if (!message || !strstr(message, needle)) {
        print_error("message \"%s\" does not name \"%s\"\n", message ? message : "(null)",
                    needle);
        _fail(file, line);
    }
}

/* Bitwise equality of two doubles (0.0 and -0.0 differ, NaN equals itself). */
static inline int cw_same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* A solver on the given grid; fails the test if it cannot be made. */
static inline cw_solver* cw_test_solver(int kind, int nx, int ny, double box_scale)
{
    cw_grid g;
    cw_grid_init(&g);
    g.kind = kind;
    g.nx = nx;
    g.ny = ny;
    g.box_scale = box_scale;
    cw_solver* s = NULL;
    char message[256];
    assert_int_equal(cw_solver_create(&g, &s, message, sizeof message), CW_OK);
    assert_string_equal(message, ""); /* "" on success */
    assert_non_null(s);
    return s;
}

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

#endif
