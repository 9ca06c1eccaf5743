#include "march/march.hpp"

#include <algorithm>
#include <cmath>

#include "calibrated/bound_shape.hpp"

namespace creepwork {

bool kernel_isa_supported(KernelIsa isa)
{
#if CREEPWORK_X86_KERNELS
    // Idempotent; needed when called before static constructors have run
    // (a solver made by another library's or program's constructor).
    __builtin_cpu_init();
#endif
    switch (isa) {
    case KernelIsa::baseline: return true;
#if CREEPWORK_X86_KERNELS
    case KernelIsa::avx2: return __builtin_cpu_supports("avx2");
    case KernelIsa::avx512:
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
               __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
#else
    case KernelIsa::avx2:
    case KernelIsa::avx512: return false;
#endif
    }
    return false;
}

KernelIsa best_kernel_isa()
{
    if (kernel_isa_supported(KernelIsa::avx512)) return KernelIsa::avx512;
    if (kernel_isa_supported(KernelIsa::avx2)) return KernelIsa::avx2;
    return KernelIsa::baseline;
}

const char* kernel_isa_name(KernelIsa isa)
{
    switch (isa) {
    case KernelIsa::baseline: return "baseline";
    case KernelIsa::avx2: return "avx2";
    case KernelIsa::avx512: return "avx512";
    }
    return "unknown";
}

MarchGeometry::MarchGeometry(const ContactGrid& grid)
    : nx(grid.nx()), ny(grid.ny()), stride(padded_strips(grid.ny()))
{
    const Eigen::Index n = static_cast<Eigen::Index>(nx) * stride;
    x_centre.setZero(n);
    x_slip.setZero(n);
    step.setOnes(n); // padding strips: a harmless step, never used
    inside.setZero(n);
    shape_parabolic.setZero(n);
    shape_elliptic.setZero(n);
    for (int m = 0; m < nx; ++m)
        for (int j = 0; j < ny; ++j) {
            const Eigen::Index k = static_cast<Eigen::Index>(m) * ny + j;
            const Eigen::Index p = static_cast<Eigen::Index>(m) * stride + j;
            x_centre[p] = grid.x_centre()[k];
            x_slip[p] = grid.x_slip()[k];
            step[p] = grid.step()[k];
            inside[p] = grid.in_contact()[k];
            shape_parabolic[p] = grid.pressure_shape(PressureKind::parabolic)[k];
            shape_elliptic[p] = grid.pressure_shape(PressureKind::elliptic)[k];
        }
    max_parabolic = shape_parabolic.size() > 0 ? shape_parabolic.maxCoeff() : 0.0;
}

void MarchGeometry::reserve_blend()
{
    if (shape_blended.size() != shape_parabolic.size()) {
        shape_blended = shape_parabolic; // blend 0
        blend = 0.0;
        blend_max = max_parabolic;
    }
}

void MarchGeometry::set_blend(double bound_blend)
{
    const Eigen::Index n = shape_parabolic.size();
    if (shape_blended.size() == n && bound_blend == blend) return;
    shape_blended.resize(n);
    // blended_bound_shape with its branch and coefficients taken out of the
    // loop, so that it vectorises (a vehicle loop remakes it every solve).
    const double* P = shape_parabolic.data();
    const double* E = shape_elliptic.data(); // sqrt(P)
    double* out = shape_blended.data();
    if (bound_blend >= 0.0) {
        const double cp = 1.0 - bound_blend, ce = bound_blend * 0.75;
        for (Eigen::Index k = 0; k < n; ++k) out[k] = cp * P[k] + ce * E[k];
    } else {
        const double cp = 1.0 + bound_blend, cq = -bound_blend * 1.5;
        for (Eigen::Index k = 0; k < n; ++k) out[k] = cp * P[k] + cq * P[k] * P[k];
    }
    // Every blend increases with P, so the largest is at the largest P.
    blend_max = blended_bound_shape(max_parabolic, std::sqrt(max_parabolic), bound_blend);
    blend = bound_blend;
}

void MarchGeometry::march_from_leading_edge(const ContactGrid& grid)
{
    if (grid.spec().kind != GridKind::uniform) return;
    for (int j = 0; j < ny; ++j) {
        const double Y = grid.y_centre()[j];
        double previous = std::sqrt(std::max(0.0, 1.0 - Y * Y)); // where the strip enters
        for (int m = 0; m < nx; ++m) {
            const Eigen::Index p = static_cast<Eigen::Index>(m) * stride + j;
            if (inside[p] == 0.0) continue; // before the ellipse, or after it
            step[p] = previous - x_centre[p];
            x_slip[p] = 0.5 * (previous + x_centre[p]);
            previous = x_centre[p];
        }
    }
}

void MarchState::resize(int n_elements, int ny_)
{
    ny = ny_;
    nx = ny > 0 ? n_elements / ny : 0;
    stride = padded_strips(ny);
    const Eigen::Index n = static_cast<Eigen::Index>(nx) * stride;
    qx.setZero(n);
    qy.setZero(n);
    factor.setZero(n);
    sum_px.setZero(stride);
    sum_py.setZero(stride);
    sum_x_py.setZero(stride);
    slip_count.setZero(stride);
    px.setZero(stride);
    py.setZero(stride);
    wx.setZero(stride);
    wy.setZero(stride);
}

namespace {

struct MarchArgs {
    int nx, first, last, stride; // strips [first, last)
    double cy;
    const double *x_centre, *x_slip, *step, *inside, *bound; // per element
    const double *wx, *wy;                                    // per strip
    double *qx, *qy, *factor;                                 // per element
    double *px, *py, *sum_px, *sum_py, *sum_x_py, *slip_count; // per strip
};

// G vectors of W strips from strip j0, leading edge to trailing edge: the G
// chains are independent, so their steps overlap in the pipeline, and each
// strip's running traction and sums stay in registers.
template <int W, int G>
CREEPWORK_INLINE void march_group(const MarchArgs& A, int j0)
{
    using V = simd::Vec<W>;
    // Locals, not A's fields: the stores below may alias anything.
    const int nx = A.nx;
    const long stride = A.stride;
    const double *x_centre = A.x_centre + j0, *x_slip = A.x_slip + j0, *step = A.step + j0,
                 *inside = A.inside + j0, *bound = A.bound + j0;
    double *qx = A.qx + j0, *qy = A.qy + j0, *factor = A.factor + j0;
    V px[G], py[G], spx[G], spy[G], sxpy[G], count[G], wx[G], wy[G];
    CREEPWORK_UNROLL
    for (int g = 0; g < G; ++g) {
        px[g] = py[g] = spx[g] = spy[g] = sxpy[g] = count[g] = simd::broadcast<W>(0.0);
        wx[g] = simd::load<W>(A.wx + j0 + g * W);
        wy[g] = simd::load<W>(A.wy + j0 + g * W);
    }
    const V cy = simd::broadcast<W>(A.cy);
    for (int m = 0; m < nx; ++m) {
        const long row = m * stride;
        CREEPWORK_UNROLL
        for (int g = 0; g < G; ++g) {
            const long e = row + g * W;
            const V xs = simd::load<W>(x_slip + e);
            const MarchStep<W> s =
                march_step<W>(px[g], py[g], simd::load<W>(step + e), simd::load<W>(inside + e),
                              simd::load<W>(bound + e), wx[g], wy[g] + cy * xs);
            simd::store<W>(qx + e, s.qx);
            simd::store<W>(qy + e, s.qy);
            simd::store<W>(factor + e, s.f);
            px[g] = s.px;
            py[g] = s.py;
            spx[g] += s.px;
            spy[g] += s.py;
            sxpy[g] += simd::load<W>(x_centre + e) * s.py;
            count[g] += s.slip;
        }
    }
    CREEPWORK_UNROLL
    for (int g = 0; g < G; ++g) {
        const int j = j0 + g * W;
        simd::store<W>(A.px + j, px[g]);
        simd::store<W>(A.py + j, py[g]);
        simd::store<W>(A.sum_px + j, spx[g]);
        simd::store<W>(A.sum_py + j, spy[g]);
        simd::store<W>(A.sum_x_py + j, sxpy[g]);
        simd::store<W>(A.slip_count + j, count[g]);
    }
}

// Groups of four vectors, then the vectors left (only those holding strips).
template <int W>
CREEPWORK_INLINE void march_body(const MarchArgs& A)
{
    const int vectors = (A.last - A.first + W - 1) / W;
    int v = 0;
    for (; v + 4 <= vectors; v += 4) march_group<W, 4>(A, A.first + v * W);
    switch (vectors - v) {
    case 3: march_group<W, 3>(A, A.first + v * W); break;
    case 2: march_group<W, 2>(A, A.first + v * W); break;
    case 1: march_group<W, 1>(A, A.first + v * W); break;
    default: break;
    }
}

__attribute__((noinline)) void march_baseline(const MarchArgs& A) { march_body<2>(A); }
#if CREEPWORK_X86_KERNELS
CREEPWORK_TARGET_AVX2 void march_avx2(const MarchArgs& A) { march_body<4>(A); }
CREEPWORK_TARGET_AVX512 void march_avx512(const MarchArgs& A) { march_body<8>(A); }
#endif

} // namespace

void march_strips(const MarchGeometry& geo, const NormalisedKinematics& kin, PressureKind pressure,
                  MarchState& s, KernelIsa isa, int first, int last)
{
    const MarchArgs A{geo.nx,
                      first,
                      last,
                      geo.stride,
                      kin.cy,
                      geo.x_centre.data(),
                      geo.x_slip.data(),
                      geo.step.data(),
                      geo.inside.data(),
                      geo.bound(pressure, kin.bound_blend).data(),
                      s.wx.data(),
                      s.wy.data(),
                      s.qx.data(),
                      s.qy.data(),
                      s.factor.data(),
                      s.px.data(),
                      s.py.data(),
                      s.sum_px.data(),
                      s.sum_py.data(),
                      s.sum_x_py.data(),
                      s.slip_count.data()};
    switch (isa) {
#if CREEPWORK_X86_KERNELS
    case KernelIsa::avx512: march_avx512(A); return;
    case KernelIsa::avx2: march_avx2(A); return;
#endif
    default: march_baseline(A); return;
    }
}

void rigid_slip_of_strips(const ContactGrid& grid, const NormalisedKinematics& kin, double* wx,
                          double* wy, int first, int last)
{
    for (int j = first; j < last; ++j) {
        wx[j] = kin.ux - kin.cx * grid.y_centre()[j];
        // Without an offset exactly uy, so that plain FASTSIM is unchanged
        // to the bit (uy + cy * 0 could flip the sign of a zero).
        wy[j] = kin.spin_offset > 0.0 ? kin.uy + kin.cy * (kin.spin_offset * grid.x_length()[j])
                                      : kin.uy;
        if (kin.edge_gain != 0.0) {
            const double Y = grid.y_centre()[j];
            const double m = (1.0 + kin.edge_gain * Y * Y) / (1.0 + kin.edge_gain / 5.0);
            wx[j] *= m;
            wy[j] *= m;
        }
    }
}

void set_rigid_slip(const ContactGrid& grid, const NormalisedKinematics& kin, MarchState& s,
                    int first, int last)
{
    rigid_slip_of_strips(grid, kin, s.wx.data(), s.wy.data(), first, last);
}

void march(const MarchGeometry& geo, const ContactGrid& grid, const NormalisedKinematics& kin,
           PressureKind pressure, MarchState& s, KernelIsa isa)
{
    const int ny = grid.ny();
    set_rigid_slip(grid, kin, s, 0, ny);
    march_strips(geo, kin, pressure, s, isa, 0, ny);
}

void march(const ContactGrid& grid, const NormalisedKinematics& kin, PressureKind pressure,
           MarchState& state, KernelIsa isa)
{
    const MarchGeometry geometry(grid);
    march(geometry, grid, kin, pressure, state, isa);
}

} // namespace creepwork
