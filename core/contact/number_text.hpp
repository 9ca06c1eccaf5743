// Numbers in the library's messages: the shortest decimal text (15 to 17
// significant digits) that reads back as the same double, so a message
// shows a value as the caller most likely wrote it ("nu = 0.6", not
// "nu = 0.59999999999999998"). Independent of the host's locale.
#pragma once

#include <locale>
#include <sstream>
#include <string>

namespace creepwork {

inline std::string number_text(double v)
{
    std::string text;
    for (int digits = 15; digits <= 17; ++digits) {
        std::ostringstream out;
        out.imbue(std::locale::classic());
        out.precision(digits);
        out << v;
        text = out.str();
        std::istringstream in(text);
        in.imbue(std::locale::classic());
        double back = 0.0;
        if ((in >> back) && back == v) break; // not finite: never equal, 17 digits
    }
    return text;
}

} // namespace creepwork
