#include "csv_text.hpp"

namespace cwcli {

int CsvRecordReader::get()
{
    const int c = buf_.sbumpc();
    if (c == std::char_traits<char>::eof()) return c;
    hash_ ^= static_cast<unsigned char>(c);
    hash_ *= 1099511628211ull;
    if (c == '\n') ++line_;
    return c;
}

namespace {

bool blank(int c) { return c == ' ' || c == '\t'; }

std::string trimmed(const std::string& s)
{
    size_t b = 0, e = s.size();
    while (b < e && blank(s[b])) ++b;
    while (e > b && blank(s[e - 1])) --e;
    return s.substr(b, e - b);
}

} // namespace

bool CsvRecordReader::next(std::vector<std::string>& fields, std::string& error)
{
    fields.clear();
    error.clear();
    const int eof = std::char_traits<char>::eof();
    int c = get();
    if (c == eof) return false;
    record_line_ = line_ - (c == '\n' ? 1 : 0);

    std::string field;
    bool quoted = false; // the current field was quoted
    for (;;) {
        if (c == eof || c == '\n') {
            fields.push_back(quoted ? field : trimmed(field));
            return true;
        }
        if (c == '\r') {
            c = get();
            continue; // CRLF, or a stray CR: neither is data
        }
        if (c == ',') {
            fields.push_back(quoted ? field : trimmed(field));
            field.clear();
            quoted = false;
            c = get();
            continue;
        }
        if (c == '"' && !quoted && trimmed(field).empty()) {
            // A quoted field: everything up to the closing quote, "" = ".
            field.clear();
            quoted = true;
            for (;;) {
                c = get();
                if (c == eof) {
                    error = "a quoted field is not closed before the end of the file";
                    fields.push_back(field);
                    return true;
                }
                if (c == '"') {
                    c = get();
                    if (c == '"') {
                        field += '"';
                        continue;
                    }
                    break;
                }
                field += static_cast<char>(c);
            }
            while (blank(c)) c = get();
            if (c != ',' && c != '\n' && c != '\r' && c != eof) {
                error = "text after the closing quote of a field";
                while (c != '\n' && c != eof) c = get(); // skip to the next record
                fields.push_back(field);
                return true;
            }
            continue;
        }
        field += static_cast<char>(c);
        c = get();
    }
}

std::string csv_quote(const std::string& field)
{
    bool needs = !field.empty() && (blank(field.front()) || blank(field.back()));
    for (char c : field)
        if (c == ',' || c == '"' || c == '\n' || c == '\r') needs = true;
    if (!needs) return field;
    std::string out = "\"";
    for (char c : field) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

} // namespace cwcli
