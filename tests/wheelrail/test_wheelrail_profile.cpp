// Wheel and rail profiles: the readers (SIMPACK, MiniProf, table), the
// spline through the points and the checks with their line-numbered errors.
#include <cmath>
#include <sstream>
#include <string>

#include "contact/error.hpp"
#include "test_support.h"
#include "wheelrail/profile_io.hpp"

namespace wr = creepwork::wheelrail;

namespace {

std::string data(const char* name) { return std::string(CW_WHEELRAIL_DATA) + "/" + name; }

// The message of the error a call throws ("" if it throws none).
template <class F> std::string error_of(F f)
{
    try {
        f();
    } catch (const creepwork::Error& e) {
        return e.what();
    }
    return "";
}

void assert_mentions(const std::string& message, const char* part)
{
    if (message.find(part) == std::string::npos) {
        print_error("message \"%s\" does not mention \"%s\"\n", message.c_str(), part);
        fail();
    }
}

wr::Profile table(const std::string& text, wr::ProfileKind kind, wr::ProfileReadOptions o = {})
{
    std::istringstream in(text);
    return wr::read_profile(in, kind, wr::ProfileFormat::table, "t.txt", o);
}

// Points on a circle of radius r [mm] around (0, r): a rail head (z down).
std::string circle_rail(double r, int n, double half_angle)
{
    std::ostringstream o;
    o.precision(17);
    for (int i = 0; i < n; ++i) {
        const double a = -half_angle + 2.0 * half_angle * i / (n - 1);
        o << r * std::sin(a) << " " << r - r * std::cos(a) << "\n";
    }
    return o.str();
}

// The Manchester benchmark profiles as CONTACT reads them: the files' own
// options (wheel: mirror.y = 1, inversion = 1), lengths in mm (units.len.f
// 1000), canonical order. Knot counts from the files (the wheel's first
// point is commented out); ends and the rail top from the data.
void test_mbench_profiles(void**)
{
    const wr::Profile rail = wr::read_profile_file(data("MBench_UIC60_v3.prr"), wr::ProfileKind::rail);
    const wr::Profile wheel = wr::read_profile_file(data("MBench_S1002_v3.prw"), wr::ProfileKind::wheel);
    assert_int_equal(rail.size(), 495);
    assert_int_equal(wheel.size(), 399);
    assert_close(rail.knots_y().front(), -43.704898e-3, 0, 1e-12);
    assert_close(rail.knots_z().front(), 38.510726e-3, 0, 1e-12);
    // wheel: field side first, y mirrored (file y = -60 mm is y = +60 mm)
    assert_close(wheel.knots_y().front(), 60e-3, 0, 1e-12);
    assert_close(wheel.knots_z().front(), -2.6356764e-3, 0, 1e-12);
    assert_close(wheel.knots_y().back(), -69.612628e-3, 0, 1e-12);
    // the spline interpolates every point
    for (int i = 0; i < rail.size(); i += 7) {
        const auto p = rail.at(rail.knots_s()[i]);
        assert_close(p.y, rail.knots_y()[i], 0, 1e-15);
        assert_close(p.z, rail.knots_z()[i], 0, 1e-15);
    }
    // s = 0 at y = 0 (monotone y), chord length along the curve
    double s = 0.0;
    assert_true(rail.visible_s_at_y(0.0, s));
    assert_close(s, 0.0, 0, 1e-9);
    // the top of the rail is the visible surface: z at y = -0.18441236 mm is
    // the data's least z, 6.0323487e-05 mm
    assert_true(rail.visible_s_at_y(-0.18441236e-3, s));
    assert_close(rail.at(s).z, 6.0323487e-8, 0, 1e-12);
    // the wheel's visible surface is its bottom: the flange tip at file
    // y = 54.892493 mm, z = 27.999518 mm
    assert_true(wheel.visible_s_at_y(-54.892493e-3, s));
    assert_close(wheel.at(s).z, 27.999518e-3, 0, 1e-10);
}

// The same rail from CONTACT's MiniProf copy (y mirrored; its quoted points
// are excluded measurements): the same surface wherever both have points.
void test_miniprof_equals_simpack(void**)
{
    wr::ProfileReadOptions o;
    o.mirror_y = true;
    const wr::Profile ban = wr::read_profile_file(data("MBench_UIC60_v3.ban"), wr::ProfileKind::rail, o);
    const wr::Profile prr = wr::read_profile_file(data("MBench_UIC60_v3.prr"), wr::ProfileKind::rail);
    assert_true(ban.size() < prr.size());
    double max_diff = 0.0;
    for (double y = -35e-3; y <= 25e-3; y += 0.37e-3) {
        double sa = 0.0, sb = 0.0;
        assert_true(ban.visible_s_at_y(y, sa));
        assert_true(prr.visible_s_at_y(y, sb));
        max_diff = std::max(max_diff, std::abs(ban.at(sa).z - prr.at(sb).z));
    }
    // the knots differ only near the ends: the splines agree in the head
    // to rounding of the interpolation (1 nm)
    assert_true(max_diff < 1e-9);
}

// A circle sampled every 1 mm: the natural spline reproduces its curvature
// and position between the points (interpolation error ~ h^4/(384 r^3)).
void test_spline_on_circle(void**)
{
    const double r = 300.0; // mm
    const wr::Profile p = table(circle_rail(r, 61, 0.1), wr::ProfileKind::rail);
    double worst_pos = 0.0, worst_curv = 0.0;
    for (double y = -25e-3; y <= 25e-3; y += 0.123e-3) {
        double s = 0.0;
        assert_true(p.visible_s_at_y(y, s));
        const auto q = p.at(s);
        const double r_m = r * 1e-3;
        const double z_exact = r_m - std::sqrt(r_m * r_m - q.y * q.y);
        worst_pos = std::max(worst_pos, std::abs(q.z - z_exact));
        const double curv = (q.dy * q.d2z - q.dz * q.d2y) / std::pow(q.dy * q.dy + q.dz * q.dz, 1.5);
        if (std::abs(y) <= 20e-3) worst_curv = std::max(worst_curv, std::abs(curv * r_m - 1.0));
    }
    // natural end conditions (zero curvature) disturb the first points; 5 mm
    // in, the error has decayed to below 1 nm
    assert_true(worst_pos < 1e-9);   // [m]
    assert_true(worst_curv < 1e-4);  // relative, 10 points in from the ends
    // inclination at y = 10 mm: atan(dz/dy) = asin(y/r)
    double s = 0.0;
    assert_true(p.visible_s_at_y(10e-3, s));
    assert_close(p.inclination(s), std::asin(10.0 / r), 0, 1e-6);
}

// Measured MiniProf wheels from CONTACT's test bank: a clean one reads
// (664 points in the file, z already downwards); one with stitching
// zig-zags is refused at the first bad point met in canonical order (the
// file runs flange back to field side, so from its end): an 82 deg kink at
// line 227; with kinks up to 86 deg accepted, the zig-zag of lines 222-224
// (the profile turns back).
void test_measured_miniprof_wheels(void**)
{
    const wr::Profile w = wr::read_profile_file(data("right-wheel-v1-pre-dry.whl"), wr::ProfileKind::wheel);
    assert_int_equal(w.size(), 664);
    assert_true(w.knots_y().front() > w.knots_y().back());
    const std::string e = error_of([] { wr::read_profile_file(data("Car7216_0001r.whl"), wr::ProfileKind::wheel); });
    assert_mentions(e, "Car7216_0001r.whl line 227: kink");
    wr::ProfileReadOptions o;
    o.checks.kink_angle = 1.5; // 86 deg: the turn back remains
    const std::string e2 = error_of([&] { wr::read_profile_file(data("Car7216_0001r.whl"), wr::ProfileKind::wheel, o); });
    assert_mentions(e2, "line 223: the profile turns back");
}

void test_table_reader(void**)
{
    // comma separated, a header line, comments; reversed order is put right
    const wr::Profile p = table("y,z\n# a comment\n" + std::string("10, 1\n5,0.25\n0,0\n-5,0.25\n-10,1\n"),
                                wr::ProfileKind::rail);
    assert_int_equal(p.size(), 5);
    assert_close(p.knots_y().front(), -10e-3, 0, 1e-15);
    wr::ProfileReadOptions m;
    m.length_unit = 1.0; // metres
    const std::string err = error_of([&] { table("0 0\n1 0.1\n2 0.3\n3 0.6\n", wr::ProfileKind::rail, m); });
    assert_mentions(err, "units");
}

void test_errors_name_the_line(void**)
{
    using K = wr::ProfileKind;
    const std::string head = "# rail\n";
    // duplicate point (line 4)
    std::string e = error_of([&] { table(head + "-10 1\n-5 0.25\n-5 0.25\n0 0\n5 0.25\n10 1\n", K::rail); });
    assert_mentions(e, "t.txt line 4");
    assert_mentions(e, "duplicate");
    // kink of 45 degrees at (-5, 0), line 3 (slope 0 to slope 1)
    e = error_of([&] { table(head + "-10 0\n-5 0\n0 5\n5 10\n10 15\n", K::rail); });
    assert_mentions(e, "t.txt line 3");
    assert_mentions(e, "kink");
    // points out of order: a step back
    e = error_of([&] { table(head + "-10 1\n-5 0.25\n0 0\n-2 0.1\n5 0.25\n10 1\n", K::rail); });
    assert_mentions(e, "turns back");
    // accepted kink: a corner of the spline, no error
    wr::ProfileReadOptions o;
    o.checks.accept_kinks = true;
    const wr::Profile v = table(head + "-10 10\n-5 5\n0 0\n5 5\n10 10\n", K::rail, o);
    assert_int_equal(v.size(), 5);
    // upside down rail (head as a valley in z)
    e = error_of([&] { table(head + circle_rail(-50.0, 41, 0.5), K::rail); });
    assert_mentions(e, "upside down");
    // a bad number
    e = error_of([&] { table(head + "-10 1\n-5 0.25\n0 x\n", K::rail); });
    assert_mentions(e, "t.txt line 4");
    // SIMPACK: a rail file read as a wheel
    e = error_of([&] { wr::read_profile_file(data("MBench_UIC60_v3.prr"), K::wheel); });
    assert_mentions(e, "header type must be 1");
    std::istringstream bad("header.begin\n type = 0\nspline.begin\n");
    e = error_of([&] { wr::read_profile(bad, K::rail, wr::ProfileFormat::simpack, "x.prr"); });
    assert_mentions(e, "x.prr line 3");
    e = error_of([&] { wr::read_profile_file(data("no_such_profile.prr"), K::rail); });
    assert_mentions(e, "cannot open");
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mbench_profiles),
        cmocka_unit_test(test_miniprof_equals_simpack),
        cmocka_unit_test(test_spline_on_circle),
        cmocka_unit_test(test_measured_miniprof_wheels),
        cmocka_unit_test(test_table_reader),
        cmocka_unit_test(test_errors_name_the_line),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
