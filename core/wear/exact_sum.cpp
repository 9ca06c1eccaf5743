#include "wear/exact_sum.hpp"

#include <cmath>
#include <cstring>

namespace creepwork::wear {

namespace {

// x = m 2^e with m < 2^53 an integer; false for zero (and for subnormal
// numbers, which the C boundary flushes to zero anyway: treated as zero so
// that the result is the same whatever the floating-point mode). Read from
// the bits, so no floating-point operation is involved.
bool decompose(double x, uint64_t& m, int& e)
{
    uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int field = static_cast<int>((bits >> 52) & 0x7FF);
    if (field == 0) return false; // zero or subnormal
    m = (bits & ((uint64_t{1} << 52) - 1)) | (uint64_t{1} << 52);
    e = field - 1075;
    return true;
}

} // namespace

bool ExactSum::fits(double p, double c) const
{
    const double product = p * c;
    return product < 0x1p120 && w_[kWords - 1] < (uint64_t{1} << 61);
}

bool ExactSum::fits_sum(const ExactSum& other) const
{
    return w_[kWords - 1] < (uint64_t{1} << 61) && other.w_[kWords - 1] < (uint64_t{1} << 61);
}

void ExactSum::add_at(int bit, unsigned __int128 v)
{
    const int q = bit / 64, r = bit % 64;
    const uint64_t lo = static_cast<uint64_t>(v), hi = static_cast<uint64_t>(v >> 64);
    uint64_t parts[3];
    parts[0] = lo << r;
    parts[1] = (r ? lo >> (64 - r) : 0) | (hi << r);
    parts[2] = r ? hi >> (64 - r) : 0;
    uint64_t carry = 0;
    for (int k = q; k < kWords; ++k) {
        const uint64_t add = (k - q < 3 ? parts[k - q] : 0);
        if (k - q >= 3 && carry == 0) break;
        const uint64_t s1 = w_[k] + add;
        const uint64_t c1 = s1 < add;
        const uint64_t s2 = s1 + carry;
        const uint64_t c2 = s2 < carry;
        w_[k] = s2;
        carry = c1 | c2;
    }
}

void ExactSum::add_product(double p, double c)
{
    uint64_t mp, mc;
    int ep, ec;
    if (!decompose(p, mp, ep) || !decompose(c, mc, ec)) return;
    unsigned __int128 product = static_cast<unsigned __int128>(mp) * mc;
    int bit = ep + ec - kLowExponent;
    if (bit < 0) {
        if (bit <= -128) return;
        product >>= -bit;
        bit = 0;
    }
    if (product != 0) add_at(bit, product);
}

void ExactSum::add(const ExactSum& other)
{
    uint64_t carry = 0;
    for (int k = 0; k < kWords; ++k) {
        const uint64_t s1 = w_[k] + other.w_[k];
        const uint64_t c1 = s1 < other.w_[k];
        const uint64_t s2 = s1 + carry;
        const uint64_t c2 = s2 < carry;
        w_[k] = s2;
        carry = c1 | c2;
    }
}

bool ExactSum::is_zero() const
{
    for (uint64_t v : w_)
        if (v) return false;
    return true;
}

void ExactSum::clear() { std::memset(w_, 0, sizeof w_); }

double ExactSum::value() const
{
    int t = kWords - 1;
    while (t >= 0 && w_[t] == 0) --t;
    if (t < 0) return 0.0;
    const int lz = __builtin_clzll(w_[t]);
    const uint64_t hi = w_[t], lo = t > 0 ? w_[t - 1] : 0;
    const uint64_t window = lz ? (hi << lz) | (lo >> (64 - lz)) : hi;
    bool sticky = (lz ? (lo << lz) : lo) != 0; // bits of lo below the window
    for (int k = t - 2; k >= 0 && !sticky; --k) sticky = w_[k] != 0;
    uint64_t mantissa = window >> 11;
    const bool round = (window >> 10) & 1;
    sticky = sticky || (window & 0x3FF) != 0;
    int msb = 64 * t + 63 - lz; // bit index of the leading one
    if (round && (sticky || (mantissa & 1))) {
        ++mantissa;
        if (mantissa == (uint64_t{1} << 53)) {
            mantissa >>= 1;
            ++msb;
        }
    }
    return std::ldexp(static_cast<double>(mantissa), msb - 52 + kLowExponent);
}

} // namespace creepwork::wear
