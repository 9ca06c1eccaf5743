#include "number_text.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace cwcampaign {

void append_number(std::string& out, double v)
{
    char buf[64];
    if (!std::isfinite(v)) {
        // Never a successful result's value; printed as printf would.
        const int n = std::snprintf(buf, sizeof buf, "%.17g", v);
        out.append(buf, static_cast<size_t>(n));
        return;
    }
    // The shortest round-trip digits (Ryu, cheap) say where to start: a value
    // that needs D significant digits cannot be printed exactly with fewer,
    // and 17 always suffice, so most values take one printing, not three.
    const auto shortest = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
    int needed = 0;
    for (const char* p = buf; p < shortest.ptr && *p != 'e'; ++p) needed += *p >= '0' && *p <= '9';
    for (int digits = needed > 15 ? needed : 15; digits <= 17; ++digits) {
        const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, digits);
        double back = 0.0;
        if (digits == 17 || (std::from_chars(buf, r.ptr, back), back == v)) {
            out.append(buf, r.ptr);
            return;
        }
    }
}

std::string number_text(double v)
{
    std::string s;
    append_number(s, v);
    return s;
}

} // namespace cwcampaign
