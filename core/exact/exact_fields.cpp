// Field export of the exact model (exact_model.hpp): element (i, j) of the
// caller's layout [i + nx j] is element (i', j) of the rolling frame with
// i' = i, or i' = nx - 1 - i when rolling towards -x (then the x parts of
// tractions and slips change sign).
#include "exact/exact_model.hpp"
#include "exact/exact_work.hpp"

namespace creepwork {
template <class Op>
void ExactModel::export_field(Field f, const Op& op, double* out) const
{
    const Level& L = *levels_[0];
    const Setup& s = setup_;
    const auto& q = L.tangential.traction();
    const auto& sl = L.tangential.slip();
    const auto& state = L.tangential.state();
    const std::vector<double>& qn = L.normal.pressure();
    const bool loaded = s.p0 > 0.0;
    const double d = s.direction, T = s.traction_scale, area = s.dx * s.dy;
    for (int j = 0; j < ny_; ++j) {
        const double y = L.geom.Y(j) * s.dx;
        for (int i = 0; i < nx_; ++i) {
            const int k = (d > 0 ? i : nx_ - 1 - i) + nx_ * j; // rolling frame
            const double x = L.geom.X(i) * s.dx;               // caller's frame
            const double px = d * T * q[k].real(), py = T * q[k].imag();
            const bool slips = state[k] == 2;
            double v = 0.0;
            switch (f) {
            case Field::x: v = x; break;
            case Field::y: v = y; break;
            // creepwork.h: 0 outside the contact, as FASTSIM reports it.
            case Field::area: v = state[k] != 0 ? area : 0.0; break;
            case Field::pz: v = loaded ? s.p0 * qn[k] : 0.0; break;
            case Field::px: v = px; break;
            case Field::py: v = py; break;
            case Field::sx: v = slips ? d * s.slip_scale * sl[k].real() : 0.0; break;
            case Field::sy: v = slips ? s.slip_scale * sl[k].imag() : 0.0; break;
            case Field::mz: v = (x * py - y * px) * area; break;
            case Field::work_paper: v = paper_[k]; break;
            case Field::work_consistent: v = consistent_[k]; break;
            }
            op(out + i + static_cast<size_t>(nx_) * j, v);
        }
    }
}

void ExactModel::copy_field(Field f, double* out) const { export_field(f, StoreField{}, out); }

void ExactModel::add_field(Field f, double scale, double* out) const
{
    export_field(f, AddScaledField{scale}, out);
}

void ExactModel::copy_state(int* out) const
{
    const auto& state = levels_[0]->tangential.state();
    for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i)
            out[i + nx_ * j] = state[(setup_.direction > 0 ? i : nx_ - 1 - i) + nx_ * j];
}

void ExactModel::copy_profile(double W, double* y, double* work, double* parabola) const
{
    const Level& L = *levels_[0];
    for (int j = 0; j < ny_; ++j) {
        const double yj = L.geom.Y(j) * setup_.dx;
        if (y) y[j] = yj;
        if (work) work[j] = profile_[j];
        if (parabola) parabola[j] = lateral_parabola(W, setup_.b, yj);
    }
}

} // namespace creepwork
