// Laws of the local slip speed s = |micro-slip| V [m/s]: Coulomb's constant
// coefficient and CONTACT's falling-friction forms (its L-digit 2, 3 and 4),
// with Polach's form accepted as input and written as the exponential law.
// Pure functions: a model asks for mu(s) and dmu/ds.
#pragma once

namespace creepwork {

// CONTACT's numbering (user guide, "Slip velocity dependent friction").
enum class SlipSpeedLawKind {
    coulomb = 0,     // mu = mu_kin at every slip speed
    linear = 2,      // mu_kin + sum mu_ek max(0, 1 - s / (2 s_hk))
    rational = 3,    // mu_kin + mu_e1 / (1 + s/s_h1) + mu_e2 / (1 + (s/s_h2)^2)
    exponential = 4, // mu_kin + sum mu_ek exp(-ln2 s / s_hk)
};

// A friction law. Each term k = 1, 2 falls from mu_ek at s = 0 to half of it
// at s = s_hk (in all three forms) and to 0 at large s; mu_kin is what is
// left at large slip speed. A term with mu_ek = 0 is absent (its s_hk is
// not read). Coulomb's law is mu_kin alone.
//
// It is a law in the sense of the models' friction hook (coefficient(s),
// slope(s), uses_slip_speed), declared after friction_value().
struct SlipSpeedLaw {
    SlipSpeedLawKind kind = SlipSpeedLawKind::coulomb;
    double mu_kin = 0.0;            // [-] >= 0
    double mu_e1 = 0.0, s_h1 = 0.0; // [-] >= 0, [m/s] > 0
    double mu_e2 = 0.0, s_h2 = 0.0; // [-] >= 0, [m/s] > 0

    static constexpr bool uses_slip_speed = true;
    double coefficient(double slip_speed) const; // mu(s)
    double slope(double slip_speed) const;       // dmu/ds [s/m]
};

// mu(s) and its derivative dmu/ds [s/m] at one slip speed s >= 0 [m/s].
// The linear law's kink at s = 2 s_hk takes the right-hand slope (0).
struct FrictionValue {
    double mu = 0.0;
    double dmu_ds = 0.0;
};

FrictionValue friction_value(const SlipSpeedLaw& law, double s);

inline double SlipSpeedLaw::coefficient(double slip_speed) const
{
    return friction_value(*this, slip_speed).mu;
}
inline double SlipSpeedLaw::slope(double slip_speed) const
{
    return friction_value(*this, slip_speed).dmu_ds;
}

// The coefficient at s = 0 (CONTACT's FSTAT): mu_kin + mu_e1 + mu_e2.
double static_friction(const SlipSpeedLaw& law);

// Coulomb's law of coefficient mu.
SlipSpeedLaw coulomb_law(double mu);

// Polach 2005's mu = mu0 [(1 - A) exp(-B s) + A] as the exponential law:
// mu_kin = A mu0, mu_e1 = (1 - A) mu0, s_h1 = ln2 / B. mu0 >= 0,
// 0 <= A <= 1, B > 0 [s/m] (checked, errors name mu, polach_A, polach_B).
SlipSpeedLaw polach_law(double mu0, double A, double B);

// Throws Error(invalid_input) naming the first bad parameter (mu_kin,
// mu_e1, s_h1, mu_e2, s_h2): non-finite, negative, or a present term
// without a positive half speed.
void check_slip_speed_law(const SlipSpeedLaw& law);

} // namespace creepwork
