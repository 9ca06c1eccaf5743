#include "solver.hpp"

#include <cmath>

#include "error.hpp"

namespace creepwork {

Solver::Solver(const GridSpec& grid) : grid_(grid)
{
    march_.resize(grid_.size(), grid_.ny());
    work_.resize(grid_.size(), grid_.ny());
}

const SolveTotals& Solver::solve(const ContactInput& input, SolveMode mode)
{
    solved_ = false;
    setup_ = make_model_setup(input);
    mode_ = mode;
    march(grid_, setup_.kin, setup_.pressure, march_);

    // Totals in the rolling frame: F = T a b sum(p' A'), A' per strip.
    const double T = setup_.traction_scale, a = setup_.a, b = setup_.b;
    double fx = 0.0, fy = 0.0, mz = 0.0;
    int n_slip = 0;
    for (int j = 0; j < grid_.ny(); ++j) {
        const double area = a * b * grid_.x_length()[j] * grid_.y_width()[j];
        const double y = b * grid_.y_centre()[j];
        fx += area * march_.sum_px[j];
        fy += area * march_.sum_py[j];
        mz += area * (a * march_.sum_x_py[j] - y * march_.sum_px[j]);
        n_slip += static_cast<int>(march_.slip_count[j]);
    }
    fx *= T;
    fy *= T;
    mz *= T;

    SolveTotals t;
    const double d = setup_.direction;
    t.Fx = d * fx;
    t.Fy = fy;
    t.Mz = d * mz;
    // Paper eq. 34 per unit rolling distance, positive when dissipating.
    t.W_macro = -(setup_.xi * fx + setup_.eta * fy + setup_.phi * mz);
    t.n_contact = grid_.n_contact();
    t.n_slip = n_slip;
    t.n_adhesion = t.n_contact - n_slip;
    t.adhesion_fraction = t.n_contact > 0 ? double(t.n_adhesion) / t.n_contact : 0.0;
    t.a = a;
    t.b = b;
    t.L1 = setup_.L1;
    t.L2 = setup_.L2;
    t.L3 = setup_.L3;
    t.C11 = setup_.C.C11;
    t.C22 = setup_.C.C22;
    t.C23 = setup_.C.C23;
    t.C33 = setup_.C.C33;

    if (mode == SolveMode::full) {
        const WorkTotals w = compute_work(grid_, setup_, march_, t.W_macro, work_);
        t.W_micro_paper = w.W_micro_paper;
        t.K = w.W_micro_paper != 0.0 ? t.W_macro / w.W_micro_paper : 0.0;
        t.W_consistent = w.W_consistent;
        t.spin_factor = w.balance;
        t.work_flags = w.flags;
        t.profile_max_diff = w.profile_max_diff;
        t.profile_rms_diff = w.profile_rms_diff;
    }

    const double checks[] = {t.Fx, t.Fy, t.Mz, t.W_macro, t.W_micro_paper, t.K, t.W_consistent,
                             t.spin_factor, t.profile_max_diff, t.profile_rms_diff};
    for (double v : checks)
        if (!std::isfinite(v))
            throw Error(ErrorKind::numeric_failure,
                        "a result overflowed: the inputs are too extreme for double precision");
    totals_ = t;
    solved_ = true;
    return totals_;
}

bool Solver::needs_work(Field f)
{
    return f == Field::sx || f == Field::sy || f == Field::work_paper ||
           f == Field::work_consistent;
}

// Physical element (i, j) -> march index: the march starts at the leading
// edge, x' = +a in the rolling frame, which is x = +a when rolling towards +x.
Eigen::Index Solver::march_index(int i, int j) const
{
    const int m = setup_.direction > 0 ? grid_.nx() - 1 - i : i;
    return static_cast<Eigen::Index>(m) * grid_.ny() + j;
}

double Solver::value(Field f, Eigen::Index k, int j) const
{
    const double d = setup_.direction, a = setup_.a, b = setup_.b;
    const double T = setup_.traction_scale;
    const double area = a * b * grid_.x_length()[j] * grid_.y_width()[j];
    switch (f) {
    case Field::x: return d * a * grid_.x_centre()[k];
    case Field::y: return b * grid_.y_centre()[j];
    case Field::area: return grid_.in_contact()[k] != 0.0 ? area : 0.0;
    case Field::pz: return setup_.pressure_scale * grid_.pressure_shape(setup_.pressure)[k];
    case Field::px: return d * T * march_.factor[k] * march_.qx[k];
    case Field::py: return T * march_.factor[k] * march_.qy[k];
    case Field::sx: return d * work_.slip_x[k];
    case Field::sy: return work_.slip_y[k];
    case Field::mz: {
        const double px = T * march_.factor[k] * march_.qx[k];
        const double py = T * march_.factor[k] * march_.qy[k];
        return d * area * (a * grid_.x_centre()[k] * py - b * grid_.y_centre()[j] * px);
    }
    case Field::work_paper: return work_.paper[k];
    case Field::work_consistent: return work_.consistent[k];
    }
    return 0.0;
}

void Solver::copy_field(Field f, double* out) const
{
    const int nx = grid_.nx(), ny = grid_.ny();
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) out[i + static_cast<long>(j) * nx] = value(f, march_index(i, j), j);
}

void Solver::add_field(Field f, double scale, double* out) const
{
    const int nx = grid_.nx(), ny = grid_.ny();
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            out[i + static_cast<long>(j) * nx] += scale * value(f, march_index(i, j), j);
}

void Solver::copy_state(int* out) const
{
    const int nx = grid_.nx(), ny = grid_.ny();
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const Eigen::Index k = march_index(i, j);
            const ElementState s = grid_.in_contact()[k] == 0.0 ? ElementState::exterior
                                   : march_.factor[k] < 1.0     ? ElementState::slip
                                                                : ElementState::adhesion;
            out[i + static_cast<long>(j) * nx] = static_cast<int>(s);
        }
}

void Solver::copy_profile(double* y, double* work, double* parabola) const
{
    for (int j = 0; j < grid_.ny(); ++j) {
        const double yj = setup_.b * grid_.y_centre()[j];
        if (y) y[j] = yj;
        if (work) work[j] = work_.profile[j];
        if (parabola) parabola[j] = equal_area_parabola(totals_.W_consistent, setup_.b, yj);
    }
}

} // namespace creepwork
