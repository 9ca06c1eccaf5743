#include "normal/gap_normal.hpp"

#include <algorithm>
#include <cstddef>
#include <string>

#include "contact/error.hpp"
#include "contact/number_text.hpp"

namespace creepwork {
namespace {

// The half-space problem: max |gap| / depth on the contact set, and bounds.
constexpr double kNormalTolerance = 1e-10;
// Its passes that still change the contact set are solved to this only
// (NormalProblem::solve_gap). Conjugate-gradient iterations from the
// semi-Hertzian start, N07_wide / N04_crescent: 39 / 37 at 1e-10
// throughout, 25 / 26 at 1e-6, 17 / 20 at 1e-4, 24 / 15 at 1e-3, 31 / 21
// at 1e-2.
constexpr double kNormalFirstTolerance = 1e-4;
constexpr int kNormalMaxIterations = 500;
// The load derivative's linear solve A_CC z = 1 to max |residual| <= 1e-12
// (the problem's own tolerance is 1e-10 on the gap relative to the depth):
// the derivative is then as good as the solution it linearises.
constexpr double kLoadDerivativeTolerance = 1e-12;
constexpr int kLoadDerivativeMaxIterations = 1000;
// dN/d(approach) is a Newton slope (the wheel/rail force balance): max
// |A z - 1| <= 1e-4 on the contact set is plenty (the exact balance took
// the same evaluations with 1e-12, 1e-6 and 1e-4 on the Manchester
// benchmark; doc/dev/decisions.md), and the linear solve then takes well
// under half the iterations of the load derivative's.
constexpr double kForceByApproachTolerance = 1e-4;

// The half-space problem's tolerance for in: its own, or a looser one the
// caller asks for (a wheel/rail force balance's trial heights).
double normal_tolerance(const ContactInput& in)
{
    return in.normal_tolerance > 0.0 ? in.normal_tolerance : kNormalTolerance;
}

} // namespace

GapNormal::GapNormal(const GridSpec& grid, GapNormalOptions options)
    : options_(options), nx_(grid.nx), ny_(grid.ny), dx_(grid.dx), dy_(grid.dy),
      semi_hertz_(grid.nx, grid.ny),
      drift_(options.warm ? static_cast<size_t>(grid.nx) * grid.ny : 0)
{
    if (!options_.half_space_on_first_use) prepare_half_space();
    const size_t n = static_cast<size_t>(nx_) * ny_;
    for (auto* v : {&gap_, &gap_in_dx_, &start_, &pressure_}) v->assign(n, 0.0);
    if (options_.warm) held_gap_.assign(n, 0.0);
    if (options_.warm) start_product_.assign(n, 0.0);
}

GapNormal::~GapNormal() = default;

void GapNormal::prepare_half_space()
{
    if (conv_) return;
    conv_ = std::make_unique<GridConvolution>(nx_, ny_, ConvolutionUse::normal);
    conv_->set_kernel_isa(isa_);
    half_space_ = std::make_unique<NormalProblem>(nx_, ny_);
    if (options_.box_products) {
        box_ = std::make_unique<GridConvolution>(nx_, ny_, ConvolutionUse::normal);
        box_->set_kernel_isa(isa_);
        half_space_->set_box_convolution(box_.get());
    }
}

void GapNormal::set_kernel_isa(KernelIsa isa)
{
    isa_ = isa;
    semi_hertz_.set_kernel_isa(isa);
    if (conv_) conv_->set_kernel_isa(isa);
    if (box_) box_->set_kernel_isa(isa);
}

const GridConvolution& GapNormal::half_space(double nu)
{
    GridConvolution& c = conv();
    c.set_coefficients(dy_ / dx_, nu);
    return c;
}

const GapNormalInfo& GapNormal::solve(const ContactInput& in, bool warm)
{
    info_ = GapNormalInfo{};
    warm = warm && options_.warm;
    if (warm && holds(in)) {
        info_.reused = true;
        return info_;
    }
    held_.valid = false;
    method_ = in.normal_method;
    G_ = in.G;
    const bool exact = in.normal_method == NormalMethod::exact;
    const bool force = in.normal_load == NormalLoad::force;
    const double* gap = rolling_gap(in);
    const bool from_last = warm && exact && held_.loaded && held_.method == NormalMethod::exact;
    // The drift's history holds one problem: the last one solved, if it is in's.
    const bool same_problem = from_last && held_.direction == in.rolling_direction &&
                              held_.G == in.G && held_.nu == in.nu &&
                              held_.load == in.normal_load;
    if (!same_problem) drift_.clear();
    if (from_last) start_from_last(in, gap);
    bool solved_half_space = false; // its product is the pressure's
    if (force && in.normal_force == 0.0) {
        std::fill(pressure_.begin(), pressure_.end(), 0.0);
        const size_t n = static_cast<size_t>(nx_) * ny_;
        approach_ = *std::min_element(gap, gap + n); // the surfaces just touch
    } else {
        if (!from_last) {
            const SemiHertzResult r = semi_hertz_.solve(
                gap, dx_, dy_, in.G / (1.0 - in.nu), force, force ? in.normal_force : in.approach,
                pressure_.data(), zero_outside_extents_);
            zero_outside_extents_ = true;
            info_.semi_hertz_iterations = r.iterations;
            approach_ = r.approach;
            if (exact)
                for (size_t k = 0; k < pressure_.size(); ++k) start_[k] = pressure_[k] / in.G;
        }
        if (exact) approach_ = solve_half_space(in, gap, from_last);
        solved_half_space = exact;
    }
    if (options_.warm) {
        hold(in);
        if (exact && held_.loaded)
            drift_.remember(gap, approach_, pressure_,
                            solved_half_space ? half_space_->product().data() : nullptr, in.G);
        else
            drift_.clear();
    }
    return info_;
}

const double* GapNormal::rolling_gap(const ContactInput& in)
{
    if (in.rolling_direction > 0) return in.gap;
    for (int j = 0; j < ny_; ++j) {
        const double* from = in.gap + static_cast<size_t>(nx_) * j;
        std::reverse_copy(from, from + nx_, gap_.begin() + static_cast<ptrdiff_t>(nx_) * j);
    }
    return gap_.data();
}

// The last pressure as the half-space problem's start, mirrored if the
// rolling direction changed, or predicted along the gap's drift.
void GapNormal::start_from_last(const ContactInput& in, const double* gap)
{
    start_product_valid_ = false;
    if (drift_.count() >= 2) {
        double g[PressureDrift::kSolutions - 1];
        drift_.predict(gap, in.normal_load == NormalLoad::force, in.approach, start_.data(), g);
        for (double& v : start_) v /= in.G;
        // The start's product from the solutions' (one FFT product fewer).
        start_product_valid_ = drift_.predict_product(g, start_product_.data());
        if (start_product_valid_)
            for (double& v : start_product_) v /= in.G;
        return;
    }
    const bool same = held_.direction == in.rolling_direction;
    for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i)
            start_[i + nx_ * j] = pressure_[(same ? i : nx_ - 1 - i) + nx_ * j] / in.G;
}

double GapNormal::solve_half_space(const ContactInput& in, const double* gap, bool warm)
{
    const size_t n = static_cast<size_t>(nx_) * ny_;
    const bool force = in.normal_load == NormalLoad::force;
    half_space(in.nu);
    zero_outside_extents_ = false; // the half-space pressure overwrites it below
    for (size_t k = 0; k < n; ++k) gap_in_dx_[k] = gap[k] / dx_;
    const double value = force ? in.normal_force / (in.G * dx_ * dy_) : in.approach / dx_;
    // A warm start's contact set is nearly the solution's: no loose passes.
    const double tolerance = normal_tolerance(in);
    const bool product = warm && start_product_valid_;
    start_product_valid_ = false;
    const NormalSolveInfo ni =
        half_space_problem().solve_gap(conv(), gap_in_dx_.data(), start_.data(), force, value,
                                       tolerance, kNormalMaxIterations,
                                       warm ? tolerance : kNormalFirstTolerance,
                                       product ? start_product_.data() : nullptr);
    info_.normal_iterations = ni.iterations;
    info_.normal_products = ni.products;
    if (!ni.converged)
        throw Error(ErrorKind::not_converged,
                    "the normal problem on the gap did not converge (residual " +
                        number_text(ni.residual) + " after " + std::to_string(ni.iterations) +
                        " iterations)");
    const std::vector<double>& q = half_space_->pressure();
    for (size_t k = 0; k < n; ++k) pressure_[k] = q[k] * in.G;
    return half_space_->approach() * dx_;
}

bool GapNormal::holds(const ContactInput& in) const
{
    const Held& h = held_;
    if (!h.valid || h.load != in.normal_load || h.method != in.normal_method || h.nu != in.nu ||
        h.G != in.G || h.direction != in.rolling_direction)
        return false;
    // a half-space solution to a looser tolerance than in's is solved again, from itself
    if (h.method == NormalMethod::exact && h.tolerance > normal_tolerance(in)) return false;
    if (h.value != (in.normal_load == NormalLoad::force ? in.normal_force : in.approach))
        return false;
    const size_t n = static_cast<size_t>(nx_) * ny_;
    for (size_t k = 0; k < n; ++k)
        if (held_gap_[k] != in.gap[k]) return false;
    return true;
}

void GapNormal::hold(const ContactInput& in)
{
    Held& h = held_;
    h.loaded = std::any_of(pressure_.begin(), pressure_.end(), [](double p) { return p > 0.0; });
    h.load = in.normal_load;
    h.method = in.normal_method;
    h.value = in.normal_load == NormalLoad::force ? in.normal_force : in.approach;
    h.nu = in.nu;
    h.G = in.G;
    h.direction = in.rolling_direction;
    h.tolerance = normal_tolerance(in);
    std::copy(in.gap, in.gap + held_gap_.size(), held_gap_.begin());
    h.valid = true;
}

double GapNormal::force() const
{
    // Four partial sums: independent additions.
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    for (int j = 0; j < ny_; ++j) {
        int lo, hi;
        row_extent(j, lo, hi);
        const double* p = pressure_.data() + static_cast<size_t>(nx_) * j;
        int i = lo;
        for (; i + 3 <= hi; i += 4) {
            s0 += p[i];
            s1 += p[i + 1];
            s2 += p[i + 2];
            s3 += p[i + 3];
        }
        for (; i <= hi; ++i) s0 += p[i];
    }
    return ((s0 + s1) + (s2 + s3)) * dx_ * dy_;
}

void GapNormal::load_derivative(double* dp_dN)
{
    if (method_ == NormalMethod::semi_hertz) {
        semi_hertz_.load_derivative(pressure_.data(), dp_dN);
        return;
    }
    if (!half_space_problem().load_derivative(conv(), kLoadDerivativeTolerance,
                                     kLoadDerivativeMaxIterations))
        throw Error(ErrorKind::not_converged,
                    "the normal problem's derivative by the normal force did not converge");
    // dq / d(sum q) with sum q = N / (G dx dy) and p = G q: dp/dN = share / (dx dy).
    const std::vector<double>& share = half_space_->pressure_by_load();
    const double inv_area = 1.0 / (dx_ * dy_);
    for (size_t k = 0; k < share.size(); ++k) dp_dN[k] = share[k] * inv_area;
}

double GapNormal::force_by_approach()
{
    if (method_ == NormalMethod::semi_hertz) return semi_hertz_.force_by_depth(pressure_.data());
    if (std::none_of(pressure_.begin(), pressure_.end(), [](double p) { return p > 0.0; })) return 0.0;
    if (!half_space_problem().load_derivative(conv(), kForceByApproachTolerance, kLoadDerivativeMaxIterations))
        throw Error(ErrorKind::not_converged,
                    "the normal problem's derivative by the approach did not converge");
    // q = p / G and the approach in units of dx: dN/d(approach) = G dx dy
    // d(sum q) / (dx d(pen)).
    return G_ * dy_ * half_space_->load_by_approach();
}

} // namespace creepwork
