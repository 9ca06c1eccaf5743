#include "fastsim/march_law.hpp"

#include "contact/fp_safe.hpp"
#include "friction/slip_speed_law_lanes.hpp"

namespace creepwork {

namespace {

// A Halley step below this fraction of the bound is the last: the root is
// within about its cube (times the law's curvature) of where it leads. Not
// across the linear law's kinks, where a step is wrong to first order in its
// length: there only a step below 1e-8 (Newton's, m'' = 0) is the last.
template <SlipSpeedLawKind Kind>
constexpr double kLawStepTolerance = Kind == SlipSpeedLawKind::linear ? 1e-8 : 1e-4;

template <SlipSpeedLawKind Kind, bool Tangents>
struct LawKernel : KernelWidths {
    static constexpr int K = kLawTangents;

    // The law at t (its slip speed s = c (P - t) >= 0) and Halley's step
    // on F(t) = t - g m(s) from there: F' = 1 + g c m', F'' = -g c^2 m'',
    // next = t - 2 F F' / (2 F'^2 - F F'') (Newton's where that denominator
    // is not positive; only where F' > 0), with m and m' moved to next to
    // second and first order: a last step costs no evaluation.
    template <int W>
    struct Step {
        simd::Vec<W> m, dm, res, slope, next, m_next, dm_next;
    };
    template <int W>
    CREEPWORK_INLINE static Step<W> step(const SlipSpeedLawLanes<Kind, W>& law,
                                         const simd::Vec<W>& t, const simd::Vec<W>& P,
                                         const simd::Vec<W>& c, const simd::Vec<W>& g)
    {
        using V = simd::Vec<W>;
        const V zero = simd::broadcast<W>(0.0), one = simd::broadcast<W>(1.0),
                two = simd::broadcast<W>(2.0), half = simd::broadcast<W>(0.5);
        Step<W> k;
        const V s0 = c * (P - t);
        const V s = s0 > zero ? s0 : zero;
        V d2m;
        law.value(s, k.m, k.dm, d2m);
        const V gc = g * c;
        k.res = t - g * k.m;
        k.slope = one + gc * k.dm;
        const V curv = -(gc * c * d2m);
        const V two_slope2 = two * k.slope * k.slope;
        const V den0 = two_slope2 - k.res * curv;
        const V den = den0 > zero ? den0 : two_slope2;
        k.next = t - two * k.res * k.slope / fp_opaque(k.slope > zero ? den : one);
        const V ds = c * (P - k.next) - s;
        k.m_next = k.m + ds * (k.dm + half * ds * d2m);
        k.dm_next = k.dm + ds * d2m;
        return k;
    }

    // G vectors of W strips from strip j0, leading edge to trailing edge.
    template <int W, int G>
    CREEPWORK_INLINE static void group(const LawMarch& A, int j0)
    {
        using V = simd::Vec<W>;
        const MarchView& v = A.view;
        const MarchRows rows(v, j0);
        const long stride = v.stride;
        const SlipSpeedLawLanes<Kind, W> law(A.law);
        const V zero = simd::broadcast<W>(0.0), one = simd::broadcast<W>(1.0),
                half = simd::broadcast<W>(0.5);
        const V tiny = simd::broadcast<W>(2.2250738585072014e-308); // DBL_MIN
        const V tol = simd::broadcast<W>(kLawStepTolerance<Kind>);
        const V cy = simd::broadcast<W>(v.cy), L1 = simd::broadcast<W>(A.L1),
                L2 = simd::broadcast<W>(A.L2), speed = simd::broadcast<W>(A.slip_speed_scale);

        V px[G], py[G], spx[G], spy[G], sxpy[G], nslip[G], wx[G], wy[G];
        V mprev[G], mstep[G], mmin[G], mmax[G], iters[G];
        [[maybe_unused]] V kwx[G], kwy[G], dpx[K][G], dpy[K][G], tsx[K][G], tsy[K][G],
            tsxy[K][G];
        CREEPWORK_UNROLL
        for (int g = 0; g < G; ++g) {
            const int j = j0 + g * W;
            px[g] = py[g] = spx[g] = spy[g] = sxpy[g] = nslip[g] = iters[g] = zero;
            wx[g] = simd::load<W>(v.wx + j);
            wy[g] = simd::load<W>(v.wy + j);
            mprev[g] = one;
            mstep[g] = zero;
            mmin[g] = simd::broadcast<W>(2.0);
            mmax[g] = -one;
            if constexpr (Tangents) {
                kwx[g] = simd::load<W>(A.kappa_wx + j);
                kwy[g] = simd::load<W>(A.kappa_wy + j);
                CREEPWORK_UNROLL
                for (int k = 0; k < K; ++k)
                    dpx[k][g] = dpy[k][g] = tsx[k][g] = tsy[k][g] = tsxy[k][g] = zero;
            }
        }

        for (int m = 0; m < v.nx; ++m) {
            const long row = m * stride;
            // The predictor of every vector, and whether any lane slips.
            V qx[G], qy[G], P[G], bnd[G], h[G], in[G], xs[G], slip[G];
            bool any = false;
            CREEPWORK_UNROLL
            for (int g = 0; g < G; ++g) {
                const long e = row + g * W;
                xs[g] = simd::load<W>(rows.x_slip + e);
                h[g] = simd::load<W>(rows.step + e);
                in[g] = simd::load<W>(rows.inside + e);
                bnd[g] = simd::load<W>(rows.bound + e);
                qx[g] = in[g] * (px[g] - h[g] * wx[g]);
                qy[g] = in[g] * (py[g] - h[g] * (wy[g] + cy * xs[g]));
                P[g] = simd::sqrt<W>(qx[g] * qx[g] + qy[g] * qy[g]);
                slip[g] = P[g] > bnd[g] ? one : zero;
                any = any || simd::max_lane(slip[g]) > 0.0;
            }
            V f[G], t[G], mu[G], dmu[G], c[G], safeP[G], lx[G], ly[G], Lq[G];
            CREEPWORK_UNROLL
            for (int g = 0; g < G; ++g) f[g] = one;
            if (any) {
                // Each slipping lane's start: m extrapolated along its strip.
                V start[G];
                CREEPWORK_UNROLL
                for (int g = 0; g < G; ++g) {
                    // Guarded divisors pass fp_opaque (contact/fp_safe.hpp): no
                    // lane, live or discarded, divides by zero.
                    safeP[g] = fp_opaque(P[g] > tiny ? P[g] : one);
                    lx[g] = L1 * qx[g];
                    ly[g] = L2 * qy[g];
                    Lq[g] = simd::sqrt<W>(lx[g] * lx[g] + ly[g] * ly[g]);
                    const V hs = slip[g] > zero ? h[g] : one;
                    c[g] = speed * Lq[g] / fp_opaque(safeP[g] * hs);
                    const V m_start = mprev[g] + mstep[g];
                    const V t0 = bnd[g] * (m_start > zero ? m_start : zero);
                    start[g] = t0 < bnd[g] ? t0 : bnd[g];
                }
                // One Halley step from the start. Where it is small and stays
                // in [0, g], it is the last (nearly every element: the start is
                // close); the other lanes iterate in the bracket below.
                V act[G], lo[G], hi[G], res[G], next[G];
                bool rest = false;
                CREEPWORK_UNROLL
                for (int g = 0; g < G; ++g) {
                    const Step<W> k = step<W>(law, start[g], P[g], c[g], bnd[g]);
                    // next is within tol g of the start: kept in [0, g].
                    const V in_range = k.next > zero ? (k.next < bnd[g] ? k.next : bnd[g]) : zero;
                    const V d = in_range - start[g];
                    const V done = k.slope > zero ? ((d < zero ? -d : d) <= tol * bnd[g] ? one : zero)
                                                  : zero;
                    t[g] = done > zero ? in_range : start[g];
                    mu[g] = done > zero ? k.m_next : k.m;
                    dmu[g] = done > zero ? k.dm_next : k.dm;
                    res[g] = k.res;
                    next[g] = k.slope > zero ? k.next : start[g];
                    iters[g] += slip[g];
                    act[g] = slip[g] > zero ? (done > zero ? zero : one) : zero;
                    rest = rest || simd::max_lane(act[g]) > 0.0;
                }
                // The other lanes: safeguarded Halley in the bracket [lo, hi]
                // of the root from that first step on, bisection where a step
                // leaves it, until a step is below tol g.
                if (rest) {
                    CREEPWORK_UNROLL
                    for (int g = 0; g < G; ++g) {
                        lo[g] = res[g] < zero ? start[g] : zero;
                        hi[g] = res[g] < zero ? bnd[g] : start[g];
                        const V mid = half * (lo[g] + hi[g]);
                        const V inside = next[g] > lo[g] ? (next[g] < hi[g] ? one : zero) : zero;
                        t[g] = act[g] > zero ? (inside > zero ? next[g] : mid) : t[g];
                        // A root at the start is not moved.
                        t[g] = act[g] > zero ? (res[g] == zero ? start[g] : t[g]) : t[g];
                        act[g] = act[g] > zero ? (res[g] == zero ? zero : one) : zero;
                    }
                }
                for (int it = 0; rest && it < 200; ++it) { // 200: bisection alone reaches rounding
                    bool more = false;
                    CREEPWORK_UNROLL
                    for (int g = 0; g < G; ++g) {
                        if (!(simd::max_lane(act[g]) > 0.0)) continue;
                        const Step<W> k = step<W>(law, t[g], P[g], c[g], bnd[g]);
                        const V live = act[g];
                        lo[g] = live > zero ? (k.res < zero ? t[g] : lo[g]) : lo[g];
                        hi[g] = live > zero ? (k.res < zero ? hi[g] : t[g]) : hi[g];
                        const V mid = half * (lo[g] + hi[g]);
                        V nx = k.slope > zero ? k.next : mid;
                        const V inside = nx > lo[g] ? (nx < hi[g] ? one : zero) : zero;
                        nx = inside > zero ? nx : mid;
                        const V d = nx - t[g];
                        const V small = (d < zero ? -d : d) <= tol * bnd[g] ? inside : zero;
                        const V root = k.res == zero ? one : zero;
                        const V last = root > zero ? zero : small;
                        mu[g] = live > zero ? (last > zero ? k.m_next : k.m) : mu[g];
                        dmu[g] = live > zero ? (last > zero ? k.dm_next : k.dm) : dmu[g];
                        t[g] = live > zero ? (root > zero ? t[g] : nx) : t[g];
                        iters[g] += live;
                        act[g] = live > zero ? (root > zero ? zero : (small > zero ? zero : one))
                                             : zero;
                        more = more || simd::max_lane(act[g]) > 0.0;
                    }
                    if (!more) break;
                }
                CREEPWORK_UNROLL
                for (int g = 0; g < G; ++g) {
                    f[g] = slip[g] > zero ? t[g] / safeP[g] : one;
                    // No step before the strip's first slipping element.
                    mstep[g] = slip[g] > zero ? (nslip[g] > zero ? mu[g] - mprev[g] : zero) : mstep[g];
                    mprev[g] = slip[g] > zero ? mu[g] : mprev[g];
                    mmin[g] = slip[g] > zero ? (mu[g] < mmin[g] ? mu[g] : mmin[g]) : mmin[g];
                    mmax[g] = slip[g] > zero ? (mu[g] > mmax[g] ? mu[g] : mmax[g]) : mmax[g];
                }
            }
            CREEPWORK_UNROLL
            for (int g = 0; g < G; ++g) {
                const long e = row + g * W;
                simd::store<W>(rows.qx + e, qx[g]);
                simd::store<W>(rows.qy + e, qy[g]);
                simd::store<W>(rows.factor + e, f[g]);
                px[g] = f[g] * qx[g];
                py[g] = f[g] * qy[g];
                spx[g] += px[g];
                spy[g] += py[g];
                const V xc = simd::load<W>(rows.x_centre + e);
                sxpy[g] += xc * py[g];
                nslip[g] += slip[g];
                if constexpr (Tangents) {
                    const V a = simd::broadcast<W>(A.a), hin = h[g] * in[g];
                    V dq[K][2] = {
                        {in[g] * dpx[0][g] - hin, in[g] * dpy[0][g]},
                        {in[g] * dpx[1][g], in[g] * dpy[1][g] - hin},
                        {in[g] * dpx[2][g] - hin * kwx[g],
                         in[g] * dpy[2][g] - hin * (kwy[g] + a * xs[g])},
                        {in[g] * dpx[3][g], in[g] * dpy[3][g]},
                    };
                    if (any) {
                        // dt = dt_dP dP + dt_dc dc; derivative 0 where 1 + g c m' = 0.
                        const V invP = one / safeP[g];
                        const V invLq = one / fp_opaque(Lq[g] > tiny ? Lq[g] : one);
                        const V dG = one + bnd[g] * c[g] * dmu[g];
                        const V gdm = (dG != zero ? bnd[g] * dmu[g] : zero) /
                                      fp_opaque(dG != zero ? dG : one);
                        const V dt_dP = gdm * c[g], dt_dc = gdm * (P[g] - t[g]);
                        CREEPWORK_UNROLL
                        for (int k = 0; k < K; ++k) {
                            const V dP = (qx[g] * dq[k][0] + qy[g] * dq[k][1]) * invP;
                            const V dLq = (L1 * lx[g] * dq[k][0] + L2 * ly[g] * dq[k][1]) * invLq;
                            V dc = c[g] * (dLq * invLq - dP * invP);
                            if (k == K - 1) dc += c[g];
                            const V dt = dt_dP * dP + dt_dc * dc;
                            const V df = (dt - f[g] * dP) * invP;
                            dpx[k][g] = slip[g] > zero ? df * qx[g] + f[g] * dq[k][0] : dq[k][0];
                            dpy[k][g] = slip[g] > zero ? df * qy[g] + f[g] * dq[k][1] : dq[k][1];
                        }
                    } else {
                        CREEPWORK_UNROLL
                        for (int k = 0; k < K; ++k) {
                            dpx[k][g] = dq[k][0];
                            dpy[k][g] = dq[k][1];
                        }
                    }
                    CREEPWORK_UNROLL
                    for (int k = 0; k < K; ++k) {
                        tsx[k][g] += dpx[k][g];
                        tsy[k][g] += dpy[k][g];
                        tsxy[k][g] += xc * dpy[k][g];
                    }
                }
            }
        }
        CREEPWORK_UNROLL
        for (int g = 0; g < G; ++g) {
            const int j = j0 + g * W;
            simd::store<W>(v.px + j, px[g]);
            simd::store<W>(v.py + j, py[g]);
            simd::store<W>(v.sum_px + j, spx[g]);
            simd::store<W>(v.sum_py + j, spy[g]);
            simd::store<W>(v.sum_x_py + j, sxpy[g]);
            simd::store<W>(v.slip_count + j, nslip[g]);
            simd::store<W>(A.ratio_min + j, mmin[g]);
            simd::store<W>(A.ratio_max + j, mmax[g]);
            simd::store<W>(A.iterations + j, iters[g]);
            if constexpr (Tangents) {
                CREEPWORK_UNROLL
                for (int k = 0; k < K; ++k) {
                    simd::store<W>(A.sum_px + k * stride + j, tsx[k][g]);
                    simd::store<W>(A.sum_py + k * stride + j, tsy[k][g]);
                    simd::store<W>(A.sum_x_py + k * stride + j, tsxy[k][g]);
                }
            }
        }
    }

    // Groups of two vectors, then one: the two strips' chains of dependent
    // operations overlap in the pipeline (the least CPU time; one vector a
    // group takes fewer instructions but as long as before, four spill more:
    // doc/dev/decisions.md); with tangents one (their state fills the
    // registers).
    template <int W>
    CREEPWORK_INLINE static void run(const LawMarch& A)
    {
        const MarchView& v = A.view;
        const int vectors = (v.last - v.first + W - 1) / W;
        int k = 0;
        if constexpr (!Tangents)
            for (; k + 2 <= vectors; k += 2) group<W, 2>(A, v.first + k * W);
        for (; k < vectors; ++k) group<W, 1>(A, v.first + k * W);
    }
};

template <SlipSpeedLawKind Kind>
void run_law(const LawMarch& A, KernelIsa isa)
{
    if (A.sum_px)
        run_kernel<LawKernel<Kind, true>>(isa, A);
    else
        run_kernel<LawKernel<Kind, false>>(isa, A);
}

} // namespace

void march_law(const LawMarch& A, KernelIsa isa)
{
    switch (A.law.kind) {
    case SlipSpeedLawKind::linear: run_law<SlipSpeedLawKind::linear>(A, isa); return;
    case SlipSpeedLawKind::rational: run_law<SlipSpeedLawKind::rational>(A, isa); return;
    case SlipSpeedLawKind::exponential: run_law<SlipSpeedLawKind::exponential>(A, isa); return;
    case SlipSpeedLawKind::coulomb: break;
    }
}

} // namespace creepwork
