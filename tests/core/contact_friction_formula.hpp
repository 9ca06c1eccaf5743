// CONTACT's coefficient of friction at steady sliding, fric_veldep_mu_steady
// of its src/m_friclaw.f90 (eve70a/CONTACT d431cdb), transcribed for the
// tests: the reference the friction laws are checked against. L = 2
// (linear), 3 (rational), 4 (exponential); slip speed and half speeds in
// CONTACT's mm/s.
#pragma once

#include <algorithm>
#include <cmath>

namespace cwtest {

inline double contact_mu_steady(int L, double fkin, double f1, double sh1, double f2, double sh2,
                                double slpvel)
{
    if (L == 2)
        return fkin + f1 * std::max(0.0, 1.0 - 0.5 * slpvel / sh1) +
               f2 * std::max(0.0, 1.0 - 0.5 * slpvel / sh2);
    if (L == 3) return fkin + f1 / (1.0 + slpvel / sh1) + f2 / (1.0 + std::pow(slpvel / sh2, 2));
    return fkin + f1 * std::exp(-std::log(2.0) * slpvel / sh1) +
           f2 * std::exp(-std::log(2.0) * slpvel / sh2);
}

} // namespace cwtest
