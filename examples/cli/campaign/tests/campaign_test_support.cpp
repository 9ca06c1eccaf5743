#include "campaign_test_support.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../../json.hpp" // shortest_exact: the digits creepwork prints

extern char** environ;

namespace cwctest {

Tools g_tools;

namespace {

std::vector<char*> c_argv(const std::vector<std::string>& v)
{
    std::vector<char*> out;
    for (const std::string& s : v) out.push_back(const_cast<char*>(s.c_str()));
    out.push_back(nullptr);
    return out;
}

std::vector<std::string> environment(const std::vector<std::string>& extra)
{
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e) env.emplace_back(*e);
    env.insert(env.end(), extra.begin(), extra.end());
    return env;
}

pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env,
            const std::string& out_file, const std::string& err_file, bool own_group)
{
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_addopen(&fa, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    if (own_group) {
        posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
        posix_spawnattr_setpgroup(&attr, 0);
    }
    const std::vector<std::string> full_env = environment(env);
    std::vector<char*> a = c_argv(argv), e = c_argv(full_env);
    pid_t pid = -1;
    if (posix_spawnp(&pid, argv[0].c_str(), &fa, &attr, a.data(), e.data()) != 0) pid = -1;
    posix_spawn_file_actions_destroy(&fa);
    posix_spawnattr_destroy(&attr);
    return pid;
}

} // namespace

Run run(const std::vector<std::string>& argv, const std::vector<std::string>& env)
{
    const std::string out = g_tools.scratch + "/run.out", err = g_tools.scratch + "/run.err";
    Run r;
    const pid_t pid = spawn(argv, env, out, err, false);
    if (pid > 0) {
        int status = 0;
        waitpid(pid, &status, 0);
        r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

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

pid_t start_group(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                  const std::string& out_file, const std::string& err_file)
{
    return spawn(argv, env, out_file, err_file, true);
}

namespace {

// State and parent of a process from /proc/PID/stat ("pid (comm) state ppid
// ..."; comm may hold spaces and parentheses, so parse after the last ')').
bool read_stat(pid_t pid, char& state, long& ppid)
{
    const std::string stat = slurp("/proc/" + std::to_string(pid) + "/stat");
    const size_t close = stat.rfind(')');
    return close != std::string::npos &&
           std::sscanf(stat.c_str() + close + 1, " %c %ld", &state, &ppid) == 2;
}

} // namespace

bool process_alive(pid_t pid)
{
    char state = 0;
    long ppid = 0;
    return read_stat(pid, state, ppid) && state != 'Z' && state != 'X';
}

bool file_locked(const std::string& path)
{
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool locked = flock(fd, LOCK_EX | LOCK_NB) != 0;
    close(fd); // releases the lock if this call took it
    return locked;
}

std::vector<pid_t> live_descendants(pid_t root)
{
    std::vector<std::pair<pid_t, long>> all; // pid, parent
    for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        const pid_t pid = static_cast<pid_t>(std::atol(name.c_str()));
        char state = 0;
        long ppid = 0;
        if (read_stat(pid, state, ppid) && state != 'Z' && state != 'X') all.emplace_back(pid, ppid);
    }
    std::vector<pid_t> out, frontier = {root};
    while (!frontier.empty()) {
        const pid_t parent = frontier.back();
        frontier.pop_back();
        for (const auto& [pid, ppid] : all)
            if (ppid == parent) {
                out.push_back(pid);
                frontier.push_back(pid);
            }
    }
    return out;
}

std::string slurp(const std::string& path)
{
    std::ifstream f(path, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

void write_text(const std::string& path, const std::string& text)
{
    std::ofstream f(path, std::ios::binary);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + path);
}

bool exists(const std::string& path)
{
    struct stat st;
    return stat(path.c_str(), &st) == 0;
}

std::vector<std::vector<std::string>> read_csv(const std::string& path)
{
    const std::string text = slurp(path);
    std::vector<std::vector<std::string>> records;
    std::vector<std::string> record;
    std::string field;
    bool quoted = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
                field += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            record.push_back(field);
            field.clear();
        } else if (c == '\n') {
            record.push_back(field);
            field.clear();
            records.push_back(record);
            record.clear();
        } else {
            field += c;
        }
    }
    if (!field.empty() || !record.empty()) {
        record.push_back(field);
        records.push_back(record);
    }
    return records;
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

void write_input(const std::string& path, const std::vector<Row>& rows)
{
    std::string text;
    for (const std::string& c : input_columns()) text += (text.empty() ? "" : ",") + c;
    text += "\n";
    for (const Row& r : rows) {
        std::string line;
        for (size_t k = 0; k < input_columns().size(); ++k) {
            const auto it = r.find(input_columns()[k]);
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
        put("residual", r.residual);
    }
    cw_solver_destroy(s);
    return e;
}

std::map<std::string, size_t> header_index(const std::vector<std::string>& header)
{
    std::map<std::string, size_t> idx;
    for (size_t k = 0; k < header.size(); ++k) idx[header[k]] = k;
    return idx;
}

} // namespace cwctest
