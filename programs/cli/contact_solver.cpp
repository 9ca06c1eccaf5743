#include "contact_solver.hpp"

#include <cctype>

#include "cli_error.hpp"

namespace cwcli {

ContactSolver::ContactSolver(const cw_grid& grid) : grid_(grid)
{
    char message[256] = "";
    const int status = cw_solver_create(&grid, &solver_, message, sizeof message);
    if (status != CW_OK)
        throw CliError(kExitUsage, std::string("library rejected the grid: ") + message);
    cw_solver_grid_size(solver_, &nx_, &ny_);
}

// The library names its struct fields; say which options set them.
std::string options_named_in(const std::string& message)
{
    static const char* const names[][2] = {
        {"a", "--a"},       {"b", "--b"},       {"normal_force", "--N"},
        {"mu", "--mu"},     {"G", "--G"},       {"nu", "--nu"},
        {"L1", "--L1"},     {"L2", "--L2"},     {"L3", "--L3"},
        {"xi_x", "--xi-x"}, {"xi_y", "--xi-y"}, {"phi", "--spin"},
        {"nx", "--nx"},     {"ny", "--ny"},     {"box_scale", "--box-scale"},
        {"model", "--model"}, {"tolerance", "--tolerance"},
        {"max_iterations", "--max-iterations"}, {"spin_offset", "--spin-offset"},
        {"T0_1", "--T0-1"}, {"T0_2", "--T0-2"}, {"heat_capacity_1", "--heat-capacity-1"},
        {"heat_capacity_2", "--heat-capacity-2"}, {"conductivity_1", "--conductivity-1"},
        {"conductivity_2", "--conductivity-2"}, {"density_1", "--density-1"},
        {"density_2", "--density-2"}, {"rolling_speed", "--speed"},
        {"discretisation", "--temperature-discretisation"}, {"k_yield", "--k-yield"},
        {"V", "--V"}, {"friction_law", "--friction-law"}, {"mu_e1", "--mu-e1"},
        {"s_h1", "--s-h1"}, {"mu_e2", "--mu-e2"}, {"s_h2", "--s-h2"},
        {"polach_A", "--polach-A"}, {"polach_B", "--polach-B"},
        {"friction_speed", "--friction-speed"}, {"k0", "--k0"}, {"alpha_inf", "--alpha-inf"},
        {"beta", "--beta"}, {"memory_distance", "--memory-distance"},
        {"memory_s0", "--memory-s0"}, {"mu_T", "--mu-T"}, {"layer_h", "--layer-h"},
        {"layer_G", "--layer-G"}, {"tau_c0", "--tau-c0"}, {"k_tau", "--k-tau"}};
    const auto is_word = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    };
    std::string options;
    for (const auto& n : names) {
        const std::string field = n[0];
        for (size_t at = message.find(field); at != std::string::npos;
             at = message.find(field, at + 1)) {
            const bool starts = at == 0 || !is_word(message[at - 1]);
            const bool ends =
                at + field.size() == message.size() || !is_word(message[at + field.size()]);
            if (starts && ends) {
                options += (options.empty() ? "" : ", ") + std::string(n[1]);
                break;
            }
        }
    }
    return options.empty() ? "" : " (options " + options + ")";
}

void ContactSolver::check(int status, const char* call) const
{
    if (status == CW_OK) return;
    std::string detail = cw_solver_last_error(solver_);
    if (detail.empty()) detail = cw_status_string(status);
    // Inputs the CLI's own checks let through (e.g. overflow) end up here.
    const int exit_status = status == CW_ERR_INTERNAL ? kExitFailure : kExitUsage;
    throw CliError(exit_status, std::string("library rejected the input (") + call +
                                    "): " + detail + options_named_in(detail));
}

cw_result ContactSolver::solve_totals(const cw_params& params)
{
    cw_result r;
    cw_result_init(&r);
    check(cw_solver_solve(solver_, &params, CW_SOLVE_FORCES, &r), "cw_solver_solve");
    return r;
}

cw_result ContactSolver::solve_states(const cw_params& params, std::vector<int>& state)
{
    const cw_result r = solve_totals(params);
    state.assign(static_cast<size_t>(nx_) * ny_, 0);
    check(cw_solver_get_state(solver_, state.data(), state.size()), "cw_solver_get_state");
    return r;
}

void ContactSolver::jacobian(const cw_params& params, double out[CW_JACOBIAN_LEN])
{
    check(cw_solver_solve_jacobian(solver_, &params, CW_SOLVE_FORCES, nullptr, out,
                                   CW_JACOBIAN_LEN),
          "cw_solver_solve_jacobian");
}

Solution ContactSolver::solve_forces(const cw_params& params)
{
    Solution s;
    s.result = solve_totals(params);
    s.params = params;
    s.grid = grid_;
    s.nx = nx_;
    s.ny = ny_;
    return s;
}

Solution ContactSolver::solve_full(const cw_params& params)
{
    check(cw_solver_solve(solver_, &params, CW_SOLVE_FULL, nullptr), "cw_solver_solve");
    return read_solution(solver_, params, grid_);
}

std::vector<cw_patch> ContactSolver::patches() const
{
    return read_patches(solver_);
}

namespace {

// A getter's failure after a successful solve: the program's fault, not the input's.
void check_read(const cw_solver* solver, int status, const char* call)
{
    if (status != CW_OK)
        throw CliError(kExitFailure, std::string("cannot read the solution (") + call +
                                         "): " + cw_solver_last_error(solver));
}

} // namespace

std::vector<cw_patch> read_patches(const cw_solver* solver)
{
    const char* call = "cw_solver_get_patches";
    size_t count = 0;
    check_read(solver, cw_solver_get_patches(solver, nullptr, 0, &count), call);
    std::vector<cw_patch> out(count);
    for (cw_patch& p : out) cw_patch_init(&p);
    if (count) check_read(solver, cw_solver_get_patches(solver, out.data(), count, &count), call);
    return out;
}

Solution read_solution(const cw_solver* solver, const cw_params& params, const cw_grid& grid)
{
    const auto check = [solver](int status, const char* call) { check_read(solver, status, call); };
    Solution s;
    cw_result_init(&s.result);
    check(cw_solver_get_result(solver, &s.result), "cw_solver_get_result");
    check(cw_solver_grid_size(solver, &s.nx, &s.ny), "cw_solver_grid_size");
    s.params = params;
    s.grid = grid;
    const size_t n = s.size();
    struct {
        int id;
        std::vector<double>* out;
    } fields[] = {{CW_FIELD_X, &s.x},
                  {CW_FIELD_Y, &s.y},
                  {CW_FIELD_AREA, &s.area},
                  {CW_FIELD_PZ, &s.pz},
                  {CW_FIELD_PX, &s.px},
                  {CW_FIELD_PY, &s.py},
                  {CW_FIELD_SX, &s.sx},
                  {CW_FIELD_SY, &s.sy},
                  {CW_FIELD_MZ, &s.mz},
                  {CW_FIELD_WORK_PAPER, &s.work_paper},
                  {CW_FIELD_WORK_CONSISTENT, &s.work_consistent}};
    for (auto& f : fields) {
        f.out->assign(n, 0.0);
        check(cw_solver_get_field(solver, f.id, f.out->data(), n), "cw_solver_get_field");
    }
    s.state.assign(n, 0);
    check(cw_solver_get_state(solver, s.state.data(), n), "cw_solver_get_state");
    const size_t m = static_cast<size_t>(s.ny);
    s.profile_y.assign(m, 0.0);
    s.profile_w.assign(m, 0.0);
    s.profile_parabola.assign(m, 0.0);
    check(cw_solver_get_profile(solver, s.profile_y.data(), s.profile_w.data(),
                                s.profile_parabola.data(), m),
          "cw_solver_get_profile");
    return s;
}

std::vector<double> spin_distribution(const Solution& s)
{
    std::vector<double> spin(s.size(), 0.0);
    for (size_t k = 0; k < spin.size(); ++k)
        if (s.state[k] == CW_STATE_SLIP) spin[k] = s.params.phi;
    return spin;
}

} // namespace cwcli
