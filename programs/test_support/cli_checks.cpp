#include "cli_checks.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>

// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

namespace cwtest {

Tools g_tools;

bool set_up(int argc, char** argv, const char* program, const std::vector<std::string>& names)
{
    if (argc < static_cast<int>(names.size()) + 1) {
        std::string usage;
        for (const std::string& n : names) usage += " <" + n + ">";
        std::fprintf(stderr, "usage: %s%s [test]\n", program, usage.c_str());
        return false;
    }
    for (size_t k = 0; k < names.size(); ++k) {
        const std::string value = argv[k + 1];
        if (names[k] == "creepwork") g_tools.creepwork = value;
        if (names[k] == "mpirun") g_tools.mpirun = value;
        if (names[k] == "scratch") g_tools.scratch = value;
    }
    g_tools.test = argc > static_cast<int>(names.size()) + 1 ? argv[names.size() + 1] : nullptr;
    std::filesystem::remove_all(g_tools.scratch);
    std::filesystem::create_directories(g_tools.scratch);
    return true;
}

std::string path(const std::string& name) { return g_tools.scratch + "/" + name; }

std::string scratch_file(const std::string& name, const std::string& text)
{
    write_text(path(name), text);
    return path(name);
}

Run run(const std::vector<std::string>& argv, const std::vector<std::string>& env)
{
    return run_captured(argv, env, path("run.out"), path("run.err"));
}

Run cli(const std::vector<std::string>& args, const std::vector<std::string>& env)
{
    return run(with({g_tools.creepwork}, args), env);
}

Run cli_ok(const std::vector<std::string>& args) { return expect_status(cli(args), 0); }

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b)
{
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

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

void expect_lacks(const std::string& text, const std::string& part)
{
    if (contains(text, part)) {
        print_error("did not expect to find\n  %s\nin\n  %s\n", part.c_str(), text.c_str());
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

void expect_refusal(const Run& r, int status, const std::string& part, const std::string& what)
{
    const bool one_line = std::count(r.err.begin(), r.err.end(), '\n') == 1 &&
                          r.err.back() == '\n' && r.err.rfind("creepwork: ", 0) == 0;
    if (r.status != status || !one_line || !contains(r.err, part) || !r.out.empty()) {
        print_error("%s -> exit %d (expected %d), stderr '%s' (expected one line holding '%s'), "
                    "stdout '%s'\n",
                    what.c_str(), r.status, status, r.err.c_str(), part.c_str(), r.out.c_str());
        fail();
    }
}

Json parse_or_fail(const std::string& text)
{
    try {
        return parse_json(text);
    } catch (const std::exception& e) {
        print_error("%s\n--- output ---\n%s\n", e.what(), text.c_str());
        fail();
    }
    return Json();
}

std::string exact(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string round_trip(double v)
{
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

cw_result library_solve(const cw_grid& g, const cw_params& p, int mode)
{
    cw_solver* s = nullptr;
    assert_int_equal(cw_solver_create(&g, &s, nullptr, 0), CW_OK);
    cw_result r;
    cw_result_init(&r);
    const int status = cw_solver_solve(s, &p, mode, &r);
    if (status != CW_OK) print_error("library: %s\n", cw_solver_last_error(s));
    cw_solver_destroy(s);
    assert_int_equal(status, CW_OK);
    return r;
}

} // namespace cwtest
