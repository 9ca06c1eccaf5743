#include "fastsim/march_tangent.hpp"

namespace creepwork {

void TangentState::resize(int ny)
{
    stride = padded_strips(ny);
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
    const double *x_centre, *x_slip, *step, *inside, *bound; // per element
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
                 *inside = A.inside + j0, *bound = A.bound + j0;
    double *qx = A.qx + j0, *qy = A.qy + j0, *factor = A.factor + j0;
    const V zero = simd::broadcast<W>(0.0);
    const V tiny = simd::broadcast<W>(2.2250738585072014e-308); // DBL_MIN
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

            // dq = inside (dp_prev - h dw_k); in slip lanes dp = f dq - r (q.dq) q
            // with r = f/|q|^2, r = 0 in adhesion (f = 1 there).
            const V hin = h * in;
            const V dq[kTangents][2] = {
                {in * tpx[0][g] - hin, in * tpy[0][g]},
                {in * tpx[1][g], in * tpy[1][g] - hin},
                {in * tpx[2][g] - hin * kwx[g], in * tpy[2][g] - hin * (kwy[g] + a * xs)},
            };
            if (s.any_slip) {
                const V n2 = s.qx * s.qx + s.qy * s.qy;
                const V r = s.slip > zero ? s.f / (n2 > tiny ? n2 : tiny) : zero;
                CREEPWORK_UNROLL
                for (int k = 0; k < kTangents; ++k) {
                    const V c = r * (s.qx * dq[k][0] + s.qy * dq[k][1]);
                    tpx[k][g] = s.f * dq[k][0] - c * s.qx;
                    tpy[k][g] = s.f * dq[k][1] - c * s.qy;
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

// Groups of two vectors (a tangent strip holds 17 vectors of state, so wider
// groups would spill), then the one left.
template <int W>
CREEPWORK_INLINE void tangent_body(const TangentArgs& A)
{
    const int vectors = (A.last - A.first + W - 1) / W;
    int v = 0;
    for (; v + 2 <= vectors; v += 2) tangent_group<W, 2>(A, A.first + v * W);
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
