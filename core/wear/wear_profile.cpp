#include "wear/wear_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "contact/contact_input.hpp"
#include "contact/error.hpp"

namespace creepwork::wear {

namespace {

constexpr double kMaxCoordinate = 1e6; // [m]: any lateral coordinate of a profile
constexpr uint64_t kStateMagic = 0x6377776561727031ull; // "cwwearp1"
constexpr long kStateHeader = 5;

void check_nodes(const double* s, long n, const char* name)
{
    if (n < 2 || n > kMaxProfileNodes)
        throw Error(ErrorKind::invalid_input,
                    std::string(name) + ": " + std::to_string(n) +
                        " nodes; a profile grid needs 2 .. 10000000");
    for (long k = 0; k < n; ++k) {
        if (!std::isfinite(s[k]) || std::fabs(s[k]) > kMaxCoordinate)
            throw Error(ErrorKind::invalid_input,
                        std::string(name) + "[" + std::to_string(k) +
                            "] must be a finite coordinate within +-1e6 m");
        if (k > 0 && !(s[k] > s[k - 1]))
            throw Error(ErrorKind::invalid_input,
                        std::string(name) + "[" + std::to_string(k) + "] = " +
                            std::to_string(s[k]) +
                            " must be greater than the node before it (strictly increasing)");
    }
}

// Cell edges and widths of the nodes.
void cells(const double* s, long n, std::vector<double>& edges, std::vector<double>& widths)
{
    edges.resize(static_cast<size_t>(n) + 1);
    widths.resize(static_cast<size_t>(n));
    edges[0] = s[0] - 0.5 * (s[1] - s[0]);
    for (long k = 1; k < n; ++k) edges[k] = 0.5 * (s[k - 1] + s[k]);
    edges[n] = s[n - 1] + 0.5 * (s[n - 1] - s[n - 2]);
    for (long k = 0; k < n; ++k) widths[k] = edges[k + 1] - edges[k];
}

// Calls f(k, overlap) for every cell k that [lo, hi] overlaps.
template <class F>
void for_overlaps(const std::vector<double>& edges, double lo, double hi, F&& f)
{
    const long n = static_cast<long>(edges.size()) - 1;
    if (!(hi > edges[0]) || !(lo < edges[n])) return;
    long k = static_cast<long>(std::upper_bound(edges.begin(), edges.end(), lo) - edges.begin()) - 1;
    k = std::max(k, 0L);
    for (; k < n && edges[k] < hi; ++k) {
        const double o = std::min(hi, edges[k + 1]) - std::max(lo, edges[k]);
        if (o > 0.0) f(k, o);
    }
}

} // namespace

ProfileAccumulator::ProfileAccumulator(const double* s, long n)
{
    check_nodes(s, n, "s");
    nodes_.assign(s, s + n);
    cells(s, n, edges_, widths_);
    normal_.resize(static_cast<size_t>(n));
    height_.resize(static_cast<size_t>(n));
}

void ProfileAccumulator::check_strips(const StripWear& st, const Placement& p) const
{
    if (st.count < 1 || st.count > 1000000)
        throw Error(ErrorKind::invalid_input,
                    "count = " + std::to_string(st.count) + " strips: must be 1 .. 1000000");
    if (!std::isfinite(p.s0) || std::fabs(p.s0) > kMaxCoordinate)
        reject_input("s0", p.s0, "must be a finite coordinate within +-1e6 m");
    if (p.orientation != 1 && p.orientation != -1)
        reject_input("orientation", p.orientation, "must be +1 or -1");
    if (!std::isfinite(p.contact_angle) || std::fabs(p.contact_angle) > kMaxContactAngle)
        reject_input("contact_angle", p.contact_angle,
                     "must lie within +-85 degrees (+-1.48353 rad)");
    if (!std::isfinite(p.passes) || p.passes < 0.0 || p.passes > kMaxPasses)
        reject_input("passes", p.passes, "must lie in [0, 1e15]");
    for (long j = 0; j < st.count; ++j) {
        const auto at = [j] { return "[" + std::to_string(j) + "]"; }; // errors only
        if (!std::isfinite(st.y[j]) || std::fabs(st.y[j]) > kMaxCoordinate)
            throw Error(ErrorKind::invalid_input, "y" + at() + " must be finite, within +-1e6 m");
        if (!std::isfinite(st.width[j]) || !(st.width[j] > 0.0) || st.width[j] > kMaxCoordinate)
            throw Error(ErrorKind::invalid_input,
                        "width" + at() + " = " + std::to_string(st.width[j]) +
                            " must be > 0 and <= 1e6 m");
        if (!std::isfinite(st.depth[j]) || st.depth[j] < 0.0)
            throw Error(ErrorKind::invalid_input,
                        "depth" + at() + " = " + std::to_string(st.depth[j]) +
                            " must be finite and >= 0");
    }
}

void ProfileAccumulator::add(const StripWear& st, const Placement& p)
{
    check_strips(st, p);
    const double cosg = std::cos(p.contact_angle);
    const double passes = p.passes;
    // The interval of strip j on the grid, and its share of cell k.
    auto interval = [&](long j, double& lo, double& hi) {
        const double a = p.s0 + p.orientation * (st.y[j] - 0.5 * st.width[j]) * cosg;
        const double b = p.s0 + p.orientation * (st.y[j] + 0.5 * st.width[j]) * cosg;
        lo = std::min(a, b);
        hi = std::max(a, b);
    };
    // First pass: would any sum leave the exact range?
    bool fits = passes_.fits(passes, 1.0);
    double volume_pass = 0.0;
    for (long j = 0; j < st.count && fits; ++j) {
        const double d = st.depth[j];
        if (d == 0.0) continue;
        volume_pass += d * st.width[j];
        double lo, hi;
        interval(j, lo, hi);
        for_overlaps(edges_, lo, hi, [&](long k, double o) {
            const double c = d * (o / widths_[k]);
            fits = fits && normal_[k].fits(passes, c) && height_[k].fits(passes, c / cosg);
        });
    }
    fits = fits && volume_.fits(passes, volume_pass) && lost_.fits(passes, volume_pass);
    if (!fits)
        throw Error(ErrorKind::numeric_failure,
                    "passes = " + std::to_string(passes) +
                        " times this contact's depth leaves the accumulator's range (2^120 m)");
    // Second pass: add exactly.
    for (long j = 0; j < st.count; ++j) {
        const double d = st.depth[j];
        if (d == 0.0) continue;
        double lo, hi;
        interval(j, lo, hi);
        double covered = 0.0;
        for_overlaps(edges_, lo, hi, [&](long k, double o) {
            const double c = d * (o / widths_[k]);
            normal_[k].add_product(passes, c);
            height_[k].add_product(passes, c / cosg);
            covered += o;
        });
        volume_.add_product(passes, d * st.width[j]);
        const double outside = st.width[j] - covered / cosg;
        if (outside > 1e-12 * st.width[j]) lost_.add_product(passes, d * outside);
    }
    passes_.add_product(passes, 1.0);
    ++adds_;
}

void ProfileAccumulator::merge(const ProfileAccumulator& other)
{
    if (other.nodes_ != nodes_)
        throw Error(ErrorKind::invalid_input,
                    "the two profile accumulators have different nodes s");
    bool fits = passes_.fits_sum(other.passes_) && volume_.fits_sum(other.volume_) &&
                lost_.fits_sum(other.lost_);
    for (size_t k = 0; k < normal_.size() && fits; ++k)
        fits = normal_[k].fits_sum(other.normal_[k]) && height_[k].fits_sum(other.height_[k]);
    if (!fits)
        throw Error(ErrorKind::numeric_failure,
                    "the merged depths would leave the accumulator's range (2^120 m)");
    for (size_t k = 0; k < normal_.size(); ++k) {
        normal_[k].add(other.normal_[k]);
        height_[k].add(other.height_[k]);
    }
    passes_.add(other.passes_);
    volume_.add(other.volume_);
    lost_.add(other.lost_);
    adds_ += other.adds_;
}

void ProfileAccumulator::reset()
{
    for (auto& v : normal_) v.clear();
    for (auto& v : height_) v.clear();
    passes_.clear();
    volume_.clear();
    lost_.clear();
    adds_ = 0;
}

void ProfileAccumulator::depth(DepthKind kind, double* out) const
{
    const std::vector<ExactSum>& src = kind == DepthKind::normal ? normal_ : height_;
    for (size_t k = 0; k < src.size(); ++k) out[k] = src[k].value();
}

ProfileTotals ProfileAccumulator::totals() const
{
    ProfileTotals t;
    t.passes = passes_.value();
    t.volume = volume_.value();
    t.volume_lost = lost_.value();
    t.adds = adds_;
    return t;
}

uint64_t ProfileAccumulator::fingerprint() const
{
    uint64_t h = 1469598103934665603ull; // FNV-1a over the node bits
    for (double s : nodes_) {
        uint64_t bits;
        std::memcpy(&bits, &s, sizeof bits);
        for (int b = 0; b < 8; ++b) {
            h ^= (bits >> (8 * b)) & 0xFF;
            h *= 1099511628211ull;
        }
    }
    return h;
}

long ProfileAccumulator::state_words() const
{
    return kStateHeader + 3 * ExactSum::kWords + 2 * ExactSum::kWords * size();
}

void ProfileAccumulator::save(uint64_t* out) const
{
    long q = 0;
    out[q++] = kStateMagic;
    out[q++] = static_cast<uint64_t>(size());
    out[q++] = fingerprint();
    out[q++] = static_cast<uint64_t>(adds_);
    out[q++] = 0; // reserved
    for (const ExactSum* e : {&passes_, &volume_, &lost_})
        for (int w = 0; w < ExactSum::kWords; ++w) out[q++] = e->word(w);
    for (long k = 0; k < size(); ++k) {
        for (int w = 0; w < ExactSum::kWords; ++w) out[q++] = normal_[k].word(w);
        for (int w = 0; w < ExactSum::kWords; ++w) out[q++] = height_[k].word(w);
    }
}

void ProfileAccumulator::add_saved(const uint64_t* in, long len)
{
    if (len != state_words() || in[0] != kStateMagic || in[1] != static_cast<uint64_t>(size()) ||
        in[2] != fingerprint())
        throw Error(ErrorKind::invalid_input,
                    "state: not a saved state of a profile accumulator on these nodes s");
    // Sums are read word by word into one ExactSum at a time: checked in a
    // first pass, added in a second, no allocation.
    auto sum_at = [&](long q) {
        ExactSum e;
        for (int w = 0; w < ExactSum::kWords; ++w) e.set_word(w, in[q + w]);
        return e;
    };
    const long body = kStateHeader + 3 * ExactSum::kWords;
    bool fits = passes_.fits_sum(sum_at(kStateHeader)) &&
                volume_.fits_sum(sum_at(kStateHeader + ExactSum::kWords)) &&
                lost_.fits_sum(sum_at(kStateHeader + 2 * ExactSum::kWords));
    for (long k = 0; k < size() && fits; ++k)
        fits = normal_[k].fits_sum(sum_at(body + 2 * ExactSum::kWords * k)) &&
               height_[k].fits_sum(sum_at(body + 2 * ExactSum::kWords * k + ExactSum::kWords));
    if (!fits)
        throw Error(ErrorKind::numeric_failure,
                    "the merged depths would leave the accumulator's range (2^120 m)");
    passes_.add(sum_at(kStateHeader));
    volume_.add(sum_at(kStateHeader + ExactSum::kWords));
    lost_.add(sum_at(kStateHeader + 2 * ExactSum::kWords));
    for (long k = 0; k < size(); ++k) {
        normal_[k].add(sum_at(body + 2 * ExactSum::kWords * k));
        height_[k].add(sum_at(body + 2 * ExactSum::kWords * k + ExactSum::kWords));
    }
    adds_ += static_cast<long long>(in[3] & 0x7FFFFFFFFFFFFFFFull);
}

void update_profile(const double* s, const double* old_profile, const double* depth, long n,
                    double smoothing, double* out)
{
    check_nodes(s, n, "s");
    for (long k = 0; k < n; ++k) {
        if (!std::isfinite(old_profile[k]))
            throw Error(ErrorKind::invalid_input,
                        "old_profile[" + std::to_string(k) + "] must be finite");
        if (!std::isfinite(depth[k]))
            throw Error(ErrorKind::invalid_input, "depth[" + std::to_string(k) + "] must be finite");
    }
    if (!std::isfinite(smoothing) || smoothing < 0.0 || smoothing > kMaxCoordinate)
        reject_input("smoothing", smoothing, "must lie in [0, 1e6] m (0: no smoothing)");
    // Into a workspace first: out may alias the inputs, and is written only
    // once every value is known to be finite.
    std::vector<double> result(static_cast<size_t>(n));
    if (smoothing == 0.0) {
        for (long k = 0; k < n; ++k) result[k] = old_profile[k] - depth[k];
    } else {
        std::vector<double> edges, widths;
        cells(s, n, edges, widths);
        // A Gaussian cut at 5 smoothing lengths and shifted down to zero there
        // (by exp(-12.5) = 3.7e-6 of its peak), so that the kernel is
        // continuous and no node's weight depends on the rounding of its
        // distance to the cut.
        const double reach = 5.0 * smoothing;
        const double inv2s2 = 0.5 / (smoothing * smoothing);
        const double cut = std::exp(-12.5);
        auto g = [&](double d) { return std::max(0.0, std::exp(-d * d * inv2s2) - cut); };
        // coef_m = d_m w_m / Z_m, Z_m = sum_k g(s_k - s_m) w_k over m's window.
        std::vector<double> coef(static_cast<size_t>(n));
        long lo = 0, hi = 0;
        for (long m = 0; m < n; ++m) {
            while (s[m] - s[lo] > reach) ++lo;
            while (hi + 1 < n && s[hi + 1] - s[m] <= reach) ++hi;
            double Z = 0.0;
            for (long k = lo; k <= hi; ++k) {
                Z += g(s[k] - s[m]) * widths[k];
            }
            coef[m] = depth[m] * widths[m] / Z; // Z >= (1 - cut) w_m > 0
        }
        lo = hi = 0;
        for (long k = 0; k < n; ++k) {
            while (s[k] - s[lo] > reach) ++lo;
            while (hi + 1 < n && s[hi + 1] - s[k] <= reach) ++hi;
            double smooth = 0.0;
            for (long m = lo; m <= hi; ++m) {
                smooth += coef[m] * g(s[k] - s[m]);
            }
            result[k] = old_profile[k] - smooth;
        }
    }
    for (long k = 0; k < n; ++k)
        if (!std::isfinite(result[k]))
            throw Error(ErrorKind::numeric_failure,
                        "new_profile[" + std::to_string(k) +
                            "] overflows: old_profile and depth are too large");
    std::copy(result.begin(), result.end(), out);
}

} // namespace creepwork::wear
