// The core raises no floating-point exception, in any vector lane of any
// kernel (SSE2, AVX2, AVX-512, each forced with Solver::set_kernel_isa),
// for valid inputs of practical magnitude -- and makes no subnormal number
// there. It runs with the traps a legacy host turns on (invalid, zero,
// overflow, denormal operand) and WITHOUT the C ABI's floating-point mode
// (capi/capi_fp_mode.hpp), so it proves the core's own arithmetic clean:
// the ABI's mode then changes no result in this range. A trap ends the
// process with the case that raised it (fptrap_support.h).
#include "fptrap_support.h"

#include <string>
#include <vector>

#include "contact/error.hpp"
#include "fastsim/kalker_normalised.hpp"
#include "solver.hpp"
#include "test_support.h"

namespace cw = creepwork;

namespace {

const cw::KernelIsa kKernels[] = {cw::KernelIsa::baseline, cw::KernelIsa::avx2,
                                  cw::KernelIsa::avx512};

cw::ContactInput input_of(const fptrap_contact_t& c)
{
    cw::ContactInput in;
    in.a = c.a;
    in.b = c.b;
    in.normal_force = 80e3;
    in.mu = 0.3;
    in.G = 82e9;
    in.nu = 0.28;
    in.xi_x = c.xi_x;
    in.xi_y = c.xi_y;
    in.phi = c.phi;
    in.pressure = c.pressure ? cw::PressureKind::elliptic : cw::PressureKind::parabolic;
    in.rolling_direction = c.rolling_direction;
    in.spin_offset = c.contact_options ? 1.0 / 6.0 : -1.0;
    in.flexibility_blending = c.contact_options != 0;
    return in;
}

// Solves in both modes and reads every field, state and profile out.
long solve_and_read(cw::Solver& s, const cw::ContactInput& in, std::vector<double>& out,
                    std::vector<int>& states, std::vector<double>& strips)
{
    const int ny = s.grid().ny();
    s.solve(in, cw::SolveMode::forces_only);
    s.copy_state(states.data());
    s.solve(in, cw::SolveMode::full);
    for (int f = 0; f <= static_cast<int>(cw::Field::work_consistent); ++f)
        s.copy_field(static_cast<cw::Field>(f), out.data());
    s.copy_state(states.data());
    s.copy_profile(strips.data(), strips.data() + ny, strips.data() + 2 * ny);
    return 2;
}

cw::GridSpec spec_of(const fptrap_grid& g)
{
    cw::GridSpec spec;
    spec.kind = g.kind ? cw::GridKind::uniform : cw::GridKind::kalker_strips;
    spec.nx = g.nx;
    spec.ny = g.ny;
    spec.box_scale = g.box_scale;
    return spec;
}

void test_contact_sweep_every_kernel(void**)
{
    long solves = 0;
    int kernels = 0;
    for (cw::KernelIsa isa : kKernels) {
        if (!cw::kernel_isa_supported(isa)) continue;
        ++kernels;
        for (int gi = 0; gi < FPTRAP_GRIDS; ++gi) {
            const fptrap_grid& g = fptrap_grids[gi];
            cw::Solver s(spec_of(g));
            s.set_kernel_isa(isa);
            std::vector<double> out(static_cast<size_t>(g.nx) * g.ny), strips(3 * g.ny);
            std::vector<int> states(out.size());
            assert_true(fptrap_enable());
            for (int k = 0; k < FPTRAP_CONTACTS; ++k) {
                const fptrap_contact_t c = fptrap_contact(k);
                snprintf(fptrap_case, sizeof fptrap_case,
                         "kernel %s, grid kind %d %dx%d, a %g b %g xi (%g, %g) phi %g "
                         "pressure %d direction %d options %d",
                         cw::kernel_isa_name(isa), g.kind, g.nx, g.ny, c.a, c.b, c.xi_x, c.xi_y,
                         c.phi, c.pressure, c.rolling_direction, c.contact_options);
                solves += solve_and_read(s, input_of(c), out, states, strips);
                // FASTSIM's march with a law of the slip speed at every
                // element (its own kernel, fastsim/march_law.cpp, with its exp).
                cw::ContactInput law = input_of(c);
                law.friction_law = cw::FrictionLaw::exponential;
                law.mu = 0.12;
                law.mu_e1 = 0.18;
                law.s_h1 = 0.5;
                law.V = 20.0;
                solves += solve_and_read(s, law, out, states, strips);
            }
            const int flags = fptrap_flags();
            fptrap_disable();
            if (flags != 0) print_error("grid %d: flags %#x raised\n", gi, flags);
            assert_int_equal(flags, 0); // not even underflow: no subnormal made
        }
    }
    print_message("%ld solves (both modes, every field read) in %d kernels, traps on\n", solves,
                  kernels);
    assert_true(kernels >= 1);
}

// Every combination of size, load, modulus and friction in the practical
// range, both flexibility sources, a few creepages: as above.
void test_physical_magnitudes_every_kernel(void**)
{
    long solves = 0;
    for (cw::KernelIsa isa : kKernels) {
        if (!cw::kernel_isa_supported(isa)) continue;
        for (int kind = 0; kind < 2; ++kind) {
            const fptrap_grid g = {kind, 8, 7, 1.0};
            cw::Solver s(spec_of(g));
            s.set_kernel_isa(isa);
            std::vector<double> out(56), strips(21);
            std::vector<int> states(56);
            assert_true(fptrap_enable());
            for (double size : fptrap_sizes)
                for (double load : fptrap_loads)
                    for (double G : fptrap_moduli)
                        for (double mu : fptrap_frictions)
                            for (int flex = 0; flex < 2; ++flex)
                                for (double xi : {1e-100, 1e-12, 1e-3, 1.0, 1e6})
                                    for (int options = 0; options < 2; ++options) {
                                        cw::ContactInput in;
                                        in.a = size;
                                        in.b = 2.0 * size;
                                        in.normal_force = load;
                                        in.mu = mu;
                                        in.G = G;
                                        in.nu = 0.28;
                                        if (flex) {
                                            in.flexibility = cw::FlexibilitySource::given;
                                            in.L1 = 2.0 * size / G;
                                            in.L2 = 3.0 * size / G;
                                            in.L3 = 2.5 * size / G;
                                        }
                                        in.xi_x = xi;
                                        in.xi_y = -0.7 * xi;
                                        in.phi = 0.3 * xi / size;
                                        in.spin_offset = options ? 1.0 / 6.0 : -1.0;
                                        in.flexibility_blending = options != 0;
                                        snprintf(fptrap_case, sizeof fptrap_case,
                                                 "kernel %s, kind %d, a %g N %g G %g mu %g "
                                                 "flex %d xi %g options %d",
                                                 cw::kernel_isa_name(isa), kind, size, load, G,
                                                 mu, flex, xi, options);
                                        solves += solve_and_read(s, in, out, states, strips);
                                    }
            const int flags = fptrap_flags();
            fptrap_disable();
            assert_int_equal(flags, 0);
        }
    }
    print_message("%ld solves over physical magnitudes, traps on\n", solves);
}

// Kalker's 1982 normalised call on its own strip layouts.
void test_kalker_normalised_every_layout(void**)
{
    long calls = 0;
    assert_true(fptrap_enable());
    for (double ux : {0.0, 1e-6, 0.3, -2.0, 50.0})
        for (double uy : {0.0, -0.4, 3.0})
            for (double f : {0.0, 1e-9, 0.5, -4.0})
                for (int m : {1, 5, 20}) {
                    snprintf(fptrap_case, sizeof fptrap_case, "normalised %g %g %g mx=my=%d", ux,
                             uy, f, m);
                    cw::kalker_fastsim_normalised(ux, uy, f, 2.0 * f, m, m, 1e-3);
                    ++calls;
                }
    const int flags = fptrap_flags();
    fptrap_disable();
    assert_int_equal(flags, 0);
    print_message("%ld normalised calls, traps on\n", calls);
}

} // namespace

int main()
{
    // No way to trap here (not glibc on x86-64): SKIP, not a pass.
    const int available = fptrap_enable();
    fptrap_disable();
    if (!available) return FPTRAP_SKIP;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_contact_sweep_every_kernel),
        cmocka_unit_test(test_physical_magnitudes_every_kernel),
        cmocka_unit_test(test_kalker_normalised_every_layout),
    };
    return cmocka_run_group_tests_name("robustness_fptrap_kernels", tests, nullptr, nullptr);
}
