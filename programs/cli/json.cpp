#include "json.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "cli_error.hpp"

namespace cwcli {

void write_json_file(const std::string& path, const JsonObject& j)
{
    std::ofstream f(path);
    f << j.str(true) << "\n";
    f.close();
    if (!f) throw CliError(kExitFailure, "cannot write " + path);
}

std::string json_quote(const std::string& s)
{
    std::string out = "\"";
    for (char c : s) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\t': out += "\\t"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", c);
                out += buf;
            } else {
                out += c;
            }
        }
    }
    return out + "\"";
}

std::string shortest_exact(double v)
{
    char buf[32];
    for (int digits = 15; digits < 17; ++digits) {
        std::snprintf(buf, sizeof buf, "%.*g", digits, v);
        if (std::strtod(buf, nullptr) == v) return buf;
    }
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string json_number(double v)
{
    if (!std::isfinite(v)) return "null"; // JSON has no NaN/Inf
    return shortest_exact(v);
}

JsonObject& JsonObject::number(const std::string& key, double value)
{
    members_.emplace_back(key, json_number(value));
    return *this;
}

JsonObject& JsonObject::integer(const std::string& key, long value)
{
    members_.emplace_back(key, std::to_string(value));
    return *this;
}

JsonObject& JsonObject::text(const std::string& key, const std::string& value)
{
    members_.emplace_back(key, json_quote(value));
    return *this;
}

// Nested values are stored compact; str() re-indents the whole document.
JsonObject& JsonObject::object(const std::string& key, const JsonObject& value)
{
    members_.emplace_back(key, value.str());
    return *this;
}

JsonObject& JsonObject::array(const std::string& key, const std::vector<JsonObject>& values)
{
    std::string s = "[";
    for (size_t k = 0; k < values.size(); ++k) s += (k ? "," : "") + values[k].str();
    members_.emplace_back(key, s + "]");
    return *this;
}

namespace {

// Pretty-prints a compact rendering: one member per line, two spaces a level.
std::string pretty(const std::string& compact)
{
    std::string out;
    int depth = 0;
    const auto newline = [&out, &depth] {
        out += "\n" + std::string(2 * static_cast<size_t>(depth), ' ');
    };
    bool in_string = false;
    for (size_t k = 0; k < compact.size(); ++k) {
        const char c = compact[k];
        if (in_string) {
            out += c;
            if (c == '\\')
                out += compact[++k];
            else if (c == '"')
                in_string = false;
            continue;
        }
        switch (c) {
        case '"':
            in_string = true;
            out += c;
            break;
        case '{':
        case '[':
            out += c;
            if (k + 1 < compact.size() && (compact[k + 1] == '}' || compact[k + 1] == ']')) {
                out += compact[++k]; // empty: keep "{}" / "[]" on one line
                break;
            }
            ++depth;
            newline();
            break;
        case '}':
        case ']':
            --depth;
            newline();
            out += c;
            break;
        case ',':
            out += c;
            newline();
            break;
        case ':': out += ": "; break;
        default: out += c;
        }
    }
    return out;
}

} // namespace

std::string JsonObject::str(bool pretty_print) const
{
    std::string s = "{";
    for (size_t k = 0; k < members_.size(); ++k)
        s += (k ? "," : "") + json_quote(members_[k].first) + ":" + members_[k].second;
    s += "}";
    return pretty_print ? pretty(s) : s;
}

} // namespace cwcli
