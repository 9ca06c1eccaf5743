// The solver object: made once per grid (it owns the grid geometry and every
// workspace, and picks the kernel for this CPU), then solve() many times
// without allocating. Fields are copied out in the caller's layout: element
// (i, j) at [i + j*nx], i along x (increasing x), j along y (increasing y) --
// column-major, i fastest, so a Fortran array (nx, ny) maps directly. The
// copy transposes the kernels' layout [m*stride + j] (fastsim.hpp) in 4 x 4
// blocks (2 x 2 for SSE2) and computes each field on the way, so no field is
// stored twice.
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
    // Marks the last solution absent: the C ABI does so when it rejects a
    // solve before reaching solve() (mode, struct sizes, enumerations).
    void discard() { solved_ = false; }
    static bool needs_work(Field f);

    // The kernel in use: best_kernel_isa() unless set. Every kernel gives
    // bitwise the same results; set_kernel_isa is for tests and benchmarks
    // and throws Error(invalid_input) when this CPU cannot run the kernel.
    KernelIsa kernel_isa() const { return isa_; }
    void set_kernel_isa(KernelIsa isa);

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
    template <class Op>
    void export_field(Field f, const Op& op, double* out) const;

    ContactGrid grid_;
    MarchGeometry geometry_; // the grid in the kernels' layout
    MarchState march_;
    WorkState work_;
    ModelSetup setup_;
    SolveTotals totals_;
    SolveMode mode_ = SolveMode::full;
    KernelIsa isa_ = KernelIsa::baseline;
    bool solved_ = false;
};

} // namespace creepwork
