#include "gap/gap_fastsim_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/contact_input.hpp"
#include "contact/error.hpp"
#include "contact/kalker_coefficients.hpp"
#include "contact/number_text.hpp"
#include "exact/exact_work.hpp"
#include "normal/gap_grid.hpp"

namespace creepwork {
namespace {

constexpr double kPi = 3.14159265358979323846;

} // namespace

namespace {

// FASTSIM solves mostly by the semi-Hertzian method: the exact normal
// problem's memory is made on its first use (or by prepare()).
GapNormalOptions fastsim_normal_options()
{
    GapNormalOptions o;
    o.half_space_on_first_use = true;
    return o;
}

} // namespace

GapFastsimModel::GapFastsimModel(const GridSpec& grid)
    : grid_(checked_gap_grid(grid)), nx_(grid.nx), ny_(grid.ny),
      normal_(grid, fastsim_normal_options()), labels_(grid.nx, grid.ny)
{
    const size_t n = static_cast<size_t>(nx_) * ny_;
    for (auto* v : {&paper_, &consistent_, &dp_dN_, &bound_p_, &bound_dp_}) v->assign(n, 0.0);
    for (auto* v : {&p_, &slip_, &rigid_}) v->assign(n, {0.0, 0.0});
    state_.assign(n, 0);
    patch_of_.assign(n, -1);
    // At most one patch per two elements (a checkerboard's contact elements).
    march_patches_.reserve(n / 2 + 1);
    march_totals_.reserve(n / 2 + 1);
    longest_.reserve(n / 2 + 1);
    elements_.reserve(n / 2 + 1);
    patches_.reserve(n / 2 + 1);
    for (auto* v : {&profile_, &row_d_, &row_pool_}) v->assign(ny_, 0.0);
    gap_centres(grid_, x_column_, y_row_);
    row_first_.assign(ny_, nx_);
    row_last_.assign(ny_, -1);
}

void GapFastsimModel::validate(const ContactInput& in) const
{
    if (in.model != ModelKind::fastsim)
        throw Error(ErrorKind::invalid_input, "the gap grid's FASTSIM model got another model");
    if (in.flexibility != FlexibilitySource::kalker_from_material)
        throw Error(ErrorKind::invalid_input,
                    "flexibility = given is invalid on a gap grid: FASTSIM takes each patch's "
                    "flexibilities from the material (G, nu) and the patch's size");
    if (in.friction_speed != FrictionSpeed::local)
        throw Error(ErrorKind::invalid_input,
                    "friction_speed = global is invalid on a gap grid: FASTSIM on a gap grid "
                    "takes the law at each element's slip speed (friction_speed = local)");
    validate_gap_input(in, static_cast<size_t>(nx_) * ny_, normal_.kernel_isa());
}

void GapFastsimModel::set_law(const SlipSpeedLaw& law, double V)
{
    check_slip_speed_law(law);
    // Coulomb's law (or mu_s = 0): the march of input.mu, bitwise; V unread.
    has_law_ = law.kind != SlipSpeedLawKind::coulomb && static_friction(law) > 0.0;
    if (!has_law_) return;
    if (!(std::isfinite(V) && V > 0.0))
        throw Error(ErrorKind::invalid_input,
                    "V (the rolling speed) must be finite and > 0 [m/s] for a law of the slip speed");
    law_ = law;
    V_ = V;
}

bool GapFastsimModel::friction_range(double& mu_min, double& mu_max) const
{
    if (!has_law_) return false;
    const bool slips = law_range_.mu_min <= law_range_.mu_max;
    mu_min = slips ? law_range_.mu_min : static_friction(law_);
    mu_max = slips ? law_range_.mu_max : static_friction(law_);
    return true;
}

// Each patch's "patch ellipse" and its flexibilities, and its spin centre
// (the centroid of its elements), rolling frame, from the labels' runs (in
// the caller's layout); patch_of_ in the rolling frame, on the contact's
// elements (the march reads no other).
void GapFastsimModel::set_patches(const ContactInput& in)
{
    const int count = labels_.count();
    march_patches_.assign(count, GapMarchPatch{});
    longest_.assign(count, 0.0);
    elements_.assign(count, 0.0);
    std::vector<GapMarchPatch>& P = march_patches_;
    const double left = direction_ > 0 ? grid_.x0 : -(grid_.x0 + (nx_ - 1) * grid_.dx);
    int i_lo = nx_, i_hi = -1, j_lo = ny_, j_hi = -1; // the contact's extent
    for (int j = 0; j < ny_; ++j) {
        const double y = grid_.y0 + j * grid_.dy;
        const int first = labels_.row_start(j), end = labels_.row_start(j + 1);
        if (first < end) j_lo = std::min(j_lo, j), j_hi = j;
        row_first_[j] = nx_;
        row_last_[j] = -1;
        for (int r = first; r < end; ++r) {
            const int p = labels_.run_patch(r);
            // The run's elements a .. b in the rolling frame.
            const int a = direction_ > 0 ? labels_.run_lo(r) : nx_ - 1 - labels_.run_hi(r);
            const int b = direction_ > 0 ? labels_.run_hi(r) : nx_ - 1 - labels_.run_lo(r);
            const double elements = b - a + 1;
            i_lo = std::min(i_lo, a), i_hi = std::max(i_hi, b);
            row_first_[j] = std::min(row_first_[j], a);
            row_last_[j] = std::max(row_last_[j], b);
            P[p].xc += elements * (left + 0.5 * (a + b) * grid_.dx);
            P[p].yc += elements * y;
            elements_[p] += elements;
            longest_[p] = std::max(longest_[p], elements * grid_.dx);
            int* row = patch_of_.data() + static_cast<size_t>(nx_) * j;
            std::fill(row + a, row + b + 1, p);
        }
    }
    extent_x_ = i_hi >= i_lo ? (i_hi - i_lo + 1) * grid_.dx : 0.0;
    extent_y_ = j_hi >= j_lo ? (j_hi - j_lo + 1) * grid_.dy : 0.0;
    y_mid_ = j_hi >= j_lo ? grid_.y0 + 0.5 * (j_lo + j_hi) * grid_.dy : 0.0;
    for (int p = 0; p < count; ++p) {
        const double elements = elements_[p];
        P[p].xc /= elements;
        P[p].yc /= elements;
        const double a = 0.5 * longest_[p], b = elements * grid_.dx * grid_.dy / (kPi * a);
        const double ratio = std::min(std::max(a / b, kMinAspect), kMaxAspect);
        const Flexibilities L = kalker_flexibilities(a, b, in.G, kalker_coefficients(ratio, in.nu));
        P[p].L1 = L.L1;
        P[p].L2 = L.L2;
        P[p].L3 = L.L3;
    }
}

SolveTotals GapFastsimModel::solve(const ContactInput& in, SolveMode mode)
{
    validate(in);
    direction_ = in.rolling_direction;
    full_ = mode == SolveMode::full;
    normal_.solve(in, false); // no warm start: every solve from scratch

    SolveTotals t;
    const double p_max = label_contact();
    t.n_patches = labels_.count();
    set_patches(in);
    check_rigid_slip(in);

    GapMarchInput m = march_input(in);
    m.bound_pressure = factored(m.pressure, bound_p_);
    march_totals_.assign(labels_.count(), GapMarchTotals{});
    GapMarchOutput out;
    out.p = p_.data();
    out.slip = full_ ? slip_.data() : nullptr; // the slips feed the work maps alone
    out.rigid = full_ ? rigid_.data() : nullptr;
    out.state = state_.data();
    out.patch_totals = march_totals_.data();
    law_range_ = GapLawRange{};
    out.law_range = &law_range_;
    gap_march(m, out);

    set_totals(in, t);
    t.p_max = p_max;
    if (full_) add_work(t);
    return t;
}

// The contact's runs, row by row in the caller's layout (the patches'
// numbering), labelled; returns the largest pressure.
double GapFastsimModel::label_contact()
{
    double p_max = 0.0;
    // pz(row, i): element i (caller's layout) of a row in the rolling frame.
    // Only the rows' extents are scanned (the pressure is zero elsewhere).
    auto scan = [&](auto pz) {
        labels_.clear_runs();
        for (int j = 0; j < ny_; ++j) {
            const double* row = normal_.pressure().data() + static_cast<size_t>(nx_) * j;
            int lo, hi; // rolling frame
            normal_.row_extent(j, lo, hi);
            const int first = direction_ > 0 ? lo : nx_ - 1 - hi; // caller's layout
            const int last = direction_ > 0 ? hi : nx_ - 1 - lo;
            for (int i = first; i <= last; ++i) {
                if (!(pz(row, i) > 0.0)) continue;
                const int lo = i;
                for (; i <= last && pz(row, i) > 0.0; ++i) p_max = std::max(p_max, pz(row, i));
                labels_.add_run(lo, i - 1);
            }
            labels_.end_row();
        }
    };
    if (direction_ > 0)
        scan([](const double* row, int i) { return row[i]; });
    else
        scan([this](const double* row, int i) { return row[nx_ - 1 - i]; });
    labels_.label_runs();
    return p_max;
}

// The largest rigid slip step dx |omega| of any patch: far below overflow,
// so that |q|^2 is finite (the march compares it squared).
void GapFastsimModel::check_rigid_slip(const ContactInput& in) const
{
    const double reach = std::max({std::fabs(grid_.x0), std::fabs(grid_.x0 + nx_ * grid_.dx),
                                   std::fabs(grid_.y0), std::fabs(grid_.y0 + ny_ * grid_.dy)});
    for (const GapMarchPatch& P : march_patches_) {
        const double step = grid_.dx * ((std::fabs(in.xi_x) + std::fabs(in.phi) * reach) / P.L1 +
                                        (std::fabs(in.xi_y) + std::fabs(in.phi) * reach) / P.L2 +
                                        4.0 * std::fabs(in.phi) * reach / P.L3);
        if (!(step <= 1e100))
            throw Error(ErrorKind::invalid_input,
                        "xi_x, xi_y or phi is so large that the rigid slip overflows");
    }
}

// Totals and patches in the caller's frame, patch by patch.
void GapFastsimModel::set_totals(const ContactInput& in, SolveTotals& t)
{
    const double d = direction_;
    patches_.assign(labels_.count(), PatchTotals{});
    t.model = ModelKind::fastsim;
    for (int p = 0; p < labels_.count(); ++p) {
        const GapMarchTotals& M = march_totals_[p];
        PatchTotals& P = patches_[p];
        P.n_contact = M.n_contact;
        P.n_slip = M.n_slip;
        P.n_adhesion = P.n_contact - P.n_slip;
        P.x_centroid = d * march_patches_[p].xc;
        P.y_centroid = march_patches_[p].yc;
        P.Fx = d * M.Fx;
        P.Fy = M.Fy;
        P.Mz = d * M.Mz;
        P.Fn = M.Fn;
        P.p_max = M.p_max;
        P.W_macro = -(P.Fx * in.xi_x + P.Fy * in.xi_y + P.Mz * in.phi);
    }
    add_patch_totals(patches_, in, t);
    t.a = 0.5 * extent_x_;
    t.b = 0.5 * extent_y_;
    half_width_ = t.b;
    t.approach = normal_.approach();
    t.normal_force = normal_.force();
}

// The work maps and their totals (full mode): the march's tractions in Pa
// and slips as numbers, unit scales.
void GapFastsimModel::add_work(SolveTotals& t)
{
    ExactWorkInput w;
    w.nx = nx_;
    w.ny = ny_;
    w.q = p_.data();
    w.s = slip_.data();
    w.w = rigid_.data();
    w.state = state_.data();
    w.traction_scale = 1.0;
    w.slip_scale = 1.0;
    w.area = grid_.dx * grid_.dy;
    w.dy = grid_.dy;
    w.b = half_width_ > 0.0 ? half_width_ : grid_.dy;
    w.y0 = grid_.y0 - y_mid_;
    w.W_macro = t.W_macro;
    set_work_totals(exact_work(w, paper_.data(), consistent_.data(), profile_.data(),
                               row_d_.data(), row_pool_.data()),
                    t);
}

const double* GapFastsimModel::factored(const double* values, std::vector<double>& out) const
{
    if (!factor_) return nullptr;
    const ElementFriction f{factor_, nx_, direction_ < 0};
    for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i) {
            const size_t k = static_cast<size_t>(nx_) * j + i;
            out[k] = values[k] * f.at(i, j);
        }
    return out.data();
}

GapMarchInput GapFastsimModel::march_input(const ContactInput& in) const
{
    const double d = direction_;
    GapMarchInput m;
    m.nx = nx_;
    m.ny = ny_;
    m.x0 = direction_ > 0 ? grid_.x0 : -(grid_.x0 + (nx_ - 1) * grid_.dx);
    m.y0 = grid_.y0;
    m.dx = grid_.dx;
    m.dy = grid_.dy;
    m.pressure = normal_.pressure().data();
    m.patch = patch_of_.data();
    m.patches = march_patches_.data();
    m.law = friction_law(in);
    m.speed_law = has_law_ ? &law_ : nullptr;
    m.V = V_;
    m.xi = d * in.xi_x;
    m.eta = in.xi_y;
    m.phi = d * in.phi;
    m.spin_offset = in.spin_offset >= 0.0 ? in.spin_offset : 0.0;
    m.row_first = row_first_.data();
    m.row_last = row_last_.data();
    return m;
}

} // namespace creepwork
