// A transient handle's committed state as bytes (save() and restore() of
// both transient models, transient_base.hpp): each value's bytes in this
// build's layout, one after the other, read back in the order written.
#pragma once

#include <cmath>
#include <complex>
#include <cstring>
#include <vector>

#include "contact/error.hpp"

namespace creepwork {

// Appends v's bytes to out.
template <class T>
void put_bytes(std::vector<unsigned char>& out, const T& v)
{
    const unsigned char* b = reinterpret_cast<const unsigned char*>(&v);
    out.insert(out.end(), b, b + sizeof(T));
}

// Reads v from p and moves p past it.
template <class T>
void get_bytes(const unsigned char*& p, T& v)
{
    std::memcpy(&v, p, sizeof(T));
    p += sizeof(T);
}

// Tractions: the real and the imaginary part of each, in order.
inline void put_tractions(std::vector<unsigned char>& out,
                          const std::vector<std::complex<double>>& q)
{
    for (const std::complex<double>& v : q) {
        put_bytes(out, v.real());
        put_bytes(out, v.imag());
    }
}

// Reads q.size() tractions from p; throws Error(invalid_input) at a
// non-finite one (q is then partly overwritten: a caller's scratch).
inline void get_tractions(const unsigned char*& p, std::vector<std::complex<double>>& q)
{
    for (std::complex<double>& v : q) {
        double re = 0.0, im = 0.0;
        get_bytes(p, re);
        get_bytes(p, im);
        if (!std::isfinite(re) || !std::isfinite(im))
            throw Error(ErrorKind::invalid_input, "restore: the bytes hold a non-finite "
                                                  "traction");
        v = std::complex<double>(re, im);
    }
}

} // namespace creepwork
