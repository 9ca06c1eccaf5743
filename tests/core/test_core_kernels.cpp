// The kernels (core/march/march.hpp): the march and the work pass are compiled
// for SSE2, AVX2 and AVX-512 and a solver picks one per CPU. Each wider
// kernel must give bitwise the baseline's totals, fields, states and profile
// (results are bitwise reproducible whatever the CPU); and the march, with its
// exact adhesion shortcut, must give bitwise what the plain one-element-at-
// a-time FASTSIM step of Kalker 1982 gives.
//
// What this proves: the SIMD arithmetic and the shortcut. Both comparisons
// run on the grid's own geometry (steps, slip points, pressure shapes), so a
// wrong grid would pass here; the geometry is checked against the
// independent FORTRAN 77 FASTSIM (tests/fortran) and CONTACT's rows.
//
// usage: test_core_kernels            ISA-independent checks
//        test_core_kernels avx2|avx512 that kernel against the baseline;
//                                      exit 77 (CTest SKIP) if this CPU
//                                      cannot run it
#include <cstring>
#include <string>
#include <vector>

#include "core_test_support.hpp"
#include "contact/error.hpp"
#include "gap_shape_grid.hpp"
#include "test_support.h"

namespace cw = creepwork;

namespace {

const cw::KernelIsa kIsas[] = {cw::KernelIsa::baseline, cw::KernelIsa::avx2,
                               cw::KernelIsa::avx512};
constexpr int kSkip = 77; // SKIP_RETURN_CODE in tests/core/CMakeLists.txt
cw::KernelIsa g_isa = cw::KernelIsa::baseline; // the kernel under test

std::vector<cw::GridSpec> grids()
{
    return {cwtest::kalker_grid(1, 1),     cwtest::kalker_grid(7, 13),
            cwtest::kalker_grid(20, 20),   cwtest::kalker_grid(33, 17),
            cwtest::uniform_grid(20, 20),  cwtest::uniform_grid(37, 23, 1.07),
            cwtest::uniform_grid(9, 30, 2.5)};
}

// Partial and full slip, spin, elliptic pressure, both rolling directions,
// one flexibility, no creepage (no slip anywhere).
std::vector<cw::ContactInput> inputs()
{
    std::vector<cw::ContactInput> v;
    auto add = [&](double ab, double xi, double eta, double phi) -> cw::ContactInput& {
        cw::ContactInput in = cwtest::steel_contact(ab);
        in.xi_x = xi;
        in.xi_y = eta;
        in.phi = phi;
        v.push_back(in);
        return v.back();
    };
    add(1.0, 6e-4, 3e-4, 0.2);
    add(1.3, 1e-2, 5e-3, 2.0);
    add(0.2, 1e-3, -4e-4, 3.0).pressure = cw::PressureKind::elliptic;
    add(5.0, 0.0, 0.0, 2.0).rolling_direction = -1;
    cw::ContactInput& single = add(1.7, 7e-4, 4e-4, 0.6);
    single.flexibility = cw::FlexibilitySource::given;
    single.L1 = single.L2 = single.L3 = 5e-14;
    add(1.0, 0.0, 0.0, 0.0);
    return v;
}

// Everything a solve returns, as raw bytes.
std::string outputs(cw::Solver& s, const cw::ContactInput& in, cw::SolveMode mode)
{
    const cw::SolveTotals t = s.solve(in, mode);
    std::string bytes(reinterpret_cast<const char*>(&t), sizeof t);
    const size_t n = static_cast<size_t>(s.grid().nx()) * s.grid().ny();
    std::vector<double> field(n, -1.0);
    for (int f = 0; f <= static_cast<int>(cw::Field::work_consistent); ++f) {
        if (!s.has_work() && cw::Solver::needs_work(static_cast<cw::Field>(f))) continue;
        s.copy_field(static_cast<cw::Field>(f), field.data());
        bytes.append(reinterpret_cast<const char*>(field.data()), n * sizeof(double));
        std::fill(field.begin(), field.end(), 0.5);
        s.add_field(static_cast<cw::Field>(f), 0.37, field.data());
        bytes.append(reinterpret_cast<const char*>(field.data()), n * sizeof(double));
    }
    std::vector<int> state(n, -1);
    s.copy_state(state.data());
    bytes.append(reinterpret_cast<const char*>(state.data()), n * sizeof(int));
    if (s.has_work()) {
        const size_t ny = static_cast<size_t>(s.grid().ny());
        std::vector<double> y(ny), w(ny), p(ny);
        s.copy_profile(y.data(), w.data(), p.data());
        for (const auto* v : {&y, &w, &p})
            bytes.append(reinterpret_cast<const char*>(v->data()), ny * sizeof(double));
    }
    return bytes;
}

// g_isa against the baseline, every grid, input and mode.
void kernel_gives_the_baseline_bits(void**)
{
    assert_true(g_isa != cw::KernelIsa::baseline);
    size_t compared = 0;
    for (const cw::GridSpec& g : grids()) {
        cw::Solver reference(g);
        reference.set_kernel_isa(cw::KernelIsa::baseline);
        cw::Solver s(g);
        s.set_kernel_isa(g_isa);
        assert_true(s.kernel_isa() == g_isa);
        for (const cw::ContactInput& in : inputs())
            for (cw::SolveMode mode : {cw::SolveMode::forces_only, cw::SolveMode::full}) {
                const std::string a = outputs(reference, in, mode);
                const std::string b = outputs(s, in, mode);
                assert_int_equal(a.size(), b.size());
                assert_true(std::memcmp(a.data(), b.data(), a.size()) == 0);
                ++compared;
            }
    }
    assert_int_equal(compared, grids().size() * inputs().size() * 2);
}

// FASTSIM with a law of the slip speed at every element (the law's SIMD
// march, fastsim/march_law.hpp, with its vectorised exp): g_isa against the
// baseline, bitwise, every grid and creeping input, each form of the law
// (two terms), forces and every field, then the Jacobian.
void law_kernel_gives_the_baseline_bits(void**)
{
    assert_true(g_isa != cw::KernelIsa::baseline);
    size_t compared = 0;
    for (const cw::GridSpec& g : grids()) {
        cw::Solver reference(g), s(g);
        reference.set_kernel_isa(cw::KernelIsa::baseline);
        s.set_kernel_isa(g_isa);
        for (cw::ContactInput in : inputs())
            for (cw::FrictionLaw law : {cw::FrictionLaw::linear, cw::FrictionLaw::rational,
                                        cw::FrictionLaw::exponential}) {
                if (in.xi_x == 0.0 && in.phi == 0.0) continue;
                in.friction_law = law;
                in.V = 20.0;
                in.mu_e1 = 0.1;
                in.s_h1 = 0.05;
                in.mu_e2 = 0.05;
                in.s_h2 = 0.01;
                const std::string a = outputs(reference, in, cw::SolveMode::forces_only);
                const std::string b = outputs(s, in, cw::SolveMode::forces_only);
                assert_int_equal(a.size(), b.size());
                assert_true(std::memcmp(a.data(), b.data(), a.size()) == 0);
                cw::Jacobian ja, jb;
                reference.solve_jacobian(in, cw::SolveMode::forces_only, ja);
                s.solve_jacobian(in, cw::SolveMode::forces_only, jb);
                assert_true(std::memcmp(&ja, &jb, sizeof ja) == 0);
                ++compared;
            }
    }
    size_t creeping = 0;
    for (const cw::ContactInput& in : inputs()) creeping += in.xi_x != 0.0 || in.phi != 0.0;
    assert_int_equal(compared, grids().size() * creeping * 3);
}

// The same on gap grids: the fast model (FASTSIM with the semi-Hertzian
// normal method, whose roots are a kernel) and the exact model (which starts
// from that method), on shapes of one and of several patches, force and
// approach prescribed, both rolling directions.
void gap_kernel_gives_the_baseline_bits(void**)
{
    size_t compared = 0;
    for (const gapshapes::Shape& sh : gapshapes::shapes()) {
        if (sh.id != "N03_three_lobes" && sh.id != "N08_approach" && sh.id != "N10_tall_cells")
            continue;
        cw::ContactInput in = gapshapes::contact_input(sh);
        in.xi_x = 4e-4;
        in.xi_y = -3e-4;
        in.phi = 0.5;
        in.warm_start = false;
        cw::Solver reference(gapshapes::grid_of(sh));
        reference.set_kernel_isa(cw::KernelIsa::baseline);
        cw::Solver s(gapshapes::grid_of(sh));
        s.set_kernel_isa(g_isa);
        for (cw::ModelKind model : {cw::ModelKind::fastsim, cw::ModelKind::exact})
            for (int direction : {1, -1}) {
                in.model = model;
                in.normal_method = model == cw::ModelKind::fastsim ? cw::NormalMethod::semi_hertz
                                                                   : cw::NormalMethod::exact;
                in.rolling_direction = direction;
                const std::string a = outputs(reference, in, cw::SolveMode::full);
                const std::string b = outputs(s, in, cw::SolveMode::full);
                assert_int_equal(a.size(), b.size());
                assert_true(std::memcmp(a.data(), b.data(), a.size()) == 0);
                ++compared;
            }
    }
    assert_int_equal(compared, 3 * 2 * 2);
}

void best_kernel_is_the_default(void**)
{
    const cw::Solver s(cwtest::kalker_grid(4, 4));
    assert_true(s.kernel_isa() == cw::best_kernel_isa());
    assert_true(cw::kernel_isa_supported(cw::best_kernel_isa()));
    printf("  default kernel: %s\n", cw::kernel_isa_name(s.kernel_isa()));
}

bool refused(cw::KernelIsa isa)
{
    cw::Solver s(cwtest::kalker_grid(4, 4));
    try {
        s.set_kernel_isa(isa);
    } catch (const cw::Error& e) {
        return e.kind() == cw::ErrorKind::invalid_input && s.kernel_isa() == cw::best_kernel_isa();
    }
    return false;
}

// A kernel the CPU cannot run is refused, and the solver keeps its own. A
// value outside the enumeration is never supported, so the refusal is
// checked on every machine (on one with AVX-512 no real ISA is refused).
void unsupported_kernel_is_refused(void**)
{
    assert_false(cw::kernel_isa_supported(static_cast<cw::KernelIsa>(99)));
    assert_true(refused(static_cast<cw::KernelIsa>(99)));
    for (cw::KernelIsa isa : kIsas)
        if (!cw::kernel_isa_supported(isa)) assert_true(refused(isa));
}

// The plain FASTSIM step, one element at a time in march order (Kalker
// 1982): the kernels vectorise it across strips and skip the square root
// where no lane can slip, which must change no bit of px, py or the state.
// It takes the steps, slip points and bounds from the grid itself, so it
// checks the kernels' arithmetic, not the geometry (see the top).
void march_matches_the_plain_step(void**)
{
    for (const cw::GridSpec& g : grids())
        for (const cw::ContactInput& in : inputs()) {
            cw::Solver s(g);
            s.solve(in, cw::SolveMode::forces_only);
            const cw::ContactGrid& grid = s.grid();
            const cw::ModelSetup setup = cw::make_model_setup(in);
            const int nx = grid.nx(), ny = grid.ny();
            const double dT = setup.direction * setup.traction_scale;
            const auto px = cwtest::field(s, cw::Field::px), py = cwtest::field(s, cw::Field::py);
            const auto st = cwtest::states(s);
            for (int j = 0; j < ny; ++j) {
                double p_x = 0.0, p_y = 0.0;
                for (int m = 0; m < nx; ++m) {
                    const long k = static_cast<long>(m) * ny + j;
                    const double h = grid.step()[k], inside = grid.in_contact()[k];
                    const double bound = grid.pressure_shape(setup.pressure)[k];
                    const double qx =
                        inside * (p_x - h * (setup.kin.ux - setup.kin.cx * grid.y_centre()[j]));
                    const double qy =
                        inside * (p_y - h * (setup.kin.uy + setup.kin.cy * grid.x_slip()[k]));
                    const double norm = std::sqrt(qx * qx + qy * qy);
                    const bool slip = norm > bound;
                    const double f = slip ? bound / std::fmax(norm, 2.2250738585072014e-308) : 1.0;
                    p_x = f * qx;
                    p_y = f * qy;
                    const int i = setup.direction > 0 ? nx - 1 - m : m;
                    const size_t c = static_cast<size_t>(i) + static_cast<size_t>(j) * nx;
                    const double expected_x = dT * (f * qx);
                    const double expected_y = setup.traction_scale * (f * qy);
                    assert_true(std::memcmp(&px[c], &expected_x, sizeof expected_x) == 0);
                    assert_true(std::memcmp(&py[c], &expected_y, sizeof expected_y) == 0);
                    assert_int_equal(st[c], inside == 0.0 ? 0 : slip ? 2 : 1);
                }
            }
        }
}

} // namespace

int main(int argc, char** argv)
{
    if (argc > 1) {
        bool known = false;
        for (cw::KernelIsa isa : kIsas)
            if (isa != cw::KernelIsa::baseline && std::strcmp(argv[1], cw::kernel_isa_name(isa)) == 0) {
                g_isa = isa;
                known = true;
            }
        if (!known) {
            fprintf(stderr, "test_core_kernels: unknown kernel '%s'\n", argv[1]);
            return 2;
        }
        if (!cw::kernel_isa_supported(g_isa)) {
            printf("kernel %s: not supported by this CPU: SKIP\n", argv[1]);
            return kSkip;
        }
        const struct CMUnitTest tests[] = {cmocka_unit_test(kernel_gives_the_baseline_bits),
                                           cmocka_unit_test(law_kernel_gives_the_baseline_bits),
                                           cmocka_unit_test(gap_kernel_gives_the_baseline_bits)};
        return cmocka_run_group_tests(tests, nullptr, nullptr);
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(best_kernel_is_the_default),
        cmocka_unit_test(unsupported_kernel_is_refused),
        cmocka_unit_test(march_matches_the_plain_step),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
