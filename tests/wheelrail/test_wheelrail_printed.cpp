// The geometry against CONTACT's printed benchmark results as they ship
// (tests/data/nonhertz/mbench_a22.csv, parsed from CONTACT's
// examples/mbench_a22_*.ref_out): at the printed wheelset height z_ws (4
// decimals in mm), every printed geometric quantity -- the number of
// patches, the contact location in track, rail and wheel coordinates, the
// contact angle, the creepages, the reference velocity, the potential
// contact's element count -- agrees to within what the printing allows:
// half a unit of the last printed digit, plus the quantity's change over
// the +-0.5e-4 mm by which the printed z_ws may differ from CONTACT's
// (found here by evaluating at z_ws +- 0.5e-4 mm), plus the agreement at
// CONTACT's exact z_ws (test_wheelrail_contact: 0.2 um, 1 urad, 3e-5
// relative for the creepages).
#include <cmath>
#include <cstdio>
#include <string>

#include "mbench_support.hpp"
#include "test_support.h"

namespace wr = creepwork::wheelrail;

namespace {

// Half a unit of the last digit of a printed number ("-5.665E-05", "751.8726", "2000.").
double half_ulp(const std::string& text)
{
    const size_t e = text.find_first_of("eE");
    const std::string mant = text.substr(0, e);
    const size_t dot = mant.find('.');
    const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mant.size() - dot - 1);
    const int exponent = e == std::string::npos ? 0 : std::stoi(text.substr(e + 1));
    return 0.5 * std::pow(10.0, exponent - decimals);
}

struct Quantity {
    const char* column;
    double scale; // printed unit in SI
    double (*get)(const wr::ContactPatch&);
    double agree_abs = 0.0, agree_rel = 0.0; // agreement at CONTACT's exact z_ws
};

const Quantity kQuantities[] = {
    {"xcp_tr_mm", 1e-3, [](const wr::ContactPatch& p) { return p.x_tr; }, 2e-7, 0},
    {"ycp_tr_mm", 1e-3, [](const wr::ContactPatch& p) { return p.y_tr; }, 2e-7, 0},
    {"zcp_tr_mm", 1e-3, [](const wr::ContactPatch& p) { return p.z_tr; }, 2e-7, 0},
    {"deltcp_rad", 1.0, [](const wr::ContactPatch& p) { return p.delta; }, 1e-6, 0},
    {"ycp_r_mm", 1e-3, [](const wr::ContactPatch& p) { return p.y_r; }, 2e-7, 0},
    {"zcp_r_mm", 1e-3, [](const wr::ContactPatch& p) { return p.z_r; }, 2e-7, 0},
    {"xcp_w_mm", 1e-3, [](const wr::ContactPatch& p) { return p.x_w; }, 2e-7, 0},
    {"ycp_w_mm", 1e-3, [](const wr::ContactPatch& p) { return p.y_w; }, 2e-7, 0},
    {"zcp_w_mm", 1e-3, [](const wr::ContactPatch& p) { return p.z_w; }, 2e-7, 0},
    {"veloc_mm_s", 1e-3, [](const wr::ContactPatch& p) { return p.veloc; }, 1e-6, 0},
    {"cksi", 1.0, [](const wr::ContactPatch& p) { return p.cksi; }, 0, 3e-5},
    {"ceta", 1.0, [](const wr::ContactPatch& p) { return p.ceta; }, 0, 3e-5},
    {"cphi_rad_mm", 1e3, [](const wr::ContactPatch& p) { return p.cphi; }, 0, 3e-5},
};

void test_printed_a22(void**)
{
    cwtest::Benchmark b;
    wr::WheelRailGeometry right = b.geometry(wr::Side::right), left = b.geometry(wr::Side::left);
    const auto rows = cwtest::read_rows(cwtest::contact_benchmark_results("mbench_a22.csv"));
    assert_int_equal(rows.size(), 42);
    int checked = 0;
    double worst = 0.0; // |difference| / tolerance
    for (const cwtest::Row& r : rows) {
        wr::WheelRailGeometry& g = r.text("wheel") == "right" ? right : left;
        wr::WheelsetPosition p;
        p.y = r.num("y_ws_mm") * 1e-3;
        p.z = r.num("z_ws_mm") * 1e-3;
        p.roll = r.num("roll_rad");
        p.yaw = r.num("yaw_rad");
        wr::WheelsetVelocity v;
        v.vs = r.num("vs_mm_s") * 1e-3;
        v.vpitch = r.num("vpitch_rad_s");
        const double dz = half_ulp(r.text("z_ws_mm")) * 1e-3;
        wr::ContactPatch at[3];
        for (int k = 0; k < 3; ++k) {
            wr::WheelsetPosition q = p;
            q.z += (k - 1) * dz;
            const wr::WheelRailState& st = g.evaluate(q, v);
            assert_int_equal(static_cast<int>(st.patches.size()), static_cast<int>(r.num("n_patches")));
            at[k] = st.patches.at(0);
        }
        for (const Quantity& q : kQuantities) {
            const double printed = r.num(q.column) * q.scale;
            const double mine = q.get(at[1]);
            const double sens = std::max(std::abs(q.get(at[2]) - mine), std::abs(q.get(at[0]) - mine));
            const double tol =
                half_ulp(r.text(q.column)) * q.scale + sens + q.agree_abs + q.agree_rel * std::abs(printed);
            if (std::abs(mine - printed) > tol)
                std::printf("%s %s: %.10g printed %.10g (tolerance %.3g)\n", r.text("wheel").c_str(),
                            q.column, mine, printed, tol);
            assert_true(std::abs(mine - printed) <= tol);
            worst = std::max(worst, std::abs(mine - printed) / tol);
            ++checked;
        }
        const int npot = at[1].nx * at[1].ny;
        assert_true(npot == static_cast<int>(r.num("npot")) ||
                    npot != at[0].nx * at[0].ny || npot != at[2].nx * at[2].ny);
    }
    // values near a rounding midpoint use up their half unit: the largest
    // ratio is near 1 by construction
    std::printf("%d printed values checked; the largest difference is %.2f of its tolerance\n", checked, worst);
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_printed_a22),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
