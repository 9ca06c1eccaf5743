#include "campaign_test_support.hpp"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include <sys/wait.h>

#include "../../cli/json.hpp" // shortest_exact: the digits creepwork prints
// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

namespace cwtest {

std::vector<std::string> campaign_argv(int np, const std::vector<std::string>& args)
{
    std::vector<std::string> argv;
    if (np > 0)
        argv = {g_tools.mpirun, "--oversubscribe", "--bind-to", "none", "-np", std::to_string(np)};
    argv.push_back(g_tools.creepwork);
    argv.push_back("campaign");
    argv.insert(argv.end(), args.begin(), args.end());
    return argv;
}

Run campaign(int np, const std::vector<std::string>& args, const std::vector<std::string>& env)
{
    return run(campaign_argv(np, args), env);
}

size_t kill_midway(int np, const std::vector<std::string>& args, int delay_ms,
                   const std::string& checkpoint, uintmax_t min_bytes)
{
    namespace fs = std::filesystem;
    const pid_t group = start_group(
        campaign_argv(np, args), {"CREEPWORK_CAMPAIGN_TEST_CHUNK_DELAY_MS=" + std::to_string(delay_ms)},
        path("killed.out"), path("killed.err"));
    assert_true(group > 0);
    const auto start = std::chrono::steady_clock::now();
    bool midway = false;
    while (!midway && std::chrono::steady_clock::now() - start < std::chrono::seconds(120)) {
        std::error_code ec;
        midway = fs::exists(checkpoint, ec) && fs::file_size(checkpoint, ec) > min_bytes;
        if (!midway) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    // The ranks: Open MPI starts them in process groups of their own, so
    // they are found as mpirun's descendants and each killed, then mpirun.
    const std::vector<pid_t> ranks = live_descendants(group);
    for (pid_t p : ranks) kill(p, SIGKILL);
    kill(group, SIGKILL);
    int status = 0;
    waitpid(group, &status, 0);
    if (!midway) print_error("the run never got midway; stderr:\n%s\n", slurp(path("killed.err")).c_str());
    assert_true(midway);
    // None of them survives (zombies waiting for a reaper do not count).
    const auto alive = [&ranks] {
        size_t n = 0;
        for (pid_t p : ranks) n += process_alive(p);
        return n;
    };
    for (int k = 0; k < 500 && alive() > 0; ++k)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    assert_int_equal(alive(), 0);
    return ranks.size();
}

void expect_resumed_part(const std::string& dir, size_t rows)
{
    const Json j = parse_json(slurp(dir + "/campaign.json"));
    const double resumed = j.num("resumed_rows"), solved = j.num("solved_this_run");
    assert_true(resumed >= 3 && resumed < static_cast<double>(rows));
    assert_true(resumed + solved == static_cast<double>(rows));
}

const std::vector<std::string>& input_columns()
{
    static const std::vector<std::string> c = {
        "id",        "model",     "grid",     "nx",       "ny",    "a",
        "b",         "N",         "mu",       "G",        "nu",    "xi_x",
        "xi_y",      "phi",       "box_scale", "pressure", "rolling_direction",
        "spin_offset", "flexibility_blending", "L1", "L2", "L3"};
    return c;
}

void write_input(const std::string& path, const std::vector<Row>& rows,
                 const std::vector<std::string>& columns)
{
    std::string text;
    for (const std::string& c : columns) text += (text.empty() ? "" : ",") + c;
    text += "\n";
    for (const Row& r : rows) {
        std::string line;
        for (size_t k = 0; k < columns.size(); ++k) {
            const auto it = r.find(columns[k]);
            line += (k ? "," : "") + (it == r.end() ? std::string() : it->second);
        }
        text += line + "\n";
    }
    write_text(path, text);
}

namespace {

std::string cell(const Row& r, const std::string& name)
{
    const auto it = r.find(name);
    return it == r.end() ? std::string() : it->second;
}

double number(const Row& r, const std::string& name)
{
    return std::strtod(cell(r, name).c_str(), nullptr);
}

std::string fmt(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

} // namespace

void row_to_structs(const Row& r, cw_grid& g, cw_params& p)
{
    cw_grid_init(&g);
    cw_params_init(&p);
    const std::string model = cell(r, "model");
    p.model = model == "exact" ? CW_MODEL_EXACT : model == "calibrated" ? CW_MODEL_CALIBRATED
                                                                        : CW_MODEL_FASTSIM;
    g.kind = cell(r, "grid") == "uniform" ? CW_GRID_UNIFORM : CW_GRID_KALKER_STRIPS;
    g.nx = std::atoi(cell(r, "nx").c_str());
    g.ny = std::atoi(cell(r, "ny").c_str());
    if (!cell(r, "box_scale").empty()) g.box_scale = number(r, "box_scale");
    p.a = number(r, "a");
    p.b = number(r, "b");
    p.normal_force = number(r, "N");
    p.mu = number(r, "mu");
    if (!cell(r, "L1").empty()) {
        p.flexibility = CW_FLEX_GIVEN;
        p.L1 = number(r, "L1");
        p.L2 = number(r, "L2");
        p.L3 = number(r, "L3");
    } else {
        p.G = number(r, "G");
        p.nu = number(r, "nu");
    }
    p.xi_x = number(r, "xi_x");
    p.xi_y = number(r, "xi_y");
    p.phi = number(r, "phi");
    if (cell(r, "pressure") == "elliptic") p.pressure = CW_PRESSURE_ELLIPTIC;
    if (cell(r, "rolling_direction") == "-1") p.rolling_direction = -1;
    if (!cell(r, "spin_offset").empty()) p.spin_offset = number(r, "spin_offset");
    if (cell(r, "flexibility_blending") == "1") p.flexibility_blending = 1;
}

std::vector<std::string> row_to_solve_args(const Row& r)
{
    std::vector<std::string> a = {"solve", "--a", cell(r, "a"), "--b", cell(r, "b"), "--N",
                                  cell(r, "N"), "--mu", cell(r, "mu")};
    if (!cell(r, "L1").empty())
        a.insert(a.end(), {"--L1", cell(r, "L1"), "--L2", cell(r, "L2"), "--L3", cell(r, "L3")});
    else
        a.insert(a.end(), {"--G", cell(r, "G"), "--nu", cell(r, "nu")});
    a.insert(a.end(), {"--xi-x", cell(r, "xi_x"), "--xi-y", cell(r, "xi_y"), "--spin",
                       cell(r, "phi"), "--grid", cell(r, "grid"), "--nx", cell(r, "nx"), "--ny",
                       cell(r, "ny")});
    if (!cell(r, "box_scale").empty()) a.insert(a.end(), {"--box-scale", cell(r, "box_scale")});
    if (!cell(r, "pressure").empty()) a.insert(a.end(), {"--pressure", cell(r, "pressure")});
    if (!cell(r, "rolling_direction").empty())
        a.insert(a.end(), {"--rolling-direction", cell(r, "rolling_direction")});
    if (!cell(r, "spin_offset").empty())
        a.insert(a.end(), {"--spin-offset", cell(r, "spin_offset")});
    if (cell(r, "flexibility_blending") == "1") a.push_back("--flexibility-blending");
    a.insert(a.end(), {"--format", "json"});
    return a;
}

std::vector<Row> mixed_rows()
{
    std::vector<Row> rows;
    for (int k = 0; k < 48; ++k) {
        Row r;
        r["id"] = "m" + std::to_string(k);
        r["model"] = "fastsim";
        switch (k % 4) {
        case 0: r["grid"] = "strips", r["nx"] = "12", r["ny"] = "10"; break;
        case 1: r["grid"] = "uniform", r["nx"] = "16", r["ny"] = "12", r["box_scale"] = "1.2"; break;
        case 2: r["grid"] = "strips", r["nx"] = "7", r["ny"] = "9"; break;
        default: r["grid"] = "uniform", r["nx"] = "10", r["ny"] = "10"; break;
        }
        r["a"] = fmt(0.004 + 0.0005 * (k % 6));
        r["b"] = fmt(0.003 + 0.0007 * (k % 5));
        r["N"] = fmt(40e3 + 5e3 * (k % 7));
        r["mu"] = fmt(0.25 + 0.05 * (k % 3));
        r["xi_x"] = fmt((k % 5 - 2) * 4e-4 * (k % 8 == 7 ? 20 : 1)); // some in full slip
        r["xi_y"] = fmt(((k * 3) % 7 - 3) * 2e-4);
        r["phi"] = fmt(((k * 5) % 9 - 4) * 0.3);
        if (k % 11 == 5) {
            r["L1"] = "5.1e-14", r["L2"] = "4.4e-14", r["L3"] = "3.9e-14"; // G, nu empty
        } else {
            r["G"] = "82e9";
            r["nu"] = fmt(0.25 + 0.01 * (k % 6));
        }
        if (k % 6 == 0) r["pressure"] = "elliptic";
        if (k % 7 == 3) r["rolling_direction"] = "-1";
        if (k % 10 == 4) r["spin_offset"] = "0.1666666666666667", r["flexibility_blending"] = "1";
        rows.push_back(r);
    }
    return rows;
}

const char* status_name(int status)
{
#define CW_TEST_STATUS_NAME_(name, value, message) \
    if (status == value) return #name;
    CW_STATUS_LIST(CW_TEST_STATUS_NAME_)
#undef CW_TEST_STATUS_NAME_
    return "unknown status";
}

Expected solve_directly(const Row& row)
{
    cw_grid g;
    cw_params p;
    row_to_structs(row, g, p);
    Expected e;
    char message[512] = "";
    cw_solver* s = nullptr;
    e.status = cw_solver_create(&g, &s, message, sizeof message);
    if (e.status != CW_OK) {
        e.message = message;
        return e;
    }
    cw_result r;
    cw_result_init(&r);
    e.status = cw_solver_solve(s, &p, CW_SOLVE_FULL, &r);
    if (e.status != CW_OK) {
        e.message = cw_solver_last_error(s);
    } else {
        const auto put = [&e](const char* name, double v) {
            e.cells[name] = cwcli::shortest_exact(v);
        };
        const auto put_int = [&e](const char* name, long v) { e.cells[name] = std::to_string(v); };
        put("Fx", r.Fx), put("Fy", r.Fy), put("Mz", r.Mz), put("W_macro", r.W_macro);
        put("W_micro_paper", r.W_micro_paper), put("K", r.K), put("W_consistent", r.W_consistent);
        put("balance_factor", r.balance_factor), put_int("work_flags", r.work_flags);
        put("adhesion_fraction", r.adhesion_fraction), put_int("n_contact", r.n_contact);
        put_int("n_adhesion", r.n_adhesion), put_int("n_slip", r.n_slip);
        put("a", r.a), put("b", r.b), put("L1", r.L1), put("L2", r.L2), put("L3", r.L3);
        put("C11", r.C11), put("C22", r.C22), put("C23", r.C23), put("C33", r.C33);
        put("profile_max_diff", r.profile_max_diff), put("profile_rms_diff", r.profile_rms_diff);
        put("p_max", r.p_max), put("approach", r.approach), put_int("iterations", r.iterations);
        put("residual", r.residual), put("Fn", r.normal_force);
        put_int("n_patches", r.n_patches);
        put("mu_static", r.mu_static), put("mu_min", r.mu_min), put("mu_max", r.mu_max);
    }
    cw_solver_destroy(s);
    return e;
}

} // namespace cwtest
