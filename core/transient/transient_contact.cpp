#include "transient/transient_contact.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/error.hpp"
#include "contact/number_text.hpp"
#include "exact/exact_model.hpp"
#include "exact/tangential_solve.hpp"
#include "transient/ellipse_gap.hpp"
#include "transient/state_bytes.hpp"

namespace creepwork {
namespace {

// Newton's method on prescribed forces: steps at most, and the linear
// solves of its derivatives (relative residual): a derivative to four digits
// costs the force's convergence nothing measurable (each step's force
// error shrinks by ~1e-4 at least) and takes a third of the products of one
// to ten.
constexpr int kMaxForceIterations = 30;
constexpr double kTangentTolerance = 1e-4;
// The step Jacobian's linear solves: well below the forces' own tolerance,
// so that it matches central differences of converged steps.
constexpr double kStepJacobianTolerance = 1e-12;
constexpr char kMagic[8] = {'c', 'w', 't', 'r', 'a', 'n', 's', '2'};

ContactInput own_gap(ContactInput in, const std::vector<double>& gap)
{
    in.gap = gap.data();
    in.gap_len = gap.size();
    return in;
}

} // namespace

TransientContact::Form TransientContact::gap_form(const GridSpec& grid, const ContactInput& in)
{
    Form f{grid, in, {}};
    if (grid.kind != GridKind::uniform) return f;
    EllipseGap e = ellipse_gap(grid, in);
    f.grid = e.grid;
    f.h = std::move(e.h);
    f.in.gap = f.h.data();
    f.in.gap_len = f.h.size();
    f.in.normal_load = NormalLoad::force;
    return f;
}

TransientContact::TransientContact(const GridSpec& grid, const ContactInput& in)
    : TransientContact(gap_form(grid, in))
{
}

TransientContact::TransientContact(const GridSpec& grid, const ContactInput& in, OnGapGrid)
    : TransientBase(grid),
      gap_(in.gap && in.gap_len >= static_cast<size_t>(n_) ? in.gap : nullptr,
           in.gap && in.gap_len >= static_cast<size_t>(n_) ? in.gap + n_ : nullptr),
      in_(own_gap(in, gap_)), normal_(grid, GapNormalOptions{false, true}),
      conv_(grid.nx, grid.ny, ConvolutionUse::tangential),
      solver_(grid.nx, grid.ny, kKrylovDimension)
{
    check_contact(in, static_cast<size_t>(n_), normal_.kernel_isa());
    in_.rolling_direction = 1;
    in_.xi_x = in_.xi_y = in_.phi = 0.0;
    tolerance_ = in.tolerance > 0.0 ? in.tolerance : kExactDefaultTolerance;
    max_steps_ = in.max_iterations > 0 ? in.max_iterations : kExactDefaultMaxIterations;
    spin_offset_ = in.spin_offset >= 0.0 ? in.spin_offset : kExactDefaultSpinOffset;
    normal_.solve(in_, false);
    const std::vector<double>& p = normal_.pressure();
    for (double v : p) p_ref_ = std::max(p_ref_, v);
    check_loaded(p_ref_);
    T_ = in.mu * p_ref_;
    U_ = T_ * dx_ / in.G;
    set_box();
    start_zero();
}

void TransientContact::set_box()
{
    const std::vector<double>& p = normal_.pressure();
    box_ = world_ ? CellBox{0, 0, nx_, ny_}
                  : cell_box(nx_, ny_, [&](std::size_t k) { return p[k] > 0.0; });
    bn_ = box_.nx * box_.ny;
    conv_.set_size(box_.nx, box_.ny);
    conv_.copy_coefficients(normal_.half_space(in_.nu));
    solver_.set_size(box_.nx, box_.ny);
    std::vector<double>& g = solver_.bound();
    for (int k = 0; k < bn_; ++k) g[k] = p[cell(k)] / p_ref_;
    for (auto* v : {&q0_, &aq0_, &bq0_, &base_, &dw_, &tangent_[0], &tangent_[1]})
        v->assign(bn_, Complex(0.0, 0.0));
    work_.assign(bn_, 0.0);
    aq_.assign(bn_, Complex(0.0, 0.0));
}

void TransientContact::move_geometry(double X)
{
    if (X == normal_position_) return;
    // h(x - X): X = m dx + f dx, between the elements m and m + 1 upstream.
    const double steps = X / dx_;
    const int m = static_cast<int>(std::floor(steps));
    const double f = steps - m;
    double far = gap_[0];
    for (double v : gap_) far = std::max(far, v);
    moved_gap_.resize(gap_.size());
    for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i) {
            const int a = i - m, b = i - m - 1; // x - X lies between element b and a
            const std::size_t row = static_cast<std::size_t>(nx_) * j;
            const double ha = a >= 0 && a < nx_ ? gap_[row + a] : far;
            const double hb = b >= 0 && b < nx_ ? gap_[row + b] : far;
            moved_gap_[row + i] = f == 0.0 ? ha : (1.0 - f) * ha + f * hb;
        }
    ContactInput in = own_gap(in_, moved_gap_);
    normal_.solve(X == 0.0 ? in_ : in, false);
    normal_position_ = X;
    const std::vector<double>& p = normal_.pressure();
    std::vector<double>& g = solver_.bound();
    for (int k = 0; k < bn_; ++k) g[k] = p[cell(k)] / p_ref_;
}

void TransientContact::set_frame(TransientFrame frame)
{
    move_geometry(0.0); // may throw: the frame is unchanged then
    world_ = frame == TransientFrame::world;
    set_box();
    start_zero();
}

void TransientContact::start_zero()
{
    position_ = trial_position_ = 0.0;
    std::fill(q0_.begin(), q0_.end(), Complex(0.0, 0.0));
    clear_committed();
    set_committed_terms();
}

void TransientContact::set_committed_terms()
{
    conv_.apply_tangential(q0_.data(), aq0_.data(), false);
    conv_.apply_tangential(q0_.data(), bq0_.data(), true);
}

double TransientContact::force_limit() const
{
    return in_.mu * normal_.force();
}

void TransientContact::set_slip(const double c[3], double dq, bool steady)
{
    // Rolling: the displacement of the step is creepage times dq (steady:
    // per dx); a shift (dq = 0) is given as the displacement itself.
    const double length = steady ? dx_ : dq > 0.0 ? dq : 1.0;
    const double offset = steady ? spin_offset_ * dx_ : spin_offset_ * dq;
    const double ux = c[0] * length / U_, uy = c[1] * length / U_, th = c[2] * length / U_;
    const double origin = world_ ? trial_position_ : 0.0;
    std::vector<Complex>& w = solver_.rigid_slip();
    for (int j = 0; j < box_.ny; ++j) {
        const double y = y0_ + (box_.j0 + j) * dy_;
        for (int i = 0; i < box_.nx; ++i) {
            const int k = i + box_.nx * j;
            const double x = x0_ + (box_.i0 + i) * dx_ + offset - origin;
            w[k] = Complex(ux - th * y, uy + th * x) + base_[k];
        }
    }
}

void TransientContact::unit_slip(int u, double length, double offset)
{
    const double t = length / U_;
    const double origin = world_ ? trial_position_ : 0.0;
    for (int j = 0; j < box_.ny; ++j) {
        const double y = y0_ + (box_.j0 + j) * dy_;
        for (int i = 0; i < box_.nx; ++i) {
            const double x = x0_ + (box_.i0 + i) * dx_ + offset - origin;
            dw_[i + box_.nx * j] = u == 0   ? Complex(t, 0.0)
                                   : u == 1 ? Complex(0.0, t)
                                            : Complex(-t * y, t * x);
        }
    }
}

const TransientStepResult& TransientContact::step(const TransientStepInput& s)
{
    validate(s, false, force_limit());
    trial_valid_ = false;
    // The committed state's share: -A q0 + d B q0 (world-fixed: -A q0 on
    // the moved geometry).
    const double d = world_ ? 0.0 : std::min(s.dq / dx_, 1.0);
    for (int k = 0; k < bn_; ++k) base_[k] = d * bq0_[k] - aq0_[k];
    if (world_) {
        trial_position_ = position_ + s.dq;
        move_geometry(trial_position_);
    }
    solver_.set_operator(SlipOperator::shift);
    solver_.traction() = q0_;
    return solve(s, false);
}

const TransientStepResult& TransientContact::start_steady(const TransientStepInput& s)
{
    validate(s, true, force_limit());
    trial_valid_ = false;
    if (world_) {
        trial_position_ = position_;
        move_geometry(position_);
    }
    std::fill(base_.begin(), base_.end(), Complex(0.0, 0.0));
    solver_.set_operator(SlipOperator::rolling);
    std::fill(solver_.traction().begin(), solver_.traction().end(), Complex(0.0, 0.0));
    solve(s, true);
    q0_ = solver_.traction();
    commit_steady();
    set_committed_terms();
    return result_;
}

const TransientStepResult& TransientContact::solve(const TransientStepInput& s, bool steady)
{
    const bool rolling = steady || s.dq > 0.0;
    double c[3];
    first_creepages(s, rolling, c);
    const int unknowns = (s.prescribe_fx ? 1 : 0) + (s.prescribe_fy ? 1 : 0);
    const int comp[2] = {s.prescribe_fx ? 0 : 1, 1};
    const double target[2] = {s.prescribe_fx ? s.Fx : s.Fy, s.Fy};
    const double length = steady ? dx_ : rolling ? s.dq : 1.0;
    const double area = dx_ * dy_, force_scale = T_ * area;
    const double ftol = tolerance_ * in_.mu * normal_.force();
    int newton = 0, products = 0, iterations = 0;
    SteadyRollingInfo ti;
    for (;;) {
        set_slip(c, s.dq, steady);
        ti = solver_.solve(conv_, tolerance_, max_steps_);
        newton += ti.newton_steps;
        products += ti.products;
        require_converged(ti, tolerance_);
        if (unknowns == 0) break;
        const std::vector<Complex>& q = solver_.traction();
        double f[2] = {0.0, 0.0};
        for (int k = 0; k < bn_; ++k) {
            f[0] += comp[0] == 0 ? q[k].real() : q[k].imag();
            f[1] += q[k].imag();
        }
        double r[2] = {force_scale * f[0] - target[0], force_scale * f[1] - target[1]};
        bool done = std::fabs(r[0]) <= ftol && (unknowns < 2 || std::fabs(r[1]) <= ftol);
        if (done) break;
        if (iterations == kMaxForceIterations)
            throw Error(ErrorKind::not_converged,
                        "transient step: the prescribed force was not reached in " +
                            std::to_string(kMaxForceIterations) + " Newton steps (residual " +
                            number_text(std::fabs(r[0])) + " N)");
        ++iterations;
        // dF/dc per unknown: the derivative of the converged problem.
        double J[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
        for (int u = 0; u < unknowns; ++u) {
            const Complex unit = comp[u] == 0 ? Complex(length / U_, 0.0)
                                              : Complex(0.0, length / U_);
            std::fill(dw_.begin(), dw_.end(), unit);
            tangent_[u] = solver_.tangent(conv_, dw_, kTangentTolerance,
                                          kMaxJacobianIterations);
            double sx = 0.0, sy = 0.0;
            for (int k = 0; k < bn_; ++k) {
                sx += tangent_[u][k].real();
                sy += tangent_[u][k].imag();
            }
            J[0][u] = force_scale * (comp[0] == 0 ? sx : sy);
            J[1][u] = force_scale * sy;
        }
        double dc[2] = {0.0, 0.0};
        if (unknowns == 1) {
            if (!(std::fabs(J[0][0]) > 0.0))
                throw Error(ErrorKind::not_converged,
                            "transient step: the force does not depend on the creepage "
                            "(full slip); the prescribed force cannot be reached");
            dc[0] = -r[0] / J[0][0];
        } else {
            const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
            if (!(std::fabs(det) > 0.0))
                throw Error(ErrorKind::not_converged,
                            "transient step: the forces do not depend on the creepages "
                            "(full slip); the prescribed forces cannot be reached");
            dc[0] = -(J[1][1] * r[0] - J[0][1] * r[1]) / det;
            dc[1] = -(J[0][0] * r[1] - J[1][0] * r[0]) / det;
        }
        // The next start: the tractions moved along their derivatives.
        std::vector<Complex>& qn = solver_.traction();
        for (int u = 0; u < unknowns; ++u) {
            c[comp[u]] += dc[u];
            for (int k = 0; k < bn_; ++k) qn[k] += dc[u] * tangent_[u][k];
        }
    }
    totals(c, ti, steady);
    last_length_ = length;
    last_offset_ = steady ? spin_offset_ * dx_ : spin_offset_ * s.dq;
    last_fx_ = s.prescribe_fx;
    last_fy_ = s.prescribe_fy;
    result_.newton_steps = newton;
    result_.products = products + 2 * (steady ? 0 : 1);
    result_.force_iterations = iterations;
    hold_trial(c, rolling);
    return result_;
}

void TransientContact::totals(const double c[3], const SteadyRollingInfo& ti, bool steady)
{
    const std::vector<Complex>& q = solver_.traction();
    // The energy balance: the rigid displacement is the solver's rigid slip
    // less the committed state's share (base_); a steady start has p_prev = p.
    conv_.apply_tangential(q.data(), aq_.data(), false);
    const std::vector<Complex>& rs = solver_.rigid_slip();
    double rigid = 0.0, energy = 0.0;
    for (int k = 0; k < bn_; ++k) {
        const Complex r = rs[k] - base_[k], qp = steady ? q[k] : q0_[k];
        const Complex mean = 0.5 * (q[k] + qp);
        rigid -= mean.real() * r.real() + mean.imag() * r.imag();
        if (!steady)
            energy += 0.5 * (q[k].real() * aq_[k].real() + q[k].imag() * aq_[k].imag() -
                             q0_[k].real() * aq0_[k].real() - q0_[k].imag() * aq0_[k].imag());
    }
    const std::vector<Complex>& sl = solver_.slip();
    const std::vector<signed char>& state = solver_.state();
    const std::vector<double>& g = solver_.bound();
    double fx = 0.0, fy = 0.0, mz = 0.0, w = 0.0;
    TransientStepResult& r = result_;
    r = TransientStepResult{};
    for (int j = 0; j < box_.ny; ++j) {
        const double y = y0_ + (box_.j0 + j) * dy_;
        for (int i = 0; i < box_.nx; ++i) {
            const int k = i + box_.nx * j;
            const double x = x0_ + (box_.i0 + i) * dx_;
            fx += q[k].real();
            fy += q[k].imag();
            mz += x * q[k].imag() - y * q[k].real();
            work_[k] = 0.0;
            if (g[k] > 0.0) {
                ++r.n_contact;
                if (state[k] == 2) {
                    ++r.n_slip;
                    work_[k] = -(q[k].real() * sl[k].real() + q[k].imag() * sl[k].imag());
                    w += work_[k];
                }
            }
        }
    }
    const double area = dx_ * dy_;
    r.xi_x = c[0];
    r.xi_y = c[1];
    r.phi = c[2];
    r.Fx = T_ * area * fx;
    r.Fy = T_ * area * fy;
    r.Mz = T_ * area * mz;
    r.n_adhesion = r.n_contact - r.n_slip;
    r.W_slip = T_ * U_ * area * w;
    r.W_step = T_ * U_ * area * (rigid - energy);
    // The map: each slip element's dissipation scaled to the step's work.
    const double factor = w > 0.0 ? (rigid - energy) / w : 0.0;
    for (double& v : work_) v *= factor;
    r.residual = ti.residual;
}

void TransientContact::commit()
{
    require_trial();
    q0_ = solver_.traction();
    aq0_ = aq_; // A q of the trial (the same bits as computing it again)
    conv_.apply_tangential(q0_.data(), bq0_.data(), true);
    if (world_) position_ = trial_position_;
    count_commit();
}

// The bytes: TransientBase's part (p_max and the traction scale T identify
// the contact), the coordinates and the rolled distance, then the committed
// tractions.
std::vector<unsigned char> TransientContact::save() const
{
    std::vector<unsigned char> out = save_committed(kMagic, p_ref_, T_);
    put_bytes(out, static_cast<std::int64_t>(world_ ? 1 : 0));
    put_bytes(out, position_);
    put_tractions(out, q0_);
    return out;
}

void TransientContact::restore(const unsigned char* bytes, std::size_t n)
{
    const std::size_t size = kCommittedBytes + 2 * 8 + 16 * q0_.size();
    const Committed c = read_committed(bytes, n, size, kMagic, "transient state", p_ref_, T_);
    const unsigned char* p = c.p;
    std::int64_t world = 0;
    double position = 0.0;
    get_bytes(p, world);
    get_bytes(p, position);
    if (world != (world_ ? 1 : 0))
        throw Error(ErrorKind::invalid_input,
                    "restore: the bytes are the state of another contact (the coordinates, "
                    "world- or contact-fixed, differ)");
    if (!std::isfinite(position) || position < 0.0)
        throw Error(ErrorKind::invalid_input, "restore: the bytes hold a bad rolled distance");
    std::vector<Complex>& q = solver_.traction(); // scratch until the next step
    get_tractions(p, q);
    q0_ = q;
    position_ = trial_position_ = position;
    set_committed(c);
    set_committed_terms();
}

void TransientContact::copy_traction(double* px, double* py) const
{
    const std::vector<Complex>& q = solver_.traction();
    if (px) std::fill(px, px + n_, 0.0);
    if (py) std::fill(py, py + n_, 0.0);
    for (int k = 0; k < bn_; ++k) {
        if (px) px[cell(k)] = T_ * q[k].real();
        if (py) py[cell(k)] = T_ * q[k].imag();
    }
}

void TransientContact::copy_slip(double* sx, double* sy) const
{
    const std::vector<Complex>& s = solver_.slip();
    const std::vector<signed char>& state = solver_.state();
    if (sx) std::fill(sx, sx + n_, 0.0);
    if (sy) std::fill(sy, sy + n_, 0.0);
    for (int k = 0; k < bn_; ++k) {
        if (state[k] == 0) continue;
        if (sx) sx[cell(k)] = U_ * s[k].real();
        if (sy) sy[cell(k)] = U_ * s[k].imag();
    }
}

void TransientContact::copy_state(int* out) const
{
    const std::vector<signed char>& state = solver_.state();
    std::fill(out, out + n_, 0);
    for (int k = 0; k < bn_; ++k) out[cell(k)] = state[k];
}

void TransientContact::copy_work(double* out) const
{
    std::fill(out, out + n_, 0.0);
    const double scale = T_ * U_ * dx_ * dy_;
    for (int k = 0; k < bn_; ++k) out[cell(k)] = scale * work_[k];
}

void TransientContact::jacobian(double out[9])
{
    if (!has_solution_)
        throw Error(ErrorKind::invalid_input,
                    "jacobian: there is no step (step() or start_steady() first)");
    const double fs = T_ * dx_ * dy_;
    double J[3][3];
    for (int u = 0; u < 3; ++u) {
        unit_slip(u, last_length_, last_offset_);
        const std::vector<Complex>& dq =
            solver_.tangent(conv_, dw_, kStepJacobianTolerance, kMaxJacobianIterations);
        double fx = 0.0, fy = 0.0, mz = 0.0;
        for (int j = 0; j < box_.ny; ++j) {
            const double y = y0_ + (box_.j0 + j) * dy_;
            for (int i = 0; i < box_.nx; ++i) {
                const int k = i + box_.nx * j;
                const double x = x0_ + (box_.i0 + i) * dx_;
                fx += dq[k].real();
                fy += dq[k].imag();
                mz += x * dq[k].imag() - y * dq[k].real();
            }
        }
        J[0][u] = fs * fx;
        J[1][u] = fs * fy;
        J[2][u] = fs * mz;
    }
    // A prescribed force and its creepage trade places: the sweep (principal
    // pivot) on that index, once per prescribed force.
    for (int p = 0; p < 2; ++p) {
        if (!(p == 0 ? last_fx_ : last_fy_)) continue;
        const double a = J[p][p];
        if (!(std::fabs(a) > 0.0))
            throw Error(ErrorKind::not_converged,
                        "jacobian: the prescribed force does not depend on its creepage "
                        "(full slip)");
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                if (r != p && c != p) J[r][c] -= J[r][p] * J[p][c] / a;
        for (int c = 0; c < 3; ++c)
            if (c != p) J[p][c] = -J[p][c] / a;
        for (int r = 0; r < 3; ++r)
            if (r != p) J[r][p] = J[r][p] / a;
        J[p][p] = 1.0 / a;
    }
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out[3 * r + c] = J[r][c];
}

void TransientContact::copy_pressure(double* out) const
{
    const std::vector<double>& p = normal_.pressure();
    std::copy(p.begin(), p.end(), out);
}

} // namespace creepwork
