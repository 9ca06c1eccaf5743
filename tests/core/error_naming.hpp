// expect_error_naming: a call that must be refused with an error whose
// message starts with the input's name (the library's convention for every
// invalid input). Include after test_support.h (cmocka).
#pragma once

#include "contact/error.hpp"

#include <string>

namespace cwtest {

// f() throws Error(invalid_input) whose message starts with name.
template <class F>
void expect_error_naming(F&& f, const char* name)
{
    try {
        f();
        fail_msg("accepted, expected an error naming %s", name);
    } catch (const creepwork::Error& e) {
        assert_true(e.kind() == creepwork::ErrorKind::invalid_input);
        if (std::string(e.what()).rfind(name, 0) != 0) fail_msg("%s", e.what());
    }
}

} // namespace cwtest
