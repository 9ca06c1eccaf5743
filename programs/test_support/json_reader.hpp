// A small strict JSON reader for the CLI tests: the CLI's output must parse
// as JSON (RFC 8259), not merely contain the right substrings.
#pragma once

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace cwtest {

struct Json {
    enum class Type { null, boolean, number, string, array, object } type = Type::null;
    bool boolean = false;
    double number = 0;
    std::string string;
    std::vector<Json> array;
    std::map<std::string, Json> object;

    bool has(const std::string& key) const { return type == Type::object && object.count(key); }
    const Json& at(const std::string& key) const
    {
        auto it = object.find(key);
        if (type != Type::object || it == object.end()) throw std::runtime_error("no key " + key);
        return it->second;
    }
    double num(const std::string& key) const
    {
        const Json& j = at(key);
        if (j.type != Type::number) throw std::runtime_error(key + " is not a number");
        return j.number;
    }
};

// Throws std::runtime_error with the offset on malformed input.
Json parse_json(const std::string& text);

} // namespace cwtest
