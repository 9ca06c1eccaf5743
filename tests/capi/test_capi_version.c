/* Versions and status strings: what a host checks first after loading the
 * library. */
#include "capi_fixtures.h"

#include <stdio.h>

/* Run-time numbers equal the macros the test was built against, and the
 * number follows the documented rule 10000*major + 100*minor + patch. */
static void version_numbers_match_header(void** state)
{
    (void)state;
    assert_int_equal(cw_version_number(), CW_VERSION_NUMBER);
    assert_int_equal(CW_VERSION_NUMBER,
                     10000 * CW_VERSION_MAJOR + 100 * CW_VERSION_MINOR + CW_VERSION_PATCH);
    assert_int_equal(cw_abi_version(), CW_ABI_VERSION);
    assert_true(CW_ABI_VERSION >= 1);
}

/* "major.minor.patch" from the macros, and the same as CMake's project()
 * version, so the header and the build cannot drift apart. */
static void version_string_matches_macros_and_project(void** state)
{
    (void)state;
    char expected[32];
    snprintf(expected, sizeof expected, "%d.%d.%d", CW_VERSION_MAJOR, CW_VERSION_MINOR,
             CW_VERSION_PATCH);
    assert_non_null(cw_version_string());
    assert_string_equal(cw_version_string(), expected);
    assert_string_equal(cw_version_string(), CW_TEST_PROJECT_VERSION);
}

/* Codes are never renumbered (header: "only appended"): the values are the
 * ABI, so they are spelled out here. */
static void status_codes_are_frozen(void** state)
{
    (void)state;
    assert_int_equal(CW_OK, 0);
    assert_int_equal(CW_ERR_NULL_POINTER, 1);
    assert_int_equal(CW_ERR_INVALID_INPUT, 2);
    assert_int_equal(CW_ERR_GRID_OUT_OF_RANGE, 3);
    assert_int_equal(CW_ERR_BUFFER_TOO_SMALL, 4);
    assert_int_equal(CW_ERR_NO_SOLUTION, 5);
    assert_int_equal(CW_ERR_NO_WORK, 6);
    assert_int_equal(CW_ERR_STRUCT_SIZE, 7);
    assert_int_equal(CW_ERR_OUT_OF_MEMORY, 8);
    assert_int_equal(CW_ERR_NUMERIC, 9);
    assert_int_equal(CW_ERR_UNKNOWN_OPTION, 10);
    assert_int_equal(CW_ERR_GRID_MISMATCH, 11);
    assert_int_equal(CW_ERR_INTERNAL, 12);
    assert_int_equal(CW_ERR_NOT_CONVERGED, 13);
    assert_true(CW_STATUS_END_ > CW_ERR_INTERNAL); /* later codes go after */
}

/* Each code's string is the message of the header's CW_STATUS_LIST, and the
 * library hands out the same static pointer every time. */
static void status_strings_come_from_the_list(void** state)
{
    (void)state;
#define CHECK_STATUS_(name, value, message)                   \
    assert_string_equal(cw_status_string(value), message);    \
    assert_ptr_equal(cw_status_string(value), cw_status_string(name));
    CW_STATUS_LIST(CHECK_STATUS_)
#undef CHECK_STATUS_
}

/* Distinct codes give distinct, non-empty messages (a host may switch on
 * the text in a log). */
static void status_strings_are_distinct(void** state)
{
    (void)state;
    for (int i = CW_OK; i < CW_STATUS_END_; ++i) {
        assert_true(strlen(cw_status_string(i)) > 0);
        for (int j = CW_OK; j < i; ++j)
            assert_string_not_equal(cw_status_string(i), cw_status_string(j));
    }
}

/* Values outside the list: the documented "unknown status code", never NULL. */
static void unknown_status_has_a_message(void** state)
{
    (void)state;
    const int unknown[] = {-1, CW_STATUS_END_, 1000, -2147483647 - 1, 2147483647};
    for (size_t k = 0; k < sizeof unknown / sizeof unknown[0]; ++k) {
        assert_non_null(cw_status_string(unknown[k]));
        assert_string_equal(cw_status_string(unknown[k]), "unknown status code");
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(version_numbers_match_header),
        cmocka_unit_test(version_string_matches_macros_and_project),
        cmocka_unit_test(status_codes_are_frozen),
        cmocka_unit_test(status_strings_come_from_the_list),
        cmocka_unit_test(status_strings_are_distinct),
        cmocka_unit_test(unknown_status_has_a_message),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
