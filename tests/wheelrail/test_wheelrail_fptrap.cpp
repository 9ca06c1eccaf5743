// The wheel/rail geometry under floating-point traps (invalid, divide by
// zero, overflow, denormal operand: what a legacy host turns on): every
// reference case of both CONTACT comparisons, the wheel lifted clear of the
// rail, and the vertical force balance. A trap ends the process naming the
// case (tests/robustness/fptrap_support.h).
#include <cstdio>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function" // the header serves several tests
#include "../robustness/fptrap_support.h"
#pragma GCC diagnostic pop
#include "mbench_support.hpp"
#include "wheelrail/hertz_patch.hpp"
#include "wheelrail/vertical_force.hpp"

namespace wr = creepwork::wheelrail;

int main()
{
    // profiles, tables and the rail sampling are made before the traps: the
    // evaluations are the host's hot path
    const cwtest::Benchmark b;
    const auto a22 = cwtest::read_rows(cwtest::wheelrail_data("contact_a22_geometry.csv"));
    const auto fresh = cwtest::read_rows(cwtest::wheelrail_data("contact_new_geometry.csv"));
    std::vector<wr::WheelRailGeometry> geometries;
    for (const auto* rows : {&a22, &fresh})
        for (const cwtest::Row& r : *rows) geometries.push_back(b.geometry(r));
    if (!fptrap_on()) {
        std::puts("floating-point traps are not available here");
        return FPTRAP_SKIP;
    }
    size_t k = 0;
    int patches = 0;
    for (const auto* rows : {&a22, &fresh})
        for (const cwtest::Row& r : *rows) {
            std::snprintf(fptrap_case, sizeof fptrap_case, "wheel/rail case %s", r.text("case").c_str());
            wr::WheelsetPosition p = cwtest::position_of(r);
            const wr::WheelsetVelocity v = cwtest::velocity_of(r);
            patches += static_cast<int>(geometries[k].evaluate(p, v).patches.size());
            p.z -= 2e-3; // lifted clear
            geometries[k].evaluate(p, v);
            p.z += 2e-3;
            if (k % 7 == 0) wr::solve_vertical_position(geometries[k], 1e4, p, v, wr::HertzPatchEstimate{});
            ++k;
        }
    std::printf("%zu rows, %d patches, no floating-point trap\n", k, patches);
    // 42 + 21 rows, one patch each but the six rows of the three two-patch
    // cases
    return k == 63 && patches == 69 ? 0 : 1;
}
