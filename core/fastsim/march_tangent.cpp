#include "fastsim/march_tangent.hpp"

#include "contact/fp_safe.hpp"

namespace creepwork {

void TangentState::resize(const MarchGeometry& geo)
{
    stride = geo.stride;
    auto inverse_square = [](const Eigen::ArrayXd& g) {
        Eigen::ArrayXd r(g.size());
        for (Eigen::Index k = 0; k < g.size(); ++k) r[k] = quotient_if_positive(1.0, g[k] * g[k]);
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
    MarchView march;
    double a = 0;
    const double* inv_bound2 = nullptr;                           // per element
    const double *kappa_wx = nullptr, *kappa_wy = nullptr;        // per strip
    double *sum_px = nullptr, *sum_py = nullptr, *sum_x_py = nullptr; // per tangent and strip
};

struct TangentKernel : KernelWidths {
    // G vectors of W strips from strip j0: the primal march (PrimalStrip)
    // plus the three tangents.
    template <int W, int G>
    CREEPWORK_INLINE static void group(const TangentArgs& A, int j0)
    {
        using V = simd::Vec<W>;
        const MarchView& v = A.march;
        const MarchRows rows(v, j0);
        const int nx = v.nx;
        const long stride = v.stride;
        const double* inv_bound2 = A.inv_bound2 + j0;
        const V zero = simd::broadcast<W>(0.0);
        PrimalStrip<W> strip[G];
        V kwx[G], kwy[G];
        V tpx[kTangents][G], tpy[kTangents][G], tspx[kTangents][G], tspy[kTangents][G],
            tsxpy[kTangents][G];
        CREEPWORK_UNROLL
        for (int g = 0; g < G; ++g) {
            strip[g].start(v, j0 + g * W);
            kwx[g] = simd::load<W>(A.kappa_wx + j0 + g * W);
            kwy[g] = simd::load<W>(A.kappa_wy + j0 + g * W);
            CREEPWORK_UNROLL
            for (int k = 0; k < kTangents; ++k)
                tpx[k][g] = tpy[k][g] = tspx[k][g] = tspy[k][g] = tsxpy[k][g] = zero;
        }
        const V cy = simd::broadcast<W>(v.cy), a = simd::broadcast<W>(A.a);
        for (int m = 0; m < nx; ++m) {
            const long row = m * stride;
            CREEPWORK_UNROLL
            for (int g = 0; g < G; ++g) {
                const long e = row + g * W;
                strip[g].advance(rows, e, cy, [&](const MarchElement<W>& el) {
                    const MarchStep<W>& s = el.s;
                    const V in = el.inside, xs = el.x_slip, xc = el.x_centre;

                    // dq = inside (dp_prev - h dw_k); in slip lanes dp = f dq - r (p.dq) p
                    // with r = f/g^2, r = 0 in adhesion (f = 1 there).
                    const V hin = el.h * in;
                    const V dq[kTangents][2] = {
                        {in * tpx[0][g] - hin, in * tpy[0][g]},
                        {in * tpx[1][g], in * tpy[1][g] - hin},
                        {in * tpx[2][g] - hin * kwx[g], in * tpy[2][g] - hin * (kwy[g] + a * xs)},
                    };
                    if (s.any_slip) {
                        const V r = s.slip * s.f * simd::load<W>(inv_bound2 + e);
                        CREEPWORK_UNROLL
                        for (int k = 0; k < kTangents; ++k)
                            projection_derivative<W>(s, r, dq[k][0], dq[k][1], tpx[k][g],
                                                     tpy[k][g]);
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
                });
            }
        }
        CREEPWORK_UNROLL
        for (int g = 0; g < G; ++g) {
            const int j = j0 + g * W;
            strip[g].finish(v, j);
            CREEPWORK_UNROLL
            for (int k = 0; k < kTangents; ++k) {
                simd::store<W>(A.sum_px + k * stride + j, tspx[k][g]);
                simd::store<W>(A.sum_py + k * stride + j, tspy[k][g]);
                simd::store<W>(A.sum_x_py + k * stride + j, tsxpy[k][g]);
            }
        }
    }

    // A strip's tangent march holds 25 vectors of state: groups of two
    // vectors fit AVX2's and SSE2's cycle better (measured), AVX-512's 32
    // registers only one vector without spilling (measured 10-15 % faster
    // than two).
    template <int W>
    CREEPWORK_INLINE static void run(const TangentArgs& A)
    {
        const MarchView& v = A.march;
        const int vectors = (v.last - v.first + W - 1) / W;
        int k = 0;
        if (W < 8)
            for (; k + 2 <= vectors; k += 2) group<W, 2>(A, v.first + k * W);
        for (; k + 1 < vectors; ++k) group<W, 1>(A, v.first + k * W);
        if (k < vectors) group<W, 1>(A, v.first + k * W);
    }
};

} // namespace

void set_kappa_slip(const ContactGrid& grid, const ModelSetup& setup, TangentState& t)
{
    const NormalisedKinematics& kin = setup.kin;
    for (int j = 0; j < grid.ny(); ++j) {
        t.kappa_wx[j] = -setup.b * grid.y_centre()[j];
        t.kappa_wy[j] = kin.spin_offset > 0.0 ? setup.a * (kin.spin_offset * grid.x_length()[j])
                                              : 0.0;
    }
}

void march_tangent(const MarchView& view, const ContactGrid& grid, const ModelSetup& setup,
                   TangentState& t, KernelIsa isa)
{
    set_kappa_slip(grid, setup, t);
    TangentArgs A;
    A.march = view;
    A.a = setup.a;
    A.inv_bound2 = setup.pressure == PressureKind::parabolic ? t.inv_bound2_parabolic.data()
                                                             : t.inv_bound2_elliptic.data();
    A.kappa_wx = t.kappa_wx.data();
    A.kappa_wy = t.kappa_wy.data();
    A.sum_px = t.sum_px.data();
    A.sum_py = t.sum_py.data();
    A.sum_x_py = t.sum_x_py.data();
    run_kernel<TangentKernel>(isa, A);
}

} // namespace creepwork
