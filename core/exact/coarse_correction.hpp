// The coarse-grid correction of a Newton step's linear solve
// (steady_rolling.hpp: a warm step's, and a cold solve's in partial slip). GMRES solves K x = f with K = I - G'(q), the
// linearised sweep already inside K; the sweep damps the rough error modes
// but the smooth (long-wave) ones of the half-space operator converge by
// only ~0.6 per iteration. Here the contact elements are grouped into
// aggregates of a x a elements (a block of the grid, its contact elements;
// at most kMaxAggregates; the blocks mirror-symmetric about the grid's
// centre), P holds each aggregate's indicator per traction
// component, and T = P^T K P is K's Galerkin operator on them, solved
// densely. GMRES then runs on K M with the right preconditioner
//   M u = u + G' P T^-1 P^T u,
// a coarse solve followed by one linearised sweep (multiplicative:
// I - K M = G' (I - K P T^-1 P^T)). G' P is built without FFT products:
// B P from the influence coefficients (kept while the contact set, grid and
// operator stay), G' of it by the sweep's local part, once per Newton step.
// Each GMRES iteration then costs one product as before, plus P^T u, the
// coarse solve and one n x 2m combination.
#pragma once

#include <complex>
#include <vector>

#include "halfspace/grid_convolution.hpp"
#include "simd/kernel_isa.hpp"

namespace creepwork {

// Aggregates at most (the coarse system has twice as many unknowns, factored
// once per Newton step); set_space may take fewer.
constexpr int kMaxAggregates = 25;
// The largest field (elements) a solver makes the correction for: its
// memory, about 2.6 kB per element, is the size of the rest of the solver's.
constexpr int kCoarseMaxElements = 4096;

class CoarseCorrection {
public:
    using Complex = std::complex<double>;

    // Makes the memory for fields of up to n elements (every later call
    // allocates nothing); without it the correction stays off.
    void reserve(int n);
    bool reserved(int n) const { return n <= capacity_; }
    // The next set_space() sets up afresh (the kernel's table, a function of
    // the operator alone, kept): the bits of a fresh correction.
    void forget()
    {
        aggregates_ = 0;
        factored_ = false;
    }
    // The aggregates of the contact set g > 0 on nx x ny and B P (the
    // operator's product on each aggregate's indicator, with the layer's
    // share: s = B v + c (v - v_ahead) rolling, A v + c v shift). Kept as
    // they are when nothing of it changed; when only some elements joined or
    // left the contact set within the aggregates' blocks, B P is updated by
    // their columns alone (other bits than a fresh set-up: the correction
    // is a preconditioner, the solve's result is GMRES's to the tolerance).
    void set_space(const GridConvolution& conv, bool rolling, double layer, int nx, int ny,
                   const std::vector<double>& g, int max_aggregates = kMaxAggregates);
    bool same_space(int nx, int ny, const std::vector<double>& g) const
    {
        if (nx != nx_ || ny != ny_) return false;
        for (int k = 0; k < nx * ny; ++k)
            if (mask_[k] != (g[k] > 0.0)) return false;
        return true;
    }
    // set_space's bound on the aggregates.
    int max_aggregates() const { return max_aggregates_; }
    // Columns of P (two per aggregate: x, then y).
    int columns() const { return 2 * aggregates_; }
    // Column c of P as a field (v, zero elsewhere on entry, left holding the
    // indicator; clear() takes it back), its B P (valid after set_space) and
    // the place for its G' P.
    void indicator(int c, Complex* v) const;
    void clear(int c, Complex* v) const;
    const Complex* bp(int c) const { return bp_.data() + static_cast<size_t>(n_) * c; }
    Complex* gp(int c) { return gp_.data() + static_cast<size_t>(n_) * c; }
    // T = P^T (P - G' P) from gp, LU-factored with partial pivoting. False
    // (and apply() is the identity) when T is singular.
    bool factor();
    // x = u + G' P T^-1 P^T u (x may not alias u).
    void apply(const Complex* u, Complex* x);
    bool active() const { return factored_; }

private:
    // The kernel's table over every offset of the grid, B_xx, B_xy, B_yy.
    void make_kernel(const GridConvolution& conv, bool rolling);
    // sign times element src's column of B (and the layer's share) into
    // aggregate a's columns of B P.
    void add_element(int src, int a, double sign);
    // The sources i0 ... i1 of row j0 (contact elements of aggregate a) into
    // its columns of B P, and an element's share of the layer.
    void add_run(int j0, int i0, int i1, int a);
    void add_layer(int src, int a, double sign);
    // The contact set g within the aggregates as they stand: B P updated by
    // the elements that joined or left it; false (nothing changed) when an
    // aggregate would be born or emptied.
    bool update(const std::vector<double>& g);
    int capacity_ = 0;
    int nx_ = 0, ny_ = 0, n_ = 0, aggregates_ = 0, bx_ = 0;
    int max_aggregates_ = 0; // set_space's bound on the aggregates
    bool rolling_ = true;
    double layer_ = 0.0, rho_ = -1.0, nu_ = -1.0;
    std::vector<unsigned char> mask_; // the contact set of bp_
    std::vector<int> agg_;            // per element: its aggregate, -1 outside
    std::vector<int> block_;          // per block of the grid: its aggregate
    std::vector<int> bxi_, byj_;      // per column and row: its block along x and y
    std::vector<int> size_, sizes_;   // per aggregate: its elements (sizes_: update's)
    std::vector<int> index_;          // the contact elements
    std::vector<double> wc_, acc_;    // G' P at them (2 doubles each, per column)
    std::vector<double> kxx_, kxy_, kyy_; // [dx + (nx - 1) + (2 nx - 1) (dy + ny - 1)]
    std::vector<double> sxx_, sxy_, syy_; // sums of m terms of their rows: [m + 2 nx (dy + ny - 1)]
    std::vector<Complex> bp_, gp_;    // n per column
    std::vector<double> t_, rhs_;     // T (row-major, LU in place), P^T u
    std::vector<int> pivot_;
    bool factored_ = false;
    KernelIsa isa_ = best_kernel_isa();
};

} // namespace creepwork
