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
    int* slip_count = s.slip_count.data();
    for (int j = 0; j < ny; ++j) {
        px[j] = py[j] = sum_px[j] = sum_py[j] = sum_x_py[j] = 0.0;
        slip_count[j] = 0;
    }

    const double ux = kin.ux, uy = kin.uy, cx = kin.cx, cy = kin.cy;
    for (int m = 0; m < nx; ++m) {
        const long base = static_cast<long>(m) * ny;
        double* qx_out = s.qx.data() + base;
        double* qy_out = s.qy.data() + base;
        double* f_out = s.factor.data() + base;
        // Elastic predictor u = u_prev - h w (here divided by L mu p0), then
        // Coulomb: scale onto the bound g when |q| > g. Exterior elements
        // (uniform grid) reset the displacement to zero.
        for (int j = 0; j < ny; ++j) {
            const long k = base + j;
            const double h = step[k];
            const double qx = inside[k] * (px[j] - h * (ux - cx * y[j]));
            const double qy = inside[k] * (py[j] - h * (uy + cy * x_slip[k]));
            const double g = bound[k];
            const double t2 = qx * qx + qy * qy;
            const bool slip = t2 > g * g;
            const double f = slip ? g / std::sqrt(t2) : 1.0;
            const double pxn = f * qx;
            const double pyn = f * qy;
            qx_out[j] = qx;
            qy_out[j] = qy;
            f_out[j] = f;
            px[j] = pxn;
            py[j] = pyn;
            sum_px[j] += pxn;
            sum_py[j] += pyn;
            sum_x_py[j] += x_centre[k] * pyn;
            slip_count[j] += slip ? 1 : 0;
        }
    }
}

} // namespace creepwork
