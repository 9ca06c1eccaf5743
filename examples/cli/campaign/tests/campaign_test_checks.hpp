// Checks shared by the campaign test programs (test_campaign,
// test_campaign_wear): a failed check prints what it saw and fails the
// current cmocka test.
#pragma once

#include <string>

#include "campaign_test_support.hpp"

namespace cwctest {

// Reads main's arguments <creepwork> <mpirun> <scratch dir> <test> into
// g_tools and makes the scratch directory empty; false (usage printed) when
// they are missing.
bool set_up_tools(int argc, char** argv, const char* program);

// A file in this test's scratch directory.
std::string path(const std::string& name);

bool contains(const std::string& text, const std::string& part);
void expect_contains(const std::string& text, const std::string& part);

// r, after checking its exit status (stderr printed when it differs).
Run expect_status(const Run& r, int status);

} // namespace cwctest
