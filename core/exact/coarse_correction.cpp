#include "exact/coarse_correction.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "simd/simd.hpp"

namespace creepwork {

namespace {

// acc[t] = sum_c z[c] w[c len + t], the columns in order for every t (the
// same bits in every ISA's copy), len a multiple of W or not.
struct Combine : KernelWidths {
    template <int W>
    static CREEPWORK_INLINE void run(double* const& acc, const double* const& w,
                                     const double* const& z, const int& m, const int& len)
    {
        using V = simd::Vec<W>;
        const size_t stride = static_cast<size_t>(len);
        int t = 0;
        // Four vectors per column's broadcast where the field allows (fewer
        // broadcasts and loop steps per term), then two, then one element.
        for (; t + 4 * W <= len; t += 4 * W) {
            V a0{}, a1{}, a2{}, a3{};
            for (int c = 0; c < m; ++c) {
                const V zc = simd::broadcast<W>(z[c]);
                const double* wc = w + c * stride + t;
                a0 += zc * simd::load<W>(wc);
                a1 += zc * simd::load<W>(wc + W);
                a2 += zc * simd::load<W>(wc + 2 * W);
                a3 += zc * simd::load<W>(wc + 3 * W);
            }
            simd::store<W>(acc + t, a0);
            simd::store<W>(acc + t + W, a1);
            simd::store<W>(acc + t + 2 * W, a2);
            simd::store<W>(acc + t + 3 * W, a3);
        }
        for (; t + 2 * W <= len; t += 2 * W) {
            V a0{}, a1{};
            for (int c = 0; c < m; ++c) {
                const V zc = simd::broadcast<W>(z[c]);
                a0 += zc * simd::load<W>(w + c * stride + t);
                a1 += zc * simd::load<W>(w + c * stride + t + W);
            }
            simd::store<W>(acc + t, a0);
            simd::store<W>(acc + t + W, a1);
        }
        for (; t < len; ++t) {
            double a = 0.0;
            for (int c = 0; c < m; ++c) a += z[c] * w[c * stride + t];
            acc[t] = a;
        }
    }
};

// The blocks of at most a elements along an axis of L, mirror-symmetric
// about its centre (elements i and L - 1 - i in mirror blocks, so that a
// contact and its mirror image get mirror corrections): their number.
int axis_blocks(int L, int a, std::vector<int>& block)
{
    int nb = (L + a - 1) / a;
    if (L % 2 == 1 && nb % 2 == 0) ++nb; // the middle element in a middle block
    block.resize(static_cast<size_t>(L));
    for (int i = 0; 2 * i + 1 <= L; ++i) {
        const int b = static_cast<int>(std::floor((2.0 * i + 1.0 - L) / (2.0 * a) + 0.5 * nb));
        block[i] = std::min(std::max(b, 0), nb - 1);
        block[L - 1 - i] = nb - 1 - block[i];
    }
    return nb;
}

} // namespace

void CoarseCorrection::make_kernel(const GridConvolution& conv, bool rolling)
{
    // s(I) = sum_J B(I - J) q_J; B(d) = A(d) - A(d + e_x) rolling
    // (grid_convolution.hpp), cf12 even in d as a whole. Each row's A is
    // read once (dx = -(nx - 1) ... nx) into the place of its sums along x
    // (add_run): those are A(-(nx - 1)) - A(dx) rolling (the differences
    // telescope), running sums of A shift.
    const int wx = 2 * nx_ - 1, wy = 2 * ny_ - 1;
    const size_t wp = static_cast<size_t>(wx) + 1;
    kxx_.resize(static_cast<size_t>(wx) * wy);
    kxy_.resize(kxx_.size());
    kyy_.resize(kxx_.size());
    for (auto* v : {&sxx_, &sxy_, &syy_}) v->resize(wp * wy);
    for (int r = 0; r < wy; ++r) {
        const int dy = r - (ny_ - 1);
        const size_t k0 = static_cast<size_t>(wx) * r, s0 = wp * r;
        double* const sums[3] = {sxx_.data() + s0, sxy_.data() + s0, syy_.data() + s0};
        double* const table[3] = {kxx_.data() + k0, kxy_.data() + k0, kyy_.data() + k0};
        for (size_t m = 0; m < wp; ++m) {
            const int dx = static_cast<int>(m) - (nx_ - 1);
            sums[0][m] = conv.cf11(dx, dy);
            sums[1][m] = conv.cf12(dx, dy);
            sums[2][m] = conv.cf22(dx, dy);
        }
        for (int c = 0; c < 3; ++c) {
            double* a = sums[c];
            double* k = table[c];
            if (rolling) {
                for (int m = 0; m < wx; ++m) k[m] = a[m] - a[m + 1];
                const double first = a[0];
                for (size_t m = 0; m < wp; ++m) a[m] = first - a[m];
            } else {
                for (int m = 0; m < wx; ++m) k[m] = a[m];
                a[0] = 0.0;
                for (int m = 0; m < wx; ++m) a[m + 1] = a[m] + k[m];
            }
        }
    }
}

void CoarseCorrection::reserve(int n)
{
    const size_t e = static_cast<size_t>(n), cols = 2 * static_cast<size_t>(kMaxAggregates);
    for (auto* v : {&kxx_, &kxy_, &kyy_, &sxx_, &sxy_, &syy_}) v->reserve(4 * e);
    mask_.reserve(e);
    agg_.reserve(e);
    block_.reserve(e);
    bxi_.reserve(e);
    byj_.reserve(e);
    index_.reserve(e);
    size_.reserve(cols);
    sizes_.reserve(cols);
    bp_.reserve(e * cols);
    gp_.reserve(e * cols);
    wc_.reserve(2 * e * cols);
    acc_.reserve(2 * e);
    t_.reserve(cols * cols);
    rhs_.reserve(cols);
    pivot_.reserve(cols);
    capacity_ = n;
}

void CoarseCorrection::add_element(int src, int a, double sign)
{
    // B's column of element src times sign, into aggregate a's x and y
    // columns at every element (a contact element may join later).
    const int ii = src % nx_, jj = src / nx_, wx = 2 * nx_ - 1;
    Complex* cx = bp_.data() + static_cast<size_t>(n_) * (2 * a);
    Complex* cy = cx + n_;
    for (int j = 0; j < ny_; ++j) {
        const size_t row = static_cast<size_t>(wx) * (j - jj + ny_ - 1) + (nx_ - 1 - ii);
        for (int i = 0; i < nx_; ++i) {
            const int k = i + nx_ * j;
            const size_t t = row + i;
            cx[k] += Complex(sign * kxx_[t], sign * kxy_[t]);
            cy[k] += Complex(sign * kxy_[t], sign * kyy_[t]);
        }
    }
    add_layer(src, a, sign);
}

void CoarseCorrection::add_run(int j0, int i0, int i1, int a)
{
    // The sources (i0 ... i1, j0) into aggregate a's columns at every
    // element: sum over i' of K(i - i') = S(i - i0 + 1) - S(i - i1), S the
    // table's sums along x.
    const int wp = 2 * nx_;
    Complex* cx = bp_.data() + static_cast<size_t>(n_) * (2 * a);
    Complex* cy = cx + n_;
    for (int j = 0; j < ny_; ++j) {
        const size_t row = static_cast<size_t>(wp) * (j - j0 + ny_ - 1);
        const size_t hi = row + nx_ - i0, lo = row + nx_ - 1 - i1;
        for (int i = 0; i < nx_; ++i) {
            const int k = i + nx_ * j;
            const double xy = sxy_[hi + i] - sxy_[lo + i];
            cx[k] += Complex(sxx_[hi + i] - sxx_[lo + i], xy);
            cy[k] += Complex(xy, syy_[hi + i] - syy_[lo + i]);
        }
    }
}

void CoarseCorrection::add_layer(int src, int a, double sign)
{
    if (layer_ == 0.0) return;
    // The layer's c (v_k - v_ahead): +c at src, -c at the element behind it.
    const int ii = src % nx_;
    Complex* cx = bp_.data() + static_cast<size_t>(n_) * (2 * a);
    Complex* cy = cx + n_;
    const double c = sign * layer_;
    cx[src] += c;
    cy[src] += Complex(0.0, c);
    if (rolling_ && ii > 0) {
        cx[src - 1] -= c;
        cy[src - 1] -= Complex(0.0, c);
    }
}

bool CoarseCorrection::update(const std::vector<double>& g)
{
    // The aggregates stay when every element that joined or left the
    // contact set falls in a block with an aggregate that keeps a member.
    for (int a = 0; a < aggregates_; ++a) sizes_[a] = size_[a];
    int changed = 0;
    for (int k = 0; k < n_; ++k) {
        const bool in = g[k] > 0.0;
        if (in == static_cast<bool>(mask_[k])) continue;
        const int a = block_[static_cast<size_t>(bxi_[k % nx_]) + static_cast<size_t>(bx_) * byj_[k / nx_]];
        if (a < 0) return false;
        sizes_[a] += in ? 1 : -1;
        ++changed;
    }
    for (int a = 0; a < aggregates_; ++a)
        if (sizes_[a] <= 0) return false;
    if (changed == 0) return true;
    for (int k = 0; k < n_; ++k) {
        const bool in = g[k] > 0.0;
        if (in == static_cast<bool>(mask_[k])) continue;
        const int a = block_[static_cast<size_t>(bxi_[k % nx_]) + static_cast<size_t>(bx_) * byj_[k / nx_]];
        add_element(k, a, in ? 1.0 : -1.0);
        mask_[k] = in;
        agg_[k] = in ? a : -1;
        size_[a] = sizes_[a];
    }
    index_.clear();
    for (int k = 0; k < n_; ++k)
        if (mask_[k]) index_.push_back(k);
    wc_.resize(2 * index_.size() * static_cast<size_t>(columns()));
    acc_.resize(2 * index_.size());
    return true;
}

void CoarseCorrection::set_space(const GridConvolution& conv, bool rolling, double layer, int nx,
                                 int ny, const std::vector<double>& g, int max_aggregates)
{
    factored_ = false;
    const bool kernel_same = nx == nx_ && ny == ny_ && rolling == rolling_ && layer == layer_ &&
                             conv.rho() == rho_ && conv.nu() == nu_;
    if (kernel_same && aggregates_ > 0 && max_aggregates == max_aggregates_ && update(g)) return;
    max_aggregates_ = std::min(max_aggregates, kMaxAggregates);
    const int n = nx * ny;
    nx_ = nx;
    ny_ = ny;
    n_ = n;
    rolling_ = rolling;
    layer_ = layer;
    rho_ = conv.rho();
    nu_ = conv.nu();
    if (!kernel_same) make_kernel(conv, rolling);
    mask_.resize(n);
    agg_.resize(n);
    for (int k = 0; k < n; ++k) mask_[k] = g[k] > 0.0;
    // The smallest block side that keeps the aggregates within max_aggregates.
    for (int side = 2;; ++side) {
        const int bx = axis_blocks(nx, side, bxi_), by = axis_blocks(ny, side, byj_);
        block_.assign(static_cast<size_t>(bx) * by, -1);
        int count = 0;
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const int k = i + nx * j;
                agg_[k] = -1;
                if (!mask_[k]) continue;
                int& b = block_[static_cast<size_t>(bxi_[i]) + static_cast<size_t>(bx) * byj_[j]];
                if (b < 0) b = count++;
                agg_[k] = b;
            }
        if (count <= max_aggregates_) {
            aggregates_ = count;
            bx_ = bx;
            break;
        }
    }
    index_.clear();
    for (int k = 0; k < n; ++k)
        if (mask_[k]) index_.push_back(k);
    size_.assign(static_cast<size_t>(aggregates_), 0);
    sizes_.assign(static_cast<size_t>(aggregates_), 0);
    for (int k = 0; k < n; ++k)
        if (agg_[k] >= 0) ++size_[agg_[k]];
    const size_t cols = static_cast<size_t>(columns());
    bp_.assign(static_cast<size_t>(n) * cols, Complex(0.0, 0.0));
    gp_.resize(static_cast<size_t>(n) * cols); // written in full by the caller
    t_.resize(cols * cols);
    wc_.resize(2 * index_.size() * cols);
    acc_.resize(2 * index_.size());
    rhs_.resize(cols);
    pivot_.resize(cols);
    // B P: each aggregate's runs of contact elements along x, row by row.
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx;) {
            const int a = agg_[i + nx * j];
            int end = i + 1;
            while (end < nx && agg_[end + nx * j] == a) ++end;
            if (a >= 0) add_run(j, i, end - 1, a);
            i = end;
        }
    for (int k : index_) add_layer(k, agg_[k], 1.0);
}

void CoarseCorrection::indicator(int c, Complex* v) const
{
    const Complex one = c % 2 == 0 ? Complex(1.0, 0.0) : Complex(0.0, 1.0);
    for (const int k : index_)
        if (agg_[k] == c / 2) v[k] = one;
}

void CoarseCorrection::clear(int c, Complex* v) const
{
    for (const int k : index_)
        if (agg_[k] == c / 2) v[k] = 0.0;
}

bool CoarseCorrection::factor()
{
    const int m = columns();
    factored_ = false;
    if (m == 0) return false;
    // T(r, c) = P_r^T P_c - P_r^T (G' P)_c, summed over the contact elements
    // (the only ones with an aggregate) in the order of the grid, in the
    // pass that gathers G' P at them (it is zero elsewhere) for apply().
    const int nk = static_cast<int>(index_.size());
    for (int c = 0; c < m; ++c) {
        for (int r = 0; r < m; ++r) t_[static_cast<size_t>(r) * m + c] = 0.0;
        const Complex* w = gp(c);
        double* out = wc_.data() + static_cast<size_t>(2 * nk) * c;
        for (int t = 0; t < nk; ++t) {
            const int k = index_[t];
            const double re = w[k].real(), im = w[k].imag();
            out[2 * t] = re;
            out[2 * t + 1] = im;
            const size_t row = static_cast<size_t>(2 * agg_[k]) * m + c;
            t_[row] -= re;
            t_[row + m] -= im;
        }
        t_[static_cast<size_t>(c) * m + c] += size_[c / 2];
    }
    for (int j = 0; j < m; ++j) {
        int p = j;
        for (int r = j + 1; r < m; ++r)
            if (std::fabs(t_[static_cast<size_t>(r) * m + j]) >
                std::fabs(t_[static_cast<size_t>(p) * m + j]))
                p = r;
        pivot_[j] = p;
        if (!(t_[static_cast<size_t>(p) * m + j] != 0.0)) return false;
        if (p != j)
            for (int c = 0; c < m; ++c)
                std::swap(t_[static_cast<size_t>(j) * m + c], t_[static_cast<size_t>(p) * m + c]);
        const double d = t_[static_cast<size_t>(j) * m + j];
        for (int r = j + 1; r < m; ++r) {
            const double l = t_[static_cast<size_t>(r) * m + j] / d;
            t_[static_cast<size_t>(r) * m + j] = l;
            for (int c = j + 1; c < m; ++c)
                t_[static_cast<size_t>(r) * m + c] -= l * t_[static_cast<size_t>(j) * m + c];
        }
    }
    factored_ = true;
    return true;
}

void CoarseCorrection::apply(const Complex* u, Complex* x)
{
    for (int k = 0; k < n_; ++k) x[k] = u[k];
    if (!factored_) return;
    const int m = columns();
    const int nk = static_cast<int>(index_.size());
    for (int c = 0; c < m; ++c) rhs_[c] = 0.0;
    for (int t = 0; t < nk; ++t) {
        const int k = index_[t];
        const int a = agg_[k];
        rhs_[2 * a] += u[k].real();
        rhs_[2 * a + 1] += u[k].imag();
    }
    for (int j = 0; j < m; ++j) std::swap(rhs_[j], rhs_[pivot_[j]]);
    for (int r = 1; r < m; ++r)
        for (int c = 0; c < r; ++c) rhs_[r] -= t_[static_cast<size_t>(r) * m + c] * rhs_[c];
    for (int r = m - 1; r >= 0; --r) {
        for (int c = r + 1; c < m; ++c) rhs_[r] -= t_[static_cast<size_t>(r) * m + c] * rhs_[c];
        rhs_[r] /= t_[static_cast<size_t>(r) * m + r];
    }
    // G' P z over the contact elements, as 2 nk doubles.
    run_kernel<Combine>(isa_, acc_.data(), static_cast<const double*>(wc_.data()),
                        static_cast<const double*>(rhs_.data()), m, 2 * nk);
    for (int t = 0; t < nk; ++t) x[index_[t]] += Complex(acc_[2 * t], acc_[2 * t + 1]);
}

} // namespace creepwork
