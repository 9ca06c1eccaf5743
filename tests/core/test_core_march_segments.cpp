// The march on a contact given element by element (MarchGeometry::
// set_contact): a mask and a traction bound from the caller instead of the
// ellipse, with strips of several separate contact segments -- what a model
// of non-Hertzian contact (a gap function's patch) hands the march.
//
// A model on such a patch is one class on MarchModel; PatchModel below is
// that class, and the tests run through it:
//  - two separated segments of one strip each give bitwise what a grid
//    holding only that segment gives (each is marched from its own leading
//    edge; the exterior elements between them reset the displacement), in
//    every kernel and with both step rules;
//  - the tractions and states equal a plain one-element-at-a-time
//    re-implementation of Kalker's step written here from the rule's
//    definition (steps and slip points computed independently of the grid
//    code: agreement to 1e-12, states exactly away from |q| = g);
//  - the ellipse given as a contact is the ellipse: bitwise FASTSIM's
//    march (CONTACT's steps);
//  - the work maps on the patch: zero outside the contact and in adhesion,
//    non-negative, summing to W_macro (the march's energy identity).
#include <cmath>
#include <cstring>
#include <vector>

#include "core_test_support.hpp"
#include "contact/error.hpp"
#include "fastsim/fastsim_model.hpp"
#include "march/march_model.hpp"
#include "test_support.h"

namespace cw = creepwork;

namespace {

// FASTSIM's setup and march on a contact given per element.
class PatchModel : public cw::MarchModel {
public:
    PatchModel(const cw::GridSpec& grid, bool leading_edges) : MarchModel(grid)
    {
        if (leading_edges) geometry().march_from_leading_edges(this->grid());
    }
    // inside and shape in the grid's march order [m * ny + j].
    void set_patch(const std::vector<double>& inside, const std::vector<double>& shape)
    {
        geometry().set_contact(grid(), inside.data(), shape.data());
    }
    cw::SolveTotals solve(const cw::ContactInput& input, cw::SolveMode mode) override
    {
        const cw::ModelSetup setup = cw::make_model_setup(input);
        begin(setup, geometry().shape_given.data(), geometry().max_given);
        if (mode == cw::SolveMode::full)
            march_with_work();
        else
            march();
        return totals(input, mode, cw::ModelKind::fastsim);
    }
    cw::SolveTotals solve_jacobian(const cw::ContactInput&, cw::SolveMode, cw::Jacobian&) override
    {
        throw cw::Error(cw::ErrorKind::invalid_input, "no Jacobian");
    }
};

constexpr int kNx = 30, kNy = 12;

// Strip j's segments [first, last) along the march (m = 0 at the leading
// edge), or empty: strip 5 holds none, strip 0 only the first, strip 11
// only the second, every other both, with 3 exterior elements between.
struct Segment {
    int first, last;
};
Segment first_segment(int j)
{
    if (j == 5 || j == 11) return {0, 0};
    return {2 + j % 3, 11};
}
Segment second_segment(int j)
{
    if (j == 5 || j == 0) return {0, 0};
    return {14, 26 - j % 4};
}

// A bound shape that varies along and across the strips, > 0.
double bound_shape(int m, int j)
{
    const double s = std::sin(0.7 * m + 0.3 * j);
    return 0.3 + 0.6 * s * s;
}

// Mask and shape in march order with the chosen segments (1: first, 2:
// second, 3: both).
void patch(int which, std::vector<double>& inside, std::vector<double>& shape)
{
    inside.assign(static_cast<size_t>(kNx) * kNy, 0.0);
    shape.assign(inside.size(), 0.0);
    for (int j = 0; j < kNy; ++j)
        for (int pick = 1; pick <= 2; ++pick) {
            if (!(which & pick)) continue;
            const Segment s = pick == 1 ? first_segment(j) : second_segment(j);
            for (int m = s.first; m < s.last; ++m) {
                const size_t k = static_cast<size_t>(m) * kNy + j;
                inside[k] = 1.0;
                shape[k] = bound_shape(m, j);
            }
        }
}

// Which of the two segments element (m, j) belongs to, 0 for none.
int segment_of(int m, int j)
{
    const Segment a = first_segment(j), b = second_segment(j);
    if (m >= a.first && m < a.last) return 1;
    if (m >= b.first && m < b.last) return 2;
    return 0;
}

// Partial slip with spin on a square ellipse: both adhesion and slip in
// every segment long enough, rolling towards +x.
cw::ContactInput contact()
{
    cw::ContactInput in = cwtest::steel_contact(1.0);
    in.xi_x = 2.5e-3;
    in.xi_y = -1.5e-3;
    in.phi = 1.5;
    return in;
}

const cw::KernelIsa kIsas[] = {cw::KernelIsa::baseline, cw::KernelIsa::avx2,
                               cw::KernelIsa::avx512};

// Field f of the last solve, in the caller's layout [i + j nx].
std::vector<double> field(const PatchModel& model, cw::Field f)
{
    std::vector<double> out(static_cast<size_t>(kNx) * kNy);
    cw::export_field(model.solved(), f, out.data());
    return out;
}
std::vector<int> states(const PatchModel& model)
{
    std::vector<int> out(static_cast<size_t>(kNx) * kNy);
    cw::export_state(model.solved(), out.data());
    return out;
}

// Caller index of march element (m, j), rolling towards +x (leading edge at
// +x: m = 0 is i = nx - 1).
size_t caller_index(int m, int j)
{
    return static_cast<size_t>(kNx - 1 - m) + static_cast<size_t>(j) * kNx;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void two_segments_march_as_two_grids(void**)
{
    std::vector<double> inside[4], shape[4];
    for (int which : {1, 2, 3}) patch(which, inside[which], shape[which]);
    const cw::GridSpec spec = cwtest::uniform_grid(kNx, kNy);
    int compared = 0, slipping = 0, adhering = 0;
    for (bool leading_edges : {false, true})
        for (cw::KernelIsa isa : kIsas) {
            if (!cw::kernel_isa_supported(isa)) continue;
            PatchModel both(spec, leading_edges), one(spec, leading_edges);
            both.set_kernel_isa(isa);
            one.set_kernel_isa(isa);
            both.set_patch(inside[3], shape[3]);
            both.solve(contact(), cw::SolveMode::forces_only);
            const auto px = field(both, cw::Field::px), py = field(both, cw::Field::py);
            const auto st = states(both);
            for (int which : {1, 2}) {
                one.set_patch(inside[which], shape[which]);
                one.solve(contact(), cw::SolveMode::forces_only);
                const auto px1 = field(one, cw::Field::px), py1 = field(one, cw::Field::py);
                const auto st1 = states(one);
                for (int j = 0; j < kNy; ++j)
                    for (int m = 0; m < kNx; ++m) {
                        if (segment_of(m, j) != which) continue;
                        const size_t c = caller_index(m, j);
                        assert_true(same_bits(px[c], px1[c]));
                        assert_true(same_bits(py[c], py1[c]));
                        assert_int_equal(st[c], st1[c]);
                        slipping += st[c] == 2;
                        adhering += st[c] == 1;
                        ++compared;
                    }
            }
            // Between and beside the segments: exterior, no traction.
            for (int j = 0; j < kNy; ++j)
                for (int m = 0; m < kNx; ++m)
                    if (segment_of(m, j) == 0) {
                        const size_t c = caller_index(m, j);
                        assert_int_equal(st[c], 0);
                        assert_true(px[c] == 0.0 && py[c] == 0.0);
                    }
        }
    printf("  %d elements compared, %d in slip, %d in adhesion\n", compared, slipping, adhering);
    assert_true(compared > 0 && slipping > 0 && adhering > 0);
}

// Kalker's step, one element at a time, on mask 3 (both segments): p = 0 at
// every exterior element; in a segment q = p_prev - h (wx, wy + cy x_slip),
// p = q if |q| <= g, else g q/|q|. CONTACT's rule: h = dx and x_slip the
// element centre; from the leading edges: the segment's first step h = dx/2
// (from its first element's front edge), the others h = dx, x_slip the
// midpoint of each step.
void segments_match_the_plain_step(void**)
{
    std::vector<double> inside, shape;
    patch(3, inside, shape);
    const cw::GridSpec spec = cwtest::uniform_grid(kNx, kNy);
    const cw::ContactInput in = contact();
    const cw::ModelSetup s = cw::make_model_setup(in);
    const double dx = 2.0 / kNx, dy = 2.0 / kNy; // box scale 1: [-1, 1]^2 in X, Y
    for (bool leading_edges : {false, true}) {
        PatchModel model(spec, leading_edges);
        model.set_patch(inside, shape);
        model.solve(in, cw::SolveMode::forces_only);
        const auto px = field(model, cw::Field::px), py = field(model, cw::Field::py);
        const auto st = states(model);
        int checked_states = 0;
        for (int j = 0; j < kNy; ++j) {
            const double Y = -1.0 + (j + 0.5) * dy;
            const double wx = s.kin.ux - s.kin.cx * Y;
            double p_x = 0.0, p_y = 0.0;
            bool starts = true;
            for (int m = 0; m < kNx; ++m) {
                const size_t c = caller_index(m, j);
                if (segment_of(m, j) == 0) {
                    p_x = p_y = 0.0;
                    starts = true;
                    continue;
                }
                const double X = 1.0 - (m + 0.5) * dx;
                const double h = leading_edges && starts ? 0.5 * dx : dx;
                const double x_slip = leading_edges ? X + 0.5 * h : X;
                starts = false;
                const double g = bound_shape(m, j);
                const double qx = p_x - h * wx;
                const double qy = p_y - h * (s.kin.uy + s.kin.cy * x_slip);
                const double norm = std::hypot(qx, qy);
                const double f = norm > g ? g / norm : 1.0;
                p_x = f * qx;
                p_y = f * qy;
                const double T = s.traction_scale;
                assert_close(px[c], T * p_x, 1e-12, 1e-12 * T);
                assert_close(py[c], T * p_y, 1e-12, 1e-12 * T);
                if (std::fabs(norm - g) > 1e-9 * g) {
                    assert_int_equal(st[c], norm > g ? 2 : 1);
                    ++checked_states;
                }
            }
        }
        assert_true(checked_states > 100);
    }
}

// The grid's own ellipse given as a contact: the totals, every field and
// the states are bitwise FASTSIM's (CONTACT's steps; the leading-edge rule
// differs by design: a given contact has no chord end).
void ellipse_given_as_a_contact_is_the_ellipse(void**)
{
    for (const cw::GridSpec& spec :
         {cwtest::uniform_grid(20, 20), cwtest::uniform_grid(37, 23, 1.07)}) {
        const cw::ContactGrid grid(spec);
        const Eigen::ArrayXd& in = grid.in_contact();
        const Eigen::ArrayXd& shape = grid.pressure_shape(cw::PressureKind::parabolic);
        PatchModel given(spec, false);
        given.set_patch(std::vector<double>(in.data(), in.data() + in.size()),
                        std::vector<double>(shape.data(), shape.data() + shape.size()));
        cw::FastsimModel fastsim(spec);
        const cw::SolveTotals a = given.solve(contact(), cw::SolveMode::full);
        const cw::SolveTotals b = fastsim.solve(contact(), cw::SolveMode::full);
        const double ta[] = {a.Fx, a.Fy, a.Mz, a.W_macro, a.W_micro_paper, a.W_consistent,
                             a.balance_factor, a.p_max, a.profile_max_diff};
        const double tb[] = {b.Fx, b.Fy, b.Mz, b.W_macro, b.W_micro_paper, b.W_consistent,
                             b.balance_factor, b.p_max, b.profile_max_diff};
        for (size_t k = 0; k < sizeof ta / sizeof ta[0]; ++k) assert_true(same_bits(ta[k], tb[k]));
        assert_int_equal(a.n_contact, b.n_contact);
        assert_int_equal(a.n_slip, b.n_slip);
        const size_t n = static_cast<size_t>(spec.nx) * spec.ny;
        std::vector<double> fa(n), fb(n);
        for (int f = 0; f <= static_cast<int>(cw::Field::work_consistent); ++f) {
            cw::export_field(given.solved(), static_cast<cw::Field>(f), fa.data());
            cw::export_field(fastsim.solved(), static_cast<cw::Field>(f), fb.data());
            assert_memory_equal(fa.data(), fb.data(), n * sizeof(double));
        }
        std::vector<int> sa(n), sb(n);
        cw::export_state(given.solved(), sa.data());
        cw::export_state(fastsim.solved(), sb.data());
        assert_memory_equal(sa.data(), sb.data(), n * sizeof(int));
        assert_true(b.n_slip > 0 && b.n_slip < b.n_contact);
    }
}

// The work maps on the two-segment patch: the energy-consistent map is zero
// outside the contact and in adhesion, non-negative, and sums to W_macro
// (the march's discrete energy identity holds segment by segment: each
// ends with its exit energy released at the exterior element after it).
void work_on_segments(void**)
{
    std::vector<double> inside, shape;
    patch(3, inside, shape);
    for (bool leading_edges : {false, true}) {
        PatchModel model(cwtest::uniform_grid(kNx, kNy), leading_edges);
        model.set_patch(inside, shape);
        const cw::SolveTotals t = model.solve(contact(), cw::SolveMode::full);
        assert_int_equal(t.work_flags, 0);
        const auto w = field(model, cw::Field::work_consistent);
        const auto st = states(model);
        double sum = 0.0;
        for (size_t c = 0; c < w.size(); ++c) {
            assert_true(w[c] >= 0.0);
            if (st[c] != 2) assert_true(w[c] == 0.0);
            sum += w[c];
        }
        assert_true(t.W_macro > 0.0);
        assert_close(sum, t.W_macro, 1e-9, 0.0);
        assert_close(t.W_consistent, t.W_macro, 1e-9, 0.0);
        int contact_elements = 0;
        for (double v : inside) contact_elements += v != 0.0;
        assert_int_equal(t.n_contact, contact_elements);
    }
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(two_segments_march_as_two_grids),
        cmocka_unit_test(segments_match_the_plain_step),
        cmocka_unit_test(ellipse_given_as_a_contact_is_the_ellipse),
        cmocka_unit_test(work_on_segments),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
