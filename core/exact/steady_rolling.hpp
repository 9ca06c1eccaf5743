// The tangential problem of steady rolling on one uniform grid
// (doc/theory/exact-discretisation.md rules 5-7). In normalised units -- lengths in
// element lengths dx, tractions q = p / (mu p0), slips s = (S / dq) G / (mu p0)
// -- the shift of element I per step dq = dx is
//   s_I = w_I + sum_J B(I - J) q_J,   B(k, l) = A(k, l) - A(k + 1, l),
// with w the rigid slip and A the half-space coefficients (halfspace/influence.hpp),
// and Coulomb's law holds element by element with bound g_I = pn_I / p0.
//
// Method. B is dominated by its diagonal and the coupling to the element
// ahead (B(0,0) ~ -B(-1,0)): a transport operator along x. A Gauss-Seidel
// sweep in the rolling direction, leading edge first, with the exact local
// Coulomb solve (local_friction.hpp) and the rest of B taken from the last
// iterate (one FFT product) defines a fixed-point map q -> G(q). Its
// fixed point is the solution. Iterating G alone stalls on the smooth modes of
// the half-space operator (their error is amplified by the transport), so
// q = G(q) is solved by a semismooth Newton method: each step solves
// (I - G'(q)) dq = G(q) - q by GMRES (each GMRES iteration one FFT product
// and one linearised sweep, so the sweep is the preconditioner), with
// forcing terms that tighten with the residual and a backtracking line search on
// |G(q) - q|. On the reference cases it converges in 3-6 steps from a good
// start; ExactModel provides one (a coarser grid's solution, or the last one).
//
// Everything is allocated by the constructor; solve() allocates nothing.
#pragma once

#include <complex>
#include <memory>
#include <vector>

#include "halfspace/grid_convolution.hpp"
#include "exact/coarse_correction.hpp"
#include "exact/local_friction.hpp"
#include "simd/kernel_isa.hpp"

namespace creepwork {

// The operator of the solve: what an element's slip is made of.
//  rolling: s = w + B q, the steady-rolling shift per element length;
//  shift:   s = w + A q, the displacement itself (a transient step: w
//           then holds the rigid slip and the previous state's share,
//           transient/transient_contact.hpp).
enum class SlipOperator { rolling, shift };

struct SteadyRollingInfo {
    int newton_steps = 0;
    int products = 0;        // FFT products (sweeps, GMRES iterations)
    double residual = 0;     // max |G(q) - q| / max(max |G(q)|, 1e-6 max g)
    bool converged = false;
    int memory_iterations = 0; // under friction memory: the solves with fixed mu_prev
};

// Throws Error(not_converged) unless info converged: the exact model's
// message, naming its bound (max_iterations) and the tolerance.
void require_converged(const SteadyRollingInfo& info, double tolerance);

class SteadyRolling {
public:
    using Complex = std::complex<double>;

    SteadyRolling(int nx, int ny, int krylov_dimension);

    // Solves on a field of nx x ny elements from now on (1 <= nx, ny <= the
    // constructor's): every vector is resized within its capacity (no
    // allocation) and keeps its first values.
    void set_size(int nx, int ny);
    // Makes the memory of the Newton steps' coarse correction
    // (coarse_correction.hpp) for the constructor's field, if it has at most
    // kCoarseMaxElements elements (about 2.6 kB per element, with the
    // correction's two work vectors, which no other level has); without it
    // Newton steps run without the correction. The finest level of a model
    // calls it.
    void reserve_coarse();
    int nx() const { return nx_; }
    int ny() const { return ny_; }
    // The operator of the next solves (rolling unless set).
    void set_operator(SlipOperator op) { rolling_ = op == SlipOperator::rolling; }
    // An interface layer's shear compliance in the normalised units, c =
    // (h / G3) G / dx >= 0 (0, the default: none): the displacement gains
    // c q at each element, A + c I in series with the half-space, so the
    // rolling operator's s_I gains c (q_I - q_ahead) and the shift's c q_I.
    void set_layer(double compliance) { layer_ = compliance; }
    // The layer's yield with hardening or softening in the normalised units
    // (local_friction.hpp, YieldBound): tau0 = tau_c0 / (mu p0) > 0 at each
    // row's leading edge, k = k_tau dx / G != 0; the yield stress is carried
    // along each row with the sweep, element by element (CONTACT's steady
    // SteadyGS), its chain inside the Newton system and the tangents. The
    // bound g is then the friction bound alone. k = 0 (the default): none
    // (a perfectly plastic yield is a cap on g, the caller's). The first
    // call with k != 0 allocates its per-element record.
    void set_yield(double tau0, double k);
    // The friction law of the next solves: Coulomb's (bound g, the default,
    // law = nullptr) or a law of the slip speed (bound g m(sigma) at each
    // element's own normalised slip sigma = |s|, local_friction.hpp), inside
    // the Newton system: the local Jacobians hold the law's slope. The first
    // call with a law allocates its per-element record. A law with memory
    // (law->memory.distance > 0, the rolling operator) is solved by
    // solve_with_memory().
    void set_law(const LocalLaw* law);
    // Under a law, of the last sweep: each element's record (m, sources;
    // m = 1 outside slip) and the scalar Newton steps of every sweep since
    // the last solve() began.
    const std::vector<ElementSlip>& element_slip() const { return slip_info_; }
    long friction_iterations() const { return friction_iterations_; }

    // conv holds this grid's coefficients; g (bound per element, 0 outside
    // the contact set) and w (rigid slip) are set by the caller through
    // bound() and rigid_slip(). q holds the first guess and returns the
    // solution; solve() stops when the residual is <= tolerance or after
    // max_steps Newton steps.
    SteadyRollingInfo solve(GridConvolution& conv, double tolerance, int max_steps)
    {
        return solve(conv, tolerance, max_steps, false);
    }
    // The same; warm = true when q is a warm start's prediction, already
    // close: the Newton steps' linear solves are then tightened faster
    // (forcing min(0.3, residual^1.5) instead of min(0.3, residual)), target
    // the tolerance itself instead of half of it, and run with the coarse
    // correction when reserve_coarse() made its memory (a cold solve too,
    // once a tenth of its contact elements adheres, with fewer aggregates
    // and made afresh: a fresh handle's bits). Fewer products from
    // such a start; from any start, a safe margin (the .cpp).
    SteadyRollingInfo solve(GridConvolution& conv, double tolerance, int max_steps, bool warm)
    {
        return memory_active_ && rolling_ ? solve_with_memory(conv, tolerance, max_steps, warm)
                              : newton(conv, tolerance, max_steps, warm);
    }
    // Under memory: each element's coefficient mu_k (mu_ref m), of the last
    // memory pass (steady_memory.cpp).
    const std::vector<double>& memory_coefficient() const { return mu_; }
    // Under memory: the rounds of the last solve's fixed point.
    int memory_iterations() const { return memory_iterations_; }

    std::vector<double>& bound() { return g_; }
    std::vector<Complex>& rigid_slip() { return w_; }
    std::vector<Complex>& traction() { return q_; }
    const std::vector<Complex>& traction() const { return q_; }
    // Of the last evaluation of G, at the returned traction: the slip
    // s = w + B q per element and the element states (0 exterior, 1
    // adhesion, 2 slip).
    const std::vector<Complex>& slip() const { return s_; }
    const std::vector<signed char>& state() const { return state_; }

    // No friction: zero traction, and the elements with contact[k] > 0 slip
    // with the rigid slip (s = w).
    void slide_freely(const std::vector<double>& contact);

    // Clips q to the bound (and zero outside the contact set).
    void project(std::vector<Complex>& q) const;

    // The derivative of the solution with respect to the rigid slip along
    // dw, by the implicit function theorem at the last solve's traction q
    // (q = G(q; w), so (I - G'(q)) dq = G_w dw), with each element's state
    // and local Jacobian as the last sweep found them (at the returned q).
    // The same GMRES and linearised sweep (the preconditioner) as Newton's
    // steps, to relative residual tolerance. Returns dq (valid until the
    // next call); the traction, slip and states are untouched. Throws
    // Error(not_converged) when GMRES does not reach the tolerance in
    // max_iterations.
    const std::vector<Complex>& tangent(GridConvolution& conv, const std::vector<Complex>& dw,
                                        double tolerance, int max_iterations);
    // The same for a change dg of the bound at fixed rigid slip:
    // (I - G'(q)) dq = G_g dg. The local solve is homogeneous of degree 1,
    // q(l c, l g) = l q(c, g), so its derivative by the bound is
    // dq/dg = (q - J c) / g with J = dq/dc: zero in adhesion (q = J c).
    // c (the rigid slip and the other elements' share) is rebuilt from the
    // last sweep: its slip w + B q, input q and output G(q).
    const std::vector<Complex>& tangent_bound(GridConvolution& conv, const std::vector<double>& dg,
                                              double tolerance, int max_iterations);
    // Under a law: the same for a change of ln kappa (the slip speed per
    // unit of normalised slip), the law's argument scaled at fixed slip.
    const std::vector<Complex>& tangent_speed(GridConvolution& conv, double tolerance,
                                              int max_iterations);
    // Under the yield (set_yield): the same for the yield stress's scale,
    // tau0 and its floor times (1 + epsilon): tau_c0 dq/dtau_c0.
    const std::vector<Complex>& tangent_yield(GridConvolution& conv, double tolerance,
                                              int max_iterations);

private:
    // solve() with the law's bounds as they stand (mu_prev held under memory).
    SteadyRollingInfo newton(GridConvolution& conv, double tolerance, int max_steps, bool warm);
    // Friction memory (steady_memory.cpp): CONTACT's outer fixed point.
    // Newton's method with every element's mu_prev held, then mu_prev again
    // from the solution, until it moves by no more than the tolerance.
    SteadyRollingInfo solve_with_memory(GridConvolution& conv, double tolerance, int max_steps,
                                        bool warm);
    // mu_ and mu_prev_ along each row from the last sweep's slip; returns
    // the largest change of mu_prev over mu_ref.
    double memory_pass();
    // Under memory, of sweep(): a slipping element's share of the chain
    // mu_k(sigma_k, mu_prev) along its row, for the tangents.
    void link_memory(int k, Complex c, Complex qk);
    // The chain in a linearised sweep (the tangents only): element k's dq
    // d gains what the change dmu of the coefficient ahead moves it by, and
    // dmu becomes element k's (speed: with the change of ln kappa).
    void memory_link(int k, double cx, double cy, Complex& d, double& dmu, bool speed) const;
    // The yield's chain in a linearised sweep: element k's dq d (J dc, with
    // dc = (cx, cy)) gains u dh from the change dtau of the yield stress
    // ahead (and dfloor of its floor), and dtau becomes element k's.
    void yield_link(int k, double cx, double cy, Complex& d, double& dtau, double dfloor) const;
    // Solves (I - G') dq = rhs (in gt_) into qt_ and checks the true residual.
    const std::vector<Complex>& solve_tangent(GridConvolution& conv, double tolerance,
                                              int max_iterations);
    // out = G(q); also s_, state_, jac_ at q. One FFT product.
    void sweep(GridConvolution& conv, const std::vector<Complex>& q, std::vector<Complex>& out);
    // s = B v (the operator's product, A v for a shift) with the layer's
    // share. One FFT product.
    void product(GridConvolution& conv, const Complex* v, Complex* s);
    // out = G'(q) v at the q of the last sweep. One FFT product.
    void linear_sweep(GridConvolution& conv, const Complex* v, Complex* out);
    // linear_sweep's part after the product: bv = the product's s of v.
    void local_sweep(const Complex* v, const Complex* bv, Complex* out) const;
    // The coarse correction's space (at most max_aggregates) and its G' P
    // at the q of the last sweep.
    void build_coarse(GridConvolution& conv, int max_aggregates);
    // Of the last sweep: the adhering share of the contact elements.
    double adhesion_share() const;
    // out = G_w dw + G_g dg (+ G_kappa under a law, with speed; + the yield
    // stress's scale, with yield) at the q of the last sweep (the sweep's
    // response to a change of the rigid slip, of the bound, of ln kappa and
    // of tau_c0; dw and dg may be null). No FFT product.
    void source_sweep(const Complex* dw, const double* dg, bool speed, Complex* out,
                      bool yield = false) const;
    // Solves (I - G') x = b to relative residual eta; returns the iterations.
    // lanes: the inner products in partial sums (faster, other bits; the
    // warm starts' Newton steps).
    int gmres(GridConvolution& conv, const std::vector<Complex>& b, std::vector<Complex>& x,
              double eta, int max_iterations, bool lanes);
    // coarse: right-preconditioned by coarse_ (its M; x = M u).
    template <int L>
    int arnoldi(GridConvolution& conv, const std::vector<Complex>& b, std::vector<Complex>& x,
                double eta, int max_iterations, bool coarse);
    double residual_norm(const std::vector<Complex>& q, const std::vector<Complex>& gq,
                         std::vector<Complex>& f, double& max_rel) const;

    int nx_, ny_, n_, m_;
    bool rolling_ = true;
    double layer_ = 0.0; // set_layer
    // The operator's own element and the one ahead (diagonal): B(0,0), B(-1,0)
    // rolling, A(0,0), A(-1,0) shift.
    double b0x_ = 0, b0y_ = 0, b1x_ = 0, b1y_ = 0;
    std::vector<double> g_;
    std::vector<Complex> w_, q_, gq_, f_, dq_, qt_, gt_, ft_, s_, work_, pre_, pre2_;
    CoarseCorrection coarse_;
    std::vector<signed char> coarse_states_; // state_ when coarse_ was made
    int coarse_age_ = 0; // Newton steps since then with other states
    std::vector<LocalJacobian> jac_;
    std::vector<signed char> state_;
    bool law_active_ = false;
    LocalLaw law_;
    std::vector<ElementSlip> slip_info_;
    bool memory_active_ = false;
    std::vector<double> mu_prev_, mu_; // per element: the element ahead's mu, its own
    int memory_iterations_ = 0;
    // A slipping element's linearisation under memory: theta at its slip
    // speed, d mu / d sigma, sigma, e = s / sigma, and the bound's change
    // per unit change of mu_prev (g theta / mu_ref).
    struct MemoryLink {
        double theta = 0.0, dmu_dsigma = 0.0, sigma = 0.0, bound = 0.0;
        Complex e{0.0, 0.0};
    };
    std::vector<MemoryLink> links_;
    double theta0_ = 0.0;        // theta at rest (adhesion, exterior)
    bool yield_active_ = false;  // set_yield
    double tau0_ = 0.0, yield_k_ = 0.0, yield_floor_ = 0.0;
    std::vector<YieldElement> yield_info_;
    bool memory_linear_ = false; // the tangents carry the chain
    size_t capacity_ = 0; // the constructor's element count
    long friction_iterations_ = 0;
    // GMRES: basis (m + 1 vectors of n), Hessenberg, Givens rotations, rhs.
    struct Release {
        void operator()(Complex* p) const { ::operator delete(p); }
    };
    std::unique_ptr<Complex, Release> basis_;
    Complex* basis(int k) { return basis_.get() + static_cast<size_t>(n_) * k; }
    std::vector<double> hessenberg_, cs_, sn_, rhs_, y_;
    KernelIsa isa_; // the copy of warm GMRES's kernel (steady_rolling.cpp)
    int products_ = 0;
};

} // namespace creepwork
