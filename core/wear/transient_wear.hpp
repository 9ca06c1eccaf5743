// Wear accumulated over the steps of transient rolling: each step's work
// map (TransientContact::copy_work, energy-consistent) fed to a wear law
// (wear/wear_map.hpp) as the work per rolled distance of the step, W_e / dq,
// with the step's slip per rolled distance S / dq as the sliding; the mass
// an element loses in the step is its rate times its area times dq. The
// masses add up on the grid (contact-fixed: where the contact is; world-
// fixed: on the material). A shift (dq = 0) rolls no distance and wears
// nothing in this accounting (the laws are per rolled distance).
#pragma once

#include <vector>

#include "transient/transient_contact.hpp"
#include "wear/wear_law.hpp"
#include "wear/wear_map.hpp"

namespace creepwork {

class TransientWear {
public:
    explicit TransientWear(const TransientContact& tc);

    // Adds the wear of tc's last step (or steady start) of rolled distance
    // dq [m] by law (its pass_length is not read). Returns the step's
    // totals (mass_per_pass: the mass of the step [kg]). Throws
    // Error(invalid_input) for a bad law or dq, or without a step.
    wear::WearTotals add(const TransientContact& tc, double dq, const wear::WearLaw& law);
    void reset();

    double mass() const { return mass_; }                     // accumulated [kg]
    const std::vector<double>& mass_map() const { return map_; } // [i + nx j] [kg]
    long steps() const { return steps_; }                     // steps added (shifts too)

private:
    int nx_, ny_;
    double dx_, dy_, y0_;
    std::vector<double> map_, area_, pz_, px_, py_, sx_, sy_, work_, step_mass_;
    std::vector<double> strip_y_, strip_width_;
    double mass_ = 0.0;
    long steps_ = 0;
};

} // namespace creepwork
