#include "wheelrail/vertical_force.hpp"

#include <cmath>
#include <string>

#include "contact/error.hpp"
#include "contact/number_text.hpp"

namespace creepwork::wheelrail {

TrackForces track_forces(const ContactPatch& p, const PatchForces& f)
{
    const double c = std::cos(p.delta), s = std::sin(p.delta);
    return {f.fx, f.fs * c - f.fn * s, f.fs * s + f.fn * c};
}

namespace {

constexpr double kMaxApproach = 10e-3; // [m] no wheel sinks this far into a rail

double vertical_force(WheelRailGeometry& g, const WheelsetPosition& pos, const WheelsetVelocity& vel,
                      const PatchSolver& solver, double& gap_min)
{
    const WheelRailState& st = g.evaluate(pos, vel);
    gap_min = st.gap_min;
    double fz = 0.0;
    for (std::size_t k = 0; k < st.patches.size(); ++k) {
        const ContactPatch& p = st.patches[k];
        const PatchForces f = solver(k, p);
        if (!std::isfinite(f.fn) || !std::isfinite(f.fx) || !std::isfinite(f.fs))
            throw Error(ErrorKind::numeric_failure, "wheel/rail: the patch solver returned a force that is not finite");
        fz += track_forces(p, f).fz;
    }
    return fz;
}

} // namespace

// Regula falsi (Illinois variant) on g(z) = Fz(z)^(2/3) - fz^(2/3), which is
// close to linear beyond first contact (Hertz: Fz ~ (z - z_touch)^1.5),
// bracketed between the height of first contact, where the vertical gap
// closes (moving the wheelset down by d closes every vertical gap by d),
// and a height with too much force.
VerticalForceSolution solve_vertical_position(WheelRailGeometry& g, double fz, const WheelsetPosition& start,
                                              const WheelsetVelocity& vel, const PatchSolver& solver,
                                              const VerticalForceOptions& opt)
{
    if (!(fz > 0.0 && std::isfinite(fz) && fz < 1e7))
        throw Error(ErrorKind::invalid_input,
                    "wheel/rail: the vertical force must lie in (0, 1e7) N, got " + number_text(fz));
    if (!(opt.tolerance > 0.0 && opt.tolerance < 0.1 && opt.max_iterations >= 2))
        throw Error(ErrorKind::invalid_input, "wheel/rail: vertical force tolerance must lie in (0, 0.1), "
                                              "max_iterations >= 2");
    if (!solver) throw Error(ErrorKind::invalid_input, "wheel/rail: no patch solver given");
    VerticalForceSolution sol;
    WheelsetPosition pos = start;
    const double target = std::cbrt(fz * fz);
    auto g_of = [&](double z, double& gap) {
        pos.z = z;
        ++sol.evaluations;
        const double f = vertical_force(g, pos, vel, solver, gap);
        sol.z = z;
        sol.fz = f;
        return std::cbrt(std::max(f, 0.0) * std::max(f, 0.0)) - target;
    };
    double gap = 0.0;
    double g0 = g_of(start.z, gap);
    // the lower end of the bracket: first contact (no force)
    double z_lo = start.z + gap, g_lo = -target;
    double z_hi = start.z, g_hi = g0;
    if (std::abs(sol.fz - fz) <= opt.tolerance * fz) return sol;
    if (g0 <= 0.0) { // not enough force yet: step down until there is
        if (gap <= 0.0) { // touching already
            z_lo = start.z;
            g_lo = g0;
        }
        const double z_touch = z_lo;
        double step = 20e-6;
        for (;;) {
            if (z_lo + step - z_touch > kMaxApproach)
                throw Error(ErrorKind::not_converged,
                            "wheel/rail: the vertical force is not reached within 10 mm below first contact");
            z_hi = z_lo + step;
            g_hi = g_of(z_hi, gap);
            if (g_hi > 0.0) break;
            z_lo = z_hi;
            g_lo = g_hi;
            step *= 2.0;
        }
    }
    int side = 0;
    for (int it = 0; it < opt.max_iterations; ++it) {
        const double z = (z_lo * g_hi - z_hi * g_lo) / (g_hi - g_lo);
        const double gz = g_of(z, gap);
        if (std::abs(sol.fz - fz) <= opt.tolerance * fz) return sol;
        if (gz > 0.0) {
            z_hi = z;
            g_hi = gz;
            if (side == 1) g_lo *= 0.5;
            side = 1;
        } else {
            z_lo = z;
            g_lo = gz;
            if (side == -1) g_hi *= 0.5;
            side = -1;
        }
    }
    throw Error(ErrorKind::not_converged,
                "wheel/rail: the vertical force did not converge within max_iterations evaluations");
}

} // namespace creepwork::wheelrail
