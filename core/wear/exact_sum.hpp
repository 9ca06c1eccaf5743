// An exact accumulator for sums of products p * c of non-negative doubles
// (a long fixed-point number, Kulisch's idea restricted to the range wear
// needs). Every product of two doubles is an integer of at most 106 bits
// times a power of two, so it can be added exactly into a fixed-point
// integer; the sum is rounded to a double only when read. Hence the value
// read does not depend on the order of the additions, on how a product
// p * c is split into p1 * c + p2 * c with p1 + p2 = p exactly, or on how
// partial sums are merged: bitwise.
//
// Range: bits of weight 2^-512 .. 2^127 (10 words of 64 bits). Bits of a
// product below 2^-512 are dropped (only products below ~1e-122 lose
// anything); a value that would reach 2^126 is refused by fits() before it
// is added.
#pragma once

#include <cstdint>

namespace creepwork::wear {

class ExactSum {
public:
    static constexpr int kWords = 10;
    static constexpr int kLowExponent = -512; // weight of bit 0 of word 0

    // Whether adding p * c (p, c >= 0, finite) keeps the sum below 2^126.
    bool fits(double p, double c) const;
    // Adds p * c exactly (p, c >= 0, finite; fits(p, c) checked by the caller).
    void add_product(double p, double c);
    // Adds another sum exactly (the caller checks fits_sum first).
    bool fits_sum(const ExactSum& other) const;
    void add(const ExactSum& other);
    // The sum, correctly rounded to the nearest double (ties to even).
    double value() const;
    bool is_zero() const;
    void clear();

    uint64_t word(int k) const { return w_[k]; }
    void set_word(int k, uint64_t v) { w_[k] = v; }

private:
    void add_at(int bit, unsigned __int128 v);
    uint64_t w_[kWords] = {};
};

} // namespace creepwork::wear
