// A law of the slip speed (slip_speed_law.hpp) on W lanes, for the SIMD
// kernels that evaluate it at every element: its form fixed at compile time
// (no branch on the kind inside a kernel's loop), its coefficients divided
// by the static one, so that it gives m(s) = mu(s)/mu_s, dm/ds [s/m] and,
// when asked, d2m/ds2 [s^2/m^2].
// The exponential form takes simd::exp_nonpositive (within 1e-15 of exp;
// a term below 1e-148 of its mu_e is 0);
// the others are the scalar formulas of slip_speed_law.cpp lane by lane.
// Every operation is an IEEE one: each ISA's copy gives the same bits.
#pragma once

#include "friction/slip_speed_law.hpp"
#include "simd/simd.hpp"
#include "simd/simd_exp.hpp"

namespace creepwork {

template <SlipSpeedLawKind Kind, int W>
struct SlipSpeedLawLanes {
    static_assert(Kind != SlipSpeedLawKind::coulomb, "Coulomb's law has no slip speed");
    using V = simd::Vec<W>;
    V kin, e1, e2; // mu_kin, mu_e1, mu_e2 over mu_s
    V rate1, rate2; // per unit slip speed: ln2/s_h (exponential), 1/s_h (the others)
    bool two = false; // the second term is present

    // law.mu_kin + law.mu_e1 + law.mu_e2 > 0 (checked by the caller). An
    // absent term (mu_e = 0) gets rate 1, so that it adds exactly 0.
    CREEPWORK_INLINE explicit SlipSpeedLawLanes(const SlipSpeedLaw& law)
    {
        const double mu_s = static_friction(law);
        const double unit = Kind == SlipSpeedLawKind::exponential ? 0.69314718055994530942 : 1.0;
        kin = simd::broadcast<W>(law.mu_kin / mu_s);
        e1 = simd::broadcast<W>(law.mu_e1 / mu_s);
        e2 = simd::broadcast<W>(law.mu_e2 / mu_s);
        rate1 = simd::broadcast<W>(law.mu_e1 > 0.0 ? unit / law.s_h1 : 1.0);
        rate2 = simd::broadcast<W>(law.mu_e2 > 0.0 ? unit / law.s_h2 : 1.0);
        two = law.mu_e2 > 0.0;
    }

    // m(s) and dm/ds at slip speeds s >= 0.
    CREEPWORK_INLINE void value(const V& s, V& m, V& dm) const
    {
        V d2m{}; // not computed
        evaluate<false>(s, m, dm, d2m);
    }
    // The same and d2m/ds2 [s^2/m^2] (the march's Halley step).
    CREEPWORK_INLINE void value(const V& s, V& m, V& dm, V& d2m) const
    {
        evaluate<true>(s, m, dm, d2m);
    }

private:
    template <bool Curvature>
    CREEPWORK_INLINE void evaluate(const V& s, V& m, V& dm, V& d2m) const
    {
        V t, dt, d2t{};
        term<1, Curvature>(e1, rate1, s, m, dm, d2m);
        m += kin;
        if (two) {
            term<2, Curvature>(e2, rate2, s, t, dt, d2t);
            m += t;
            dm += dt;
            if constexpr (Curvature) d2m += d2t;
        }
    }

    template <int Index, bool Curvature>
    CREEPWORK_INLINE static void term(const V& e, const V& rate, const V& s, V& m, V& dm,
                                      V& d2m)
    {
        if constexpr (Kind == SlipSpeedLawKind::exponential) {
            // A term below exp(-340) ~ 1e-148 of its mu_e is 0: the
            // kernels' products with it stay normal numbers.
            const V x = -(rate * s);
            const V cutoff = simd::broadcast<W>(-340.0), zero = simd::broadcast<W>(0.0);
            m = x > cutoff ? e * simd::exp_nonpositive<W>(x) : zero;
            dm = -(rate * m);
            if constexpr (Curvature) d2m = -(rate * dm);
        } else if constexpr (Kind == SlipSpeedLawKind::linear) {
            const V zero = simd::broadcast<W>(0.0), one = simd::broadcast<W>(1.0);
            // mu_e max(0, 1 - s/(2 s_h)); the right-hand slope 0 at the kink.
            const V f = one - simd::broadcast<W>(0.5) * (s * rate);
            m = f > zero ? e * f : zero;
            dm = f > zero ? -(simd::broadcast<W>(0.5) * e * rate) : zero;
            if constexpr (Curvature) d2m = zero;
        } else if constexpr (Index == 1) { // rational: mu_e / (1 + s/s_h)
            const V one = simd::broadcast<W>(1.0);
            const V d = one + s * rate;
            m = e / d;
            dm = -(e * rate) / (d * d);
            if constexpr (Curvature) d2m = -(simd::broadcast<W>(2.0) * rate * dm) / d;
        } else { // rational: mu_e / (1 + (s/s_h)^2)
            const V one = simd::broadcast<W>(1.0);
            const V r = s * rate, d = one + r * r;
            m = e / d;
            dm = -(simd::broadcast<W>(2.0) * e * r * rate) / (d * d);
            // e rate^2 (6 r^2 - 2) / d^3
            if constexpr (Curvature)
                d2m = e * rate * rate * (simd::broadcast<W>(6.0) * r * r - simd::broadcast<W>(2.0)) /
                      (d * d * d);
        }
    }
};

} // namespace creepwork
