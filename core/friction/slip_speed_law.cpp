#include "friction/slip_speed_law.hpp"

#include "contact/error.hpp"

#include <cmath>
#include <string>

namespace creepwork {

namespace {

constexpr double kLn2 = 0.69314718055994530942;

// One falling term of the law: its value and slope at slip speed s.
FrictionValue term(SlipSpeedLawKind kind, int index, double mu_e, double s_h, double s)
{
    if (mu_e == 0.0) return {};
    const double r = s / s_h;
    switch (kind) {
    case SlipSpeedLawKind::linear: {
        // CONTACT: mu_e max(0, 1 - 0.5 s/s_h); zero from s = 2 s_h on.
        const double f = 1.0 - 0.5 * r;
        if (f <= 0.0) return {};
        return {mu_e * f, -0.5 * mu_e / s_h};
    }
    case SlipSpeedLawKind::rational: {
        if (index == 1) { // mu_e / (1 + s/s_h)
            const double d = 1.0 + r;
            return {mu_e / d, -mu_e / (s_h * d * d)};
        }
        const double d = 1.0 + r * r; // mu_e / (1 + (s/s_h)^2)
        return {mu_e / d, -2.0 * mu_e * r / (s_h * d * d)};
    }
    case SlipSpeedLawKind::exponential: {
        const double e = mu_e * std::exp(-kLn2 * r);
        return {e, -kLn2 * e / s_h};
    }
    case SlipSpeedLawKind::coulomb:
        break;
    }
    return {};
}

void require(bool ok, const char* name, const std::string& why)
{
    if (!ok) throw Error(ErrorKind::invalid_input, std::string(name) + " " + why);
}

} // namespace

FrictionValue friction_value(const SlipSpeedLaw& law, double s)
{
    FrictionValue v{law.mu_kin, 0.0};
    if (law.kind == SlipSpeedLawKind::coulomb) return v;
    const FrictionValue t1 = term(law.kind, 1, law.mu_e1, law.s_h1, s);
    const FrictionValue t2 = term(law.kind, 2, law.mu_e2, law.s_h2, s);
    v.mu += t1.mu + t2.mu;
    v.dmu_ds = t1.dmu_ds + t2.dmu_ds;
    return v;
}

double static_friction(const SlipSpeedLaw& law)
{
    if (law.kind == SlipSpeedLawKind::coulomb) return law.mu_kin;
    return law.mu_kin + law.mu_e1 + law.mu_e2;
}

SlipSpeedLaw coulomb_law(double mu)
{
    SlipSpeedLaw law;
    law.mu_kin = mu;
    return law;
}

SlipSpeedLaw polach_law(double mu0, double A, double B)
{
    require(std::isfinite(mu0) && mu0 >= 0.0, "mu", "(Polach's mu0) must be finite and >= 0");
    require(std::isfinite(A) && A >= 0.0 && A <= 1.0, "polach_A",
            "must lie in [0, 1] (the ratio of friction at infinite slip speed to mu0)");
    require(std::isfinite(B) && B > 0.0, "polach_B", "must be finite and > 0 [s/m]");
    SlipSpeedLaw law;
    law.kind = SlipSpeedLawKind::exponential;
    law.mu_kin = A * mu0;
    law.mu_e1 = (1.0 - A) * mu0;
    law.s_h1 = kLn2 / B;
    return law;
}

void check_slip_speed_law(const SlipSpeedLaw& law)
{
    require(std::isfinite(law.mu_kin) && law.mu_kin >= 0.0, "mu_kin", "must be finite and >= 0");
    if (law.kind == SlipSpeedLawKind::coulomb) return;
    require(law.kind == SlipSpeedLawKind::linear || law.kind == SlipSpeedLawKind::rational ||
                law.kind == SlipSpeedLawKind::exponential,
            "friction_law", "must be coulomb, linear, rational or exponential");
    require(std::isfinite(law.mu_e1) && law.mu_e1 >= 0.0, "mu_e1", "must be finite and >= 0");
    require(std::isfinite(law.mu_e2) && law.mu_e2 >= 0.0, "mu_e2", "must be finite and >= 0");
    require(law.mu_e1 == 0.0 || (std::isfinite(law.s_h1) && law.s_h1 > 0.0), "s_h1",
            "must be finite and > 0 [m/s] when mu_e1 > 0");
    require(law.mu_e2 == 0.0 || (std::isfinite(law.s_h2) && law.s_h2 > 0.0), "s_h2",
            "must be finite and > 0 [m/s] when mu_e2 > 0");
}

} // namespace creepwork
