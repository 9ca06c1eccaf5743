// Transient rolling in Kalker's exact half-space theory (Kalker 1990, ch. 5;
// doc/theory/transient.md) on a gap grid, in contact-fixed coordinates
// (CONTACT's T = 2): the tractions carry memory from one step to the next.
// Over a step in which the body rolls dq (0 <= dq <= dx) the slip of the
// element at x is the rigid slip plus the change of the displacement
// difference u of the particle now at x, which was at x + dq:
//   S(x) = r(x) + u(x, now) - u(x + dq, previous),
// with r = (dx_r - theta y, dy_r + theta (x + spin_offset dq)) the rigid
// displacement of the step: creepage times dq when rolling, the shift itself
// when dq = 0 (a shift: Cattaneo's problem). In the normalised units of
// exact/steady_rolling.hpp (lengths in dx, tractions per mu p_max, slips per
// mu p_max dx / G) with d = dq / dx and u(x + d dx) interpolated linearly
// between the elements (exact for d = 0 and d = 1):
//   s = r + A (q - q_prev) + d B q_prev,   B(k, l) = A(k, l) - A(k + 1, l),
// so that s = r + A q + (a field of the committed state alone), which the
// steady-rolling solver solves with its shift operator
// (SlipOperator::shift), and with q = q_prev, d = 1 it is the steady
// problem: the steady solution is a fixed point of the step.
//
// The handle. The normal problem is solved once, by the constructor (the
// geometry and load stay; CONTACT's N = 1 with the same gap). A committed
// state holds the tractions of the last committed step. step() solves one
// step from it without changing it (a trial; its fields are the exports);
// commit() makes the trial the state; rewind() drops the trial. step()
// depends only on the committed state and its input, so a trial repeated
// after rewind() gives the same bits. save() and restore() give and take
// the committed state as bytes (this build's layout). With Fx and/or Fy
// prescribed, the step's creepages (the shift when dq = 0) are found by
// Newton's method on the force, with the derivative of the converged
// discrete problem (SteadyRolling::tangent).
//
// The problem runs on the smallest box of the grid that holds the contact
// (the tractions vanish outside; the same discrete problem with smaller
// FFTs), as the steady model on a gap grid does.
//
// World-fixed coordinates (CONTACT's T = 1; set_frame(world)): the grid
// stays with the material and the geometry moves over it, by dq towards +x
// per step: the gap of a step at rolled distance X is the given gap at
// x - X (interpolated linearly between the elements; exact for X a
// multiple of dx; elements whose geometry comes from beyond the grid's -x
// edge take the grid's largest gap), the normal problem is solved per step
// (cold, so a trial repeats bitwise), and nothing is transported:
//   s = r + A (q - q_prev),
// the spin's rigid slip taken about x = X (the geometry's origin now). The
// problem runs on the whole grid, which must hold the contact over the run.
// With dq = dx this is the contact-fixed step seen from the ground: the two
// agree to the solver's tolerance.
//
// Frame: the leading edge at +x (rolling towards +x); positions from the
// grid's origin; forces on the wheel (body 1) as in the steady models.
#pragma once

#include <complex>
#include <cstdint>
#include <vector>

#include "contact/params.hpp"
#include "exact/steady_rolling.hpp"
#include "halfspace/cell_box.hpp"
#include "halfspace/grid_convolution.hpp"
#include "normal/gap_normal.hpp"
#include "transient/transient_base.hpp"

namespace creepwork {

// Where the grid is fixed: to the contact (CONTACT's T = 2), or to the
// world (the material; T = 1).
enum class TransientFrame { contact = 0, world = 1 };

class TransientContact : public TransientBase {
public:
    using Complex = std::complex<double>;

    // grid: a gap grid (normal/gap_grid.hpp); in: the contact -- its gap
    // (copied), normal force or approach, normal method, mu > 0, G, nu,
    // tolerance, max_iterations, spin_offset (creepages and the rolling
    // direction are not read: the leading edge is at +x). Or the exact
    // model's uniform grid and an elliptic contact (a, b, normal force;
    // transient/ellipse_gap.hpp): its Hertzian gap on that grid. Solves the
    // normal problem. Starts from zero tractions. Throws Error naming a bad
    // input, or Error(not_converged).
    TransientContact(const GridSpec& grid, const ContactInput& in);

    // The committed state: zero tractions (the geometry back at its start).
    void start_zero();
    // Chooses the coordinates (the handle starts contact-fixed) and starts
    // from zero tractions with the geometry at its start.
    void set_frame(TransientFrame frame);
    TransientFrame frame() const { return world_ ? TransientFrame::world : TransientFrame::contact; }
    // World-fixed: the distance the geometry has rolled over the grid [m]
    // (committed); 0 contact-fixed.
    double position() const { return position_; }
    // The committed state: the steady-rolling solution of step's creepages
    // (dq is not read; its forces may be prescribed). Returns it.
    const TransientStepResult& start_steady(const TransientStepInput& step);
    // One step from the committed state (a trial). Throws Error naming a bad
    // input (the state is unchanged), or Error(not_converged).
    const TransientStepResult& step(const TransientStepInput& step);
    // The last trial becomes the committed state; throws Error(invalid_input)
    // without one. rewind(), the grid and the trial's state: TransientBase's.
    void commit();

    // The committed state as bytes (a whole number of 8-byte words), and
    // back. restore() throws
    // Error(invalid_input) for bytes of another contact or grid, or not of
    // save().
    std::vector<unsigned char> save() const;
    void restore(const unsigned char* bytes, std::size_t n);

    double p_max() const { return p_ref_; }
    // Of the last step (or steady start), [i + nx j]: tangential tractions
    // on the wheel [Pa], slip over the step [m], element states (0
    // exterior, 1 adhesion, 2 slip), pressure [Pa].
    void copy_traction(double* px, double* py) const;
    void copy_slip(double* sx, double* sy) const;
    void copy_state(int* out) const;
    void copy_pressure(double* out) const;
    // Of the last step (or steady start), [i + nx j]: the frictional work of
    // each element over the step [J], its dissipation |p_t| |S| dA times
    // W_step / W_slip (0 in adhesion and outside the contact); its sum is
    // W_step (0 everywhere when no element slips).
    void copy_work(double* out) const;

    // The step map's derivative at the last step (or steady start), row-major
    // J[3 r + c], rows the step's outputs, columns its inputs, as an
    // integrator linearises the step. With creepages given (no force
    // prescribed): rows Fx, Fy, Mz [N, N, N m]; columns xi_x, xi_y, phi
    // (rolling; a shift: the shift along x, y [m] and the rotation [rad]).
    // With Fx (and Fy) prescribed, the prescribed force and the found
    // creepage trade places: row 0 is xi_x and column 0 is Fx (row 1, column
    // 1 likewise with Fy prescribed). From the derivative of the converged
    // discrete problem (SteadyRolling::tangent), to a relative residual of
    // kStepJacobianTolerance; the tractions, states and the trial are
    // untouched. Throws Error(invalid_input) without a step, or
    // Error(not_converged) when a prescribed force does not depend on its
    // creepage (full slip).
    void jacobian(double J[9]);

private:
    // The contact as a gap grid: the caller's, or an ellipse's (h owns the
    // gap in.gap points to).
    struct Form {
        GridSpec grid;
        ContactInput in;
        std::vector<double> h;
    };
    static Form gap_form(const GridSpec& grid, const ContactInput& in);
    struct OnGapGrid {};
    explicit TransientContact(const Form& f) : TransientContact(f.grid, f.in, OnGapGrid{}) {}
    TransientContact(const GridSpec& grid, const ContactInput& in, OnGapGrid);

    double force_limit() const; // mu N [N]
    // The rigid displacement of creepages c (rolling) or shift c (dq = 0)
    // plus base_, into the solver's rigid slip.
    void set_slip(const double c[3], double dq, bool steady);
    void set_committed_terms(); // aq0_ = A q0, bq0_ = B q0
    // The box the problem runs on (the contact's, or the whole grid
    // world-fixed), its bound from the normal solution, the fields' sizes.
    void set_box();
    // World-fixed: the normal problem of the geometry rolled by X [m] over
    // the grid, and the bound from it (nothing when it is solved already).
    void move_geometry(double X);
    const TransientStepResult& solve(const TransientStepInput& s, bool steady);
    void totals(const double c[3], const SteadyRollingInfo& ti, bool steady);
    // The rigid-slip change of a unit change of input column u (xi_x, xi_y,
    // phi) of a step of length (dq; dx steady; 1 a shift) into dw_.
    void unit_slip(int u, double length, double offset);

    CellBox box_; // of the contact; every field below is on it
    int bn_ = 0;
    std::size_t cell(int k) const // box element k -> grid element
    {
        return box_.i0 + k % box_.nx + static_cast<std::size_t>(nx_) * (box_.j0 + k / box_.nx);
    }
    std::vector<double> gap_;
    ContactInput in_;
    GapNormal normal_;
    GridConvolution conv_;
    SteadyRolling solver_;
    double p_ref_ = 0.0, T_ = 0.0, U_ = 0.0, tolerance_ = 0.0, spin_offset_ = 0.0;
    int max_steps_ = 0;
    // The committed state: tractions (normalised), A q0 and B q0 (its
    // creepages and steps: TransientBase's).
    std::vector<Complex> q0_, aq0_, bq0_, base_, dw_, tangent_[2];
    std::vector<Complex> aq_; // A q of the last solve (the next commit's A q0)
    // The last solve (trial or steady start): its step length and spin
    // offset [m] (in set_slip's sense), prescribed forces and work per
    // element (normalised, box).
    double last_length_ = 0.0, last_offset_ = 0.0;
    // World-fixed: the frame, the committed and the trial rolled distance,
    // that of the normal solution, and the moved gap.
    bool world_ = false;
    double position_ = 0.0, trial_position_ = 0.0, normal_position_ = 0.0;
    std::vector<double> moved_gap_;
    bool last_fx_ = false, last_fy_ = false;
    std::vector<double> work_;
};

} // namespace creepwork
