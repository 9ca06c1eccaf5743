// The friction law of an exact model (ExactModel, GapExactModel): Coulomb's
// with the input's mu (the default), or a law of the slip speed with the
// rolling speed V, set on the model. Under a law every element's bound is
// mu(s) p at its own slip speed s = |micro-slip| V, inside the Newton system
// (local_friction.hpp); the traction unit is mu(0) times the model's
// reference pressure, and the input's mu is not read. With friction memory
// (set_memory) each element's coefficient also remembers the element ahead
// of it (exact/steady_memory.cpp).
#pragma once

#include <memory>
#include <vector>

#include "contact/params.hpp"
#include "exact/tangential_solve.hpp"
#include "friction/friction_memory.hpp"
#include "friction/slip_speed_law.hpp"

namespace creepwork {

class ExactLaw {
public:
    // Throws Error(invalid_input) naming the input: the law's parameters, or
    // V unless finite and > 0 [m/s]. True when it changes the law (the
    // model's warm start belongs to the last law; the solver sets the law
    // before every solve).
    bool set(const SlipSpeedLaw& law, double V);
    // True when a law was set (the next solve is then cold).
    bool clear()
    {
        const bool was = active_;
        active_ = false;
        return was;
    }
    bool active() const { return active_; }
    // Friction memory for the next solves under a law (distance 0: none;
    // checked by the input's validation). True when it changes the memory.
    bool set_memory(const FrictionMemory& memory)
    {
        const bool same = memory.distance == memory_.distance && memory.s0 == memory_.s0;
        memory_ = memory;
        return !same;
    }
    bool memory_active() const { return active_ && memory_.distance > 0.0; }
    // Under a law, info's range of mu (diagnose) into mu_min, mu_max; false
    // under Coulomb's law (ContactModel::friction_range).
    bool friction_range(const TangentialInfo& info, double& mu_min, double& mu_max) const
    {
        if (!active_) return false;
        mu_min = info.mu_min;
        mu_max = info.mu_max;
        return true;
    }
    // The coefficient that scales the tractions: mu(0) under a law, in.mu
    // otherwise.
    double coefficient(const ContactInput& in) const;
    // The traction unit [Pa] at the reference pressure [Pa].
    double traction_scale(const ContactInput& in, double pressure) const;
    // Each level's local law: kappa = V slip_scale [m/s] turns the
    // normalised slip into slip speed (on every level of the hierarchy);
    // Coulomb's when no law is set. Under memory dx(level) is the level's
    // element length in the rolling direction [m] (dt = dx / V).
    template <class Level, class Dx>
    void apply(std::vector<std::unique_ptr<Level>>& levels, double slip_scale, Dx dx) const
    {
        LocalLaw local{law_, law_.coefficient(0.0), V_ * slip_scale, FrictionMemory{}, 0.0, 0.0};
        for (auto& L : levels) {
            if (memory_active()) set_local_memory(local, dx(*L));
            L->tangential.set_law(active_ ? &local : nullptr);
        }
    }
    // Under a law, into info: the range of mu over the fine level's slipping
    // elements (mu(0) when none slips), their mean local Newton steps in the
    // final sweep, and the local Newton steps of the
    // levels solved (the first n_levels unless the solve was warm and not
    // retried: the finest alone).
    template <class Level>
    void diagnose(const std::vector<std::unique_ptr<Level>>& levels, size_t n_levels,
                  TangentialInfo& info) const
    {
        if (!active_) return;
        range(levels[0]->tangential, info);
        const bool warm_only = info.warm && !info.retried_cold;
        const size_t used = warm_only ? 1 : n_levels;
        for (size_t l = 0; l < used; ++l)
            info.friction_iterations += levels[l]->tangential.friction_iterations();
        if (memory_active()) info.memory_iterations = levels[0]->tangential.memory_iterations();
    }

private:
    void range(const SteadyRolling& fine, TangentialInfo& info) const;
    void set_local_memory(LocalLaw& local, double dx) const;
    bool active_ = false;
    FrictionMemory memory_;
    SlipSpeedLaw law_;
    double V_ = 0.0;
};

} // namespace creepwork
