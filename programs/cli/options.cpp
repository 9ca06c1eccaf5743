#include "options.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>

#include <creepwork/creepwork.h>

#include "cli_error.hpp"

namespace cwcli {

bool parse_finite_double(const std::string& text, double& value)
{
    if (text.empty()) return false;
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    // strtod accepts "nan" and "inf"; a physical input never is either.
    if (*end != '\0' || errno == ERANGE || !std::isfinite(v)) return false;
    value = v;
    return true;
}

bool parse_int(const std::string& text, int& value)
{
    if (text.empty()) return false;
    errno = 0;
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (*end != '\0' || errno == ERANGE || v < INT_MIN || v > INT_MAX) return false;
    value = static_cast<int>(v);
    return true;
}

std::string round_trip_text(double v)
{
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

namespace {

std::string folded(const std::string& s)
{
    std::string out = s;
    for (char& c : out) c = c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

// Edit distance counting an insertion, deletion, substitution or swap of
// two neighbours as one edit (optimal string alignment), so "slove" is one
// edit from "solve".
size_t edit_distance(const std::string& a, const std::string& b)
{
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
        for (size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1,
                                d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

// The library's spelling of a name typed another way (cw_input_name:
// "fast" -> "fastsim", "Semi-Hertz" -> "semi_hertz").
std::string canonical(const std::string& typed)
{
    char name[128];
    return cw_input_name(typed.c_str(), name, sizeof name) == CW_OK ? std::string(name) : typed;
}

} // namespace

std::string match_choice(const std::string& typed, const std::vector<std::string>& choices)
{
    for (const std::string& c : choices)
        if (folded(c) == folded(typed)) return c;
    const std::string name = canonical(typed);
    for (const std::string& c : choices)
        if (canonical(c) == name) return c;
    return "";
}

std::string nearest(const std::string& word, const std::vector<std::string>& candidates)
{
    const std::string w = folded(word);
    const size_t limit = std::max<size_t>(1, w.size() / 3);
    std::string best;
    size_t best_distance = limit + 1;
    for (const std::string& c : candidates) {
        const size_t d = edit_distance(w, folded(c));
        if (d < best_distance) {
            best_distance = d;
            best = c;
        }
    }
    return best;
}

namespace {

const OptionSpec* find_spec(const std::vector<OptionSpec>& specs, const std::string& name)
{
    for (const OptionSpec& s : specs)
        if (s.name == name) return &s;
    for (const OptionSpec& s : specs)
        for (const std::string& alias : s.aliases)
            if (alias == name) return &s;
    return nullptr;
}

// Checks value against the spec (opt: the option as typed); a choice is
// returned in the spec's own spelling (match_choice).
std::string check_value(const OptionSpec& spec, const std::string& opt, const std::string& value)
{
    double d = 0.0;
    int i = 0;
    switch (spec.kind) {
    case OptionKind::number:
        if (!parse_finite_double(value, d))
            throw usage_error(opt, "expected a finite number, got '" + value + "'");
        break;
    case OptionKind::integer:
        if (!parse_int(value, i))
            throw usage_error(opt, "expected an integer, got '" + value + "'");
        break;
    case OptionKind::choice: {
        const std::string match = match_choice(value, spec.choices);
        if (!match.empty()) return match;
        std::string list;
        for (const std::string& c : spec.choices) list += (list.empty() ? "" : "|") + c;
        const std::string hint = nearest(value, spec.choices);
        throw usage_error(opt, "expected one of " + list + ", got '" + value + "'" +
                                   (hint.empty() ? "" : " (did you mean " + hint + "?)"));
    }
    case OptionKind::flag:
    case OptionKind::text:
        if (spec.kind == OptionKind::text && value.empty())
            throw usage_error(opt, "the value must not be empty");
        break;
    }
    return value;
}

} // namespace

ParsedOptions parse_options(const std::vector<OptionSpec>& specs, int argc, char** argv, int first)
{
    ParsedOptions parsed;
    for (int k = first; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg.size() < 3 || arg.compare(0, 2, "--") != 0)
            throw usage_error(arg.empty() ? "''" : arg,
                              "unexpected argument (options start with --)");
        std::string name = arg.substr(2), value;
        const std::string::size_type eq = name.find('=');
        const bool inline_value = eq != std::string::npos;
        if (inline_value) {
            value = name.substr(eq + 1);
            name = name.substr(0, eq);
        }
        const OptionSpec* spec = find_spec(specs, name);
        if (!spec) {
            std::vector<std::string> names;
            for (const OptionSpec& s : specs) names.push_back(s.name);
            const std::string hint = nearest(name, names);
            throw usage_error("--" + name, "unknown option" +
                                               (hint.empty() ? std::string(" (see --help)")
                                                             : "; did you mean --" + hint + "?"));
        }
        if (parsed.has(spec->name))
            throw usage_error("--" + name, parsed.typed(spec->name) == name
                                               ? "given more than once"
                                               : "given twice, as --" + parsed.typed(spec->name) +
                                                     " and --" + name);
        if (spec->kind == OptionKind::flag) {
            if (inline_value) throw usage_error("--" + name, "takes no value");
            value = "1";
        } else if (!inline_value) {
            // A following "--x" is the next option, not a value; "-1" is a value.
            if (k + 1 >= argc || std::string(argv[k + 1]).compare(0, 2, "--") == 0)
                throw usage_error("--" + name, "missing value");
            value = argv[++k];
        }
        parsed.values_[spec->name] = check_value(*spec, "--" + name, value);
        parsed.typed_[spec->name] = name;
    }
    return parsed;
}

double ParsedOptions::number(const std::string& name, double fallback) const
{
    auto it = values_.find(name);
    double v = fallback;
    if (it != values_.end()) parse_finite_double(it->second, v);
    return v;
}

int ParsedOptions::integer(const std::string& name, int fallback) const
{
    auto it = values_.find(name);
    int v = fallback;
    if (it != values_.end()) parse_int(it->second, v);
    return v;
}

std::string ParsedOptions::typed(const std::string& name) const
{
    auto it = typed_.find(name);
    return it != typed_.end() ? it->second : name;
}

std::string ParsedOptions::text(const std::string& name, const std::string& fallback) const
{
    auto it = values_.find(name);
    return it != values_.end() ? it->second : fallback;
}

} // namespace cwcli
