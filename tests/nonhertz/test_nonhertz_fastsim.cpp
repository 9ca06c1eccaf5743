// FASTSIM on a gap grid (gap/gap_fastsim_model.hpp) through the core's
// Solver:
//  - against the exact model (Kalker's exact theory on the same gap, the
//    source of every accuracy bound here) on the DEV shapes of
//    tests/data/nonhertz/dev and the shapes of gap_shapes.hpp, with
//    the semi-Hertzian normal method (the fast path) and with the exact
//    normal problem (FASTSIM's tangential part alone);
//  - the march on an elliptic patch with the ellipse's flexibilities is the
//    uniform grid's FASTSIM march (an identity, to rounding);
//  - moving a contact across the grid with the spin's translation taken
//    into the lateral creepage changes nothing but Mz's transfer term (the
//    spin about each patch's centroid);
//  - patches add up to the totals; the work maps sum to W_macro, are >= 0
//    and zero in adhesion; rolling towards -x mirrors; errors name inputs.
// `test_nonhertz_fastsim --markdown` prints the accuracy table of
// doc/validation/non-hertzian.md (scripts/doc-tables.sh pastes and checks it).
#include "ellipse_march.hpp"
#include "gap_shape_grid.hpp"
#include "gap_shapes.hpp"
#include "gap_test_support.hpp"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "contact/error.hpp"
#include "gap/gap_march.hpp"

namespace cw = creepwork;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Worst errors over the shapes, as fractions.
struct Worst {
    double fast_force = 0, fast_mz = 0, fast_area = 0, fast_mz_rel = 0;
    double march_force = 0, march_mz = 0;
    std::string fast_force_id, fast_mz_rel_id;
};

std::string pct(double v, bool sign = false)
{
    char b[16];
    std::snprintf(b, sizeof b, sign ? "%+.1f" : "%.1f", 100.0 * v);
    return b;
}

// The exact model, FASTSIM with the semi-Hertzian normal method and FASTSIM
// with the exact normal problem on one case; appends the table's row.
void compare(const std::string& id, const cw::GridSpec& g, cw::ContactInput in, Worst& w,
             std::string& table)
{
    in.warm_start = false;
    in.model = cw::ModelKind::exact;
    in.normal_method = cw::NormalMethod::exact;
    cw::Solver s(g);
    const cw::SolveTotals e = s.solve(in, cw::SolveMode::forces_only);
    in.model = cw::ModelKind::fastsim;
    const cw::SolveTotals m = s.solve(in, cw::SolveMode::forces_only);
    in.normal_method = cw::NormalMethod::semi_hertz;
    const cw::SolveTotals f = s.solve(in, cw::SolveMode::forces_only);
    const double muN = in.mu * e.normal_force;
    const double c = std::sqrt(e.n_contact * g.dx * g.dy / kPi);
    auto force = [&](const cw::SolveTotals& t) {
        return std::max(std::fabs(t.Fx - e.Fx), std::fabs(t.Fy - e.Fy)) / muN;
    };
    auto moment = [&](const cw::SolveTotals& t) { return std::fabs(t.Mz - e.Mz) / (muN * c); };
    const double area = double(f.n_contact) / e.n_contact - 1.0;
    // Mz relative to itself where it is not small (|Mz| >= 0.01 mu N c).
    const bool mz_counts = std::fabs(e.Mz) >= 0.01 * muN * c;
    const double mz_rel = mz_counts ? std::fabs(f.Mz / e.Mz - 1.0) : 0.0;
    table += "| " + id + " | " + pct(area, true) + " | " + pct(force(f)) + " | " + pct(moment(f)) +
             " | " + (mz_counts ? pct(mz_rel) : std::string("-")) + " | " + pct(force(m)) + " | " +
             pct(moment(m)) + " |\n";
    if (force(f) > w.fast_force) w.fast_force = force(f), w.fast_force_id = id;
    w.fast_mz = std::max(w.fast_mz, moment(f));
    w.fast_area = std::max(w.fast_area, std::fabs(area));
    if (mz_rel > w.fast_mz_rel) w.fast_mz_rel = mz_rel, w.fast_mz_rel_id = id;
    w.march_force = std::max(w.march_force, force(m));
    w.march_mz = std::max(w.march_mz, moment(m));
}

cw::ContactInput input_of(const gapshapes::Shape& s)
{
    cw::ContactInput in = gapshapes::contact_input(s);
    in.model = cw::ModelKind::fastsim;
    in.warm_start = false;
    return in;
}

const gapshapes::Shape& shape(const std::string& id)
{
    static const std::vector<gapshapes::Shape> all = gapshapes::shapes();
    for (const gapshapes::Shape& s : all)
        if (s.id == id) return s;
    throw std::runtime_error("no shape " + id);
}

Worst run_all(std::string& table)
{
    table = "| case | area | forces / mu N | Mz / (mu N c) | Mz / Mz | exact normal: forces / mu N | "
            "exact normal: Mz / (mu N c) |\n|---|---:|---:|---:|---:|---:|---:|\n";
    Worst w;
    for (const cwtest::GapCase& c : cwtest::dev_cases()) compare(c.id, c.gap.grid, c.bind(), w, table);
    const cwtest::CsvTable t =
        cwtest::read_quoted_csv(std::string(CW_NONHERTZ_DATA_DIR) + "/contact_cases.csv");
    const std::vector<gapshapes::Shape> shapes = gapshapes::shapes();
    for (size_t r = 0; r < shapes.size(); ++r) {
        cw::ContactInput in = input_of(shapes[r]);
        in.xi_x = t.number(r, "xi_x");
        in.xi_y = t.number(r, "xi_y");
        in.phi = t.number(r, "phi_per_m");
        compare(shapes[r].id, gapshapes::grid_of(shapes[r]), in, w, table);
    }
    char b[256];
    std::snprintf(b, sizeof b, "| worst | %s | %s | %s | %s | %s | %s |\n",
                  ("±" + pct(w.fast_area)).c_str(), pct(w.fast_force).c_str(),
                  pct(w.fast_mz).c_str(), pct(w.fast_mz_rel).c_str(), pct(w.march_force).c_str(),
                  pct(w.march_mz).c_str());
    table += b;
    return w;
}

// The march on the uniform grid's elliptic contact, with its parabolic
// pressure and the ellipse's flexibilities (one patch, spin about the
// ellipse's centre = its centroid by symmetry), is FASTSIM's march on that
// grid (CONTACT's steps: one element, the slip at the element centre):
// the same numbers to rounding (sums in another order).
void march_is_fastsim_on_an_ellipse(void**)
{
    const int nx = 24, ny = 18;
    cw::ContactInput e = cwtest::steel_contact(1.4);
    e.xi_x = 4e-4;
    e.xi_y = -3e-4;
    e.phi = 0.8;
    cw::Solver fastsim(cwtest::uniform_grid(nx, ny, 1.0));
    const cw::SolveTotals te = fastsim.solve(e, cw::SolveMode::full);
    const auto px = cwtest::field(fastsim, cw::Field::px), py = cwtest::field(fastsim, cw::Field::py);
    const cwtest::EllipseMarch march(fastsim, te, e);
    const cw::GapMarchInput& in = march.in;
    const std::vector<double>& pz = march.pz;
    std::vector<std::complex<double>> p(pz.size()), s(pz.size()), w(pz.size());
    std::vector<signed char> state(pz.size());
    cw::GapMarchTotals t; // the one patch's
    cw::gap_march(in, {p.data(), s.data(), w.data(), state.data(), &t});
    const double muN = e.mu * e.normal_force;
    print_message("march vs FASTSIM: dFx %.2g, dFy %.2g mu N, dMz %.2g mu N a\n",
                  (t.Fx - te.Fx) / muN, (t.Fy - te.Fy) / muN, (t.Mz - te.Mz) / (muN * e.a));
    assert_close(t.Fx, te.Fx, 0.0, 1e-12 * muN);
    assert_close(t.Fy, te.Fy, 0.0, 1e-12 * muN);
    assert_close(t.Mz, te.Mz, 0.0, 1e-12 * muN * e.a);
    assert_int_equal(t.n_contact, te.n_contact);
    assert_int_equal(t.n_slip, te.n_slip);
    assert_true(te.n_slip > 0 && te.n_adhesion > 0);
    const double scale = e.mu * te.p_max;
    for (size_t k = 0; k < pz.size(); ++k) {
        assert_close(p[k].real(), px[k], 0.0, 1e-12 * scale);
        assert_close(p[k].imag(), py[k], 0.0, 1e-12 * scale);
    }
}

// The contact moved across the grid by (X, Y) (the grid's origin moved,
// the gap values kept) with the spin's translation taken into the
// creepages (xi + phi Y, eta - phi X) sees the same rigid slip: the same
// forces, Mz + X Fy - Y Fx (to rounding). With the spin about the grid's
// origin instead of each patch's centroid FASTSIM's L3 would scale that
// translation and the forces would change.
void moving_the_contact_changes_only_the_transfer_term(void**)
{
    for (const char* id : {"N04_crescent", "N03_three_lobes"}) {
        const gapshapes::Shape& s = shape(id);
        cw::ContactInput in = input_of(s);
        in.normal_method = cw::NormalMethod::semi_hertz;
        in.xi_x = 2e-4;
        in.xi_y = -1e-4;
        in.phi = 0.6;
        cw::Solver a(gapshapes::grid_of(s));
        const cw::SolveTotals ta = a.solve(in, cw::SolveMode::full);
        const double X = 7.0 * s.dx, Y = -3.0 * s.dy;
        cw::GridSpec g = gapshapes::grid_of(s);
        g.x0 += X;
        g.y0 += Y;
        cw::ContactInput im = in;
        im.xi_x = in.xi_x + in.phi * Y;
        im.xi_y = in.xi_y - in.phi * X;
        cw::Solver b(g);
        const cw::SolveTotals tb = b.solve(im, cw::SolveMode::full);
        const double muN = s.mu * s.normal_force, c = std::sqrt(ta.n_contact * s.dx * s.dy / kPi);
        assert_close(tb.Fx, ta.Fx, 0.0, 1e-9 * muN);
        assert_close(tb.Fy, ta.Fy, 0.0, 1e-9 * muN);
        assert_close(tb.Mz, ta.Mz + X * ta.Fy - Y * ta.Fx, 0.0, 1e-9 * muN * c);
        assert_int_equal(tb.n_slip, ta.n_slip);
        assert_true(std::fabs(ta.Fy) > 0.05 * muN); // the spin's share is not negligible
    }
}

// Mirroring the gap along x and rolling towards -x with xi_x and phi of the
// other sign is the same problem in the rolling frame.
void rolling_direction_mirrors(void**)
{
    const gapshapes::Shape& s = shape("N04_crescent");
    cw::ContactInput in = input_of(s);
    in.rolling_direction = 1;
    in.xi_x = 3e-4, in.xi_y = -2e-4, in.phi = 0.4;
    cw::Solver a(gapshapes::grid_of(s));
    const cw::SolveTotals ta = a.solve(in, cw::SolveMode::full);
    gapshapes::Shape m = s;
    for (int j = 0; j < s.ny; ++j)
        for (int i = 0; i < s.nx; ++i) m.h[i + s.nx * j] = s.h[(s.nx - 1 - i) + s.nx * j];
    m.x0 = -(s.x0 + (s.nx - 1) * s.dx);
    cw::ContactInput im = input_of(m);
    im.rolling_direction = -1;
    im.xi_x = -3e-4, im.xi_y = -2e-4, im.phi = -0.4;
    cw::Solver b(gapshapes::grid_of(m));
    const cw::SolveTotals tb = b.solve(im, cw::SolveMode::full);
    const double muN = s.mu * s.normal_force;
    assert_close(tb.Fx, -ta.Fx, 0.0, 1e-12 * muN);
    assert_close(tb.Fy, ta.Fy, 0.0, 1e-12 * muN);
    assert_close(tb.Mz, -ta.Mz, 0.0, 1e-12 * muN * 0.01);
    assert_close(tb.W_consistent, ta.W_consistent, 1e-12, 0.0);
    assert_int_equal(tb.n_slip, ta.n_slip);
    const auto pa = cwtest::field(a, cw::Field::py), pb = cwtest::field(b, cw::Field::py);
    for (int j = 0; j < s.ny; ++j)
        for (int i = 0; i < s.nx; ++i)
            assert_close(pb[(s.nx - 1 - i) + s.nx * j], pa[i + s.nx * j], 0.0,
                         1e-9 * s.mu * ta.p_max);
}

// Patches add up to the totals; the work maps sum to W_macro, are >= 0 and
// zero in adhesion; the fields sum to the totals; forces-only and full
// solves agree bitwise.
void patches_and_work_maps_add_up(void**)
{
    for (const char* id : {"N03_three_lobes", "N06_flange_root", "N05_ring", "D03_twolobes"}) {
        const bool dev = id[0] == 'D';
        cwtest::GapCase dc;
        if (dev)
            for (const cwtest::GapCase& c : cwtest::dev_cases())
                if (c.id == id) dc = c;
        const gapshapes::Shape* sp = dev ? nullptr : &shape(id);
        const cw::GridSpec g = dev ? dc.gap.grid : gapshapes::grid_of(*sp);
        cw::ContactInput in = dev ? dc.bind() : input_of(*sp);
        in.model = cw::ModelKind::fastsim;
        in.warm_start = false;
        in.normal_method = cw::NormalMethod::semi_hertz;
        in.xi_x = 5e-4, in.xi_y = 4e-4, in.phi = 0.6;
        cw::Solver solver(g);
        const cw::SolveTotals t = solver.solve(in, cw::SolveMode::full);
        const std::vector<cw::PatchTotals>& P = solver.patches();
        assert_int_equal(static_cast<int>(P.size()), t.n_patches);
        if (std::string(id) != "N06_flange_root" && std::string(id) != "N05_ring")
            assert_true(t.n_patches >= 2);
        double fx = 0, fy = 0, mz = 0, fn = 0, w = 0, pmax = 0;
        int nc = 0, ns = 0;
        for (const cw::PatchTotals& p : P) {
            fx += p.Fx, fy += p.Fy, mz += p.Mz, fn += p.Fn, w += p.W_macro;
            nc += p.n_contact, ns += p.n_slip;
            pmax = std::max(pmax, p.p_max);
            assert_int_equal(p.n_adhesion + p.n_slip, p.n_contact);
        }
        const double muN = in.mu * t.normal_force;
        const double c = std::sqrt(t.n_contact * g.dx * g.dy / kPi);
        assert_close(fx, t.Fx, 0.0, 1e-12 * muN);
        assert_close(fy, t.Fy, 0.0, 1e-12 * muN);
        assert_close(mz, t.Mz, 0.0, 1e-12 * muN * c);
        assert_close(fn, t.normal_force, 1e-12, 0.0);
        if (in.normal_load == cw::NormalLoad::force) assert_close(fn, in.normal_force, 1e-12, 0.0);
        assert_close(w, t.W_macro, 1e-12, 0.0);
        assert_int_equal(nc, t.n_contact);
        assert_int_equal(ns, t.n_slip);
        assert_true(pmax == t.p_max);
        assert_true(t.n_slip > 0 && t.n_adhesion > 0);

        const auto paper = cwtest::field(solver, cw::Field::work_paper);
        const auto consistent = cwtest::field(solver, cw::Field::work_consistent);
        const std::vector<int> st = cwtest::states(solver);
        double sum = 0.0, sum_paper = 0.0;
        for (size_t k = 0; k < st.size(); ++k) {
            assert_true(consistent[k] >= 0.0 && paper[k] >= 0.0);
            if (st[k] != 2) assert_true(consistent[k] == 0.0 && paper[k] == 0.0);
            sum += consistent[k];
            sum_paper += paper[k];
        }
        assert_true(t.W_macro > 0.0 && t.work_flags == 0);
        assert_close(sum, t.W_macro, 1e-12, 0.0);
        assert_close(t.W_consistent, t.W_macro, 1e-12, 0.0);
        assert_close(sum_paper, t.W_micro_paper, 1e-12, 0.0);
        // The march's friction dissipation is part of W_macro.
        assert_true(t.W_micro_paper <= t.W_macro * (1 + 1e-12) / t.balance_factor);
        // The fields sum to the totals (Mz about the grid's origin).
        const double area = g.dx * g.dy;
        assert_close(area * cwtest::sum(cwtest::field(solver, cw::Field::px)), t.Fx, 0.0,
                     1e-12 * muN);
        assert_close(area * cwtest::sum(cwtest::field(solver, cw::Field::py)), t.Fy, 0.0,
                     1e-12 * muN);
        assert_close(cwtest::sum(cwtest::field(solver, cw::Field::mz)), t.Mz, 0.0,
                     1e-12 * muN * c);
        assert_close(area * cwtest::sum(cwtest::field(solver, cw::Field::pz)), t.normal_force,
                     1e-12, 0.0);
        // Slip only where the state says so, against the traction.
        const auto sx = cwtest::field(solver, cw::Field::sx), sy = cwtest::field(solver, cw::Field::sy);
        const auto px = cwtest::field(solver, cw::Field::px), py = cwtest::field(solver, cw::Field::py);
        for (size_t k = 0; k < st.size(); ++k) {
            if (st[k] != 2) assert_true(sx[k] == 0.0 && sy[k] == 0.0);
            else assert_true(px[k] * sx[k] + py[k] * sy[k] < 0.0);
        }
        // The lateral profile: per row the consistent work per unit width.
        std::vector<double> py_row(g.ny), work(g.ny), parabola(g.ny);
        solver.copy_profile(py_row.data(), work.data(), parabola.data());
        double profile = 0.0;
        for (int j = 0; j < g.ny; ++j) {
            assert_close(py_row[j], g.y0 + j * g.dy, 0.0, 1e-15);
            profile += work[j] * g.dy;
        }
        assert_close(profile, t.W_consistent, 1e-12, 0.0);
        const cw::SolveTotals tf = solver.solve(in, cw::SolveMode::forces_only);
        assert_true(tf.Fx == t.Fx && tf.Fy == t.Fy && tf.Mz == t.Mz && tf.n_slip == t.n_slip);
    }
}

// A solver's solve does not depend on what it solved before: after solves
// with the exact normal problem, another load and the other rolling
// direction, a semi-Hertzian solve gives bitwise what a new solver's does
// (pressure, traction, state, totals).
void a_solve_does_not_depend_on_the_last(void**)
{
    for (const char* id : {"N03_three_lobes", "N06_flange_root"}) {
        const gapshapes::Shape& s = shape(id);
        cw::ContactInput in = input_of(s);
        in.normal_method = cw::NormalMethod::semi_hertz;
        cw::Solver fresh(gapshapes::grid_of(s));
        const cw::SolveTotals expected = fresh.solve(in, cw::SolveMode::full);
        cw::Solver used(gapshapes::grid_of(s));
        cw::ContactInput other = in;
        other.normal_method = cw::NormalMethod::exact;
        used.solve(other, cw::SolveMode::full);
        const cw::SolveTotals after_exact = used.solve(in, cw::SolveMode::full);
        other = in;
        other.normal_force *= 1.7;
        other.rolling_direction = -in.rolling_direction;
        used.solve(other, cw::SolveMode::forces_only);
        const cw::SolveTotals after_other = used.solve(in, cw::SolveMode::full);
        for (const cw::SolveTotals* t : {&after_exact, &after_other}) {
            for (auto m : {&cw::SolveTotals::Fx, &cw::SolveTotals::Fy, &cw::SolveTotals::Mz,
                           &cw::SolveTotals::normal_force, &cw::SolveTotals::approach,
                           &cw::SolveTotals::p_max, &cw::SolveTotals::W_consistent})
                assert_true(std::memcmp(&(t->*m), &(expected.*m), sizeof(double)) == 0);
            assert_int_equal(t->n_contact, expected.n_contact);
            assert_int_equal(t->n_slip, expected.n_slip);
            for (cw::Field f : {cw::Field::pz, cw::Field::px, cw::Field::py})
                assert_true(cwtest::field(used, f) == cwtest::field(fresh, f));
            assert_true(cwtest::states(used) == cwtest::states(fresh));
        }
    }
}

void expect_error(cw::Solver& s, const cw::ContactInput& in, cw::ErrorKind kind,
                  const char* names)
{
    try {
        s.solve(in, cw::SolveMode::full);
    } catch (const cw::Error& e) {
        assert_int_equal(static_cast<int>(e.kind()), static_cast<int>(kind));
        if (!std::strstr(e.what(), names)) fail_msg("'%s' does not name %s", e.what(), names);
        assert_false(s.has_solution());
        return;
    }
    fail_msg("no error for %s", names);
}

void errors_name_the_input(void**)
{
    const gapshapes::Shape& s = shape("N10_tall_cells");
    cw::Solver solver(gapshapes::grid_of(s));
    cw::ContactInput ok = input_of(s);
    ok.xi_x = 1e-4;
    solver.solve(ok, cw::SolveMode::full);
    cw::ContactInput in = ok;
    in.flexibility = cw::FlexibilitySource::given;
    in.L1 = in.L2 = in.L3 = 1e-11;
    expect_error(solver, in, cw::ErrorKind::invalid_input, "flexibility = given");
    in = ok;
    in.model = cw::ModelKind::calibrated;
    expect_error(solver, in, cw::ErrorKind::invalid_input, "model = calibrated");
    in = ok;
    in.gap = nullptr;
    expect_error(solver, in, cw::ErrorKind::invalid_input, "gap is NULL");
    in = ok;
    in.nu = 0.7;
    expect_error(solver, in, cw::ErrorKind::invalid_input, "nu");
    in = ok;
    in.spin_offset = 2.0;
    expect_error(solver, in, cw::ErrorKind::invalid_input, "spin_offset");
    in = ok;
    in.mu = -0.1;
    expect_error(solver, in, cw::ErrorKind::invalid_input, "mu");
    in = ok;
    in.xi_y = 1e200;
    expect_error(solver, in, cw::ErrorKind::invalid_input, "rigid slip overflows");
    in = ok;
    in.normal_method = static_cast<cw::NormalMethod>(5);
    expect_error(solver, in, cw::ErrorKind::invalid_input, "normal_method");
    cw::Jacobian J;
    in = ok;
    in.normal_force = 0.0; // the forces grow as mu N from N = 0: no derivative there
    try {
        solver.solve_jacobian(in, cw::SolveMode::forces_only, J);
        fail_msg("no error for a Jacobian at normal_force = 0");
    } catch (const cw::Error& e) {
        assert_non_null(std::strstr(e.what(), "normal_force"));
    }
    try {
        solver.prepare(cw::ModelKind::calibrated);
        fail_msg("no error for the calibrated model on a gap grid");
    } catch (const cw::Error& e) {
        assert_non_null(std::strstr(e.what(), "model = calibrated"));
    }
    // No contact, no friction, no creepage.
    in = ok;
    in.normal_load = cw::NormalLoad::approach;
    in.approach = *std::min_element(s.h.begin(), s.h.end()) - 1e-6;
    const cw::SolveTotals apart = solver.solve(in, cw::SolveMode::full);
    assert_true(apart.n_contact == 0 && apart.n_patches == 0 && apart.Fx == 0.0 &&
                apart.W_macro == 0.0 && solver.patches().empty());
    in = ok;
    in.mu = 0.0;
    const cw::SolveTotals tf = solver.solve(in, cw::SolveMode::full);
    assert_true(tf.Fx == 0.0 && tf.n_slip == tf.n_contact && tf.n_contact > 0);
    in = ok;
    in.xi_x = 0.0;
    const cw::SolveTotals tr = solver.solve(in, cw::SolveMode::full);
    assert_true(tr.Fx == 0.0 && tr.Fy == 0.0 && tr.n_slip == 0 && tr.W_consistent == 0.0);
}

void accuracy_against_the_exact_model(void**)
{
    std::string table;
    const Worst w = run_all(table);
    print_message("semi-Hertz + FASTSIM: forces %.1f %% (%s), Mz %.1f %% of mu N c, Mz/Mz %.1f %% "
                  "(%s), area %.1f %%; exact normal + FASTSIM: forces %.1f %%, Mz %.1f %%\n",
                  100 * w.fast_force, w.fast_force_id.c_str(), 100 * w.fast_mz,
                  100 * w.fast_mz_rel, w.fast_mz_rel_id.c_str(), 100 * w.fast_area,
                  100 * w.march_force, 100 * w.march_mz);
    // Bounds: the measured worst of doc/validation/non-hertzian.md rounded up.
    assert_true(w.fast_force <= 0.07);
    assert_true(w.fast_mz <= 0.16);
    assert_true(w.fast_area <= 0.12);
    assert_true(w.march_force <= 0.10);
    assert_true(w.march_mz <= 0.09);
}

} // namespace

int main(int argc, char** argv)
{
    if (argc == 2 && std::strcmp(argv[1], "--markdown") == 0) {
        std::string table;
        run_all(table);
        std::fputs(table.c_str(), stdout);
        return 0;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(march_is_fastsim_on_an_ellipse),
        cmocka_unit_test(moving_the_contact_changes_only_the_transfer_term),
        cmocka_unit_test(rolling_direction_mirrors),
        cmocka_unit_test(patches_and_work_maps_add_up),
        cmocka_unit_test(a_solve_does_not_depend_on_the_last),
        cmocka_unit_test(errors_name_the_input),
        cmocka_unit_test(accuracy_against_the_exact_model),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
