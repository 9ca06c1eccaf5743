#include "contact/solved_contact.hpp"

#include <cstddef>

namespace creepwork {

namespace {

// Every field's value at the caller's (i, j), written through op (store
// or add scaled). The formulas keep the order of operations of the models'
// own exports, so the bits are theirs.
template <class Op>
void export_with(const SolvedContact& c, Field f, const Op& op, double* out)
{
    const double d = c.direction, T = c.traction_scale, area = c.element_area;
    for (int j = 0; j < c.ny; ++j) {
        const double y = c.y_row[j];
        for (int i = 0; i < c.nx; ++i) {
            const long k = c.index(i, j);
            const double x = c.x_column[i];
            const std::complex<double> q = c.traction[k];
            const double px = d * T * q.real(), py = T * q.imag();
            const bool slips = c.state[k] == 2;
            const bool slip_zero = c.slip_masked && !slips;
            double v = 0.0;
            switch (f) {
            case Field::x: v = x; break;
            case Field::y: v = y; break;
            // 0 outside the contact (creepwork.h).
            case Field::area: v = c.state[k] != 0 ? area : 0.0; break;
            case Field::pz: v = c.pressure ? c.pressure_scale * c.pressure[k] : 0.0; break;
            case Field::px: v = px; break;
            case Field::py: v = py; break;
            case Field::sx: v = slip_zero ? 0.0 : d * c.slip_scale * c.slip[k].real(); break;
            case Field::sy: v = slip_zero ? 0.0 : c.slip_scale * c.slip[k].imag(); break;
            case Field::mz: v = (x * py - y * px) * area; break;
            case Field::work_paper: v = c.work_paper[k]; break;
            case Field::work_consistent: v = c.work_consistent[k]; break;
            }
            op(out + i + static_cast<size_t>(c.nx) * j, v);
        }
    }
}

} // namespace

void export_field(const SolvedContact& c, Field f, double* out)
{
    export_with(c, f, StoreField{}, out);
}

void add_field(const SolvedContact& c, Field f, double scale, double* out)
{
    export_with(c, f, AddScaledField{scale}, out);
}

void export_state(const SolvedContact& c, int* out)
{
    for (int j = 0; j < c.ny; ++j)
        for (int i = 0; i < c.nx; ++i) out[i + static_cast<size_t>(c.nx) * j] = c.state[c.index(i, j)];
}

void export_profile(const SolvedContact& c, double W, double* y, double* work, double* parabola)
{
    for (int j = 0; j < c.ny; ++j) {
        const double yj = c.y_row[j];
        if (y) y[j] = yj;
        if (work) work[j] = c.profile[j];
        if (parabola) parabola[j] = lateral_parabola(W, c.profile_b, yj - c.profile_y_mid);
    }
}

double lateral_parabola(double W, double b, double y)
{
    const double r = 1.0 - (y / b) * (y / b);
    return r > 0.0 ? 0.75 * W / b * r : 0.0;
}

} // namespace creepwork
