// A minimal JSON object builder for the CLI's machine-readable output: keys
// keep their insertion order (so the documented order is the printed one),
// doubles print exactly (see shortest_exact).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace cwcli {

class JsonObject {
public:
    JsonObject& number(const std::string& key, double value);
    JsonObject& integer(const std::string& key, long value);
    JsonObject& text(const std::string& key, const std::string& value);
    JsonObject& object(const std::string& key, const JsonObject& value);
    JsonObject& array(const std::string& key, const std::vector<JsonObject>& values);

    // Compact (one line) or pretty (one member per line, 2-space indent).
    std::string str(bool pretty_print = false) const;

private:
    std::vector<std::pair<std::string, std::string>> members_; // key, rendered value
};

// Writes j pretty-printed to path; throws CliError(kExitFailure) when it cannot.
void write_json_file(const std::string& path, const JsonObject& j);

std::string json_quote(const std::string& s);
std::string json_number(double v);

// The shortest of %.15g, %.16g, %.17g that reads back as exactly v: output
// stays exact (strtod gives back the same double) without "0.299999...".
std::string shortest_exact(double v);

} // namespace cwcli
