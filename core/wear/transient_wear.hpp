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

#include "wear/wear_law.hpp"
#include "wear/wear_map.hpp"

namespace creepwork {

class TransientWear {
public:
    // Contact: TransientContact or TransientModel (the exact model's or
    // FASTSIM's step; transient/transient_model.hpp).
    template <class Contact>
    explicit TransientWear(const Contact& tc)
    {
        init(tc.nx(), tc.ny(), tc.dx(), tc.dy(), tc.y0());
    }

    // Adds the wear of tc's last step (or steady start) of rolled distance
    // dq [m] by law (its pass_length is not read). Returns the step's
    // totals (mass_per_pass: the mass of the step [kg]). Throws
    // Error(invalid_input) for a bad law or dq, or without a step.
    template <class Contact>
    wear::WearTotals add(const Contact& tc, double dq, const wear::WearLaw& law)
    {
        check(tc.nx(), tc.ny(), tc.has_solution(), dq, law);
        if (dq == 0.0) return wear::WearTotals{};
        tc.copy_pressure(pz_.data());
        tc.copy_traction(px_.data(), py_.data());
        tc.copy_slip(sx_.data(), sy_.data());
        tc.copy_work(work_.data());
        return add_fields(dq, law);
    }
    void reset();

    double mass() const { return mass_; }                     // accumulated [kg]
    const std::vector<double>& mass_map() const { return map_; } // [i + nx j] [kg]
    long steps() const { return steps_; }                     // steps added (shifts too)

private:
    void init(int nx, int ny, double dx, double dy, double y0);
    // Throws for another grid, no step, a bad dq or law; counts the step.
    void check(int nx, int ny, bool has_solution, double dq, const wear::WearLaw& law);
    // The wear of the fields copied into pz_ .. work_ over dq > 0.
    wear::WearTotals add_fields(double dq, const wear::WearLaw& law);

    int nx_ = 0, ny_ = 0;
    double dx_ = 0.0, dy_ = 0.0, y0_ = 0.0;
    std::vector<double> map_, area_, pz_, px_, py_, sx_, sy_, work_, step_mass_;
    std::vector<double> strip_y_, strip_width_;
    double mass_ = 0.0;
    long steps_ = 0;
};

} // namespace creepwork
