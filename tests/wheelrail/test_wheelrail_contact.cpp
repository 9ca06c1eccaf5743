// The geometry against CONTACT's module 1 (v25.1, commit d431cdb) at the
// same wheelset positions: the Manchester benchmark case A-2.2 (21 lateral
// shifts x 2 wheels, CONTACT's own example) and 21 patches of 18 new cases
// with other shifts, yaw, roll, velocities, grids, cant, curvature, rail
// placement, patch separation and turned contact angles
// (tools/contact_reference/wheelrail). The
// vertical position is CONTACT's z_ws for 10-20 kN in full precision, so the
// comparison is of the geometry alone; CONTACT's reference point is its
// geometric weighted centre, fixed before its normal solution.
//
// Tolerances, from what differs by construction:
//  * positions 1e-5 m, angle 1e-4 rad: the reference point is a weighted
//    centre of the lateral gap samples; CONTACT interpolates the contact
//    locus with a spline through the wheel's knots, here Hermite with the
//    locus' exact slopes (3 um apart at a 70 deg flange contact, where
//    CONTACT's locus is 5 um off the exact one; < 1e-6 m elsewhere).
//  * creepages 1e-4 relative (2e-4 at contact angles beyond 1.2 rad,
//    through the 3 um above: d ceta / d x = omega sin(delta) / V).
//  * the approach (least h) 1 %: CONTACT samples the wheel surface every ds
//    and interpolates it bilinearly (an error of ds^2 kappa / 8, 0.2 um in
//    a flange root, 0.6 % of the approach); here the surface is solved.
//  * grid sizes and origins exactly; the number of patches exactly.
#include <cmath>
#include <cstdio>
#include <string>

#include "mbench_support.hpp"
#include "test_support.h"

namespace wr = creepwork::wheelrail;

namespace {

struct Worst {
    double pos = 0, angle = 0, creep = 0, approach_tread = 0, approach_flange = 0;
};

void compare_file(const char* file, Worst& w)
{
    cwtest::Benchmark b;
    const auto rows = cwtest::read_rows(cwtest::wheelrail_data(file));
    assert_true(rows.size() >= 17);
    for (const cwtest::Row& r : rows) {
        wr::WheelRailGeometry g = b.geometry(r);
        const wr::WheelRailState& st = g.evaluate(cwtest::position_of(r), cwtest::velocity_of(r));
        assert_int_equal(static_cast<int>(st.patches.size()), static_cast<int>(r.num("n_patches")));
        const wr::ContactPatch& p = st.patches.at(static_cast<size_t>(r.num("patch")) - 1);
        const double mm = 1e-3;
        const double pos[][2] = {{p.x_tr, r.num("xcp_tr")}, {p.y_tr, r.num("ycp_tr")}, {p.z_tr, r.num("zcp_tr")},
                                 {p.y_r, r.num("ycp_r")},   {p.z_r, r.num("zcp_r")},   {p.s_r, r.num("scp_r")},
                                 {p.x_w, r.num("xcp_w")},   {p.y_w, r.num("ycp_w")},   {p.z_w, r.num("zcp_w")},
                                 {p.x_ws, r.num("xcp_ws")}, {p.y_ws, r.num("ycp_ws")}, {p.z_ws, r.num("zcp_ws")}};
        for (const auto& q : pos) {
            assert_close(q[0], q[1] * mm, 0, 1e-5);
            w.pos = std::max(w.pos, std::abs(q[0] - q[1] * mm));
        }
        assert_close(p.delta, r.num("deltcp_tr"), 0, 1e-4);
        w.angle = std::max(w.angle, std::abs(p.delta - r.num("deltcp_tr")));
        const double rel = std::abs(p.delta) > 1.2 ? 2e-4 : 1e-4;
        const double creep[][2] = {{p.cksi, r.num("cksi")}, {p.ceta, r.num("ceta")}, {p.cphi * mm, r.num("cphi")}};
        for (const auto& q : creep) {
            assert_close(q[0], q[1], rel, 1e-10);
            if (std::abs(p.delta) <= 1.2)
                w.creep = std::max(w.creep, std::abs(q[0] - q[1]) / std::max(std::abs(q[1]), 1e-6));
        }
        assert_close(p.veloc, r.num("veloc") * mm, 1e-6, 0);
        assert_int_equal(p.nx, static_cast<int>(r.num("mx")));
        assert_int_equal(p.ny, static_cast<int>(r.num("my")));
        assert_close(p.x0, r.num("xc1") * mm, 0, 1e-12);
        assert_close(p.s0, r.num("yc1") * mm, 0, 1e-12);
        assert_close(p.dx, r.num("dx") * mm, 1e-12, 0);
        const double pen = r.num("pen") * mm, dpen = std::abs(p.approach - pen) / pen;
        assert_true(dpen < 1e-2);
        if (std::abs(p.delta) > 0.1)
            w.approach_flange = std::max(w.approach_flange, dpen);
        else
            w.approach_tread = std::max(w.approach_tread, dpen);
    }
}

void test_mbench_a22(void**)
{
    Worst w;
    compare_file("contact_a22_geometry.csv", w);
    std::printf("A-2.2 worst: position %.2e m, angle %.2e rad, creepage %.2e (|delta| <= 1.2), "
                "approach %.2e tread (|delta| <= 0.1), %.2e elsewhere\n",
                w.pos, w.angle, w.creep, w.approach_tread, w.approach_flange);
}

void test_new_cases(void**)
{
    Worst w;
    compare_file("contact_new_geometry.csv", w);
    std::printf("new cases worst: position %.2e m, angle %.2e rad, creepage %.2e (|delta| <= 1.2), "
                "approach %.2e tread (|delta| <= 0.1), %.2e elsewhere\n",
                w.pos, w.angle, w.creep, w.approach_tread, w.approach_flange);
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mbench_a22),
        cmocka_unit_test(test_new_cases),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
