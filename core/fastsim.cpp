#include "fastsim.hpp"

#include <cmath>

namespace creepwork {

void MarchState::resize(int n_elements, int ny)
{
    qx.setZero(n_elements);
    qy.setZero(n_elements);
    factor.setZero(n_elements);
    sum_px.setZero(ny);
    sum_py.setZero(ny);
    sum_x_py.setZero(ny);
    slip_count.setZero(ny);
    px.setZero(ny);
    py.setZero(ny);
}

namespace {

constexpr double kTiny = 2.2250738585072014e-308; // DBL_MIN

// One step of every strip: the elastic predictor u = u_prev - h w (divided
// by L mu p0), then Coulomb: slip when |q| > g, and then p = f q with
// f = g/|q| < 1; otherwise f = 1 (exterior elements have q = g = 0).
// Exterior elements (uniform grid) reset the displacement to zero. Written
// branch-free over restrict pointers so the compiler vectorises across
// strips; the division never sees a zero (hosts may trap FP exceptions).
void step_strips(int ny, double ux, double uy, double cx, double cy,
                 const double* __restrict y, const double* __restrict x_centre,
                 const double* __restrict x_slip, const double* __restrict step,
                 const double* __restrict inside, const double* __restrict bound,
                 double* __restrict px, double* __restrict py, double* __restrict qx_out,
                 double* __restrict qy_out, double* __restrict f_out,
                 double* __restrict sum_px, double* __restrict sum_py,
                 double* __restrict sum_x_py, double* __restrict slip_count)
{
    for (int j = 0; j < ny; ++j) {
        const double h = step[j];
        const double qx = inside[j] * (px[j] - h * (ux - cx * y[j]));
        const double qy = inside[j] * (py[j] - h * (uy + cy * x_slip[j]));
        const double norm = std::sqrt(qx * qx + qy * qy);
        const double safe_norm = norm > kTiny ? norm : kTiny;
        const bool slip = norm > bound[j];
        const double f = slip ? bound[j] / safe_norm : 1.0;
        const double pxn = f * qx;
        const double pyn = f * qy;
        qx_out[j] = qx;
        qy_out[j] = qy;
        f_out[j] = f;
        px[j] = pxn;
        py[j] = pyn;
        sum_px[j] += pxn;
        sum_py[j] += pyn;
        sum_x_py[j] += x_centre[j] * pyn;
        slip_count[j] += slip ? 1.0 : 0.0;
    }
}

} // namespace

void march(const ContactGrid& grid, const NormalisedKinematics& kin, PressureKind pressure,
           MarchState& s)
{
    const int nx = grid.nx();
    const int ny = grid.ny();
    const double* x_centre = grid.x_centre().data();
    const double* x_slip = grid.x_slip().data();
    const double* step = grid.step().data();
    const double* inside = grid.in_contact().data();
    const double* bound = grid.pressure_shape(pressure).data();
    const double* y = grid.y_centre().data();

    double* px = s.px.data();
    double* py = s.py.data();
    double* sum_px = s.sum_px.data();
    double* sum_py = s.sum_py.data();
    double* sum_x_py = s.sum_x_py.data();
    double* slip_count = s.slip_count.data();
    for (int j = 0; j < ny; ++j) {
        px[j] = py[j] = sum_px[j] = sum_py[j] = sum_x_py[j] = 0.0;
        slip_count[j] = 0.0;
    }

    const double ux = kin.ux, uy = kin.uy, cx = kin.cx, cy = kin.cy;
    for (int m = 0; m < nx; ++m) {
        const long base = static_cast<long>(m) * ny;
        step_strips(ny, ux, uy, cx, cy, y, x_centre + base, x_slip + base, step + base,
                    inside + base, bound + base, px, py, s.qx.data() + base,
                    s.qy.data() + base, s.factor.data() + base, sum_px, sum_py, sum_x_py,
                    slip_count);
    }
}

} // namespace creepwork
