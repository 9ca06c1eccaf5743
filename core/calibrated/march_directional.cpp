#include "calibrated/march_directional.hpp"

#include "march/march_step.hpp"

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
    // d(shape)/d(blend) = ce sqrt(P) + cp P + cq P^2 (bound_shape.hpp).
    double ce = 0, cp = 0, cq = 0;
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
        const V cy = simd::broadcast<W>(v.cy), ce = simd::broadcast<W>(A.ce),
                cp = simd::broadcast<W>(A.cp), cq = simd::broadcast<W>(A.cq);
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
                    const V dshape_over_g = (ce * E + cp * P + cq * P * P) * inv_g;
                    for (int k = 0; k < K; ++k) {
                        const V c = r * (s.px * dq[k][0] + s.py * dq[k][1]) -
                                    dblend[k] * dshape_over_g;
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

void march_directional(const MarchGeometry& geo, const ContactGrid& grid, const ModelSetup& setup,
                       MarchState& s, MarchDirections& d, KernelIsa isa)
{
    const NormalisedKinematics& kin = setup.kin;
    set_rigid_slip(grid, kin, s, 0, grid.ny());
    const bool quartic = kin.bound_blend < 0.0;
    DirectionalArgs A;
    A.march = march_view(geo, geo.bound(setup.pressure, kin.bound_blend).data(), kin.cy, s, 0,
                         grid.ny());
    A.ce = quartic ? 0.0 : 0.75;
    A.cp = -1.0;
    A.cq = quartic ? 1.5 : 0.0;
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
