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
    for (int digits = 15; digits <= 17; ++digits) {
        const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, digits);
        double back = 0.0;
        std::from_chars(buf, r.ptr, back);
        if (back == v || digits == 17) {
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
