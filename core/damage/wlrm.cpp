#include "damage/wlrm.hpp"

#include "contact/contact_input.hpp"

namespace creepwork::damage {

void validate(const WlrmFunction& f)
{
    require_non_negative("wlrm_onset", f.onset);
    require_finite("wlrm_peak", f.peak);
    require_finite("wlrm_zero", f.zero);
    if (!(f.peak > f.onset)) reject_input("wlrm_peak", f.peak, "must be > wlrm_onset");
    if (!(f.zero > f.peak)) reject_input("wlrm_zero", f.zero, "must be > wlrm_peak");
    if (!(f.zero <= 1e6)) reject_input("wlrm_zero", f.zero, "must be <= 1e6 N");
    require_non_negative("wlrm_peak_damage", f.peak_damage);
    if (!(f.peak_damage <= 1.0))
        reject_input("wlrm_peak_damage", f.peak_damage, "must be <= 1 (a fraction of the life)");
}

double wlrm_damage(double T_gamma, const WlrmFunction& f)
{
    if (!(T_gamma > f.onset) || !(T_gamma < f.zero)) return 0.0;
    if (T_gamma <= f.peak) return f.peak_damage * (T_gamma - f.onset) / (f.peak - f.onset);
    return f.peak_damage * (f.zero - T_gamma) / (f.zero - f.peak);
}

} // namespace creepwork::damage
