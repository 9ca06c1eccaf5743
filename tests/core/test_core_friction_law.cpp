// The friction-law hook (core/contact/friction_law.hpp) on its own:
//  - the constant law, written as a law of the slip speed, gives Coulomb's
//    bits: its bound at every slip speed, and the projections and their
//    derivatives at that bound (vector and scalar forms);
//  - the projection against its definition: p = q in adhesion (bitwise),
//    |p| = g along q in slip (to 4 ulp), the vector form's decisions and
//    values equal to the scalar form's (the same operations);
//  - both derivative forms against central differences of the projection
//    (step 1e-6 |q|, agreement 1e-7 of |dp|: the difference's truncation
//    is O(h^2) of a smooth map away from |q| = g), and against each other
//    (1e-14: the same formula in two roundings);
//  - a change of the bound alone (dg/g) moves p by p dg/g (central
//    differences in g).
#include <cfloat>
#include <cmath>
#include <cstring>
#include <random>

#include "contact/friction_law.hpp"
#include "test_support.h"

namespace cw = creepwork;

namespace {

constexpr int W = 2;
using V = cw::simd::Vec<W>;

V pair(double a, double b)
{
    double d[W] = {a, b};
    return cw::simd::load<W>(d);
}
double lane(const V& v, int l)
{
    double d[W];
    cw::simd::store<W>(d, v);
    return d[l];
}
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Sample {
    double qx, qy, g;
};

// Trial tractions in adhesion and slip around bounds from 1e-3 to 1e3.
Sample sample(std::mt19937_64& rng)
{
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double g = std::pow(10.0, 3.0 * u(rng));
    const double r = g * (1.0 + 0.9 * u(rng)), t = 3.14159265358979 * u(rng);
    return {r * std::cos(t), r * std::sin(t), g};
}

void constant_law_gives_coulomb_bits(void**)
{
    std::mt19937_64 rng(35);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int n = 0; n < 10000; ++n) {
        const double mu = u(rng), p = 1e9 * u(rng), s = 10.0 * u(rng);
        const cw::CoulombLaw coulomb{mu};
        const cw::ConstantLaw constant{mu};
        const double gc = cw::traction_bound(coulomb, p), gk = cw::traction_bound(constant, p, s);
        assert_true(same_bits(gc, gk));
        assert_true(same_bits(gc, mu * p)); // mu applied once, as the models did
        assert_true(coulomb.slope(s) == 0.0 && constant.slope(s) == 0.0);

        // The projection at either law's bound, in both forms.
        const Sample q = sample(rng);
        double cx = q.qx, cy = q.qy, kx = q.qx, ky = q.qy;
        const cw::ScalarProjection sc = cw::project_traction(cx, cy, q.g * gc);
        const cw::ScalarProjection sk = cw::project_traction(kx, ky, q.g * gk);
        assert_true(sc.slips == sk.slips && same_bits(cx, kx) && same_bits(cy, ky));
        const auto vc = cw::project_traction<W>(pair(q.qx, -q.qy), pair(q.qy, q.qx),
                                                cw::simd::broadcast<W>(q.g * gc));
        const auto vk = cw::project_traction<W>(pair(q.qx, -q.qy), pair(q.qy, q.qx),
                                                cw::simd::broadcast<W>(q.g * gk));
        for (int l = 0; l < W; ++l)
            assert_true(same_bits(lane(vc.px, l), lane(vk.px, l)) &&
                        same_bits(lane(vc.py, l), lane(vk.py, l)) &&
                        same_bits(lane(vc.f, l), lane(vk.f, l)));
    }
}

void projection_meets_the_bound(void**)
{
    std::mt19937_64 rng(7);
    int slips = 0;
    for (int n = 0; n < 20000; ++n) {
        const Sample q = sample(rng);
        double px = q.qx, py = q.qy;
        const cw::ScalarProjection s = cw::project_traction(px, py, q.g);
        const double norm = std::hypot(q.qx, q.qy);
        if (norm < q.g * (1 - 1e-12)) {
            assert_false(s.slips);
            assert_true(same_bits(px, q.qx) && same_bits(py, q.qy));
        } else if (norm > q.g * (1 + 1e-12)) {
            ++slips;
            assert_true(s.slips);
            assert_close(std::hypot(px, py), q.g, 0.0, 4 * DBL_EPSILON * q.g);
            // along q: the cross product vanishes, the dot product is positive
            assert_close(px * q.qy - py * q.qx, 0.0, 0.0, 4 * DBL_EPSILON * q.g * norm);
            assert_true(px * q.qx + py * q.qy > 0.0);
        }
        // The vector form: the same decision and bits in each lane.
        const auto v = cw::project_traction<W>(pair(q.qx, 0.0), pair(q.qy, 0.0),
                                               pair(q.g, q.g));
        assert_true((lane(v.slip, 0) == 1.0) == s.slips && lane(v.slip, 1) == 0.0);
        assert_true(v.any_slip == s.slips);
        assert_true(same_bits(lane(v.px, 0), px) && same_bits(lane(v.py, 0), py));
        assert_true(lane(v.px, 1) == 0.0 && lane(v.f, 1) == 1.0); // q = 0: f = 1, p = 0
    }
    assert_true(slips > 5000 && slips < 15000); // both branches tested
    // No bound (exterior): any q projects to zero, without a division by zero.
    double px = 3.0, py = -4.0;
    const cw::ScalarProjection s = cw::project_traction(px, py, 0.0);
    assert_true(s.slips && px == 0.0 && py == 0.0);
}

// p(q) of the scalar form, for differences.
void project(double qx, double qy, double g, double& px, double& py)
{
    px = qx;
    py = qy;
    cw::project_traction(px, py, g);
}

void derivatives_match_differences(void**)
{
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int tested = 0;
    for (int n = 0; n < 5000; ++n) {
        const Sample q = sample(rng);
        const double norm = std::hypot(q.qx, q.qy);
        if (std::fabs(norm / q.g - 1.0) < 1e-3) continue; // no kink inside the step
        ++tested;
        const double dqx = u(rng), dqy = u(rng), h = 1e-6 * norm;
        double pxp, pyp, pxm, pym;
        project(q.qx + h * dqx, q.qy + h * dqy, q.g, pxp, pyp);
        project(q.qx - h * dqx, q.qy - h * dqy, q.g, pxm, pym);
        const double fx = (pxp - pxm) / (2 * h), fy = (pyp - pym) / (2 * h);
        const double tol = 1e-7 * (std::fabs(dqx) + std::fabs(dqy));

        // The scalar form (slip only; dp = dq in adhesion).
        double px = q.qx, py = q.qy;
        const cw::ScalarProjection s = cw::project_traction(px, py, q.g);
        double sx = dqx, sy = dqy;
        if (s.slips) cw::projection_derivative(s, q.qx / s.norm, q.qy / s.norm, sx, sy);
        assert_close(sx, fx, 0.0, tol);
        assert_close(sy, fy, 0.0, tol);

        // The vector form, r = f/g^2 in slip and 0 in adhesion.
        const auto v = cw::project_traction<W>(cw::simd::broadcast<W>(q.qx),
                                               cw::simd::broadcast<W>(q.qy),
                                               cw::simd::broadcast<W>(q.g));
        const V r = v.slip * v.f * cw::simd::broadcast<W>(1.0 / (q.g * q.g));
        V vx, vy;
        cw::projection_derivative<W>(v, r, cw::simd::broadcast<W>(dqx),
                                     cw::simd::broadcast<W>(dqy), vx, vy);
        assert_close(lane(vx, 0), sx, 0.0, 1e-14 * (std::fabs(dqx) + std::fabs(dqy)));
        assert_close(lane(vy, 1), sy, 0.0, 1e-14 * (std::fabs(dqx) + std::fabs(dqy)));

        // A change of the bound alone: dp = p dg/g in slip, 0 in adhesion.
        const double dg = 1e-6 * q.g;
        project(q.qx, q.qy, q.g + dg, pxp, pyp);
        project(q.qx, q.qy, q.g - dg, pxm, pym);
        V bx, by;
        const V zero = cw::simd::broadcast<W>(0.0);
        cw::projection_derivative<W>(v, r, zero, zero, v.slip * cw::simd::broadcast<W>(1.0 / q.g),
                                     bx, by);
        assert_close(lane(bx, 0), (pxp - pxm) / (2 * dg), 0.0, 1e-7);
        assert_close(lane(by, 0), (pyp - pym) / (2 * dg), 0.0, 1e-7);
    }
    assert_true(tested > 4000);
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(constant_law_gives_coulomb_bits),
        cmocka_unit_test(projection_meets_the_bound),
        cmocka_unit_test(derivatives_match_differences),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
