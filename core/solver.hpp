// The solver object: made once per grid (it owns the grid geometry and every
// workspace), then solve() many times without allocating. Fields are copied
// out in the caller's layout: element (i, j) at [i + j*nx], i along x
// (increasing x), j along y (increasing y) -- column-major, i fastest, so a
// Fortran array (nx, ny) maps directly.
#pragma once

#include "contact_grid.hpp"
#include "fastsim.hpp"
#include "model_setup.hpp"
#include "params.hpp"
#include "work.hpp"

namespace creepwork {

enum class Field {
    x,               // element centre x [m]
    y,               // element centre y [m]
    area,            // element area [m^2]
    pz,              // normal pressure [Pa]
    px,              // tangential traction on the wheel, x [Pa]
    py,              // tangential traction on the wheel, y [Pa]
    sx,              // micro-slip W_x/V [-] (model slip, 0 in adhesion)
    sy,              // micro-slip W_y/V [-]
    mz,              // moment contribution (x py - y px) area [N m]
    work_paper,      // paper's local work per unit rolling distance [J/m]
    work_consistent, // energy-consistent local work [J/m]
};

enum class ElementState { exterior = 0, adhesion = 1, slip = 2 };

enum class SolveMode {
    forces_only, // totals, tractions and states; no slip or work fields
    full,        // also micro-slip, moment, both work maps and the profile
};

class Solver {
public:
    explicit Solver(const GridSpec& grid);

    // Throws Error(invalid_input) naming a bad input; the previous solution
    // is then marked absent.
    const SolveTotals& solve(const ContactInput& input, SolveMode mode = SolveMode::full);

    const ContactGrid& grid() const { return grid_; }
    const SolveTotals& totals() const { return totals_; }
    bool has_solution() const { return solved_; }
    bool has_work() const { return solved_ && mode_ == SolveMode::full; }
    static bool needs_work(Field f);

    // out[i + j*nx] for i < nx, j < ny. Preconditions (checked by the
    // caller): has_solution(), and has_work() for fields that need it.
    void copy_field(Field f, double* out) const;
    // out[i + j*nx] += scale * field: accumulation without temporaries.
    void add_field(Field f, double scale, double* out) const;
    void copy_state(int* out) const;
    // Per strip j < ny: strip centre y [m], work per unit width [J/m per m],
    // and the equal-area parabola at y.
    void copy_profile(double* y, double* work, double* parabola) const;

private:
    double value(Field f, Eigen::Index k, int j) const;
    Eigen::Index march_index(int i, int j) const;

    ContactGrid grid_;
    MarchState march_;
    WorkState work_;
    ModelSetup setup_;
    SolveTotals totals_;
    SolveMode mode_ = SolveMode::full;
    bool solved_ = false;
};

} // namespace creepwork
