#include "campaign_test_checks.hpp"

#include <cstdio>
#include <filesystem>

// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

namespace cwctest {

bool set_up_tools(int argc, char** argv, const char* program)
{
    if (argc < 5) {
        std::fprintf(stderr, "usage: %s <creepwork> <mpirun> <scratch dir> <test>\n", program);
        return false;
    }
    g_tools.creepwork = argv[1];
    g_tools.mpirun = argv[2];
    g_tools.scratch = argv[3];
    std::filesystem::remove_all(g_tools.scratch);
    std::filesystem::create_directories(g_tools.scratch);
    return true;
}

std::string path(const std::string& name) { return g_tools.scratch + "/" + name; }

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

void expect_contains(const std::string& text, const std::string& part)
{
    if (!contains(text, part)) {
        print_error("expected to find\n  %s\nin\n  %s\n", part.c_str(), text.c_str());
        fail();
    }
}

Run expect_status(const Run& r, int status)
{
    if (r.status != status)
        print_error("exit status %d, expected %d; stderr:\n%s\n", r.status, status, r.err.c_str());
    assert_int_equal(r.status, status);
    return r;
}

} // namespace cwctest
