#include "exact/steady_rolling.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/error.hpp"
#include "contact/number_text.hpp"
#include "simd/simd.hpp"

namespace creepwork {

void require_converged(const SteadyRollingInfo& info, double tolerance)
{
    if (!info.converged)
        throw Error(ErrorKind::not_converged,
                    "model = exact did not converge: residual " + number_text(info.residual) +
                        " > tolerance " + number_text(tolerance) + " after " +
                        std::to_string(info.newton_steps) +
                        " Newton steps (max_iterations); raise max_iterations or tolerance");
}

namespace {

using Complex = std::complex<double>;

// Real inner product of complex fields seen as real vectors (x and y parts).
double dot(const Complex* a, const Complex* b, int n)
{
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += a[i].real() * b[i].real() + a[i].imag() * b[i].imag();
    return s;
}
double dot(const std::vector<Complex>& a, const std::vector<Complex>& b)
{
    return dot(a.data(), b.data(), static_cast<int>(a.size()));
}

// The lanes of subtract_dot: L partial sums (element t of the fields seen
// as doubles goes to sum t mod L), whatever the ISA's width W (W divides
// L), so every ISA's copy gives the same bits (kernel_isa.hpp).
template <int L>
struct PartialSums : KernelWidths {
    template <int W>
    static CREEPWORK_INLINE void run(double* const& a, const double* const& b, const double& h,
                                     const double* const& c, const int& m, const bool& apply,
                                     double* const& out)
    {
        static_assert(L % W == 0, "the partial sums hold whole vectors");
        using V = simd::Vec<W>;
        constexpr int G = L / W;
        V sum[G];
        for (int g = 0; g < G; ++g) sum[g] = V{};
        const V hv = simd::broadcast<W>(h);
        int t = 0;
        for (; t + L <= m; t += L) {
            CREEPWORK_UNROLL
            for (int g = 0; g < G; ++g) {
                const int o = t + g * W;
                const V av = simd::load<W>(a + o), bv = simd::load<W>(b + o);
                const V r = apply ? bv - av : av - hv * bv;
                simd::store<W>(a + o, r);
                sum[g] += r * simd::load<W>(c + o);
            }
        }
        double s[L];
        for (int g = 0; g < G; ++g) simd::store<W>(s + g * W, sum[g]);
        for (; t < m; ++t) {
            a[t] = apply ? b[t] - a[t] : a[t] - h * b[t];
            s[0] += a[t] * c[t];
        }
        for (int k = L / 2; k >= 1; k /= 2) // pairwise: (s0 + s1) + (s2 + s3)
            for (int l = 0; l < k; ++l) s[l] = s[2 * l] + s[2 * l + 1];
        *out = s[0];
    }
};

// Of GMRES's modified Gram-Schmidt: v -= h u (Apply: v = u - v, the
// operator I - G' applied to u), then v . w (w may be v), in one pass.
// L = 1 sums the inner product in element order, as dot(). L > 1 (a power
// of 2) runs over the fields as 2n doubles into L partial sums
// (PartialSums, isa's copy), added pairwise at the end: other bits, but
// the loop vectorises and no chain of dependent additions runs through
// the whole field.
template <int L, bool Apply>
double subtract_dot(KernelIsa isa, Complex* v, const Complex* u, double h, const Complex* w,
                    int n)
{
    if constexpr (L == 1) {
        (void)isa;
        double s = 0.0;
        for (int t = 0; t < n; ++t) {
            if (Apply)
                v[t] = u[t] - v[t];
            else
                v[t] -= h * u[t];
            s += v[t].real() * w[t].real() + v[t].imag() * w[t].imag();
        }
        return s;
    } else {
        // Complex is layout-compatible with double[2] ([complex.numbers]).
        double s = 0.0;
        run_kernel<PartialSums<L>>(isa, reinterpret_cast<double*>(v),
                                   reinterpret_cast<const double*>(u), h,
                                   reinterpret_cast<const double*>(w), 2 * n, Apply, &s);
        return s;
    }
}

// Newton's method: the loosest forcing term, and the line search.
constexpr double kFirstForcing = 0.3;
// The last linear solve's target, times tolerance / residual. From any start
// half the tolerance (a margin: GMRES's 2-norm is not the residual's largest
// element). From a warm start's prediction the tolerance itself: fewer
// products (doc/dev/decisions.md); from any start it would move the cold
// results, within the tolerance, by more than the tables against CONTACT
// print.
constexpr double kLastForcing = 0.5;
constexpr double kWarmLastForcing = 1.0;
constexpr double kArmijo = 1e-4;
constexpr int kMaxHalvings = 8;
constexpr int kMaxGmresPerStep = 200;
// A warm Newton step's coarse correction is made again once the element
// states have differed from those it was made at on this many Newton steps
// (doc/dev/decisions.md: 1, 3, 6, 10 and never measured).
constexpr int kCoarseRefresh = 10;
// Partial sums of GMRES's inner products in a warm start's Newton steps
// (subtract_dot), and in a cold solve's steps with the coarse correction;
// 1 everywhere else (the Jacobians' linear solves among them).
constexpr int kLanes = 8;
// A cold solve's Newton steps run with the coarse correction once this share
// of the contact elements adheres (full slip: the sweep alone converges in a
// few iterations and the set-up would not pay), with at most this many
// aggregates (its set-up pays back over one solve only;
// doc/dev/decisions.md).
constexpr double kColdAdhesion = 0.1;
constexpr int kColdAggregates = 16;

} // namespace

SteadyRolling::SteadyRolling(int nx, int ny, int krylov_dimension)
    : nx_(nx), ny_(ny), n_(nx * ny), m_(krylov_dimension), g_(n_, 0.0), w_(n_), q_(n_),
      gq_(n_), f_(n_), dq_(n_), qt_(n_), gt_(n_), ft_(n_), s_(n_), work_(n_), jac_(n_),
      state_(n_, 0),
      // Raw storage: a basis vector's pages are touched (and, on this
      // machine's VM, page faults are dear) only if GMRES gets that far.
      // Every vector is written in full before it is read.
      basis_(static_cast<Complex*>(::operator new(sizeof(Complex) * n_ * (m_ + 1)))),
      hessenberg_(static_cast<size_t>(m_ + 1) * m_), cs_(m_), sn_(m_), rhs_(m_ + 1), y_(m_),
      isa_(best_kernel_isa())
{
    capacity_ = static_cast<size_t>(n_);
}

void SteadyRolling::reserve_coarse()
{
    if (static_cast<int>(capacity_) > kCoarseMaxElements) return;
    coarse_.reserve(static_cast<int>(capacity_));
    coarse_states_.reserve(capacity_);
    for (auto* v : {&pre_, &pre2_}) {
        v->reserve(capacity_);
        v->resize(static_cast<size_t>(n_));
    }
}

void SteadyRolling::set_law(const LocalLaw* law)
{
    law_active_ = law != nullptr;
    memory_active_ = law && law->memory.distance > 0.0;
    if (!law) return;
    law_ = *law;
    slip_info_.reserve(capacity_);
    slip_info_.resize(static_cast<size_t>(n_));
    if (!memory_active_) return;
    for (auto* v : {&mu_prev_, &mu_}) {
        v->reserve(capacity_);
        v->resize(static_cast<size_t>(n_));
    }
    links_.reserve(capacity_);
    links_.resize(static_cast<size_t>(n_));
    theta0_ = law->memory.distance / (law->memory.distance + law->dt * law->memory.s0);
}

void SteadyRolling::set_yield(double tau0, double k)
{
    yield_active_ = k != 0.0 && tau0 > 0.0;
    if (!yield_active_) return;
    tau0_ = tau0;
    yield_k_ = k;
    yield_floor_ = 0.1 * tau0; // CONTACT's floor of a softening yield stress
    yield_info_.reserve(capacity_);
    yield_info_.resize(static_cast<size_t>(n_));
}

void SteadyRolling::set_size(int nx, int ny)
{
    nx_ = nx;
    ny_ = ny;
    n_ = nx * ny;
    const size_t n = static_cast<size_t>(n_);
    g_.resize(n);
    for (auto* v : {&w_, &q_, &gq_, &f_, &dq_, &qt_, &gt_, &ft_, &s_, &work_}) v->resize(n);
    if (coarse_.reserved(n_)) // the correction's work vectors, reserve_coarse()'s
        for (auto* v : {&pre_, &pre2_}) v->resize(n);
    jac_.resize(n);
    state_.resize(n);
    if (law_active_) slip_info_.resize(n);
    if (yield_active_) yield_info_.resize(n);
    if (memory_active_) {
        mu_prev_.resize(n);
        mu_.resize(n);
        links_.resize(n);
    }
}

void SteadyRolling::project(std::vector<Complex>& q) const
{
    for (int k = 0; k < n_; ++k) {
        const double a2 = std::norm(q[k]);
        if (!(g_[k] > 0.0))
            q[k] = 0.0;
        else if (a2 > g_[k] * g_[k])
            q[k] *= g_[k] / std::sqrt(a2);
    }
}

void SteadyRolling::slide_freely(const std::vector<double>& contact)
{
    for (int k = 0; k < n_; ++k) {
        q_[k] = 0.0;
        const bool in = contact[k] > 0.0;
        s_[k] = in ? w_[k] : Complex(0.0, 0.0);
        state_[k] = in ? 2 : 0;
    }
}

void SteadyRolling::product(GridConvolution& conv, const Complex* v, Complex* s)
{
    conv.apply_tangential(v, s, rolling_);
    ++products_;
    if (layer_ == 0.0) return;
    // The layer's diagonal c I in A: B = A(k) - A(k + 1) couples an element
    // to itself (+c) and to the one ahead along x (-c).
    for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i) {
            const int k = i + nx_ * j;
            const Complex ahead = rolling_ && i + 1 < nx_ ? v[k + 1] : Complex(0.0, 0.0);
            s[k] += layer_ * (v[k] - ahead);
        }
}

void SteadyRolling::sweep(GridConvolution& conv, const std::vector<Complex>& q,
                          std::vector<Complex>& out)
{
    product(conv, q.data(), s_.data());
    for (int k = 0; k < n_; ++k) s_[k] += w_[k];
    for (int j = 0; j < ny_; ++j) {
        Complex ahead(0.0, 0.0); // change of q at the element ahead (i + 1)
        double tau = tau0_;      // under the yield: the yield stress ahead
        for (int i = nx_ - 1; i >= 0; --i) {
            const int k = i + nx_ * j;
            if (!(g_[k] > 0.0)) {
                out[k] = 0.0;
                state_[k] = 0;
                jac_[k] = {};
                ahead = 0.0;
                continue;
            }
            const Complex c(s_[k].real() - b0x_ * q[k].real() + b1x_ * ahead.real(),
                            s_[k].imag() - b0y_ * q[k].imag() + b1y_ * ahead.imag());
            Complex qk;
            bool slips;
            if (yield_active_) {
                YieldElement& y = yield_info_[k];
                slips = solve_local_yield(YieldBound{g_[k], tau, yield_k_, yield_floor_}, c, b0x_,
                                          b0y_, qk, jac_[k], y);
                friction_iterations_ += y.iterations;
                tau = y.tau;
            } else if (law_active_) {
                ElementSlip& e = slip_info_[k];
                if (memory_active_) law_.mu_prev = mu_prev_[k];
                slips = solve_local_friction(law_, c, b0x_, b0y_, g_[k], qk, jac_[k], e);
                friction_iterations_ += e.iterations;
                if (memory_active_ && slips) link_memory(k, c, qk);
            } else {
                slips = solve_local_friction(c, b0x_, b0y_, g_[k], qk, jac_[k]);
            }
            state_[k] = slips ? 2 : 1;
            out[k] = qk;
            ahead = qk - q[k];
        }
    }
}

void SteadyRolling::linear_sweep(GridConvolution& conv, const Complex* v, Complex* out)
{
    product(conv, v, work_.data());
    local_sweep(v, work_.data(), out);
}

void SteadyRolling::local_sweep(const Complex* v, const Complex* bv, Complex* out) const
{
    for (int j = 0; j < ny_; ++j) {
        Complex ahead(0.0, 0.0);
        double dmu = 0.0;  // under memory (tangents): the change of mu ahead
        double dtau = 0.0; // under the yield: the change of the yield stress ahead
        for (int i = nx_ - 1; i >= 0; --i) {
            const int k = i + nx_ * j;
            if (!(g_[k] > 0.0)) {
                out[k] = 0.0;
                ahead = 0.0;
                dmu *= theta0_;
                continue;
            }
            const double cx = bv[k].real() - b0x_ * v[k].real() + b1x_ * ahead.real();
            const double cy = bv[k].imag() - b0y_ * v[k].imag() + b1y_ * ahead.imag();
            const LocalJacobian& J = jac_[k];
            Complex d(J.j11 * cx + J.j12 * cy, J.j21 * cx + J.j22 * cy);
            if (yield_active_) yield_link(k, cx, cy, d, dtau, 0.0);
            if (memory_linear_) memory_link(k, cx, cy, d, dmu, false);
            out[k] = d;
            ahead = d - v[k];
        }
    }
}

void SteadyRolling::build_coarse(GridConvolution& conv, int max_aggregates)
{
    // Kept while every element keeps its state, and for kCoarseRefresh - 1
    // Newton steps after a state changed: the slip elements' local Jacobians
    // drift with q, but a correction a little stale costs few products
    // (GMRES's residual is the true one) and saves its set-up.
    if (coarse_.active() && coarse_.max_aggregates() == max_aggregates &&
        coarse_.same_space(nx_, ny_, g_) &&
        (coarse_states_ == state_ || ++coarse_age_ < kCoarseRefresh))
        return;
    coarse_age_ = 0;
    coarse_states_ = state_;
    coarse_.set_space(conv, rolling_, layer_, nx_, ny_, g_, max_aggregates);
    Complex* v = pre_.data();
    std::fill(pre_.begin(), pre_.end(), Complex(0.0, 0.0));
    for (int c = 0; c < coarse_.columns(); ++c) {
        coarse_.indicator(c, v);
        local_sweep(v, coarse_.bp(c), coarse_.gp(c));
        coarse_.clear(c, v);
    }
    coarse_.factor();
}

int SteadyRolling::gmres(GridConvolution& conv, const std::vector<Complex>& b,
                         std::vector<Complex>& x, double eta, int max_iterations, bool lanes)
{
    return lanes ? arnoldi<kLanes>(conv, b, x, eta, max_iterations, false)
                 : arnoldi<1>(conv, b, x, eta, max_iterations, false);
}

template <int L>
int SteadyRolling::arnoldi(GridConvolution& conv, const std::vector<Complex>& b,
                           std::vector<Complex>& x, double eta, int max_iterations, bool coarse)
{
    std::fill(x.begin(), x.end(), Complex(0.0, 0.0));
    const double bnorm = std::sqrt(dot(b, b));
    if (!(bnorm > 0.0)) return 0;
    const double target = eta * bnorm;
    std::vector<Complex>& r = ft_; // free during the linear solve
    r = b;
    double beta = bnorm;
    int total = 0;
    auto H = [&](int i, int k) -> double& { return hessenberg_[i + static_cast<size_t>(m_ + 1) * k]; };
    while (total < max_iterations) {
        Complex* v0 = basis(0);
        for (int t = 0; t < n_; ++t) v0[t] = r[t] / beta;
        std::fill(rhs_.begin(), rhs_.end(), 0.0);
        rhs_[0] = beta;
        int k = 0;
        bool done = false;
        for (; k < m_ && total < max_iterations; ++k) {
            ++total;
            Complex* v = basis(k + 1);
            const Complex* vk = basis(k);
            if (coarse) { // right preconditioner: (I - G') M v_k
                coarse_.apply(vk, pre_.data());
                vk = pre_.data();
            }
            linear_sweep(conv, vk, v);
            // Modified Gram-Schmidt, each subtraction fused with the next
            // inner product: (I - G') v_k, then v -= h_i v_i for i = 0..k.
            H(0, k) = subtract_dot<L, true>(isa_, v, vk, 0.0, basis(0), n_);
            for (int i = 1; i <= k; ++i)
                H(i, k) = subtract_dot<L, false>(isa_, v, basis(i - 1), H(i - 1, k), basis(i), n_);
            const double h = std::sqrt(subtract_dot<L, false>(isa_, v, basis(k), H(k, k), v, n_));
            H(k + 1, k) = h;
            if (h > 0.0 && L == 1)
                for (int t = 0; t < n_; ++t) v[t] /= h;
            else if (h > 0.0) // by the reciprocal: other bits, no division per element
                for (int t = 0; t < n_; ++t) v[t] *= 1.0 / h;
            for (int i = 0; i < k; ++i) {
                const double a = cs_[i] * H(i, k) + sn_[i] * H(i + 1, k);
                H(i + 1, k) = -sn_[i] * H(i, k) + cs_[i] * H(i + 1, k);
                H(i, k) = a;
            }
            const double d = std::hypot(H(k, k), H(k + 1, k));
            cs_[k] = d > 0.0 ? H(k, k) / d : 1.0;
            sn_[k] = d > 0.0 ? H(k + 1, k) / d : 0.0;
            H(k, k) = d;
            H(k + 1, k) = 0.0;
            rhs_[k + 1] = -sn_[k] * rhs_[k];
            rhs_[k] = cs_[k] * rhs_[k];
            if (std::fabs(rhs_[k + 1]) <= target || !(h > 0.0)) {
                ++k;
                done = true;
                break;
            }
        }
        // x += V y with H y = rhs (upper triangular, k columns), in one
        // pass over x (each element sums its terms in the order of i).
        for (int i = k - 1; i >= 0; --i) {
            double v = rhs_[i];
            for (int c = i + 1; c < k; ++c) v -= H(i, c) * y_[c];
            y_[i] = H(i, i) != 0.0 ? v / H(i, i) : 0.0;
        }
        if (coarse) { // x += M V y
            for (int t = 0; t < n_; ++t) {
                Complex ut(0.0, 0.0);
                for (int i = 0; i < k; ++i) ut += y_[i] * basis(i)[t];
                pre2_[t] = ut;
            }
            coarse_.apply(pre2_.data(), pre_.data());
            for (int t = 0; t < n_; ++t) x[t] += pre_[t];
        } else {
            for (int t = 0; t < n_; ++t) {
                Complex xt = x[t];
                for (int i = 0; i < k; ++i) xt += y_[i] * basis(i)[t];
                x[t] = xt;
            }
        }
        if (done || total >= max_iterations) break;
        // Restart: the true residual b - (I - G') x.
        linear_sweep(conv, x.data(), r.data());
        for (int t = 0; t < n_; ++t) r[t] = b[t] - (x[t] - r[t]);
        beta = std::sqrt(dot(r, r));
        if (beta <= target) break;
    }
    return total;
}

double SteadyRolling::residual_norm(const std::vector<Complex>& q, const std::vector<Complex>& gq,
                                    std::vector<Complex>& f, double& max_rel) const
{
    double sum = 0.0, fmax2 = 0.0, qmax2 = 0.0, gmax = 0.0;
    for (int k = 0; k < n_; ++k) {
        f[k] = gq[k] - q[k];
        const double a2 = std::norm(f[k]);
        sum += a2;
        fmax2 = std::max(fmax2, a2);
        qmax2 = std::max(qmax2, std::norm(gq[k]));
        gmax = std::max(gmax, g_[k]);
    }
    const double fmax = std::sqrt(fmax2), qmax = std::sqrt(qmax2);
    // Relative to the largest traction, but never to less than a millionth of
    // the largest bound: a contact near zero creepage need not be resolved
    // beyond what matters next to mu p0.
    const double scale = std::max(qmax, 1e-6 * gmax);
    max_rel = scale > 0.0 ? fmax / scale : 0.0;
    return std::sqrt(sum);
}

SteadyRollingInfo SteadyRolling::newton(GridConvolution& conv, double tolerance, int max_steps,
                                        bool warm)
{
    SteadyRollingInfo info;
    products_ = 0;
    friction_iterations_ = 0;
    memory_linear_ = false; // Newton's steps hold mu_prev
    if (rolling_) {
        b0x_ = conv.cf11(0, 0) - conv.cf11(1, 0);
        b0y_ = conv.cf22(0, 0) - conv.cf22(1, 0);
        b1x_ = conv.cf11(-1, 0) - conv.cf11(0, 0);
        b1y_ = conv.cf22(-1, 0) - conv.cf22(0, 0);
    } else {
        b0x_ = conv.cf11(0, 0);
        b0y_ = conv.cf22(0, 0);
        b1x_ = conv.cf11(-1, 0);
        b1y_ = conv.cf22(-1, 0);
    }
    // (cf12 vanishes on the row of the loaded element: B(0,0), B(-1,0) are diagonal.)
    // The layer's c I: +c on the own element, -c on the one ahead (rolling).
    b0x_ += layer_;
    b0y_ += layer_;
    if (rolling_) {
        b1x_ -= layer_;
        b1y_ -= layer_;
    }

    // A cold solve makes its own correction: a fresh handle's bits.
    if (!warm) coarse_.forget();
    project(q_);
    sweep(conv, q_, gq_);
    double rel = 0.0;
    double fnorm = residual_norm(q_, gq_, f_, rel);
    for (;;) {
        info.residual = rel;
        if (rel <= tolerance) {
            info.converged = true;
            break;
        }
        if (info.newton_steps >= max_steps) break;
        // Forcing term: the linear solve reduces the residual by the residual
        // itself (superlinear Newton; from a warm start at 3e-3 one step does
        // what Eisenstat-Walker's choice 2 did in two: 10 % fewer products
        // warm at N = 40 ... 100), at most 0.3, and no further than the
        // tolerance needs. From a warm start's prediction by the residual to
        // the power 1.5, to the tolerance itself (kWarm*: GMRES stops beyond
        // its target, and a step that lands just above the tolerance needs
        // a short one more).
        double eta = std::min(kFirstForcing, warm ? rel * std::sqrt(rel) : rel);
        eta = std::max(eta, (warm ? kWarmLastForcing : kLastForcing) * tolerance / rel);
        ++info.newton_steps;
        if (warm && coarse_.reserved(n_)) {
            build_coarse(conv, kMaxAggregates);
            arnoldi<kLanes>(conv, f_, dq_, eta, kMaxGmresPerStep, coarse_.active());
        } else if (coarse_.reserved(n_) && (coarse_.active() || adhesion_share() >= kColdAdhesion)) {
            build_coarse(conv, kColdAggregates);
            arnoldi<kLanes>(conv, f_, dq_, eta, kMaxGmresPerStep, coarse_.active());
        } else {
            gmres(conv, f_, dq_, eta, kMaxGmresPerStep, warm);
        }

        double lambda = 1.0, fnew = 0.0, rel_new = 0.0;
        for (int halving = 0;; ++halving) {
            for (int k = 0; k < n_; ++k) qt_[k] = q_[k] + lambda * dq_[k];
            project(qt_);
            sweep(conv, qt_, gt_);
            fnew = residual_norm(qt_, gt_, ft_, rel_new);
            if (fnew <= (1.0 - kArmijo * lambda) * fnorm || halving == kMaxHalvings) break;
            lambda *= 0.5;
        }
        q_.swap(qt_);
        gq_.swap(gt_);
        f_.swap(ft_);
        fnorm = fnew;
        rel = rel_new;
    }
    info.products = products_;
    return info;
}

double SteadyRolling::adhesion_share() const
{
    int adhesion = 0, contact = 0;
    for (int k = 0; k < n_; ++k) {
        adhesion += state_[k] == 1;
        contact += state_[k] != 0;
    }
    return contact > 0 ? static_cast<double>(adhesion) / contact : 0.0;
}

void SteadyRolling::source_sweep(const Complex* dw, const double* dg, bool speed, Complex* out,
                                 bool yield) const
{
    // The sweep of sweep() with q held: c = w + (B q - own diagonal) + b1
    // (change ahead), so dc = dw + b1 (dG ahead); a bound change moves a
    // slipping element's own traction by dq/dg = (G(q)_k - J c) / g (the
    // local problem is homogeneous of degree 1 in (c, g)).
    for (int j = 0; j < ny_; ++j) {
        Complex ahead(0.0, 0.0);
        double dmu = 0.0; // under memory (tangents): the change of mu ahead
        // Under the yield: the change of the yield stress ahead, tau0 at the
        // leading edge for the yield stress's scale (and its floor's).
        double dtau = yield ? tau0_ : 0.0;
        const double dfloor = yield ? yield_floor_ : 0.0;
        for (int i = nx_ - 1; i >= 0; --i) {
            const int k = i + nx_ * j;
            if (!(g_[k] > 0.0)) {
                out[k] = 0.0;
                ahead = 0.0;
                dmu *= theta0_;
                continue;
            }
            double cx = b1x_ * ahead.real(), cy = b1y_ * ahead.imag();
            if (dw) {
                cx = dw[k].real() + cx;
                cy = dw[k].imag() + cy;
            }
            const LocalJacobian& J = jac_[k];
            Complex d(J.j11 * cx + J.j12 * cy, J.j21 * cx + J.j22 * cy);
            if (law_active_ && state_[k] == 2) {
                // Under a law: dq = u (m dg + sigma h' dln kappa), local_friction.hpp.
                const ElementSlip& e = slip_info_[k];
                if (dg && dg[k] != 0.0) d += e.u * (e.m * dg[k]);
                if (speed) d += e.u * e.speed_source;
            } else if (dg && state_[k] == 2 && dg[k] != 0.0) {
                // c as sweep() built it: s = w + B q holds the element's own
                // diagonal b0 q_k, the element ahead's change is G(q) - q.
                const Complex up = i + 1 < nx_ ? gq_[k + 1] - q_[k + 1] : Complex(0.0, 0.0);
                const double c0x = s_[k].real() - b0x_ * q_[k].real() + b1x_ * up.real();
                const double c0y = s_[k].imag() - b0y_ * q_[k].imag() + b1y_ * up.imag();
                const Complex jc(J.j11 * c0x + J.j12 * c0y, J.j21 * c0x + J.j22 * c0y);
                d += (gq_[k] - jc) * (dg[k] / g_[k]);
            }
            if (yield_active_) yield_link(k, cx, cy, d, dtau, dfloor);
            if (memory_linear_) memory_link(k, cx, cy, d, dmu, speed);
            out[k] = d;
            ahead = d;
        }
    }
}

const std::vector<SteadyRolling::Complex>& SteadyRolling::tangent(GridConvolution& conv,
                                                                  const std::vector<Complex>& dw,
                                                                  double tolerance,
                                                                  int max_iterations)
{
    memory_linear_ = memory_active_ && rolling_;
    source_sweep(dw.data(), nullptr, false, gt_.data()); // gt_, qt_, ft_: scratch after solve()
    return solve_tangent(conv, tolerance, max_iterations);
}

const std::vector<SteadyRolling::Complex>& SteadyRolling::tangent_bound(
    GridConvolution& conv, const std::vector<double>& dg, double tolerance, int max_iterations)
{
    memory_linear_ = memory_active_ && rolling_;
    source_sweep(nullptr, dg.data(), false, gt_.data());
    return solve_tangent(conv, tolerance, max_iterations);
}

const std::vector<SteadyRolling::Complex>& SteadyRolling::tangent_speed(GridConvolution& conv,
                                                                        double tolerance,
                                                                        int max_iterations)
{
    memory_linear_ = memory_active_ && rolling_;
    source_sweep(nullptr, nullptr, law_active_, gt_.data());
    return solve_tangent(conv, tolerance, max_iterations);
}

const std::vector<SteadyRolling::Complex>& SteadyRolling::tangent_yield(GridConvolution& conv,
                                                                        double tolerance,
                                                                        int max_iterations)
{
    memory_linear_ = false;
    source_sweep(nullptr, nullptr, false, gt_.data(), yield_active_);
    return solve_tangent(conv, tolerance, max_iterations);
}

void SteadyRolling::yield_link(int k, double cx, double cy, Complex& d, double& dtau,
                               double dfloor) const
{
    // Adhesion keeps the yield stress ahead (dtau carried); a flowing
    // element's bound moves by dh, its flow by dphi = e . ds.
    if (state_[k] != 2) return;
    const YieldElement& y = yield_info_[k];
    const double dh = y.h_t * dtau + y.h_f * dfloor;
    d += y.u * dh;
    if (!y.follows) return;
    const double dphi =
        y.e.real() * (cx + b0x_ * d.real()) + y.e.imag() * (cy + b0y_ * d.imag());
    dtau = y.h_phi * dphi + dh;
}

const std::vector<SteadyRolling::Complex>& SteadyRolling::solve_tangent(GridConvolution& conv,
                                                                        double tolerance,
                                                                        int max_iterations)
{
    std::vector<Complex>& rhs = gt_;
    std::vector<Complex>& dq = qt_;
    gmres(conv, rhs, dq, tolerance, max_iterations, false);
    // The true residual of the linear system, checked rather than trusted.
    std::vector<Complex>& r = ft_;
    linear_sweep(conv, dq.data(), r.data());
    double r2 = 0.0;
    for (int t = 0; t < n_; ++t) {
        r[t] = rhs[t] - (dq[t] - r[t]);
        r2 += std::norm(r[t]);
    }
    const double b2 = dot(rhs, rhs);
    if (!(r2 <= 100.0 * tolerance * tolerance * b2))
        throw Error(ErrorKind::not_converged,
                    "model = exact: the Jacobian's linear solve did not reach the tolerance "
                    "in max_iterations GMRES iterations; raise max_iterations or tolerance");
    return dq;
}

} // namespace creepwork
