// The field export of the view's strips layout (solved_contact.hpp: the
// march models'): each field is computed from the march's (q', f) while it
// is copied into the caller's layout.
#include <cstring>
#include <type_traits>

#include "contact/solved_contact.hpp"
#include "simd/simd.hpp"

// The vector types below never cross a non-inlined call: their ABI is moot.
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace creepwork {

// ------------------------------------------------------------ field export
//
// Element (i, j) of the caller's layout [i + j*nx] is kernel element (m, j)
// at [m*stride + j], with m = nx-1-i when the view is mirrored (the march
// rolling towards +x starts at the leading edge x = +a) and m = i otherwise. Each field is a
// functor evaluated on B consecutive strips of one march row at once (GCC/
// Clang vector extensions: one source for every kernel ISA; B = 2 for SSE2,
// 4 otherwise); B rows are transposed in registers and stored as B runs of i.
namespace {

template <int B>
using Vec = simd::Vec<B>;
using simd::load_as;

// c != 0 ? x : y and c < 1 ? x : y, lane by lane.
template <class V>
CREEPWORK_INLINE V select_nonzero(const V& c, const V& x, const V& y)
{
    return c != V{} ? x : y;
}
template <class V>
CREEPWORK_INLINE V select_below_one(const V& c, const V& x, const V& y)
{
    return c < V{} + 1.0 ? x : y;
}

// Fields: value at kernel index k (first lane) in strip j (first lane).
// Each computes exactly what the per-element formula in the comment says.
struct Scaled { // c * src[k]: x (c = d a), pz (c = p0), sx (c = d)
    const double* src;
    double c;
    template <class V>
    CREEPWORK_INLINE V operator()(long k, int) const { return c * load_as<V>(src + k); }
};
struct Copied { // src[k]: sy, work_paper, work_consistent
    const double* src;
    template <class V>
    CREEPWORK_INLINE V operator()(long k, int) const { return load_as<V>(src + k); }
};
struct StripY { // b * Y_j
    const double* y_centre;
    double b;
    template <class V>
    CREEPWORK_INLINE V operator()(long, int j) const { return b * load_as<V>(y_centre + j); }
};
struct Area { // a b dX_j dY_j inside, 0 outside
    const SolvedStrips* S;
    double ab;
    template <class V>
    CREEPWORK_INLINE V operator()(long k, int j) const
    {
        const V area = ab * load_as<V>(S->x_length + j) * load_as<V>(S->y_width + j);
        return select_nonzero(load_as<V>(S->inside + k), area, V{});
    }
};
struct Traction { // scale * (f q'): f q' first, T f alone can underflow
    const double *q, *factor;
    double scale;
    template <class V>
    CREEPWORK_INLINE V operator()(long k, int) const
    {
        return scale * (load_as<V>(factor + k) * load_as<V>(q + k));
    }
};
struct Moment { // d area (x py - y px), tractions on the wheel
    const SolvedStrips* S;
    double T, ab, d;
    template <class V>
    CREEPWORK_INLINE V operator()(long k, int j) const
    {
        const V f = load_as<V>(S->factor + k);
        const V px = T * (f * load_as<V>(S->qx + k));
        const V py = T * (f * load_as<V>(S->qy + k));
        const V area = ab * load_as<V>(S->x_length + j) * load_as<V>(S->y_width + j);
        return d * area *
               (S->a * load_as<V>(S->x_centre + k) * py - S->b * load_as<V>(S->y_centre + j) * px);
    }
};
struct State { // CW_STATE_*: 0 exterior, 1 adhesion, 2 slip
    const SolvedStrips* S;
    template <class V>
    CREEPWORK_INLINE V operator()(long k, int) const
    {
        const V one = V{} + 1.0;
        return select_nonzero(load_as<V>(S->inside + k),
                              select_below_one(load_as<V>(S->factor + k), one + one, one), V{});
    }
};

// Stores: out = v, out += scale v, out = int(v).
struct Assign {
    CREEPWORK_INLINE void operator()(double* out, double v) const { *out = v; }
    template <class V>
    CREEPWORK_INLINE void operator()(double* out, const V& v) const
    {
        std::memcpy(out, &v, sizeof v);
    }
};
struct AddScaled {
    double scale;
    CREEPWORK_INLINE void operator()(double* out, double v) const { *out += scale * v; }
    template <class V>
    CREEPWORK_INLINE void operator()(double* out, const V& v) const
    {
        V o;
        std::memcpy(&o, out, sizeof o);
        o += scale * v;
        std::memcpy(out, &o, sizeof o);
    }
};
struct AssignInt {
    CREEPWORK_INLINE void operator()(int* out, double v) const { *out = static_cast<int>(v); }
    template <class V>
    CREEPWORK_INLINE void operator()(int* out, const V& v) const
    {
        typedef int Ints __attribute__((vector_size(sizeof(V) / 2)));
        const Ints w = __builtin_convertvector(v, Ints);
        std::memcpy(out, &w, sizeof w);
    }
};

// r[r][q] = field(i0 + r, j0 + q) -> stored as column q: out[i0.. + (j0+q) nx].
template <class Op, class Out>
CREEPWORK_INLINE void store_transposed(const Op& op, Out* o, int nx, const Vec<2> (&r)[2])
{
    op(o, __builtin_shufflevector(r[0], r[1], 0, 2));
    op(o + nx, __builtin_shufflevector(r[0], r[1], 1, 3));
}
template <class Op, class Out>
CREEPWORK_INLINE void store_transposed(const Op& op, Out* o, int nx, const Vec<4> (&r)[4])
{
    const Vec<4> t0 = __builtin_shufflevector(r[0], r[1], 0, 4, 2, 6);
    const Vec<4> t1 = __builtin_shufflevector(r[0], r[1], 1, 5, 3, 7);
    const Vec<4> t2 = __builtin_shufflevector(r[2], r[3], 0, 4, 2, 6);
    const Vec<4> t3 = __builtin_shufflevector(r[2], r[3], 1, 5, 3, 7);
    op(o, __builtin_shufflevector(t0, t2, 0, 1, 4, 5));
    op(o + nx, __builtin_shufflevector(t1, t3, 0, 1, 4, 5));
    op(o + 2 * nx, __builtin_shufflevector(t0, t2, 2, 3, 6, 7));
    op(o + 3 * nx, __builtin_shufflevector(t1, t3, 2, 3, 6, 7));
}

template <int B, class F, class Op, class Out>
CREEPWORK_INLINE void export_grid(const SolvedContact& c, const F& f, const Op& op, Out* out)
{
    using V = Vec<B>;
    const int nx = c.nx, ny = c.ny, stride = c.strips.stride;
    const int nxb = nx / B * B, nyb = ny / B * B;
    const bool reverse = c.mirrored;
    auto row = [nx, stride, reverse](int i) {
        return static_cast<long>(reverse ? nx - 1 - i : i) * stride;
    };
    for (int j0 = 0; j0 < nyb; j0 += B) {
        Out* o = out + static_cast<long>(j0) * nx;
        for (int i0 = 0; i0 < nxb; i0 += B) {
            V r[B];
            CREEPWORK_UNROLL
            for (int q = 0; q < B; ++q) r[q] = f.template operator()<V>(row(i0 + q) + j0, j0);
            store_transposed(op, o + i0, nx, r);
        }
        for (int q = 0; q < B; ++q)
            for (int i = nxb; i < nx; ++i)
                op(o + q * nx + i, f.template operator()<double>(row(i) + j0 + q, j0 + q));
    }
    for (int j = nyb; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            op(out + static_cast<long>(j) * nx + i, f.template operator()<double>(row(i) + j, j));
}

// The export kernels: every field (with a store Op) and the state map. Four
// lanes suffice for AVX-512 too: the export is bound by its stores.
struct ExportKernel : KernelWidths {
    static constexpr int avx512 = 4;
    template <int B, class Op>
    CREEPWORK_INLINE static void run(const SolvedContact& c, const Field& f, const Op& op,
                                     double* const& out)
    {
        const SolvedStrips& s = c.strips;
        const double d = c.direction, T = c.traction_scale;
        switch (f) {
        case Field::x: export_grid<B>(c, Scaled{s.x_centre, d * s.a}, op, out); return;
        case Field::y: export_grid<B>(c, StripY{s.y_centre, s.b}, op, out); return;
        case Field::area: export_grid<B>(c, Area{&s, s.a * s.b}, op, out); return;
        case Field::pz: export_grid<B>(c, Scaled{c.pressure, c.pressure_scale}, op, out); return;
        case Field::px: export_grid<B>(c, Traction{s.qx, s.factor, d * T}, op, out); return;
        case Field::py: export_grid<B>(c, Traction{s.qy, s.factor, T}, op, out); return;
        case Field::sx: export_grid<B>(c, Scaled{s.slip_x, d}, op, out); return;
        case Field::sy: export_grid<B>(c, Copied{s.slip_y}, op, out); return;
        case Field::mz: export_grid<B>(c, Moment{&s, T, s.a * s.b, d}, op, out); return;
        case Field::work_paper: export_grid<B>(c, Copied{c.work_paper}, op, out); return;
        case Field::work_consistent:
            export_grid<B>(c, Copied{c.work_consistent}, op, out);
            return;
        }
    }
};
struct StateKernel : KernelWidths {
    static constexpr int avx512 = 4;
    template <int B>
    CREEPWORK_INLINE static void run(const SolvedContact& c, int* const& out)
    {
        export_grid<B>(c, State{&c.strips}, AssignInt{}, out);
    }
};

} // namespace

void export_strips(const SolvedContact& c, Field f, double* out)
{
    run_kernel<ExportKernel>(c.strips.isa, c, f, Assign{}, out);
}

void add_strips(const SolvedContact& c, Field f, double scale, double* out)
{
    run_kernel<ExportKernel>(c.strips.isa, c, f, AddScaled{scale}, out);
}

void export_strips_state(const SolvedContact& c, int* out)
{
    run_kernel<StateKernel>(c.strips.isa, c, out);
}

} // namespace creepwork
