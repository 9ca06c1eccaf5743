// The frictional power density q [W/m^2] that heats the surfaces, per
// element, from a solved contact's fields: what the flash temperature
// (flash_temperature.hpp) is fed with.
//  - from the work map: q = V W_e / A_e, W_e the element's frictional work
//    per rolled distance [J/m] (the energy-consistent map sums to W_macro,
//    so the heat released is the power V W_macro of the rigid-body motion);
//  - from traction and slip, as CONTACT: q = |p_t| |s| V, s the micro-slip
//    W/V (zero in adhesion).
// Elements of zero area (exterior) get q = 0; negative work counts as 0.
#pragma once

namespace creepwork::thermal {

void heat_from_work(long n, const double* work, const double* area, double rolling_speed,
                    double* q);

void heat_from_slip(long n, const double* px, const double* py, const double* sx,
                    const double* sy, double rolling_speed, double* q);

} // namespace creepwork::thermal
