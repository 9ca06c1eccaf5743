#include "json_reader.hpp"

#include <cctype>
#include <cstdlib>

namespace cwtest {

namespace {

class Parser {
public:
    explicit Parser(const std::string& s) : s_(s) {}

    Json document()
    {
        Json j = value();
        skip_space();
        if (pos_ != s_.size()) fail("trailing characters");
        return j;
    }

private:
    [[noreturn]] void fail(const std::string& what) const
    {
        throw std::runtime_error("JSON: " + what + " at offset " + std::to_string(pos_));
    }
    void skip_space()
    {
        while (pos_ < s_.size() &&
               (s_[pos_] == ' ' || s_[pos_] == '\n' || s_[pos_] == '\r' || s_[pos_] == '\t'))
            ++pos_;
    }
    char peek()
    {
        skip_space();
        if (pos_ >= s_.size()) fail("unexpected end");
        return s_[pos_];
    }
    void expect(char c)
    {
        if (peek() != c) fail(std::string("expected '") + c + "'");
        ++pos_;
    }
    bool literal(const char* word)
    {
        const std::string w(word);
        if (s_.compare(pos_, w.size(), w) != 0) return false;
        pos_ += w.size();
        return true;
    }

    Json value()
    {
        const char c = peek();
        Json j;
        if (c == '{') return object();
        if (c == '[') return array();
        if (c == '"') {
            j.type = Json::Type::string;
            j.string = string();
        } else if (literal("true") || literal("false")) {
            j.type = Json::Type::boolean;
            j.boolean = s_[pos_ - 1] == 'e' && s_[pos_ - 2] == 'u';
        } else if (literal("null")) {
            j.type = Json::Type::null;
        } else {
            j.type = Json::Type::number;
            j.number = number();
        }
        return j;
    }

    double number()
    {
        // RFC 8259 grammar: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
        const size_t start = pos_;
        if (s_[pos_] == '-') ++pos_;
        if (pos_ < s_.size() && s_[pos_] == '0')
            ++pos_;
        else if (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_])))
            while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
        else
            fail("bad number");
        if (pos_ < s_.size() && s_[pos_] == '.') {
            ++pos_;
            if (!(pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))))
                fail("bad fraction");
            while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
        }
        if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
            ++pos_;
            if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) ++pos_;
            if (!(pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))))
                fail("bad exponent");
            while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
        }
        return std::strtod(s_.substr(start, pos_ - start).c_str(), nullptr);
    }

    std::string string()
    {
        expect('"');
        std::string out;
        while (true) {
            if (pos_ >= s_.size()) fail("unterminated string");
            const char c = s_[pos_++];
            if (c == '"') return out;
            if (static_cast<unsigned char>(c) < 0x20) fail("control character in string");
            if (c != '\\') {
                out += c;
                continue;
            }
            if (pos_ >= s_.size()) fail("bad escape");
            const char e = s_[pos_++];
            switch (e) {
            case '"':
            case '\\':
            case '/': out += e; break;
            case 'n': out += '\n'; break;
            case 't': out += '\t'; break;
            case 'r': out += '\r'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'u':
                if (pos_ + 4 > s_.size()) fail("bad \\u escape");
                out += '?'; // code point not needed by the tests
                pos_ += 4;
                break;
            default: fail("bad escape");
            }
        }
    }

    Json array()
    {
        Json j;
        j.type = Json::Type::array;
        expect('[');
        if (peek() == ']') {
            ++pos_;
            return j;
        }
        while (true) {
            j.array.push_back(value());
            if (peek() == ',') {
                ++pos_;
                continue;
            }
            expect(']');
            return j;
        }
    }

    Json object()
    {
        Json j;
        j.type = Json::Type::object;
        expect('{');
        if (peek() == '}') {
            ++pos_;
            return j;
        }
        while (true) {
            if (peek() != '"') fail("expected a key");
            const std::string key = string();
            if (j.object.count(key)) fail("duplicate key " + key);
            expect(':');
            j.object[key] = value();
            if (peek() == ',') {
                ++pos_;
                continue;
            }
            expect('}');
            return j;
        }
    }

    const std::string& s_;
    size_t pos_ = 0;
};

} // namespace

Json parse_json(const std::string& text)
{
    return Parser(text).document();
}

} // namespace cwtest
