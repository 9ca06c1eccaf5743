// FASTSIM's march with a falling law of the slip speed at every element, as
// a SIMD kernel over strips (march/march.hpp's layout and ISAs): the plain
// march's predictor, then in each slipping element (|q'| = P > bound g) the
// root of
//   t = g m(c (P - t)),   m = mu/mu_s,  c = (V T / a) |(L1 q'_x, L2 q'_y)| / (P h)
// (the slip speed s = c (P - t) [m/s], fastsim_law_model.hpp), which keeps
// q's direction: f = t / P. Halley's method (m and m' and m'' from one
// evaluation) from m extrapolated along the strip from its last two
// slipping elements: a step below 1e-4 g is the last, taken without another
// evaluation (m moves with it to second order), and the root is within about
// the cube of that step of it (every element meets its law within 1e-12 of
// p_n mu_s, test_core_friction_fastsim); nearly every element takes one
// evaluation. Lanes whose first step is larger go on in [0, g] (g(0) <= 0 <=
// g(g) there), safeguarded by bisection, each frozen once its step is small
// (the linear law, whose kinks a small step may cross: below 1e-8 g). The
// law's form is a template parameter: no branch on it in the loop.
//
// With tangents, the forward derivatives of every traction by ux, uy,
// kappa (march_tangent.hpp) and ln T (c is proportional to T): per
// slipping element
//   dt = (g m' (c dP + (P - t) dc)) / (1 + g c m'),  dc = c (dLq/Lq - dP/P)
// (plus c for ln T), dp = (dt - f dP)/P q' + f dq'. The primal operations
// are the same with or without tangents, and on every ISA (IEEE operations
// only, simd_exp.hpp): the state and sums are bitwise those of the primal
// march on any kernel.
#pragma once

#include "friction/slip_speed_law.hpp"
#include "march/march_step.hpp"
#include "simd/kernel_isa.hpp"

namespace creepwork {

constexpr int kLawTangents = 4; // ux, uy, kappa, ln T

struct LawMarch {
    MarchView view;               // every strip's geometry, bound, rigid slip and state
    SlipSpeedLaw law;             // linear, rational or exponential; static coefficient > 0
    double L1 = 0.0, L2 = 0.0;    // flexibilities [m/Pa]
    double slip_speed_scale = 0.0; // V T / a [m/s per unit of q' and step]
    // Per strip, out: the smallest and largest m over its slipping
    // elements (2 and -1 when none slips) and the Newton evaluations.
    double *ratio_min = nullptr, *ratio_max = nullptr, *iterations = nullptr;
    // Tangents, or null sums for the primal march alone: dw of kappa per
    // strip (-b Y and the strip part of a (X_slip + offset dX)), a, and the
    // sums of dp'_x, dp'_y, X dp'_y at [k * stride + j], k < kLawTangents.
    double a = 0.0;
    const double *kappa_wx = nullptr, *kappa_wy = nullptr;
    double *sum_px = nullptr, *sum_py = nullptr, *sum_x_py = nullptr;
};

// Marches every strip of m.view (writes its state, the per-strip outputs and,
// with sums, the tangents); allocates nothing.
void march_law(const LawMarch& m, KernelIsa isa);

} // namespace creepwork
