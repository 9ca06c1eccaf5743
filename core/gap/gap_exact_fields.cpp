// Field export of the exact gap model (gap_exact_model.hpp): element (i, j) of the
// caller's layout [i + nx j] is element (i', j) of the rolling frame with
// i' = i, or i' = nx - 1 - i when rolling towards -x (then the x parts of
// tractions and slips change sign). Positions are the grid's own: x0 + i dx,
// y0 + j dy; the moment is about the grid's origin.
#include "exact/exact_work.hpp"
#include "gap/gap_exact_model.hpp"

namespace creepwork {
template <class Op>
void GapExactModel::export_field(Field f, const Op& op, double* out) const
{
    const Setup& s = setup_;
    const auto& q = traction_;
    const auto& sl = slip_;
    const auto& state = state_;
    const std::vector<double>& pressure = normal_.pressure();
    const double d = s.direction, T = s.traction_scale, area = grid_.dx * grid_.dy;
    for (int j = 0; j < ny_; ++j) {
        const double y = grid_.y0 + j * grid_.dy;
        for (int i = 0; i < nx_; ++i) {
            const int k = caller_index(i) + nx_ * j; // rolling frame
            const double x = grid_.x0 + i * grid_.dx;
            const double px = d * T * q[k].real(), py = T * q[k].imag();
            const bool slips = state[k] == 2;
            double v = 0.0;
            switch (f) {
            case Field::x: v = x; break;
            case Field::y: v = y; break;
            case Field::area: v = state[k] != 0 ? area : 0.0; break;
            case Field::pz: v = pressure[k]; break;
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

void GapExactModel::copy_field(Field f, double* out) const { export_field(f, StoreField{}, out); }

void GapExactModel::add_field(Field f, double scale, double* out) const
{
    export_field(f, AddScaledField{scale}, out);
}

void GapExactModel::copy_state(int* out) const
{
    for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i) out[i + nx_ * j] = state_[caller_index(i) + nx_ * j];
}

void GapExactModel::copy_profile(double W, double* y, double* work, double* parabola) const
{
    const double b = setup_.half_width > 0.0 ? setup_.half_width : grid_.dy;
    for (int j = 0; j < ny_; ++j) {
        const double yj = grid_.y0 + j * grid_.dy;
        if (y) y[j] = yj;
        if (work) work[j] = profile_[j];
        if (parabola) parabola[j] = lateral_parabola(W, b, yj - setup_.y_mid);
    }
}

bool GapExactModel::copy_strips(double* y, double* width) const
{
    copy_gap_rows(grid_, y, width);
    return true;
}

} // namespace creepwork
