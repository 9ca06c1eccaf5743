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
    MarchView march;
    const double *shape_p = nullptr, *shape_e = nullptr;          // per element
    const double *dwx = nullptr, *dwy = nullptr;                  // per direction and strip
    const double *dcy = nullptr, *dblend = nullptr;               // per direction
    double *sum_px = nullptr, *sum_py = nullptr, *sum_x_py = nullptr; // per direction and strip
};

struct DirectionalKernel : KernelWidths {
    // One vector of W strips: the primal march (PrimalStrip) plus the K
    // directions.
    template <int W>
    CREEPWORK_INLINE static void vector(const DirectionalArgs& A, int j0)
    {
        using V = simd::Vec<W>;
        const MarchView& v = A.march;
        const MarchRows rows(v, j0);
        const long stride = v.stride;
        const double *shape_p = A.shape_p + j0, *shape_e = A.shape_e + j0;
        const V zero = simd::broadcast<W>(0.0), tiny = simd::broadcast<W>(2.2250738585072014e-308);
        PrimalStrip<W> strip;
        strip.start(v, j0);
        V dwx[K], dwy[K], dcy[K], dblend[K], tpx[K], tpy[K], tspx[K], tspy[K], tsxpy[K];
        for (int k = 0; k < K; ++k) {
            dwx[k] = simd::load<W>(A.dwx + k * stride + j0);
            dwy[k] = simd::load<W>(A.dwy + k * stride + j0);
            dcy[k] = simd::broadcast<W>(A.dcy[k]);
            dblend[k] = simd::broadcast<W>(A.dblend[k]);
            tpx[k] = tpy[k] = tspx[k] = tspy[k] = tsxpy[k] = zero;
        }
        const V cy = simd::broadcast<W>(v.cy), three_quarters = simd::broadcast<W>(0.75);
        for (int m = 0; m < v.nx; ++m) {
            const long e = m * stride;
            strip.advance(rows, e, cy, [&](const MarchElement<W>& el) {
                const MarchStep<W>& s = el.s;
                const V in = el.inside, xs = el.x_slip, xc = el.x_centre, g = el.bound;

                const V hin = el.h * in;
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
                    const V P = simd::load<W>(shape_p + e), E = simd::load<W>(shape_e + e);
                    // d(shape)/d(blend) = (3/4) sqrt(P) - P (blended_bound.hpp).
                    const V dshape_over_g = (three_quarters * E - P) * inv_g;
                    for (int k = 0; k < K; ++k)
                        projection_derivative<W>(s, r, dq[k][0], dq[k][1],
                                                 dblend[k] * dshape_over_g, tpx[k], tpy[k]);
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
            });
        }
        strip.finish(v, j0);
        for (int k = 0; k < K; ++k) {
            simd::store<W>(A.sum_px + k * stride + j0, tspx[k]);
            simd::store<W>(A.sum_py + k * stride + j0, tspy[k]);
            simd::store<W>(A.sum_x_py + k * stride + j0, tsxpy[k]);
        }
    }

    template <int W>
    CREEPWORK_INLINE static void run(const DirectionalArgs& A)
    {
        for (int j0 = A.march.first; j0 < A.march.last; j0 += W) vector<W>(A, j0);
    }
};

} // namespace

void march_directional(const MarchView& view, const MarchGeometry& geo, MarchDirections& d,
                       KernelIsa isa)
{
    DirectionalArgs A;
    A.march = view;
    A.shape_p = geo.shape_parabolic.data();
    A.shape_e = geo.shape_elliptic.data();
    A.dwx = d.wx.data();
    A.dwy = d.wy.data();
    A.dcy = d.cy;
    A.dblend = d.blend;
    A.sum_px = d.sum_px.data();
    A.sum_py = d.sum_py.data();
    A.sum_x_py = d.sum_x_py.data();
    run_kernel<DirectionalKernel>(isa, A);
}

Jacobian directional_jacobian(const ModelSetup& setup, const ContactGrid& grid,
                              const MarchState& march, const MarchDirections& d)
{
    static_assert(K == kStripTangents, "scaled_forces sums three directions");
    StripTangents sums;
    sums.sum_px = d.sum_px.data();
    sums.sum_py = d.sum_py.data();
    sums.sum_x_py = d.sum_x_py.data();
    sums.stride = d.stride;
    double Phi[3], dPhi[3][kStripTangents];
    scaled_forces(grid, setup.a, setup.b, march, sums, Phi, dPhi);
    // Rolling-frame forces f_i = T Phi_i, T fixed along the creepages; the
    // caller's Fx = d fx, Fy = fy, Mz = d mz (march_model.cpp).
    const double T = setup.traction_scale, dir = setup.direction;
    const double frame[3] = {dir, 1.0, dir};
    Jacobian J;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < K; ++k)
            J.d[i][k] = frame[i] * T * dPhi[i][k];
    return J;
}

} // namespace creepwork
