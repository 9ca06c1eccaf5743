#include "march/march.hpp"

#include "march/march_step.hpp"

namespace creepwork {

MarchView march_view(const MarchGeometry& geo, const double* bound, double cy, MarchState& s,
                     int first, int last)
{
    MarchView v;
    v.nx = geo.nx;
    v.stride = geo.stride;
    v.first = first;
    v.last = last;
    v.cy = cy;
    v.x_centre = geo.x_centre.data();
    v.x_slip = geo.x_slip.data();
    v.step = geo.step.data();
    v.inside = geo.inside.data();
    v.bound = bound;
    v.wx = s.wx.data();
    v.wy = s.wy.data();
    v.qx = s.qx.data();
    v.qy = s.qy.data();
    v.factor = s.factor.data();
    v.px = s.px.data();
    v.py = s.py.data();
    v.sum_px = s.sum_px.data();
    v.sum_py = s.sum_py.data();
    v.sum_x_py = s.sum_x_py.data();
    v.slip_count = s.slip_count.data();
    return v;
}

namespace {

// The plain march.
struct MarchKernel : KernelWidths {
    // G vectors of W strips from strip j0, leading edge to trailing edge: the
    // G chains are independent, so their steps overlap in the pipeline.
    template <int W, int G>
    CREEPWORK_INLINE static void group(const MarchView& v, int j0)
    {
        const MarchRows rows(v, j0);
        const int nx = v.nx;
        const long stride = v.stride;
        const simd::Vec<W> cy = simd::broadcast<W>(v.cy);
        PrimalStrip<W> strip[G];
        CREEPWORK_UNROLL
        for (int g = 0; g < G; ++g) strip[g].start(v, j0 + g * W);
        for (int m = 0; m < nx; ++m) {
            const long row = m * stride;
            CREEPWORK_UNROLL
            for (int g = 0; g < G; ++g) strip[g].advance(rows, row + g * W, cy);
        }
        CREEPWORK_UNROLL
        for (int g = 0; g < G; ++g) strip[g].finish(v, j0 + g * W);
    }

    // Groups of four vectors, then the vectors left (only those holding strips).
    template <int W>
    CREEPWORK_INLINE static void run(const MarchView& v)
    {
        const int vectors = (v.last - v.first + W - 1) / W;
        int k = 0;
        for (; k + 4 <= vectors; k += 4) group<W, 4>(v, v.first + k * W);
        switch (vectors - k) {
        case 3: group<W, 3>(v, v.first + k * W); break;
        case 2: group<W, 2>(v, v.first + k * W); break;
        case 1: group<W, 1>(v, v.first + k * W); break;
        default: break;
        }
    }
};

} // namespace

void march(const MarchView& view, KernelIsa isa) { run_kernel<MarchKernel>(isa, view); }

void rigid_slip_of_strips(const ContactGrid& grid, const NormalisedKinematics& kin, double* wx,
                          double* wy, int first, int last)
{
    for (int j = first; j < last; ++j) {
        wx[j] = kin.ux - kin.cx * grid.y_centre()[j];
        // Without an offset exactly uy, so that plain FASTSIM is unchanged
        // to the bit (uy + cy * 0 could flip the sign of a zero).
        wy[j] = kin.spin_offset > 0.0 ? kin.uy + kin.cy * (kin.spin_offset * grid.x_length()[j])
                                      : kin.uy;
    }
}

void set_rigid_slip(const ContactGrid& grid, const NormalisedKinematics& kin, MarchState& s,
                    int first, int last)
{
    rigid_slip_of_strips(grid, kin, s.wx.data(), s.wy.data(), first, last);
}

void march(const ContactGrid& grid, const NormalisedKinematics& kin, PressureKind pressure,
           MarchState& state, KernelIsa isa)
{
    const MarchGeometry geo(grid);
    const int ny = grid.ny();
    set_rigid_slip(grid, kin, state, 0, ny);
    march(march_view(geo, geo.shape(pressure).data(), kin.cy, state, 0, ny), isa);
}

namespace {

// N = 0: the forces alone, with no per-strip test of the tangent count.
template <int N>
void forces_and_tangents(const ContactGrid& grid, double a, double b, const MarchState& march,
                         const StripTangents* tangents, double Phi[3], double (*dPhi)[3])
{
    for (int i = 0; i < 3; ++i) {
        Phi[i] = 0.0;
        for (int k = 0; k < N; ++k) dPhi[i][k] = 0.0;
    }
    for (int j = 0; j < grid.ny(); ++j) {
        const double area = a * b * grid.x_length()[j] * grid.y_width()[j];
        const double y = b * grid.y_centre()[j];
        Phi[0] += area * march.sum_px[j];
        Phi[1] += area * march.sum_py[j];
        Phi[2] += area * (a * march.sum_x_py[j] - y * march.sum_px[j]);
        for (int k = 0; k < N; ++k) {
            const long e = static_cast<long>(k) * tangents->stride + j;
            dPhi[0][k] += area * tangents->sum_px[e];
            dPhi[1][k] += area * tangents->sum_py[e];
            dPhi[2][k] += area * (a * tangents->sum_x_py[e] - y * tangents->sum_px[e]);
        }
    }
}

} // namespace

void scaled_forces(const ContactGrid& grid, double a, double b, const MarchState& march,
                   double Phi[3])
{
    forces_and_tangents<0>(grid, a, b, march, nullptr, Phi, nullptr);
}

void scaled_forces(const ContactGrid& grid, double a, double b, const MarchState& march,
                   const StripTangents& tangents, double Phi[3],
                   double dPhi[3][kStripTangents])
{
    forces_and_tangents<kStripTangents>(grid, a, b, march, &tangents, Phi, dPhi);
}

} // namespace creepwork
