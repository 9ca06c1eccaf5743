// Wear laws applied element by element to the frictional-work map of a
// solved contact (any model: they read only the shared per-element fields).
//
// Both laws give a mass loss per unit contact area per unit rolled distance,
// the "rate" [kg/m^2 per m = kg/m^3], from local quantities of one element:
//
//  - USFD (Lewis & Dwyer-Joyce 2004; as used by Braghin, Lewis, Dwyer-Joyce
//    & Bruni, Wear 261 (2006) 1253-1264, for R8T wheel / UIC60 900A rail
//    steel). With the wear index T_gamma/A of the element = its frictional
//    work per rolled distance / its area (a stress, N/mm^2 in the paper):
//        K = k1 T_gamma/A            T_gamma/A <  t1   (mild)
//        K = k2                      t1 <= T_gamma/A <= t2 (severe)
//        K = k3 T_gamma/A - c3       T_gamma/A >  t2   (catastrophic)
//    K in ug/(m mm^2) in the paper: mass per rolled metre per mm^2 of
//    contact. Published: k1 = 5.3, t1 = 10.4 N/mm^2, k2 = 55.0, t2 = 77.2
//    N/mm^2, k3 = 61.9, c3 = 4778.7. Here in SI (1 ug/(m mm^2) = 1e-3
//    kg/m^3, 1 N/mm^2 = 1e6 Pa): k1 = 5.3e-9 kg/(N m), t1 = 10.4e6 Pa,
//    k2 = 55.0e-3 kg/m^3, t2 = 77.2e6 Pa, k3 = 61.9e-9 kg/(N m), c3 =
//    4.7787 kg/m^3. As published the third branch starts at
//    61.9 x 77.2 - 4778.7 = -0.02 (a drop from 55 to about 0 at t2, back to
//    55 at 78.1 N/mm^2): it is applied as printed, negative values clamped
//    to 0.
//
//  - Archard with the KTH wear map (Jendel, Wear 253 (2002) 89-99): worn
//    volume = k N s / H, k from the element's sliding velocity v and its
//    pressure p: p > 0.8 H (seizure) k = 300-400e-4; otherwise v < 0.2 m/s
//    k = 1-10e-4, 0.2 <= v <= 0.7 m/s k = 30-40e-4, v > 0.7 m/s k =
//    1-10e-4. Defaults are the middles of these bands (doc/theory/wear.md).
//    Per element, during a rolled distance D the element carries the normal
//    force N_e = p A_e and the two surfaces slide over s_e D relative to
//    each other (s_e = sliding per rolled distance, the dimensionless
//    micro-slip magnitude |W|/V), so
//        rate = rho k p s_e / H,   v = s_e V.
#pragma once

namespace creepwork::wear {

enum class Law { usfd = 0, archard_kth = 1 };

// Which frictional work (and sliding) the laws are fed with.
enum class Source {
    consistent = 0, // energy-consistent map (default): sums to W_macro
    paper = 1,      // the paper's eq. 36 map (negative values, in adhesion with spin, -> 0)
    slip = 2,       // the model's own traction x micro-slip, -p.s A, and |s|
};

struct UsfdCoefficients {
    double k1 = 5.3e-9;  // [kg/(N m)]  Braghin et al. 2006: 5.3 ug/(m mm^2) per N/mm^2
    double t1 = 10.4e6;  // [Pa]        10.4 N/mm^2
    double k2 = 55.0e-3; // [kg/m^3]    55.0 ug/(m mm^2)
    double t2 = 77.2e6;  // [Pa]        77.2 N/mm^2
    double k3 = 61.9e-9; // [kg/(N m)]  61.9 ug/(m mm^2) per N/mm^2
    double c3 = 4.7787;  // [kg/m^3]    4778.7 ug/(m mm^2)
};

struct KthMap {
    double hardness = 2.5e9;     // H [Pa]: about 255 HB (1 HB = 9.807 MPa), a wheel steel
    double v1 = 0.2;             // [m/s] Jendel 2002: sliding-velocity boundaries
    double v2 = 0.7;             // [m/s]
    double seizure_ratio = 0.8;  // p > 0.8 H: seizure
    double k_seizure = 350e-4;   // Jendel 2002: 300-400e-4
    double k_slow = 5.5e-4;      //              1-10e-4   (v < v1)
    double k_severe = 35e-4;     //              30-40e-4  (v1 <= v <= v2)
    double k_fast = 5.5e-4;      //              1-10e-4   (v > v2)
};

struct WearLaw {
    Law law = Law::usfd;
    Source source = Source::consistent;
    double density = 7800.0;     // rho [kg/m^3], steel
    double rolling_speed = 0.0;  // V [m/s], Archard (sliding velocity s V); > 0 there
    double pass_length = 1.0;    // rolled distance of one pass [m], for the mass per pass
    UsfdCoefficients usfd;
    KthMap kth;
};

// Throws Error(invalid_input) naming the first offending parameter.
void validate(const WearLaw& law);

// Regimes, per element (0: no wear).
constexpr int kRegimeNone = 0;
// USFD: 1 mild (< t1), 2 severe (t1..t2), 3 catastrophic (> t2).
// KTH:  1 v < v1, 2 v1 <= v <= v2, 3 v > v2, 4 seizure (p > ratio H).
constexpr int kRegimeCount = 4;

// USFD rate [kg/m^3] for a wear index t = T_gamma/A [Pa] >= 0; regime out.
inline double usfd_rate(const UsfdCoefficients& c, double t, int& regime)
{
    if (!(t > 0.0)) {
        regime = kRegimeNone;
        return 0.0;
    }
    if (t < c.t1) {
        regime = 1;
        return c.k1 * t;
    }
    if (t <= c.t2) {
        regime = 2;
        return c.k2;
    }
    regime = 3;
    // As published the branch starts slightly below zero (see above).
    const double r = c.k3 * t - c.c3;
    return r > 0.0 ? r : 0.0;
}

// KTH wear coefficient [-] for sliding velocity v [m/s] >= 0 and pressure
// p [Pa]; regime out (0 when v == 0).
inline double kth_coefficient(const KthMap& m, double v, double p, int& regime)
{
    if (!(v > 0.0)) {
        regime = kRegimeNone;
        return 0.0;
    }
    if (p > m.seizure_ratio * m.hardness) {
        regime = 4;
        return m.k_seizure;
    }
    if (v < m.v1) {
        regime = 1;
        return m.k_slow;
    }
    if (v <= m.v2) {
        regime = 2;
        return m.k_severe;
    }
    regime = 3;
    return m.k_fast;
}

} // namespace creepwork::wear
