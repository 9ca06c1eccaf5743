#include "calibrated/march_directional.hpp"

namespace creepwork {

void MarchDirections::resize(int ny)
{
    stride = padded_strips(ny);
    wx.setZero(kMarchDirections * stride);
    wy.setZero(kMarchDirections * stride);
    sum_px.setZero(kMarchDirections * stride);
    sum_py.setZero(kMarchDirections * stride);
    sum_x_py.setZero(kMarchDirections * stride);
}

namespace {

constexpr int K = kMarchDirections;

struct DirectionalArgs {
    int nx, ny, stride;
    double cy;
    // d(shape)/d(blend) = ce sqrt(P) + cp P + cq P^2 (bound_shape.hpp).
    double ce, cp, cq;
    const double *x_centre, *x_slip, *step, *inside, *bound, *shape_p, *shape_e; // per element
    const double *wx, *wy;                                     // per strip
    const double *dwx, *dwy, *dcy, *dblend;                    // per direction (and strip)
    double *qx, *qy, *factor;                                  // per element
    double *px, *py, *sum_px, *sum_py, *sum_x_py, *slip_count; // per strip
    double *t_sum_px, *t_sum_py, *t_sum_x_py;                  // per direction and strip
};

// One vector of W strips: march_group() of march.cpp (the same primal
// operations in the same order) plus the K directions.
template <int W>
CREEPWORK_INLINE void directional_vector(const DirectionalArgs& A, int j0)
{
    using V = simd::Vec<W>;
    const long stride = A.stride;
    const V zero = simd::broadcast<W>(0.0), tiny = simd::broadcast<W>(2.2250738585072014e-308);
    V px = zero, py = zero, spx = zero, spy = zero, sxpy = zero, count = zero;
    const V wx = simd::load<W>(A.wx + j0), wy = simd::load<W>(A.wy + j0);
    V dwx[K], dwy[K], dcy[K], dblend[K], tpx[K], tpy[K], tspx[K], tspy[K], tsxpy[K];
    for (int k = 0; k < K; ++k) {
        dwx[k] = simd::load<W>(A.dwx + k * stride + j0);
        dwy[k] = simd::load<W>(A.dwy + k * stride + j0);
        dcy[k] = simd::broadcast<W>(A.dcy[k]);
        dblend[k] = simd::broadcast<W>(A.dblend[k]);
        tpx[k] = tpy[k] = tspx[k] = tspy[k] = tsxpy[k] = zero;
    }
    const V cy = simd::broadcast<W>(A.cy), ce = simd::broadcast<W>(A.ce),
            cp = simd::broadcast<W>(A.cp), cq = simd::broadcast<W>(A.cq);
    for (int m = 0; m < A.nx; ++m) {
        const long e = m * stride + j0;
        const V xs = simd::load<W>(A.x_slip + e), h = simd::load<W>(A.step + e),
                in = simd::load<W>(A.inside + e), xc = simd::load<W>(A.x_centre + e),
                g = simd::load<W>(A.bound + e);
        const MarchStep<W> s = march_step<W>(px, py, h, in, g, wx, wy + cy * xs);
        simd::store<W>(A.qx + e, s.qx);
        simd::store<W>(A.qy + e, s.qy);
        simd::store<W>(A.factor + e, s.f);
        px = s.px;
        py = s.py;
        spx += s.px;
        spy += s.py;
        sxpy += xc * s.py;
        count += s.slip;

        const V hin = h * in;
        V dq[K][2];
        for (int k = 0; k < K; ++k) {
            dq[k][0] = in * tpx[k] - hin * dwx[k];
            dq[k][1] = in * tpy[k] - hin * (dwy[k] + dcy[k] * xs);
        }
        if (s.any_slip) {
            // Slip lanes only (r = inv_g = 0 elsewhere); g > 0 there, since
            // |q| > g >= 0.
            const V safe_g = g > tiny ? g : tiny;
            const V inv_g = s.slip / safe_g;
            const V r = s.f * inv_g * inv_g;
            const V P = simd::load<W>(A.shape_p + e), E = simd::load<W>(A.shape_e + e);
            const V dshape_over_g = (ce * E + cp * P + cq * P * P) * inv_g;
            for (int k = 0; k < K; ++k) {
                const V c = r * (s.px * dq[k][0] + s.py * dq[k][1]) - dblend[k] * dshape_over_g;
                tpx[k] = s.f * dq[k][0] - c * s.px;
                tpy[k] = s.f * dq[k][1] - c * s.py;
            }
        } else {
            for (int k = 0; k < K; ++k) {
                tpx[k] = dq[k][0];
                tpy[k] = dq[k][1];
            }
        }
        for (int k = 0; k < K; ++k) {
            tspx[k] += tpx[k];
            tspy[k] += tpy[k];
            tsxpy[k] += xc * tpy[k];
        }
    }
    simd::store<W>(A.px + j0, px);
    simd::store<W>(A.py + j0, py);
    simd::store<W>(A.sum_px + j0, spx);
    simd::store<W>(A.sum_py + j0, spy);
    simd::store<W>(A.sum_x_py + j0, sxpy);
    simd::store<W>(A.slip_count + j0, count);
    for (int k = 0; k < K; ++k) {
        simd::store<W>(A.t_sum_px + k * stride + j0, tspx[k]);
        simd::store<W>(A.t_sum_py + k * stride + j0, tspy[k]);
        simd::store<W>(A.t_sum_x_py + k * stride + j0, tsxpy[k]);
    }
}

template <int W>
CREEPWORK_INLINE void directional_body(const DirectionalArgs& A)
{
    for (int j0 = 0; j0 < A.ny; j0 += W) directional_vector<W>(A, j0);
}

__attribute__((noinline)) void directional_baseline(const DirectionalArgs& A)
{
    directional_body<2>(A);
}
#if CREEPWORK_X86_KERNELS
CREEPWORK_TARGET_AVX2 void directional_avx2(const DirectionalArgs& A) { directional_body<4>(A); }
CREEPWORK_TARGET_AVX512 void directional_avx512(const DirectionalArgs& A)
{
    directional_body<8>(A);
}
#endif

} // namespace

void march_directional(const MarchGeometry& geo, const ContactGrid& grid, const ModelSetup& setup,
                       MarchState& s, MarchDirections& d, KernelIsa isa)
{
    const NormalisedKinematics& kin = setup.kin;
    set_rigid_slip(grid, kin, s, 0, grid.ny());
    const bool quartic = kin.bound_blend < 0.0;
    const DirectionalArgs A{geo.nx,
                            grid.ny(),
                            geo.stride,
                            kin.cy,
                            quartic ? 0.0 : 0.75,
                            -1.0,
                            quartic ? 1.5 : 0.0,
                            geo.x_centre.data(),
                            geo.x_slip.data(),
                            geo.step.data(),
                            geo.inside.data(),
                            geo.bound(setup.pressure, kin.bound_blend).data(),
                            geo.shape_parabolic.data(),
                            geo.shape_elliptic.data(),
                            s.wx.data(),
                            s.wy.data(),
                            d.wx.data(),
                            d.wy.data(),
                            d.cy,
                            d.blend,
                            s.qx.data(),
                            s.qy.data(),
                            s.factor.data(),
                            s.px.data(),
                            s.py.data(),
                            s.sum_px.data(),
                            s.sum_py.data(),
                            s.sum_x_py.data(),
                            s.slip_count.data(),
                            d.sum_px.data(),
                            d.sum_py.data(),
                            d.sum_x_py.data()};
    switch (isa) {
#if CREEPWORK_X86_KERNELS
    case KernelIsa::avx512: directional_avx512(A); return;
    case KernelIsa::avx2: directional_avx2(A); return;
#endif
    default: directional_baseline(A); return;
    }
}

Jacobian directional_jacobian(const ModelSetup& setup, const ContactGrid& grid,
                              const MarchState& march, const MarchDirections& d)
{
    double Phi[3], dPhi[3][4];
    scaled_forces_and_derivatives(grid, setup.a, setup.b, march, d.sum_px.data(), d.sum_py.data(),
                                  d.sum_x_py.data(), d.stride, K, Phi, dPhi);
    // Rolling-frame forces f_i = T Phi_i, T fixed along the creepages; the
    // caller's Fx = d fx, Fy = fy, Mz = d mz (fastsim_model.cpp).
    const double T = setup.traction_scale, dir = setup.direction;
    const double frame[3] = {dir, 1.0, dir};
    Jacobian J;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < K; ++k)
            J.d[i][k] = frame[i] * T * dPhi[i][k];
    return J;
}

void scaled_forces_and_derivatives(const ContactGrid& grid, double a, double b,
                                   const MarchState& march, const double* t_sum_px,
                                   const double* t_sum_py, const double* t_sum_x_py, int stride,
                                   int n, double Phi[3], double dPhi[3][4])
{
    for (int i = 0; i < 3; ++i) {
        Phi[i] = 0.0;
        for (int k = 0; k < 4; ++k) dPhi[i][k] = 0.0;
    }
    for (int j = 0; j < grid.ny(); ++j) {
        const double area = a * b * grid.x_length()[j] * grid.y_width()[j];
        const double y = b * grid.y_centre()[j];
        Phi[0] += area * march.sum_px[j];
        Phi[1] += area * march.sum_py[j];
        Phi[2] += area * (a * march.sum_x_py[j] - y * march.sum_px[j]);
        for (int k = 0; k < n; ++k) {
            const long e = static_cast<long>(k) * stride + j;
            dPhi[0][k] += area * t_sum_px[e];
            dPhi[1][k] += area * t_sum_py[e];
            dPhi[2][k] += area * (a * t_sum_x_py[e] - y * t_sum_px[e]);
        }
    }
}

} // namespace creepwork
