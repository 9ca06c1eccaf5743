#include "fastsim/march_tangent.hpp"

namespace creepwork {

void TangentState::resize(const MarchGeometry& geo)
{
    stride = geo.stride;
    auto inverse_square = [](const Eigen::ArrayXd& g) {
        Eigen::ArrayXd r(g.size());
        for (Eigen::Index k = 0; k < g.size(); ++k) r[k] = g[k] > 0.0 ? 1.0 / (g[k] * g[k]) : 0.0;
        return r;
    };
    inv_bound2_parabolic = inverse_square(geo.shape_parabolic);
    inv_bound2_elliptic = inverse_square(geo.shape_elliptic);
    sum_px.setZero(kTangents * stride);
    sum_py.setZero(kTangents * stride);
    sum_x_py.setZero(kTangents * stride);
    kappa_wx.setZero(stride);
    kappa_wy.setZero(stride);
}

namespace {

struct TangentArgs {
    int nx, first, last, stride; // strips [first, last)
    double cy, a;
    const double *x_centre, *x_slip, *step, *inside, *bound, *inv_bound2; // per element
    const double *wx, *wy, *kappa_wx, *kappa_wy;             // per strip
    double *qx, *qy, *factor;                                // per element
    double *px, *py, *sum_px, *sum_py, *sum_x_py, *slip_count; // per strip
    double *t_sum_px, *t_sum_py, *t_sum_x_py;                // per tangent and strip
};

// G vectors of W strips from strip j0: march_group() of march.cpp (the same
// primal operations in the same order) plus the three tangents.
template <int W, int G>
CREEPWORK_INLINE void tangent_group(const TangentArgs& A, int j0)
{
    using V = simd::Vec<W>;
    const int nx = A.nx;
    const long stride = A.stride;
    const double *x_centre = A.x_centre + j0, *x_slip = A.x_slip + j0, *step = A.step + j0,
                 *inside = A.inside + j0, *bound = A.bound + j0, *inv_bound2 = A.inv_bound2 + j0;
    double *qx = A.qx + j0, *qy = A.qy + j0, *factor = A.factor + j0;
    const V zero = simd::broadcast<W>(0.0);
    V px[G], py[G], spx[G], spy[G], sxpy[G], count[G], wx[G], wy[G];
    V kwx[G], kwy[G];
    V tpx[kTangents][G], tpy[kTangents][G], tspx[kTangents][G], tspy[kTangents][G],
        tsxpy[kTangents][G];
    CREEPWORK_UNROLL
    for (int g = 0; g < G; ++g) {
        px[g] = py[g] = spx[g] = spy[g] = sxpy[g] = count[g] = zero;
        wx[g] = simd::load<W>(A.wx + j0 + g * W);
        wy[g] = simd::load<W>(A.wy + j0 + g * W);
        kwx[g] = simd::load<W>(A.kappa_wx + j0 + g * W);
        kwy[g] = simd::load<W>(A.kappa_wy + j0 + g * W);
        CREEPWORK_UNROLL
        for (int k = 0; k < kTangents; ++k)
            tpx[k][g] = tpy[k][g] = tspx[k][g] = tspy[k][g] = tsxpy[k][g] = zero;
    }
    const V cy = simd::broadcast<W>(A.cy), a = simd::broadcast<W>(A.a);
    for (int m = 0; m < nx; ++m) {
        const long row = m * stride;
        CREEPWORK_UNROLL
        for (int g = 0; g < G; ++g) {
            const long e = row + g * W;
            const V xs = simd::load<W>(x_slip + e), h = simd::load<W>(step + e),
                    in = simd::load<W>(inside + e), xc = simd::load<W>(x_centre + e);
            const MarchStep<W> s = march_step<W>(px[g], py[g], h, in, simd::load<W>(bound + e),
                                                 wx[g], wy[g] + cy * xs);
            simd::store<W>(qx + e, s.qx);
            simd::store<W>(qy + e, s.qy);
            simd::store<W>(factor + e, s.f);
            px[g] = s.px;
            py[g] = s.py;
            spx[g] += s.px;
            spy[g] += s.py;
            sxpy[g] += xc * s.py;
            count[g] += s.slip;

            // dq = inside (dp_prev - h dw_k); in slip lanes dp = f dq - r (p.dq) p
            // with r = f/g^2, r = 0 in adhesion (f = 1 there).
            const V hin = h * in;
            const V dq[kTangents][2] = {
                {in * tpx[0][g] - hin, in * tpy[0][g]},
                {in * tpx[1][g], in * tpy[1][g] - hin},
                {in * tpx[2][g] - hin * kwx[g], in * tpy[2][g] - hin * (kwy[g] + a * xs)},
            };
            if (s.any_slip) {
                const V r = s.slip * s.f * simd::load<W>(inv_bound2 + e);
                CREEPWORK_UNROLL
                for (int k = 0; k < kTangents; ++k) {
                    const V c = r * (s.px * dq[k][0] + s.py * dq[k][1]);
                    tpx[k][g] = s.f * dq[k][0] - c * s.px;
                    tpy[k][g] = s.f * dq[k][1] - c * s.py;
                }
            } else {
                CREEPWORK_UNROLL
                for (int k = 0; k < kTangents; ++k) {
                    tpx[k][g] = dq[k][0];
                    tpy[k][g] = dq[k][1];
                }
            }
            CREEPWORK_UNROLL
            for (int k = 0; k < kTangents; ++k) {
                tspx[k][g] += tpx[k][g];
                tspy[k][g] += tpy[k][g];
                tsxpy[k][g] += xc * tpy[k][g];
            }
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
        CREEPWORK_UNROLL
        for (int k = 0; k < kTangents; ++k) {
            simd::store<W>(A.t_sum_px + k * stride + j, tspx[k][g]);
            simd::store<W>(A.t_sum_py + k * stride + j, tspy[k][g]);
            simd::store<W>(A.t_sum_x_py + k * stride + j, tsxpy[k][g]);
        }
    }
}

// A strip's tangent march holds 25 vectors of state: groups of two vectors
// fit AVX2's and SSE2's cycle better (measured), AVX-512's 32 registers only
// one vector without spilling (measured 10-15 % faster than two).
template <int W>
CREEPWORK_INLINE void tangent_body(const TangentArgs& A)
{
    const int vectors = (A.last - A.first + W - 1) / W;
    int v = 0;
    if (W < 8)
        for (; v + 2 <= vectors; v += 2) tangent_group<W, 2>(A, A.first + v * W);
    for (; v + 1 < vectors; ++v) tangent_group<W, 1>(A, A.first + v * W);
    if (v < vectors) tangent_group<W, 1>(A, A.first + v * W);
}

__attribute__((noinline)) void tangent_baseline(const TangentArgs& A) { tangent_body<2>(A); }
#if CREEPWORK_X86_KERNELS
CREEPWORK_TARGET_AVX2 void tangent_avx2(const TangentArgs& A) { tangent_body<4>(A); }
CREEPWORK_TARGET_AVX512 void tangent_avx512(const TangentArgs& A) { tangent_body<8>(A); }
#endif

} // namespace

void march_tangent(const MarchGeometry& geo, const ContactGrid& grid, const ModelSetup& setup,
                   MarchState& s, TangentState& t, KernelIsa isa)
{
    const int ny = grid.ny();
    const NormalisedKinematics& kin = setup.kin;
    set_rigid_slip(grid, kin, s, 0, ny);
    for (int j = 0; j < ny; ++j) {
        t.kappa_wx[j] = -setup.b * grid.y_centre()[j];
        t.kappa_wy[j] = kin.spin_offset > 0.0 ? setup.a * (kin.spin_offset * grid.x_length()[j])
                                              : 0.0;
    }
    const TangentArgs A{geo.nx,
                        0,
                        ny,
                        geo.stride,
                        kin.cy,
                        setup.a,
                        geo.x_centre.data(),
                        geo.x_slip.data(),
                        geo.step.data(),
                        geo.inside.data(),
                        geo.bound(setup.pressure).data(),
                        setup.pressure == PressureKind::parabolic ? t.inv_bound2_parabolic.data()
                                                                  : t.inv_bound2_elliptic.data(),
                        s.wx.data(),
                        s.wy.data(),
                        t.kappa_wx.data(),
                        t.kappa_wy.data(),
                        s.qx.data(),
                        s.qy.data(),
                        s.factor.data(),
                        s.px.data(),
                        s.py.data(),
                        s.sum_px.data(),
                        s.sum_py.data(),
                        s.sum_x_py.data(),
                        s.slip_count.data(),
                        t.sum_px.data(),
                        t.sum_py.data(),
                        t.sum_x_py.data()};
    switch (isa) {
#if CREEPWORK_X86_KERNELS
    case KernelIsa::avx512: tangent_avx512(A); return;
    case KernelIsa::avx2: tangent_avx2(A); return;
#endif
    default: tangent_baseline(A); return;
    }
}

} // namespace creepwork
