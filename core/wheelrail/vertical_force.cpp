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
constexpr int kFinalMisses = 2;        // final solves that miss before trials stop
constexpr int kTrialRun = 4;           // trial heights in a row before a final solve is due

// The vertical force at a wheelset position and its slope dFz/dz [N/m]
// (0 when no patch knows its derivative). Moving the wheelset down by dz
// moves a patch's surfaces together by dz cos(delta) along its normal; the
// normal force follows its method's derivative, the tangential force fs
// is taken along with fn at its ratio fs / fn (exact in full sliding, where
// |fs| is a fixed share of fn; the steps after the first correct for the
// rest by secant).
struct Evaluation {
    double fz = 0.0, slope = 0.0, gap_min = 0.0;
};

// The patches of the geometry's current state solved by `solver`.
Evaluation patch_forces(const WheelRailState& st, const PatchSolver& solver)
{
    Evaluation e;
    e.gap_min = st.gap_min;
    for (std::size_t k = 0; k < st.patches.size(); ++k) {
        const ContactPatch& p = st.patches[k];
        const PatchForces f = solver(k, p);
        if (!std::isfinite(f.fn) || !std::isfinite(f.fx) || !std::isfinite(f.fs) || !std::isfinite(f.fn_by_approach))
            throw Error(ErrorKind::numeric_failure, "wheel/rail: the patch solver returned a force that is not finite");
        e.fz += track_forces(p, f).fz;
        if (f.fn > 0.0 && f.fn_by_approach > 0.0) {
            const double c = std::cos(p.delta), s = std::sin(p.delta);
            e.slope += f.fn_by_approach * c * (c + s * f.fs / f.fn);
        }
    }
    return e;
}

Evaluation vertical_force(WheelRailGeometry& g, const WheelsetPosition& pos, const WheelsetVelocity& vel,
                          const PatchSolver& solver, bool height_only)
{
    return patch_forces(g.evaluate(pos, vel, height_only), solver);
}

// A point of g(z) = Fz(z)^(2/3) - fz^(2/3) and its slope (0: not known).
struct Point {
    double z = 0.0, g = 0.0, slope = 0.0;
    double fz = 0.0;    // [N] the force g was made from
    bool trial = false; // from a trial solve (corrected by the bias then)
};

} // namespace

// Newton's method on g(z) = Fz(z)^(2/3) - fz^(2/3), which is close to linear
// beyond first contact (Hertz: Fz ~ (z - z_touch)^1.5), with the slope from
// the patches' normal methods; after the first step that slope is scaled by
// the ratio of the secant through the last two points to it, because the
// tangential forces' share is only estimated and the patch grids move with
// the height (the fast model's derivative is exact on a fixed grid, the
// secant over a step of a wheelset drifting as in examples/rail_wear_hunting
// is about 7 % below it). Safeguarded by a bracket: between the height of first
// contact, where the vertical gap closes (moving the wheelset down by d
// closes every vertical gap by d), and a height with too much force; a step
// that leaves the bracket, or that did not halve |g|, is a regula falsi step
// (Illinois variant) on it instead; without force yet, the wheelset steps
// down until there is. A host that drifts pays the evaluation at its height
// and two or three Newton steps (bench/bench_wheelrail.cpp counts them).
VerticalForceSolution solve_vertical_position(WheelRailGeometry& g, double fz, const WheelsetPosition& start,
                                              const WheelsetVelocity& vel, const PatchSolver& solver,
                                              const VerticalForceOptions& opt)
{
    return solve_vertical_position(g, fz, start, vel, solver, PatchSolver{}, opt);
}

// With a final solver: a height whose trial force meets the tolerance, or
// the fifth trial height in a row (a trial whose force is too rough to
// meet it), is solved again by it, and that force decides; the point keeps
// the trial's slope (the exact model's final solve computes none).
VerticalForceSolution solve_vertical_position(WheelRailGeometry& g, double fz, const WheelsetPosition& start,
                                              const WheelsetVelocity& vel, const PatchSolver& solver,
                                              const PatchSolver& final, const VerticalForceOptions& opt)
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
    double gap = 0.0;
    // With a final solver: the trial forces corrected by the last final
    // solve's difference to them (bias), and after kFinalMisses final solves
    // that missed the tolerance, the final solver at every height.
    double bias = 0.0, rebias = 0.0; // rebias: the bias's change at the last height
    int misses = 0, trials = 0; // trials: trial heights since the last final solve
    auto g_of = [&](double f) { return std::cbrt(std::max(f, 0.0) * std::max(f, 0.0)) - target; };
    auto at = [&](double z) {
        pos.z = z;
        ++sol.evaluations;
        // after the first height only the height changes: the contact
        // search shifts the first height's samples of the wheel
        const bool trial = final && misses < kFinalMisses;
        Evaluation e = vertical_force(g, pos, vel, final && !trial ? final : solver, sol.evaluations > 1);
        if (trial) e.fz += bias;
        bool from_trial = trial;
        ++trials;
        if (trial && (std::abs(e.fz - fz) <= opt.tolerance * fz || trials > kTrialRun)) {
            trials = 0;
            ++sol.final_solves;
            const Evaluation f = patch_forces(g.state(), final);
            rebias = f.fz - e.fz;
            bias += rebias;
            misses += std::abs(f.fz - fz) > opt.tolerance * fz;
            e.fz = f.fz;
            from_trial = false;
        } else if (final && !trial) {
            ++sol.final_solves;
        }
        gap = e.gap_min;
        sol.z = z;
        sol.fz = e.fz;
        Point p{z, g_of(e.fz), 0.0, e.fz, from_trial};
        if (e.fz > 0.0 && e.slope > 0.0) p.slope = 2.0 / 3.0 * e.slope / std::cbrt(e.fz);
        return p;
    };
    auto converged = [&] { return std::abs(sol.fz - fz) <= opt.tolerance * fz; };
    Point now = at(start.z);
    if (converged()) return sol;
    rebias = 0.0; // nothing tried before
    // the bracket: lo at first contact (no force), hi once there is too much
    Point lo{start.z + gap, -target, 0.0}, hi;
    bool has_hi = false;
    if (now.g > 0.0) {
        hi = now;
        has_hi = true;
    } else if (gap <= 0.0) { // touching already
        lo = now;
    }
    const double z_touch = lo.z;
    Point last;
    bool has_last = false, newton = true;
    int side = 0;
    double step = 20e-6; // the first step down without force
    for (int it = 0; it < opt.max_iterations; ++it) {
        double slope = now.slope;
        if (has_last && now.g > -target && last.g > -target && now.z != last.z) {
            // the secant, or the derivative scaled by the secant's ratio to it
            const double secant = (now.g - last.g) / (now.z - last.z);
            slope = now.slope > 0.0 && last.slope > 0.0
                        ? now.slope * secant / (0.5 * (now.slope + last.slope))
                        : secant;
        }
        double z = newton && slope > 0.0 && now.g > -target ? now.z - now.g / slope : lo.z;
        const bool inside = z > lo.z && (!has_hi || z < hi.z);
        if (!inside && has_hi) {
            z = (lo.z * hi.g - hi.z * lo.g) / (hi.g - lo.g);
        } else if (!inside) { // no force yet, or a step back: step down from lo
            z = lo.z + step;
            step *= 2.0;
        }
        if (z - z_touch > kMaxApproach)
            throw Error(ErrorKind::not_converged,
                        "wheel/rail: the vertical force is not reached within 10 mm below first contact");
        const bool falsi = !inside && has_hi;
        last = now;
        has_last = true;
        now = at(z);
        if (converged()) return sol;
        // a final solve that missed: the trial points move by its difference
        // to the trial there, and the bracket keeps the ends still on their
        // side; once only final solves count, it keeps no trial's end
        const bool rebiased = rebias != 0.0;
        if (rebiased) {
            const bool finals_only = misses >= kFinalMisses;
            for (Point* p : {&last, &lo, &hi})
                if (p->trial) {
                    p->fz += rebias;
                    p->g = g_of(p->fz);
                }
            if (!(lo.g < 0.0) || (finals_only && lo.trial)) lo = Point{z_touch, -target};
            has_hi = has_hi && hi.g > 0.0 && !(finals_only && hi.trial);
            rebias = 0.0;
        }
        // a Newton step that did not halve |g| hands over to the bracket
        newton = rebiased || std::abs(now.g) <= 0.5 * std::abs(last.g);
        if (now.g > 0.0) {
            hi = now;
            has_hi = true;
            if (falsi && side == 1) lo.g *= 0.5;
            side = falsi ? 1 : 0;
        } else {
            lo = now;
            if (falsi && side == -1 && has_hi) hi.g *= 0.5;
            side = falsi ? -1 : 0;
        }
    }
    throw Error(ErrorKind::not_converged,
                "wheel/rail: the vertical force did not converge within max_iterations evaluations");
}

} // namespace creepwork::wheelrail
