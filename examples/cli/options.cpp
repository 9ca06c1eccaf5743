#include "options.hpp"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>

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

namespace {

const OptionSpec* find_spec(const std::vector<OptionSpec>& specs, const std::string& name)
{
    for (const OptionSpec& s : specs)
        if (s.name == name) return &s;
    return nullptr;
}

void check_value(const OptionSpec& spec, const std::string& value)
{
    const std::string opt = "--" + spec.name;
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
        std::string list;
        for (const std::string& c : spec.choices) {
            if (c == value) return;
            list += (list.empty() ? "" : "|") + c;
        }
        throw usage_error(opt, "expected one of " + list + ", got '" + value + "'");
    }
    case OptionKind::flag:
    case OptionKind::text:
        if (spec.kind == OptionKind::text && value.empty())
            throw usage_error(opt, "the value must not be empty");
        break;
    }
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
        if (!spec) throw usage_error("--" + name, "unknown option (see --help)");
        if (parsed.has(name)) throw usage_error("--" + name, "given more than once");
        if (spec->kind == OptionKind::flag) {
            if (inline_value) throw usage_error("--" + name, "takes no value");
            value = "1";
        } else if (!inline_value) {
            // A following "--x" is the next option, not a value; "-1" is a value.
            if (k + 1 >= argc || std::string(argv[k + 1]).compare(0, 2, "--") == 0)
                throw usage_error("--" + name, "missing value");
            value = argv[++k];
        }
        check_value(*spec, value);
        parsed.values_[name] = value;
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

std::string ParsedOptions::text(const std::string& name, const std::string& fallback) const
{
    auto it = values_.find(name);
    return it != values_.end() ? it->second : fallback;
}

} // namespace cwcli
