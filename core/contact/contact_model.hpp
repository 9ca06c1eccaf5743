// The interface every model of the contact implements: how the tangential
// tractions are found differs (fastsim/, calibrated/, exact/, gap/), what a solve
// returns does not. The solver (../solver.hpp) makes each model on first use
// from one registration (make_model in solver.cpp) and holds the one that
// solved last, whose view (solved()) it exports.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "contact/error.hpp"
#include "contact/fields.hpp"
#include "contact/jacobian.hpp"
#include "contact/params.hpp"
#include "contact/solved_contact.hpp"
#include "simd/kernel_isa.hpp"

namespace creepwork {

// A friction law of the slip speed (friction/slip_speed_law.hpp, a layer
// above): declared only, the interface passes it on by reference.
struct SlipSpeedLaw;

class ContactModel {
public:
    virtual ~ContactModel() = default;

    // Throws Error naming a bad input (or not_converged, numeric_failure).
    // A model is made once per grid and solves many times without
    // allocating.
    virtual SolveTotals solve(const ContactInput& input, SolveMode mode) = 0;
    // The same solve (totals bitwise those of solve()) and rows Fx, Fy, Mz
    // of the Jacobian by xi_x, xi_y, phi, N (contact/jacobian.hpp; the
    // W_macro row is the solver's). jacobian is written only on success.
    virtual SolveTotals solve_jacobian(const ContactInput& input, SolveMode mode,
                                       Jacobian& jacobian) = 0;

    // The last successful solve per element (contact/solved_contact.hpp):
    // pointers into the model's arrays, made when asked for, in the rows
    // or the strips layout. Its one export (export_field, export_state,
    // export_profile) gives the fields in the caller's layout; the caller
    // checks that there is a solve, and that it was full for fields that
    // need the work.
    virtual SolvedContact solved() const = 0;

    // The friction law of the slip speed and the rolling speed V [m/s] > 0
    // that the next solves use (the solver sets it before each solve of an
    // input beyond Coulomb's law). A model that takes only Coulomb's law
    // refuses it by name.
    virtual void set_law(const SlipSpeedLaw& /*law*/, double /*V*/)
    {
        throw Error(ErrorKind::invalid_input,
                    "friction_law: " + name_ + " takes Coulomb's law only");
    }
    // Back to Coulomb's law (input.mu) for the next solves: the solver calls
    // it before a solve of an input without a law, so that a law set for
    // one call does not stay with a model that serves both.
    virtual void clear_law() {}
    // Element-wise factors on the friction coefficient of the next solves
    // (contact/friction_law.hpp, ElementFriction: nx*ny values in the
    // caller's layout, kept by the caller; null: none, the default). The
    // solver sets them before every solve. A model without them refuses
    // factors by name.
    virtual void set_friction_factors(const double* factor)
    {
        if (factor)
            throw Error(ErrorKind::invalid_input,
                        "mu_T: " + name_ +
                            " takes no friction that varies element by element (the exact "
                            "model on every grid and FASTSIM on the ellipse's grids with "
                            "Coulomb's law or friction_speed = local do)");
    }
    // Friction memory under a law of the slip speed for the next solves: the
    // characteristic distance d_c [m] (0: none) and s0 [m/s], validated.
    // False from a model without it (the solver then refuses d_c > 0).
    virtual bool set_friction_memory(double /*distance*/, double /*s0*/) { return false; }
    // The smallest and largest friction coefficient of the last solve over
    // its slipping elements, for a model under a law of the slip speed;
    // false for a model that holds one mu.
    virtual bool friction_range(double& /*mu_min*/, double& /*mu_max*/) const { return false; }
    // Whether the model takes an interface layer (ContactInput::layer_h,
    // tau_c0, k_tau); the solver refuses a layer, naming its input, for a
    // model that does not.
    virtual bool takes_interface_layer() const { return false; }
    // The model's name in messages ("the exact model"), set by the solver
    // that makes it.
    void set_name(std::string name) { name_ = std::move(name); }
    const std::string& name() const { return name_; }

    // The separate patches of the last solve, for models that find them
    // (those on a gap grid); null otherwise (the solver reports the contact
    // as one patch).
    virtual const std::vector<PatchTotals>* patches() const { return nullptr; }
    // Per row j < ny of a model whose rows have sizes of their own (those on
    // a gap grid): centre y [m] and width [m]; false otherwise (the solver
    // scales its grid's strips by the last solve's semi-axis b).
    virtual bool copy_strips(double* /*y*/, double* /*width*/) const { return false; }

    // Makes the memory a first solve would make, so that no solve
    // allocates (Solver::prepare); a model that makes it all when made
    // does nothing.
    virtual void prepare() {}
    // dN/d(approach) [N/m] at the last solve, by a model that solves its own
    // normal problem on a gap grid (its normal method's, throws as that);
    // 0 otherwise.
    virtual double normal_force_by_approach() { return 0.0; }

    // The ISA of the model's SIMD kernels (simd/kernel_isa.hpp), supported
    // by this CPU; every ISA gives bitwise the same results. Models without
    // such kernels ignore it.
    virtual void set_kernel_isa(KernelIsa) {}

private:
    std::string name_ = "this model";
};

} // namespace creepwork
