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
#include <string.h>

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

/* Skips must be visible to CTest: a test that cannot run here calls
 * cw_skip() (not cmocka's skip(), which cmocka counts as a pass), and main
 * returns cw_run_tests(tests, name): the whole group, or with a name only the
 * test of exactly that name (an unknown name is an error: a filter matching
 * nothing would run zero tests and pass). It returns CW_TEST_SKIP, the
 * SKIP_RETURN_CODE of the CTest entries that can skip, when every test it ran
 * was skipped. */
#define CW_TEST_SKIP 77
static inline int* cw_test_skips(void)
{
    static int skips = 0;
    return &skips;
}
#define cw_skip()              \
    do {                       \
        ++*cw_test_skips();    \
        skip();                \
    } while (0)
#define cw_run_tests(tests, name) \
    cw_test_run_tests(__FILE__, tests, sizeof(tests) / sizeof((tests)[0]), (name))

static inline int cw_test_run_tests(const char* group, const struct CMUnitTest* tests, size_t n,
                                    const char* name)
{
    size_t first = 0, count = n;
    if (name) {
        for (first = 0; first < n && strcmp(tests[first].name, name) != 0; ++first) {
        }
        if (first == n) {
            fprintf(stderr, "%s: no test is named '%s'\n", group, name);
            return 2;
        }
        count = 1;
    }
    const int failed = _cmocka_run_group_tests(group, tests + first, count, NULL, NULL);
    return failed == 0 && *cw_test_skips() == (int)count ? CW_TEST_SKIP : failed;
}

#endif
