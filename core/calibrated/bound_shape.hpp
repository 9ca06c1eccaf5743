// Traction-bound shapes between and beyond FASTSIM's two pressure laws, for
// the calibrated model (calibrated/): one number, the blend, moves the bound
// from the parabolic law towards the elliptic (Hertz) law or towards a
// quartic one, with the normal force unchanged.
//
// In units of the parabolic law's p0 = 2N/(pi a b), with P = 1 - X^2 - Y^2
// the parabolic shape (X = x/a, Y = y/b):
//   parabolic  P                   (p0 = 2N/(pi a b))
//   elliptic   (3/4) sqrt(P)       (p0 = 3N/(2 pi a b), Hertz)
//   quartic    (3/2) P^2           (p0 = 3N/(pi a b))
// Each integrates over the unit disc to pi/2, so each carries the force N:
// int P = pi/2, int sqrt(P) = 2 pi/3, int P^2 = pi/3. The blend
//   blend >= 0:  (1 - blend) P + blend (3/4) sqrt(P)
//   blend <  0:  (1 + blend) P - blend (3/2) P^2
// therefore carries N too, for blend in [-1, 1]. Positive blends lower the
// bound in the middle and raise it near the edge (elliptic: more adhesion at
// the trailing edge); negative ones do the opposite (a larger slip zone).
#pragma once

namespace creepwork {

// Largest |blend| accepted; callers clamp to it.
constexpr double kMaxBoundBlend = 1.0;

// The blended bound at one point from its parabolic shape P (>= 0) and
// sqrt(P), in units of the parabolic p0. 0 outside the contact (P = 0).
inline double blended_bound_shape(double parabolic, double sqrt_parabolic, double blend)
{
    return blend >= 0.0 ? (1.0 - blend) * parabolic + blend * 0.75 * sqrt_parabolic
                        : (1.0 + blend) * parabolic - blend * 1.5 * parabolic * parabolic;
}

} // namespace creepwork
