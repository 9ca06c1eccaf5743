// Field export of FASTSIM on a gap grid (gap_fastsim_model.hpp): element
// (i, j) of the caller's layout [i + nx j] is element (i', j) of the rolling
// frame with i' = i, or i' = nx - 1 - i when rolling towards -x (then the x
// parts of tractions and slips change sign), as the exact gap model's
// (gap/gap_exact_fields.cpp). The moment is about the grid's origin.
#include "exact/exact_work.hpp"
#include "gap/gap_fastsim_model.hpp"

namespace creepwork {

template <class Op>
void GapFastsimModel::export_field(Field f, const Op& op, double* out) const
{
    const double d = direction_, area = grid_.dx * grid_.dy;
    const std::vector<double>& pressure = normal_.pressure();
    for (int j = 0; j < ny_; ++j) {
        const double y = grid_.y0 + j * grid_.dy;
        for (int i = 0; i < nx_; ++i) {
            const int k = caller_index(i) + nx_ * j; // rolling frame
            const double x = grid_.x0 + i * grid_.dx;
            const double px = d * p_[k].real(), py = p_[k].imag();
            double v = 0.0;
            switch (f) {
            case Field::x: v = x; break;
            case Field::y: v = y; break;
            case Field::area: v = state_[k] != 0 ? area : 0.0; break;
            case Field::pz: v = pressure[k]; break;
            case Field::px: v = px; break;
            case Field::py: v = py; break;
            case Field::sx: v = d * slip_[k].real(); break; // zero unless slipping
            case Field::sy: v = slip_[k].imag(); break;
            case Field::mz: v = (x * py - y * px) * area; break;
            case Field::work_paper: v = paper_[k]; break;
            case Field::work_consistent: v = consistent_[k]; break;
            }
            op(out + i + static_cast<size_t>(nx_) * j, v);
        }
    }
}

void GapFastsimModel::copy_field(Field f, double* out) const { export_field(f, StoreField{}, out); }

void GapFastsimModel::add_field(Field f, double scale, double* out) const
{
    export_field(f, AddScaledField{scale}, out);
}

void GapFastsimModel::copy_state(int* out) const
{
    for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i) out[i + nx_ * j] = state_[caller_index(i) + nx_ * j];
}

void GapFastsimModel::copy_profile(double W, double* y, double* work, double* parabola) const
{
    const double b = half_width_ > 0.0 ? half_width_ : grid_.dy;
    for (int j = 0; j < ny_; ++j) {
        const double yj = grid_.y0 + j * grid_.dy;
        if (y) y[j] = yj;
        if (work) work[j] = profile_[j];
        if (parabola) parabola[j] = lateral_parabola(W, b, yj - y_mid_);
    }
}

} // namespace creepwork
