#include "contact/solved_contact.hpp"

#include <cstddef>

namespace creepwork {

namespace {

// op(out[i + nx j], value(k, i, j)) over the caller's elements, k the
// model's element: one tight loop per field.
template <class Op, class Value>
void each_element(const SolvedContact& c, const Op& op, double* out, const Value& value)
{
    const int nx = c.nx, ny = c.ny;
    const bool mirrored = c.mirrored;
    for (int j = 0; j < ny; ++j) {
        double* row = out + static_cast<size_t>(nx) * j;
        const long k0 = static_cast<long>(nx) * j;
        for (int i = 0; i < nx; ++i) op(row + i, value(k0 + (mirrored ? nx - 1 - i : i), i, j));
    }
}

// Every field's value at the caller's (i, j), written through op (store
// or add scaled). The formulas keep the order of operations of the models'
// own exports, so the bits are theirs. The view's members are read into
// locals first: the stores to out may alias anything.
template <class Op>
void export_with(const SolvedContact& c, Field f, const Op& op, double* out)
{
    const double d = c.direction, T = c.traction_scale, area = c.element_area;
    const double *x = c.x_column, *y = c.y_row;
    const std::complex<double>* q = c.traction;
    const std::complex<double>* s = c.slip;
    const signed char* state = c.state;
    const double S = c.slip_scale;
    switch (f) {
    case Field::x: each_element(c, op, out, [=](long, int i, int) { return x[i]; }); return;
    case Field::y: each_element(c, op, out, [=](long, int, int j) { return y[j]; }); return;
    // 0 outside the contact (creepwork.h).
    case Field::area:
        each_element(c, op, out, [=](long k, int, int) { return state[k] != 0 ? area : 0.0; });
        return;
    case Field::pz: {
        const double *p = c.pressure, P = c.pressure_scale;
        if (p)
            each_element(c, op, out, [=](long k, int, int) { return P * p[k]; });
        else
            each_element(c, op, out, [](long, int, int) { return 0.0; });
        return;
    }
    case Field::px:
        each_element(c, op, out, [=](long k, int, int) { return d * T * q[k].real(); });
        return;
    case Field::py:
        each_element(c, op, out, [=](long k, int, int) { return T * q[k].imag(); });
        return;
    case Field::sx:
        if (c.slip_masked)
            each_element(c, op, out, [=](long k, int, int) {
                return state[k] == 2 ? d * S * s[k].real() : 0.0;
            });
        else
            each_element(c, op, out, [=](long k, int, int) { return d * S * s[k].real(); });
        return;
    case Field::sy:
        if (c.slip_masked)
            each_element(c, op, out, [=](long k, int, int) {
                return state[k] == 2 ? S * s[k].imag() : 0.0;
            });
        else
            each_element(c, op, out, [=](long k, int, int) { return S * s[k].imag(); });
        return;
    case Field::mz:
        each_element(c, op, out, [=](long k, int i, int j) {
            const double px = d * T * q[k].real(), py = T * q[k].imag();
            return (x[i] * py - y[j] * px) * area;
        });
        return;
    case Field::work_paper: {
        const double* w = c.work_paper;
        each_element(c, op, out, [=](long k, int, int) { return w[k]; });
        return;
    }
    case Field::work_consistent: {
        const double* w = c.work_consistent;
        each_element(c, op, out, [=](long k, int, int) { return w[k]; });
        return;
    }
    }
}

} // namespace

void export_rows(const SolvedContact& c, Field f, double* out)
{
    export_with(c, f, StoreField{}, out);
}

void add_rows(const SolvedContact& c, Field f, double scale, double* out)
{
    export_with(c, f, AddScaledField{scale}, out);
}

void export_rows_state(const SolvedContact& c, int* out)
{
    for (int j = 0; j < c.ny; ++j)
        for (int i = 0; i < c.nx; ++i) out[i + static_cast<size_t>(c.nx) * j] = c.state[c.index(i, j)];
}

void export_profile(const SolvedContact& c, double W, double* y, double* work, double* parabola)
{
    for (int j = 0; j < c.ny; ++j) {
        const double yj = c.y(j);
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
