// What both transient models (transient_contact.hpp: the exact theory;
// transient_fastsim.hpp: FASTSIM's transient form) share: a step's input
// and result, the gap grid, the committed state's bookkeeping (steps, the
// last rolling creepages, the trial and whether there is a solution), the
// checks of a contact and of a step's input, and the part of the saved
// bytes every model writes (state_bytes.hpp). A model derives from
// TransientBase and adds its tractions and its solver.
#pragma once

#include <cstddef>
#include <vector>

#include "contact/params.hpp"
#include "simd/kernel_isa.hpp"

namespace creepwork {

// What one step is given.
struct TransientStepInput {
    double dq = 0.0; // distance rolled in the step [m], 0 <= dq <= dx; 0: a shift
    // Rolling (dq > 0): the creepages xi_x, xi_y [-] and spin phi [1/m].
    // Shift (dq = 0): the rigid shift along x, y [m] and rotation [rad].
    double xi_x = 0.0, xi_y = 0.0, phi = 0.0;
    // Prescribed forces on the wheel [N]: the matching xi_x (xi_y) is found.
    bool prescribe_fx = false, prescribe_fy = false;
    double Fx = 0.0, Fy = 0.0;
};

// What one step gave (in the input's units).
struct TransientStepResult {
    double xi_x = 0.0, xi_y = 0.0, phi = 0.0; // as given, the prescribed forces' found
    double Fx = 0.0, Fy = 0.0, Mz = 0.0;      // on the wheel [N, N, N m], Mz about the origin
    int n_contact = 0, n_adhesion = 0, n_slip = 0;
    // Frictional work of the step [J], energy-consistent: the work of the
    // rigid displacement r of the step under the mean of the old and new
    // tractions less the change of the elastic energy,
    //   W_step = -sum 1/2 (p_prev + p) . r dA - (E(p) - E(p_prev)),
    // E(p) = 1/2 sum p . u(p) dA; in steady rolling (p = p_prev) it is
    // dq (W_macro - phi s dq Fy) (s the spin offset), the steady model's
    // W_macro per rolled distance. The sum of the work map (copy_work).
    double W_step = 0.0;
    // The friction dissipation of the step's own slip, sum of |p_t| |S| dA
    // [J] (CONTACT's frictional work): below W_step by the exact theory's
    // numerical dissipation (exact/exact_work.hpp).
    double W_slip = 0.0;
    int newton_steps = 0;     // of the tangential problem, all force iterations
    int products = 0;         // FFT products, all of the step
    int force_iterations = 0; // Newton steps on the prescribed forces
    double residual = 0.0;    // the tangential problem's, relative
};

class TransientBase {
public:
    int nx() const { return nx_; }
    int ny() const { return ny_; }
    double dx() const { return dx_; }
    double dy() const { return dy_; }
    double x0() const { return x0_; }
    double y0() const { return y0_; }
    // A step or steady start since the last start, frame change or restore:
    // the fields (and the exact model's jacobian()) are of it.
    bool has_solution() const { return has_solution_; }
    long steps_committed() const { return steps_; }
    bool has_trial() const { return trial_valid_; }
    const TransientStepResult& last() const { return result_; }
    // Drops the last trial (the committed state stays).
    void rewind() { trial_valid_ = false; }

protected:
    // grid: a gap grid (normal/gap_grid.hpp), checked.
    explicit TransientBase(const GridSpec& grid);
    ~TransientBase() = default;

    // What a transient model reads of its contact on n elements (the gap,
    // load, normal method, G, nu; the creepages and the rolling direction
    // are not read) and mu > 0. Throws Error(invalid_input) naming the input.
    static void check_contact(const ContactInput& in, std::size_t n, KernelIsa isa);
    // Throws Error(invalid_input) unless the normal problem put an element
    // in contact (p_max > 0).
    static void check_loaded(double p_max);
    // A step's input (steady: a steady start, dq not read); limit = mu N
    // [N], what a prescribed force must stay below. Throws Error naming a
    // bad input.
    void validate(const TransientStepInput& s, bool steady, double limit) const;

    // The committed state at its start: no steps, no creepages, no trial,
    // no solution.
    void clear_committed();
    // The force iteration's first creepages (c[3] from s): the last rolling
    // step's for a prescribed force when rolling, else no shift.
    void first_creepages(const TransientStepInput& s, bool rolling, double c[3]) const;
    // A solve's end: its creepages c[3] are the trial's.
    void hold_trial(const double c[3], bool rolling);
    // A steady start's end: its solve is the committed state (no step).
    void commit_steady();
    // commit(): throws Error(invalid_input) without a trial ...
    void require_trial() const;
    // ... and, once the model holds the trial's tractions, counts the step.
    void count_commit();

    // The saved state's first part (after an 8-byte magic): the grid, two
    // numbers of the contact restore() compares (the load and the friction
    // in the model's units), the steps and the creepages. Then each model's
    // own, and its tractions.
    static constexpr std::size_t kCommittedBytes = 8 + 2 * 4 + 2 * 8 + 8 + 3 * 8;
    std::vector<unsigned char> save_committed(const char (&magic)[8], double id0,
                                              double id1) const;
    // What restore() reads of save_committed()'s part. read_committed checks
    // the bytes (n of them; size expected, what names the state in the
    // message) and that they are of this grid and contact (id0, id1), and
    // leaves p after the part; nothing of the handle changes.
    struct Committed {
        const unsigned char* p = nullptr;
        long steps = 0;
        double creep[3] = {0.0, 0.0, 0.0};
    };
    Committed read_committed(const unsigned char* bytes, std::size_t n, std::size_t size,
                             const char (&magic)[8], const char* what, double id0,
                             double id1) const;
    // The restored steps and creepages become the committed ones; no trial,
    // no solution.
    void set_committed(const Committed& c);

    int nx_, ny_, n_;
    double x0_, y0_, dx_, dy_;
    // The committed state's creepages (the last rolling step's: the force
    // iteration's start) and steps.
    double creep0_[3] = {0.0, 0.0, 0.0};
    long steps_ = 0;
    // The trial.
    TransientStepResult result_;
    bool trial_valid_ = false, trial_rolling_ = false, has_solution_ = false;
    double trial_creep_[3] = {0.0, 0.0, 0.0};
};

} // namespace creepwork
