// Field export of the models built on the march (march_model.hpp): each
// field is computed from the march's (q', f) while it is copied into the
// caller's layout.
#include <cstring>
#include <type_traits>

#include "march/march_model.hpp"
#include "simd/simd.hpp"

// The vector types below never cross a non-inlined call: their ABI is moot.
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace creepwork {

// ------------------------------------------------------------ field export
//
// Element (i, j) of the caller's layout [i + j*nx] is kernel element (m, j)
// at [m*stride + j], with m = nx-1-i when rolling towards +x (the march
// starts at the leading edge x = +a) and m = i otherwise. Each field is a
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

struct ExportArgs {
    int nx = 0, ny = 0, stride = 0; // per-element arrays are [m * stride + j]
    bool reverse = false;
    double d = 0, a = 0, b = 0, ab = 0, T = 0, dT = 0, p0 = 0;
    const double *x_centre = nullptr, *inside = nullptr, *shape = nullptr; // per element (MarchGeometry)
    const double *y_centre = nullptr, *x_length = nullptr, *y_width = nullptr; // per strip (ContactGrid)
    const double *qx = nullptr, *qy = nullptr, *factor = nullptr; // per element (MarchState)
    const double *slip_x = nullptr, *slip_y = nullptr, *paper = nullptr,
                 *consistent = nullptr; // per element (WorkState)
};

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
    const ExportArgs* A;
    template <class V>
    CREEPWORK_INLINE V operator()(long k, int j) const
    {
        const V area = A->ab * load_as<V>(A->x_length + j) * load_as<V>(A->y_width + j);
        return select_nonzero(load_as<V>(A->inside + k), area, V{});
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
    const ExportArgs* A;
    template <class V>
    CREEPWORK_INLINE V operator()(long k, int j) const
    {
        const V f = load_as<V>(A->factor + k);
        const V px = A->T * (f * load_as<V>(A->qx + k));
        const V py = A->T * (f * load_as<V>(A->qy + k));
        const V area = A->ab * load_as<V>(A->x_length + j) * load_as<V>(A->y_width + j);
        return A->d * area *
               (A->a * load_as<V>(A->x_centre + k) * py - A->b * load_as<V>(A->y_centre + j) * px);
    }
};
struct State { // CW_STATE_*: 0 exterior, 1 adhesion, 2 slip
    const ExportArgs* A;
    template <class V>
    CREEPWORK_INLINE V operator()(long k, int) const
    {
        const V one = V{} + 1.0;
        return select_nonzero(load_as<V>(A->inside + k),
                              select_below_one(load_as<V>(A->factor + k), one + one, one), V{});
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
CREEPWORK_INLINE void export_grid(const ExportArgs& A, const F& f, const Op& op, Out* out)
{
    using V = Vec<B>;
    const int nx = A.nx, ny = A.ny, stride = A.stride;
    const int nxb = nx / B * B, nyb = ny / B * B;
    const bool reverse = A.reverse;
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
    CREEPWORK_INLINE static void run(const ExportArgs& A, const Field& f, const Op& op,
                                     double* const& out)
    {
        switch (f) {
        case Field::x: export_grid<B>(A, Scaled{A.x_centre, A.d * A.a}, op, out); return;
        case Field::y: export_grid<B>(A, StripY{A.y_centre, A.b}, op, out); return;
        case Field::area: export_grid<B>(A, Area{&A}, op, out); return;
        case Field::pz: export_grid<B>(A, Scaled{A.shape, A.p0}, op, out); return;
        case Field::px: export_grid<B>(A, Traction{A.qx, A.factor, A.dT}, op, out); return;
        case Field::py: export_grid<B>(A, Traction{A.qy, A.factor, A.T}, op, out); return;
        case Field::sx: export_grid<B>(A, Scaled{A.slip_x, A.d}, op, out); return;
        case Field::sy: export_grid<B>(A, Copied{A.slip_y}, op, out); return;
        case Field::mz: export_grid<B>(A, Moment{&A}, op, out); return;
        case Field::work_paper: export_grid<B>(A, Copied{A.paper}, op, out); return;
        case Field::work_consistent: export_grid<B>(A, Copied{A.consistent}, op, out); return;
        }
    }
};
struct StateKernel : KernelWidths {
    static constexpr int avx512 = 4;
    template <int B>
    CREEPWORK_INLINE static void run(const ExportArgs& A, int* const& out)
    {
        export_grid<B>(A, State{&A}, AssignInt{}, out);
    }
};

ExportArgs export_args(const MarchGeometry& geo, const double* bound, const ContactGrid& g,
                       const ModelSetup& s, const MarchState& m, const WorkState& w)
{
    ExportArgs A;
    A.nx = g.nx();
    A.ny = g.ny();
    A.stride = geo.stride;
    A.reverse = s.direction > 0;
    A.d = s.direction;
    A.a = s.a;
    A.b = s.b;
    A.ab = s.a * s.b;
    A.T = s.traction_scale;
    A.dT = A.d * A.T;
    A.p0 = s.pressure_scale;
    A.x_centre = geo.x_centre.data();
    A.inside = geo.inside.data();
    A.shape = bound;
    A.y_centre = g.y_centre().data();
    A.x_length = g.x_length().data();
    A.y_width = g.y_width().data();
    A.qx = m.qx.data();
    A.qy = m.qy.data();
    A.factor = m.factor.data();
    A.slip_x = w.slip_x.data();
    A.slip_y = w.slip_y.data();
    A.paper = w.paper.data();
    A.consistent = w.consistent.data();
    return A;
}

} // namespace

template <class Op>
void MarchModel::export_field(Field f, const Op& op, double* out) const
{
    const ExportArgs A = export_args(geometry_, bound_, *grid_, setup_, state_, work_);
    run_kernel<ExportKernel>(isa_, A, f, op, out);
}

void MarchModel::copy_field(Field f, double* out) const { export_field(f, Assign{}, out); }

void MarchModel::add_field(Field f, double scale, double* out) const
{
    export_field(f, AddScaled{scale}, out);
}

void MarchModel::copy_state(int* out) const
{
    const ExportArgs A = export_args(geometry_, bound_, *grid_, setup_, state_, work_);
    run_kernel<StateKernel>(isa_, A, out);
}

} // namespace creepwork
