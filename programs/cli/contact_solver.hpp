// The CLI's only door to the library: the public C ABI (creepwork.h), as any
// user program would call it. A small RAII owner for cw_solver and a
// Solution that holds the totals and every per-element field in SI.
#pragma once

#include <string>
#include <vector>

#include <creepwork/creepwork.h>

namespace cwcli {

struct Solution {
    cw_result result;
    cw_params params; // the inputs solved (SI)
    cw_grid grid;
    int nx = 0, ny = 0;
    // One value per element at [i + j*nx] (the library's layout), SI.
    std::vector<double> x, y, area, pz, px, py, sx, sy, mz, work_paper, work_consistent;
    std::vector<int> state;
    // Lateral profile, one value per strip j.
    std::vector<double> profile_y, profile_w, profile_parabola;

    size_t size() const { return static_cast<size_t>(nx) * static_cast<size_t>(ny); }
};

class ContactSolver {
public:
    explicit ContactSolver(const cw_grid& grid); // throws CliError(kExitUsage) on a bad grid
    ~ContactSolver() { cw_solver_destroy(solver_); }
    ContactSolver(const ContactSolver&) = delete;
    ContactSolver& operator=(const ContactSolver&) = delete;

    // Totals only (CW_SOLVE_FORCES), e.g. inside a fit or a sweep.
    cw_result solve_totals(const cw_params& params);
    // Totals plus states only (for slip/adhesion maps).
    cw_result solve_states(const cw_params& params, std::vector<int>& state);
    // The totals alone (CW_SOLVE_FORCES) as a Solution without fields.
    Solution solve_forces(const cw_params& params);
    // Everything (CW_SOLVE_FULL).
    Solution solve_full(const cw_params& params);
    // The 4 x 4 Jacobian of the totals (cw_solver_solve_jacobian, row-major).
    void jacobian(const cw_params& params, double out[CW_JACOBIAN_LEN]);
    // The separate contact patches of the last solve (cw_solver_get_patches).
    std::vector<cw_patch> patches() const;

    int nx() const { return nx_; }
    int ny() const { return ny_; }
    // The library's handle, for the post-processors that read a solver.
    const cw_solver* handle() const { return solver_; }
    // The same for the calls that solve on it (cw_temperature_solve).
    cw_solver* handle() { return solver_; }
    const cw_grid& grid() const { return grid_; }

private:
    void check(int status, const char* call) const;

    cw_solver* solver_ = nullptr;
    cw_grid grid_;
    int nx_ = 0, ny_ = 0;
};

// Everything a solver holds after a CW_SOLVE_FULL solve (its result, fields,
// states and lateral profile), with the params and grid it was solved for;
// for a solver this program does not own (cw_wheelrail_patch_solver).
// Throws CliError(kExitFailure) naming the getter that failed.
Solution read_solution(const cw_solver* solver, const cw_params& params, const cw_grid& grid);

// The separate contact patches of a solver's last solve (cw_solver_get_patches).
std::vector<cw_patch> read_patches(const cw_solver* solver);

// " (options --a, --N)": the options that set the struct fields a library
// message names ("" when it names none).
std::string options_named_in(const std::string& message);

// Spin creepage felt by each element: phi where it slips, 0 in adhesion (no
// relative motion) and outside -- the paper's "spin distribution" (Fig. 6).
std::vector<double> spin_distribution(const Solution& s);

} // namespace cwcli
