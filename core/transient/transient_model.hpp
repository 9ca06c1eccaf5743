// The transient handle's model: the exact theory (transient_contact.hpp) or
// FASTSIM's transient form (transient_fastsim.hpp), chosen by the contact's
// model at construction. One interface for the C API: each call goes to the
// model made. FASTSIM takes the elliptic contact (its gap on the uniform
// grid, as the exact model) and gives the work map; it runs contact-fixed
// only and has no step Jacobian: set_frame(world) and jacobian() throw
// Error(invalid_input) naming the model.
#pragma once

#include <memory>
#include <vector>

#include "transient/transient_contact.hpp"
#include "transient/transient_fastsim.hpp"

namespace creepwork {

class TransientModel {
public:
    // in.model exact or fastsim (another throws Error(invalid_input) naming
    // model); grid a gap grid, or an ellipse's uniform grid
    // (transient/ellipse_gap.hpp).
    TransientModel(const GridSpec& grid, const ContactInput& in);

    // Contact-fixed starts from zero; world-fixed is the exact model's.
    void set_frame(TransientFrame frame);
    TransientFrame frame() const { return exact_ ? exact_->frame() : TransientFrame::contact; }
    double position() const { return exact_ ? exact_->position() : 0.0; }
    // The exact model's step Jacobian (TransientContact::jacobian).
    void jacobian(double J[9]);

    void start_zero() { exact_ ? exact_->start_zero() : fastsim_->start_zero(); }
    const TransientStepResult& start_steady(const TransientStepInput& s)
    {
        return exact_ ? exact_->start_steady(s) : fastsim_->start_steady(s);
    }
    const TransientStepResult& step(const TransientStepInput& s)
    {
        return exact_ ? exact_->step(s) : fastsim_->step(s);
    }
    void commit() { exact_ ? exact_->commit() : fastsim_->commit(); }
    void rewind() { base().rewind(); }
    std::vector<unsigned char> save() const { return exact_ ? exact_->save() : fastsim_->save(); }
    void restore(const unsigned char* bytes, std::size_t n)
    {
        exact_ ? exact_->restore(bytes, n) : fastsim_->restore(bytes, n);
    }
    int nx() const { return base().nx(); }
    int ny() const { return base().ny(); }
    double dx() const { return base().dx(); }
    double dy() const { return base().dy(); }
    double x0() const { return base().x0(); }
    double y0() const { return base().y0(); }
    bool has_solution() const { return base().has_solution(); }
    long steps_committed() const { return base().steps_committed(); }
    bool has_trial() const { return base().has_trial(); }
    const TransientStepResult& last() const { return base().last(); }
    void copy_traction(double* px, double* py) const
    {
        exact_ ? exact_->copy_traction(px, py) : fastsim_->copy_traction(px, py);
    }
    void copy_slip(double* sx, double* sy) const
    {
        exact_ ? exact_->copy_slip(sx, sy) : fastsim_->copy_slip(sx, sy);
    }
    void copy_state(int* out) const
    {
        exact_ ? exact_->copy_state(out) : fastsim_->copy_state(out);
    }
    void copy_pressure(double* out) const
    {
        exact_ ? exact_->copy_pressure(out) : fastsim_->copy_pressure(out);
    }
    void copy_work(double* out) const
    {
        exact_ ? exact_->copy_work(out) : fastsim_->copy_work(out);
    }

private:
    // What both models share: the grid and the trial's state.
    const TransientBase& base() const
    {
        return exact_ ? static_cast<const TransientBase&>(*exact_) : *fastsim_;
    }
    TransientBase& base() { return exact_ ? static_cast<TransientBase&>(*exact_) : *fastsim_; }
    std::unique_ptr<TransientContact> exact_;
    std::unique_ptr<TransientFastsim> fastsim_;
};

} // namespace creepwork
