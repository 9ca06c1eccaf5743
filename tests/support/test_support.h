/* Shared by the cmocka tests (C and C++): includes cmocka in the order it
 * needs and adds the one assertion it lacks. */
#ifndef CREEPWORK_TEST_SUPPORT_H
#define CREEPWORK_TEST_SUPPORT_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#ifdef __cplusplus
extern "C" { /* cmocka 1.1.5 has no C++ guards of its own */
#endif
#include <cmocka.h>
#ifdef __cplusplus
}
#endif
#include <math.h>
#include <stdio.h>

/* |a - b| <= atol + rtol * |b|; prints both values on failure. */
#define assert_close(a, b, rtol, atol) \
    cw_test_assert_close((double)(a), (double)(b), (rtol), (atol), #a, #b, __FILE__, __LINE__)

static inline void cw_test_assert_close(double a, double b, double rtol, double atol,
                                        const char* ea, const char* eb, const char* file,
                                        int line)
{
    const double tol = atol + rtol * fabs(b);
    if (!(fabs(a - b) <= tol)) {
        print_error("%s = %.17g is not within %.3g of %s = %.17g (diff %.3g)\n", ea, a, tol, eb,
                    b, fabs(a - b));
        _fail(file, line);
    }
}

#endif
