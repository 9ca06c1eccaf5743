// CSV at the level of text (RFC 4180): splitting a stream into records of
// fields, and quoting a field for output. Knows nothing of contacts.
#pragma once

#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace cwcli {

class CsvRecordReader {
public:
    explicit CsvRecordReader(std::istream& in) : in_(in), buf_(*in.rdbuf()) {}

    // Reads the next record into fields; false at the end of the input.
    // Fields are trimmed of surrounding spaces and tabs unless quoted; ""
    // inside quotes is a quote; a quoted field may span lines; CRLF and LF
    // both end a record. A record with a syntax error (text after a closing
    // quote, an unterminated quote) is returned with `error` set, and
    // reading goes on with the next line.
    bool next(std::vector<std::string>& fields, std::string& error);

    // Line (1-based) on which the last record started.
    long line() const { return record_line_; }
    // FNV-1a hash of every byte read so far (the input's identity on resume).
    uint64_t hash() const { return hash_; }
    bool bad() const { return in_.bad(); }

private:
    int get();

    std::istream& in_;
    std::streambuf& buf_; // read directly: istream::get per character is slow
    long line_ = 1, record_line_ = 0;
    uint64_t hash_ = 14695981039346656037ull;
};

// The field as CSV output: quoted (with quotes doubled) when it holds a
// comma, quote, CR, LF or leading/trailing space, else as is.
std::string csv_quote(const std::string& field);

} // namespace cwcli
