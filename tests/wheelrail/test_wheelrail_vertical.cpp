// The vertical position for a prescribed vertical force: the forces of a
// patch in track coordinates against CONTACT's totals, the solve with a
// linear spring (exact answer), Newton's step with the patch's derivative
// on a sphere-like contact, the Hertz estimate against Hertz's sphere
// and against CONTACT's non-Hertzian normal forces, the benchmark's
// wheelset heights, and the undeformed distance of the balance's later
// heights (the wheel solved from the last height's points) against the
// solve from the rail.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "contact/error.hpp"
#include "mbench_support.hpp"
#include "test_support.h"
#include "wheelrail/hertz_patch.hpp"
#include "wheelrail/patch_combination.hpp"
#include "wheelrail/patch_grid.hpp"
#include "wheelrail/placement.hpp"
#include "wheelrail/profile_table.hpp"
#include "wheelrail/vertical_force.hpp"

namespace wr = creepwork::wheelrail;

namespace {

// A flat wheel (a cylinder of radius r) over a rail with a circular crown
// of radius rc, one wheel at the track origin.
struct Cylinder {
    wr::Profile rail, wheel;
    wr::Track track;
    wr::Wheelset ws;
    Cylinder(double r, double rc)
    {
        std::ostringstream w, c;
        c.precision(17);
        for (int i = 0; i <= 120; ++i) w << 60.0 - i << " 0\n";
        for (int i = 0; i <= 240; ++i) {
            const double y = -30.0 + 0.25 * i;
            c << y << " " << rc * 1e3 - std::sqrt(rc * rc * 1e6 - y * y) << "\n";
        }
        std::istringstream wi(w.str()), ci(c.str());
        wheel = wr::read_profile(wi, wr::ProfileKind::wheel, wr::ProfileFormat::table, "cylinder");
        rail = wr::read_profile(ci, wr::ProfileKind::rail, wr::ProfileFormat::table, "crown");
        track.gauge_height = -1.0;
        ws.nominal_radius = r;
        ws.flange_back_position = 0.3;
        ws.flange_back_distance = 0.6;
    }
    wr::WheelRailGeometry geometry() const { return wr::WheelRailGeometry(rail, wheel, track, ws, wr::Side::right); }
};

// CONTACT prints per patch FN, FX, FS (on the rail, patch frame) and the
// totals FX_TR, FY_TR, FZ_TR (track frame): the rotation by the contact
// angle reproduces them to their 4 printed digits.
void test_track_forces_against_contact(void**)
{
    const auto rows = cwtest::read_rows(cwtest::contact_benchmark_results("mbench_a22.csv"));
    assert_int_equal(rows.size(), 42);
    for (const cwtest::Row& r : rows) {
        wr::ContactPatch p;
        p.delta = r.num("deltcp_rad");
        const wr::TrackForces t = wr::track_forces(p, {r.num("fn_N"), r.num("fx_N"), r.num("fs_N")});
        // 4 significant digits on every input and output
        const double tol = 1e-3 * (std::abs(r.num("fn_N")) + std::abs(r.num("fs_N")) + std::abs(r.num("fx_N")));
        assert_close(t.fx, r.num("fx_tr_N"), 0, tol);
        assert_close(t.fy, r.num("fy_tr_N"), 0, tol);
        assert_close(t.fz, r.num("fz_tr_N"), 0, tol);
    }
}

// A spring Fn = k * approach on a cylinder over a crown: the approach of
// this contact is z_ws itself (the wheel's bottom is at z_ws, the crown's
// top at 0), so the height for Fz is Fz / k.
void test_spring_solve(void**)
{
    const Cylinder cyl(0.46, 0.3);
    wr::WheelRailGeometry g = cyl.geometry();
    const double k = 4e8; // [N/m]
    const wr::PatchSolver spring = [&](std::size_t, const wr::ContactPatch& p) {
        wr::PatchForces f;
        f.fn = k * p.approach;
        return f;
    };
    for (double start : {-0.2e-3, 0.0, 1e-5, 0.3e-3}) {
        wr::WheelsetPosition p;
        p.z = start;
        const wr::VerticalForceSolution s = wr::solve_vertical_position(g, 12e3, p, {}, spring);
        assert_close(s.z, 12e3 / k, 1e-6, 0);
        assert_close(s.fz, 12e3, 1e-6, 0);
        assert_true(s.evaluations <= 12);
    }
}

// A trial solver that is off and a final one that is right (the spring
// above, the trial's stiffness 1e-3 or 30 % too high): the height returned
// is the final spring's, Fz / k, its force a final solve's at that height;
// a trial 1e-3 off is corrected by the final's difference to it and ends
// within three final solves, one 30 % off hands over to the final solver
// at every height after two misses, and one too rough to meet the
// tolerance gets a final solve at its fifth height in a row.
void test_trial_and_final_solvers(void**)
{
    const Cylinder cyl(0.46, 0.3);
    wr::WheelRailGeometry g = cyl.geometry();
    const double k = 4e8, load = 12e3; // [N/m], [N]
    int finals = 0;
    const wr::PatchSolver exact = [&](std::size_t, const wr::ContactPatch& p) {
        ++finals;
        wr::PatchForces f;
        f.fn = k * p.approach;
        return f;
    };
    for (double off : {1e-3, 0.3}) {
        const wr::PatchSolver trial = [&](std::size_t, const wr::ContactPatch& p) {
            wr::PatchForces f;
            f.fn = (1.0 + off) * k * p.approach;
            return f;
        };
        for (double start : {0.0, 20e-6, 40e-6}) {
            wr::WheelsetPosition p;
            p.z = start;
            finals = 0;
            const wr::VerticalForceSolution s = wr::solve_vertical_position(g, load, p, {}, trial, exact);
            assert_close(s.z, load / k, 1e-6, 0);
            assert_close(s.fz, load, 1e-6, 0);
            // the force returned is the final spring's at the height returned
            assert_true(s.fz == k * g.state().patches.at(0).approach);
            assert_int_equal(s.final_solves, finals);
            assert_true(s.final_solves >= 1 && s.final_solves <= (off < 0.01 ? 3 : s.evaluations));
            assert_true(s.evaluations <= (off < 0.01 ? 12 : 16));
        }
    }
    // A trial that never meets the tolerance (its force pushed 1e-5 of the
    // load away from the target): the fifth trial height in a row is solved
    // finally, and the balance ends on the final spring's height all the same.
    const wr::PatchSolver rough = [&](std::size_t, const wr::ContactPatch& p) {
        wr::PatchForces f;
        f.fn = k * p.approach;
        f.fn += f.fn < load ? -1e-5 * load : 1e-5 * load;
        return f;
    };
    wr::WheelsetPosition p;
    p.z = 20e-6;
    finals = 0;
    const wr::VerticalForceSolution s = wr::solve_vertical_position(g, load, p, {}, rough, exact);
    assert_close(s.z, load / k, 1e-6, 0);
    assert_true(s.fz == k * g.state().patches.at(0).approach);
    assert_int_equal(s.final_solves, finals);
    assert_true(s.final_solves >= 1 && s.evaluations <= 16);
}

// The Hertz estimate on a cylinder over a crown of the same radius r: a
// sphere-like contact, N = 4/3 E* sqrt(r) d^(3/2) (Johnson, eq. 4.23, for
// the relative radius r).
void test_hertz_estimate_sphere(void**)
{
    const double r = 0.46;
    const Cylinder cyl(r, r);
    wr::WheelRailGeometry g = cyl.geometry();
    wr::WheelsetPosition p;
    p.z = 30e-6;
    const wr::WheelRailState& st = g.evaluate(p, {});
    assert_int_equal(st.patches.size(), 1);
    const wr::HertzPatchEstimate hertz;
    const double e_star = hertz.G / (1.0 - hertz.nu);
    const double n = 4.0 / 3.0 * e_star * std::sqrt(r) * std::pow(p.z, 1.5);
    assert_close(hertz(st.patches[0]).fn, n, 1e-4, 0);
}

// Newton's method with the patch's own derivative: with the Hertz estimate
// on the sphere-like contact above, Fz = K z^(3/2) (the approach is z_ws,
// the estimate's dfn/d(approach) = 3/2 fn / approach), so g(z) = Fz^(2/3) -
// fz^(2/3) is linear in z and one Newton step from any height in contact
// lands on the answer: two evaluations. Without the derivative (fn_by_
// approach = 0), from below, the search steps down once more.
void test_newton_step_on_a_sphere(void**)
{
    const double r = 0.46;
    const Cylinder cyl(r, r);
    wr::WheelRailGeometry g = cyl.geometry();
    const wr::HertzPatchEstimate hertz;
    const double e_star = hertz.G / (1.0 - hertz.nu), load = 60e3;
    const double z = std::pow(load / (4.0 / 3.0 * e_star * std::sqrt(r)), 2.0 / 3.0); // Johnson eq. 4.23
    const wr::PatchSolver without = [&](std::size_t, const wr::ContactPatch& q) {
        wr::PatchForces f = hertz(q);
        f.fn_by_approach = 0.0;
        return f;
    };
    for (double start : {0.9 * z, 0.99 * z, 1.3 * z}) {
        wr::WheelsetPosition p;
        p.z = start;
        const wr::VerticalForceSolution s = wr::solve_vertical_position(g, load, p, {}, hertz);
        assert_close(s.fz, load, 1e-6, 0);
        assert_close(s.z, z, 1e-4, 0); // the estimate's N to 1e-4 (test_hertz_estimate_sphere)
        assert_int_equal(s.evaluations, 2);
        // from above, regula falsi on the linear g is exact too
        if (start < z) assert_int_equal(wr::solve_vertical_position(g, load, p, {}, without).evaluations, 3);
    }
}

// The benchmark at CONTACT's wheelset heights: the Hertz estimate of the
// normal force against CONTACT's non-Hertzian one, within 4 % wherever the
// patch is Hertz-like (all positions but the wide conformal patches at
// y_ws = 0, the near two-point contact at 0.5 mm and the two lobes at 5 mm
// on the right wheel, where Hertz is 13-33 % low). Then the balance:
// solving for 10 kN per wheel with the Hertz normal force and CONTACT's
// tangential forces (fixed), the heights are CONTACT's within 3 % of the
// approach at the Hertz-like positions (approach ~ force^(2/3): 4 % of force
// is 2.7 % of approach); the tangential forces carry up to 38 % of the load
// in flange contact (y_ws = 6.5 mm, right wheel).
bool hertz_like(const cwtest::Row& r)
{
    const double y = r.num("y_ws_mm");
    return !(y == 0.0 || (r.text("side") == "right" && (y == 0.5 || y == 5.0)));
}

void test_benchmark_heights(void**)
{
    cwtest::Benchmark b;
    wr::WheelRailGeometry right = b.geometry(wr::Side::right), left = b.geometry(wr::Side::left);
    const auto rows = cwtest::read_rows(cwtest::wheelrail_data("contact_a22_geometry.csv"));
    const wr::HertzPatchEstimate hertz;
    double worst_fn = 0.0, worst_z = 0.0;
    for (const cwtest::Row& r : rows) {
        wr::WheelRailGeometry& g = cwtest::side_of(r) == wr::Side::right ? right : left;
        wr::WheelsetPosition p = cwtest::position_of(r);
        const double z_contact = p.z;
        const wr::ContactPatch& cp = g.evaluate(p, cwtest::velocity_of(r)).patches.at(0);
        const double pen = cp.approach, ratio = hertz(cp).fn / r.num("fn");
        const wr::PatchSolver balance = [&](std::size_t, const wr::ContactPatch& q) {
            wr::PatchForces f = hertz(q);
            f.fx = r.num("fx");
            f.fs = r.num("fs");
            return f;
        };
        p.z = 0.0;
        const wr::VerticalForceSolution s = wr::solve_vertical_position(g, 1e4, p, cwtest::velocity_of(r), balance);
        assert_close(s.fz, 1e4, 1e-6, 0);
        if (!hertz_like(r)) {
            assert_true(ratio > 0.6 && ratio < 0.9);
            continue;
        }
        assert_close(ratio, 1.0, 0.04, 0);
        assert_close(s.z, z_contact, 0, 0.03 * pen);
        worst_fn = std::max(worst_fn, std::abs(ratio - 1.0));
        worst_z = std::max(worst_z, std::abs(s.z - z_contact) / pen);
    }
    std::printf("Hertz-like positions: Fn within %.2f %% of CONTACT's, height within %.2f %% of the "
                "approach\n", 100.0 * worst_fn, 100.0 * worst_z);
}

// The balance's later heights solve the wheel's surface on a patch grid from
// the last height's points (undeformed_distance with kept nodes): on the
// benchmark's wheel in tread (y = 3.7 mm) and flange contact (y = 7 mm),
// the wheel moved along track z by steps up to 1 mm on the same patch
// frame and grid, those solves give the undeformed distance of the solves
// from the rail within 1e-13 m (Newton's error after a last step d is
// about c d^2, c < 40 /m: below 4e-15 m after a step below 1e-8 m, while
// a step of 1 mm moves the start by up to 1e-4 m on the flange); a wheel
// also moved across the track (2 um) or along it is solved from the rail:
// the same bits as without kept points.
void test_later_heights_from_the_last_points(void**)
{
    const cwtest::Benchmark b;
    const wr::SearchOptions opt = b.options(0.5, 0.5);
    const wr::Side side = wr::Side::right;
    const wr::Profile rail = b.rail.placed(wr::place_rail(b.rail, b.track, side));
    const wr::ProfileTable table(b.wheel, 2e-5);
    const double R = b.wheelset.nominal_radius;
    wr::ContactSearch search(rail, b.wheel, opt, R);
    for (const double y : {3.7e-3, 7e-3}) {
        wr::WheelsetPosition pos;
        pos.y = y;
        pos.yaw = 0.004;
        pos.z = 0.1e-3;
        const wr::Frame wheel = wr::wheelset_in_track(pos, b.wheelset, side).compose(wr::wheel_in_wheelset(b.wheelset));
        std::vector<wr::Region> regions;
        search.find(wheel, regions);
        wr::combine_regions(regions, opt);
        assert_true(!regions.empty() && regions[0].gap_min < 0.0);
        double s_rail = 0.0;
        const wr::Frame ref = wr::contact_reference(regions[0], rail, s_rail);
        wr::PatchGrid grid;
        wr::potential_contact(regions[0], rail, s_rail, ref, opt, grid);
        assert_true(grid.nx > wr::WheelNodes::kPerRow && grid.ny > 4);
        wr::WheelNodes nodes;
        wr::PatchGrid warm = grid, cold = grid;
        wr::undeformed_distance(ref, rail, s_rail, table, wheel, R, warm, &nodes, false);
        double worst = 0.0;
        wr::Frame moved = wheel;
        for (const double dz : {1e-3, -0.4e-3, 2e-8, -0.6e-3}) {
            moved.o(2) += dz;
            wr::undeformed_distance(ref, rail, s_rail, table, moved, R, cold);
            wr::undeformed_distance(ref, rail, s_rail, table, moved, R, warm, &nodes, true);
            int in_contact = 0;
            for (std::size_t i = 0; i < cold.h.size(); ++i) {
                assert_close(warm.h[i], cold.h[i], 0, 1e-13);
                worst = std::max(worst, std::abs(warm.h[i] - cold.h[i]));
                in_contact += cold.h[i] < 0.0;
            }
            assert_true(in_contact > 0);
        }
        for (const int axis : {1, 0}) {
            moved.o(axis) += 2e-6;
            wr::undeformed_distance(ref, rail, s_rail, table, moved, R, cold);
            wr::undeformed_distance(ref, rail, s_rail, table, moved, R, warm, &nodes, true);
            assert_true(warm.h == cold.h);
        }
        std::printf("y = %.1f mm: h from the last height's points within %.1e m of the solve from the rail\n",
                    1e3 * y, worst);
    }
}

void test_errors(void**)
{
    const Cylinder cyl(0.46, 0.3);
    wr::WheelRailGeometry g = cyl.geometry();
    const wr::HertzPatchEstimate hertz;
    bool threw = false;
    try {
        wr::solve_vertical_position(g, -5.0, {}, {}, hertz);
    } catch (const creepwork::Error& e) {
        threw = std::string(e.what()).find("vertical force") != std::string::npos;
    }
    assert_true(threw);
    threw = false;
    try { // a solver that never pushes back
        wr::solve_vertical_position(g, 1e4, {}, {}, [](std::size_t, const wr::ContactPatch&) { return wr::PatchForces{}; });
    } catch (const creepwork::Error& e) {
        threw = e.kind() == creepwork::ErrorKind::not_converged || e.kind() == creepwork::ErrorKind::invalid_input;
    }
    assert_true(threw);
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_track_forces_against_contact),
        cmocka_unit_test(test_spring_solve),
        cmocka_unit_test(test_trial_and_final_solvers),
        cmocka_unit_test(test_hertz_estimate_sphere),
        cmocka_unit_test(test_newton_step_on_a_sphere),
        cmocka_unit_test(test_benchmark_heights),
        cmocka_unit_test(test_later_heights_from_the_last_points),
        cmocka_unit_test(test_errors),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
