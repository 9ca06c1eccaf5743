#include "transient/transient_fastsim.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/error.hpp"
#include "contact/kalker_coefficients.hpp"
#include "contact/number_text.hpp"
#include "exact/exact_model.hpp"
#include "normal/patches.hpp"
#include "transient/state_bytes.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Newton's method on prescribed forces: passes at most. Each pass is
// explicit and the force piecewise linear in the creepages, so Newton ends
// in a few passes once the slip set settles; bisection keeps Fx's bracket.
constexpr int kMaxForceIterations = 100;
constexpr char kMagic[8] = {'c', 'w', 't', 'r', 'f', 's', 't', '1'};

// FASTSIM's normal problem: the semi-Hertzian method needs no half-space
// memory (made on the first exact solve).
GapNormalOptions fastsim_normal()
{
    GapNormalOptions o;
    o.half_space_on_first_use = true;
    return o;
}

} // namespace

TransientFastsim::TransientFastsim(const GridSpec& grid, const ContactInput& in)
    : TransientBase(grid), normal_(grid, fastsim_normal())
{
    if (in.flexibility != FlexibilitySource::kalker_from_material)
        throw Error(ErrorKind::invalid_input,
                    "flexibility = given is invalid for transient FASTSIM on a gap grid: each "
                    "patch's flexibilities come from the material (G, nu) and its size");
    check_contact(in, static_cast<size_t>(n_), normal_.kernel_isa());
    ContactInput own = in;
    own.xi_x = own.xi_y = own.phi = 0.0;
    own.rolling_direction = 1;
    gap_.assign(in.gap, in.gap + n_);
    own.gap = gap_.data();
    own.gap_len = gap_.size();
    mu_ = in.mu;
    tolerance_ = in.tolerance > 0.0 ? in.tolerance : kExactDefaultTolerance;
    spin_offset_ = in.spin_offset >= 0.0 ? in.spin_offset : 0.0;
    normal_.solve(own, false);
    pz_ = normal_.pressure();
    load_ = normal_.force();
    check_loaded(*std::max_element(pz_.begin(), pz_.end()));
    set_patches(own);
    for (auto* v : {&p0_, &p_, &slip_, &dp_[0], &dp_[1]}) v->assign(n_, Complex(0.0, 0.0));
    state_.assign(n_, 0);
    start_zero();
}

// Each patch's flexibilities by the steady gap FASTSIM's rule
// (gap_fastsim_model.hpp): its "patch ellipse" a = half its longest run
// along x, b = its area / (pi a); its centroid the spin's centre.
void TransientFastsim::set_patches(const ContactInput& in)
{
    std::vector<signed char> contact(n_);
    for (int k = 0; k < n_; ++k) contact[k] = pz_[k] > 0.0;
    PatchLabels labels(nx_, ny_);
    const int count = labels.label(contact.data());
    patch_of_.assign(n_, -1);
    patches_.assign(count, Patch{});
    std::vector<double> elements(count, 0.0), longest(count, 0.0);
    for (int j = 0; j < ny_; ++j) {
        int run = 0;
        for (int i = 0; i < nx_; ++i) {
            const int k = i + nx_ * j, p = labels.of(k);
            patch_of_[k] = p;
            run = p >= 0 && i > 0 && labels.of(k - 1) == p ? run + 1 : (p >= 0 ? 1 : 0);
            if (p < 0) continue;
            elements[p] += 1.0;
            longest[p] = std::max(longest[p], run * dx_);
            patches_[p].xc += x0_ + i * dx_;
            patches_[p].yc += y0_ + j * dy_;
        }
    }
    for (int p = 0; p < count; ++p) {
        Patch& P = patches_[p];
        P.xc /= elements[p];
        P.yc /= elements[p];
        const double a = 0.5 * longest[p], b = elements[p] * dx_ * dy_ / (kPi * a);
        const double ratio = std::min(std::max(a / b, kMinAspect), kMaxAspect);
        const Flexibilities L = kalker_flexibilities(a, b, in.G, kalker_coefficients(ratio, in.nu));
        P.L1 = L.L1;
        P.L2 = L.L2;
        P.L3 = L.L3;
        P.Ls = kPi * std::sqrt(a * b) * (2.0 - in.nu) / (4.0 * in.G);
    }
}

void TransientFastsim::start_zero()
{
    std::fill(p0_.begin(), p0_.end(), Complex(0.0, 0.0));
    clear_committed();
}

void TransientFastsim::pass(const double c[3], double dq, bool steady, bool derivative)
{
    const double d = steady ? 1.0 : std::min(dq / dx_, 1.0);
    const bool rolling = steady || dq > 0.0;
    const double length = steady ? dx_ : rolling ? dq : 1.0;
    const double offset = spin_offset_ * (steady ? dx_ : dq);
    const Complex zero(0.0, 0.0);
    for (int j = 0; j < ny_; ++j) {
        const double y = y0_ + j * dy_;
        // From the leading edge (+x): the steady march reads the element
        // just done upstream.
        for (int i = nx_ - 1; i >= 0; --i) {
            const int k = i + nx_ * j;
            const int p = patch_of_[k];
            if (p < 0) {
                p_[k] = slip_[k] = dp_[0][k] = dp_[1][k] = zero;
                state_[k] = 0;
                continue;
            }
            const bool last = i + 1 == nx_;
            Complex src, dsrc[2] = {zero, zero};
            if (steady) {
                src = last ? zero : p_[k + 1];
                if (derivative && !last) dsrc[0] = dp_[0][k + 1], dsrc[1] = dp_[1][k + 1];
            } else {
                src = (1.0 - d) * p0_[k] + d * (last ? zero : p0_[k + 1]);
            }
            const Patch& P = patches_[p];
            const double x = x0_ + i * dx_ + offset;
            const double L1 = rolling ? P.L1 : P.Ls, L2 = rolling ? P.L2 : P.Ls;
            const Complex w(length * ((c[0] - c[2] * P.yc) / L1 - c[2] * (y - P.yc) / P.L3),
                            length * ((c[1] + c[2] * P.xc) / L2 + c[2] * (x - P.xc) / P.L3));
            const Complex q = src - w;
            const Complex dq_dc[2] = {dsrc[0] - Complex(length / L1, 0.0),
                                      dsrc[1] - Complex(0.0, length / L2)};
            const double bound = mu_ * pz_[k], size = std::abs(q);
            if (size <= bound) {
                p_[k] = q;
                slip_[k] = zero;
                state_[k] = 1;
                if (derivative) dp_[0][k] = dq_dc[0], dp_[1][k] = dq_dc[1];
                continue;
            }
            const Complex e = q / size;
            p_[k] = bound * e;
            const Complex s = p_[k] - q; // L times this is the slip: it opposes p
            slip_[k] = Complex(L1 * s.real(), L2 * s.imag());
            state_[k] = 2;
            if (derivative)
                for (int u = 0; u < 2; ++u) {
                    const double along = e.real() * dq_dc[u].real() + e.imag() * dq_dc[u].imag();
                    dp_[u][k] = (bound / size) * (dq_dc[u] - along * e);
                }
        }
    }
}

const TransientStepResult& TransientFastsim::step(const TransientStepInput& s)
{
    validate(s, false, mu_ * load_);
    trial_valid_ = false;
    has_solution_ = false;
    return solve(s, false);
}

const TransientStepResult& TransientFastsim::start_steady(const TransientStepInput& s)
{
    validate(s, true, mu_ * load_);
    trial_valid_ = false;
    has_solution_ = false;
    solve(s, true);
    p0_ = p_;
    commit_steady();
    return result_;
}

const TransientStepResult& TransientFastsim::solve(const TransientStepInput& s, bool steady)
{
    const bool rolling = steady || s.dq > 0.0;
    double c[3];
    first_creepages(s, rolling, c);
    const int unknowns = (s.prescribe_fx ? 1 : 0) + (s.prescribe_fy ? 1 : 0);
    const double area = dx_ * dy_, ftol = tolerance_ * mu_ * load_;
    // A creepage (or shift) that saturates a step from zero traction: the
    // scale of the search for Fx.
    double L1 = 0.0;
    for (const Patch& P : patches_) L1 = std::max(L1, rolling ? P.L1 : P.Ls);
    const double p_max = *std::max_element(pz_.begin(), pz_.end());
    const double scale = mu_ * p_max * L1 / (steady ? dx_ : rolling ? s.dq : 1.0);
    double lo = -HUGE_VAL, hi = HUGE_VAL; // Fx's bracket on c[0] (Fx falls as c[0] grows)
    int passes = 0, iterations = 0;
    double last_norm = HUGE_VAL, last_c[2] = {c[0], c[1]}, last_dc[2] = {0.0, 0.0};
    for (;;) {
        pass(c, s.dq, steady, unknowns > 0);
        ++passes;
        if (unknowns == 0) break;
        double f[2] = {0.0, 0.0}, J[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
        for (int k = 0; k < n_; ++k) {
            f[0] += p_[k].real();
            f[1] += p_[k].imag();
            for (int u = 0; u < 2; ++u) {
                J[0][u] += dp_[u][k].real();
                J[1][u] += dp_[u][k].imag();
            }
        }
        const double r[2] = {area * f[0] - s.Fx, area * f[1] - s.Fy};
        const bool done = (!s.prescribe_fx || std::fabs(r[0]) <= ftol) &&
                          (!s.prescribe_fy || std::fabs(r[1]) <= ftol);
        if (done) break;
        if (iterations == kMaxForceIterations)
            throw Error(ErrorKind::not_converged,
                        "transient FASTSIM step: the prescribed force was not reached in " +
                            std::to_string(kMaxForceIterations) + " Newton steps (residual " +
                            number_text(std::hypot(s.prescribe_fx ? r[0] : 0.0,
                                                   s.prescribe_fy ? r[1] : 0.0)) +
                            " N)");
        ++iterations;
        if (unknowns == 1 && s.prescribe_fx) {
            // Fx alone: Newton inside the bracket, else bisection or a wider search.
            (r[0] > 0.0 ? lo : hi) = c[0];
            const double J00 = area * J[0][0];
            double next = J00 < 0.0 ? c[0] - r[0] / J00 : HUGE_VAL;
            if (!(next > lo && next < hi)) {
                if (std::isfinite(lo) && std::isfinite(hi))
                    next = 0.5 * (lo + hi);
                else
                    next = std::isfinite(lo) ? lo + std::max(2.0 * std::fabs(lo), scale)
                                             : hi - std::max(2.0 * std::fabs(hi), scale);
            }
            c[0] = next;
            continue;
        }
        // Fy alone or both: damped Newton on |r|.
        const double norm = std::hypot(s.prescribe_fx ? r[0] : 0.0, r[1]);
        if (norm >= last_norm && iterations > 1) {
            // Backtrack: half the last step.
            last_dc[0] *= 0.5;
            last_dc[1] *= 0.5;
            c[0] = last_c[0] + last_dc[0];
            c[1] = last_c[1] + last_dc[1];
            continue;
        }
        last_norm = norm;
        last_c[0] = c[0];
        last_c[1] = c[1];
        double dc[2] = {0.0, 0.0};
        if (unknowns == 1) {
            const double J11 = area * J[1][1];
            if (!(std::fabs(J11) > 0.0))
                throw Error(ErrorKind::not_converged,
                            "transient FASTSIM step: the force does not depend on the creepage "
                            "(full slip); the prescribed force cannot be reached");
            dc[1] = -r[1] / J11;
        } else {
            const double j00 = area * J[0][0], j01 = area * J[0][1], j10 = area * J[1][0],
                         j11 = area * J[1][1], det = j00 * j11 - j01 * j10;
            if (!(std::fabs(det) > 0.0))
                throw Error(ErrorKind::not_converged,
                            "transient FASTSIM step: the forces do not depend on the creepages "
                            "(full slip); the prescribed forces cannot be reached");
            dc[0] = -(j11 * r[0] - j01 * r[1]) / det;
            dc[1] = -(j00 * r[1] - j10 * r[0]) / det;
        }
        last_dc[0] = dc[0];
        last_dc[1] = dc[1];
        c[0] += dc[0];
        c[1] += dc[1];
    }
    totals(c);
    result_.newton_steps = passes;
    result_.force_iterations = iterations;
    hold_trial(c, rolling);
    return result_;
}

void TransientFastsim::totals(const double c[3])
{
    TransientStepResult& r = result_;
    r = TransientStepResult{};
    double fx = 0.0, fy = 0.0, mz = 0.0, w = 0.0;
    for (int j = 0; j < ny_; ++j) {
        const double y = y0_ + j * dy_;
        for (int i = 0; i < nx_; ++i) {
            const int k = i + nx_ * j;
            if (state_[k] == 0) continue;
            const double x = x0_ + i * dx_;
            fx += p_[k].real();
            fy += p_[k].imag();
            mz += x * p_[k].imag() - y * p_[k].real();
            ++r.n_contact;
            if (state_[k] == 2) {
                ++r.n_slip;
                w -= p_[k].real() * slip_[k].real() + p_[k].imag() * slip_[k].imag();
            }
        }
    }
    const double area = dx_ * dy_;
    r.xi_x = c[0];
    r.xi_y = c[1];
    r.phi = c[2];
    r.Fx = area * fx;
    r.Fy = area * fy;
    r.Mz = area * mz;
    r.n_adhesion = r.n_contact - r.n_slip;
    r.W_step = area * w;
    r.W_slip = r.W_step; // explicit: no numerical dissipation
}

void TransientFastsim::commit()
{
    require_trial();
    p0_ = p_;
    count_commit();
}

// The bytes: TransientBase's part (the load and mu identify the contact),
// then the committed tractions.
std::vector<unsigned char> TransientFastsim::save() const
{
    std::vector<unsigned char> out = save_committed(kMagic, load_, mu_);
    put_tractions(out, p0_);
    return out;
}

void TransientFastsim::restore(const unsigned char* bytes, std::size_t n)
{
    const std::size_t size = kCommittedBytes + 16 * p0_.size();
    const Committed c =
        read_committed(bytes, n, size, kMagic, "transient FASTSIM state", load_, mu_);
    const unsigned char* p = c.p;
    std::vector<Complex> q(p0_.size());
    get_tractions(p, q);
    p0_ = q;
    set_committed(c);
}

void TransientFastsim::copy_work(double* out) const
{
    const double area = dx_ * dy_;
    for (int k = 0; k < n_; ++k)
        out[k] = state_[k] == 2 ? -area * (p_[k].real() * slip_[k].real() +
                                           p_[k].imag() * slip_[k].imag())
                                : 0.0;
}

void TransientFastsim::copy_traction(double* px, double* py) const
{
    for (int k = 0; k < n_; ++k) {
        if (px) px[k] = p_[k].real();
        if (py) py[k] = p_[k].imag();
    }
}

void TransientFastsim::copy_slip(double* sx, double* sy) const
{
    for (int k = 0; k < n_; ++k) {
        if (sx) sx[k] = slip_[k].real();
        if (sy) sy[k] = slip_[k].imag();
    }
}

void TransientFastsim::copy_state(int* out) const
{
    for (int k = 0; k < n_; ++k) out[k] = state_[k];
}

void TransientFastsim::copy_pressure(double* out) const
{
    std::copy(pz_.begin(), pz_.end(), out);
}

} // namespace creepwork
