// Files of contact rows: the CSV input of creepwork campaign and the states
// of creepwork wear, read by one reader with one schema (doc/input-schema.md).
// Columns are the inputs of contact_inputs.hpp under their column names
// (spin is another name for phi); a column the schema knows but the command
// does not read is ignored with a note, an unknown one is an error that
// suggests the nearest name. A row is a ContactSource over its cells, so its
// contact goes through the same rules, checks and warnings as the command
// line's; an empty cell takes the default, as an option left out does.
#pragma once

#include <cstdint>
#include <fstream>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact_inputs.hpp"
#include "csv_text.hpp"

namespace cwcli {

// Which command reads the file: what it requires and what it ignores.
enum class RowFile {
    campaign,      // creepwork campaign: id, a, b, N required (a row with a
                   // gap_file: id and N or approach)
    campaign_wear, // creepwork campaign --wear: also s0 and the wear columns
    wear           // creepwork wear: s0, a, b, N required; id ignored
};

// A problem with the file itself (cannot open, no header, a column unknown,
// twice or missing): the message names the file.
class RowFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A problem with one row: "line L, column C: problem", and why (the status a
// campaign row gets).
struct RowError {
    std::string message;
    ContactSource::Refusal why = ContactSource::Refusal::unreadable;
};

// The header of a file, checked against the schema.
class RowHeader {
public:
    RowHeader() = default;
    // Throws RowFileError naming path.
    RowHeader(const std::vector<std::string>& fields, RowFile kind, const std::string& path);

    bool has(Input in) const { return field_.count(in) != 0; }
    size_t field(Input in) const { return field_.at(in); }
    // The column's name as the header spells it (spin or phi).
    std::string spelling(Input in) const;
    size_t columns() const { return columns_; }
    RowFile kind() const { return kind_; }
    // Notes on columns the command ignores ("note: ..."), for stderr.
    const std::vector<std::string>& notes() const { return notes_; }

private:
    std::map<Input, size_t> field_;
    std::map<Input, std::string> spelling_;
    size_t columns_ = 0;
    RowFile kind_ = RowFile::campaign;
    std::vector<std::string> notes_;
};

// A file's rows in order. Blank lines and lines starting with # are
// skipped; a UTF-8 byte-order mark before the header is not part of it.
class RowFileReader {
public:
    // Opens path and reads its header; throws RowFileError.
    RowFileReader(const std::string& path, RowFile kind);

    const RowHeader& header() const { return header_; }
    // The next row's cells and line; false at the end of the file. A record
    // the CSV rules or the header's column count refuse comes back with
    // `error` set ("line L: ...").
    bool next(std::vector<std::string>& cells, long& line, std::string& error);
    // FNV-1a hash of the file's bytes read so far (all of them at the end).
    uint64_t hash() const { return csv_->hash(); }
    bool bad() const { return csv_->bad(); }

private:
    std::ifstream file_;
    std::unique_ptr<CsvRecordReader> csv_;
    RowHeader header_;
};

// One row as a contact source: messages name "column a" in SI.
class RowSource : public ContactSource {
public:
    RowSource(const RowHeader& header, const std::vector<std::string>& cells, long line)
        : header_(header), cells_(cells), line_(line)
    {
    }
    std::string name(Input in) const override { return header_.spelling(in); }
    std::string label(Input in) const override { return "column " + name(in); }
    const Units& units() const override;
    bool has(Input in) const override { return !text(in).empty(); }
    double number(Input in) const override;
    int integer(Input in) const override;
    std::string choice(Input in, const std::vector<std::string>& choices) const override;
    bool flag(Input in) const override; // 0 or 1

    const std::string& text(Input in) const;
    long line() const { return line_; }
    const RowHeader& header() const { return header_; }
    // Fails unless the cell has a value; require_values: every required
    // column's cell (id, s0, a, b, N as the command requires them; a row
    // with a gap_file needs no a, b, N).
    void require(Input in) const;
    void require_values() const;

protected:
    void raise(const std::string& names, const std::string& problem, Refusal why) const override;

private:
    const RowHeader& header_;
    const std::vector<std::string>& cells_;
    long line_;
};

// How a row's wear columns resolve (the options of creepwork wear and
// creepwork campaign --wear).
struct WearRules {
    int default_body = 0;        // 0 rail, 1 wheel (--body)
    double wheel_radius = 0;     // --wheel-radius [m]; 0: not given
    bool speed_given = false;    // --speed
    bool archard = false;        // --law archard: a row needs a rolling speed
};

// Where a row's patch sits and how many passes it stands for.
struct WearPlacement {
    int body = 0;         // 0 rail, 1 wheel
    double s0 = 0;        // profile coordinate of the patch centre [m]
    double angle = 0;     // contact angle [rad]
    double passes = 0;    // axle passages (rail) or wheel revolutions (wheel)
    double speed = 0;     // rolling speed [m/s]; 0: the option's
};

// s0 (required); passes, or for a wheel distance / (2 pi R); contact_angle,
// body, speed. Throws RowError.
WearPlacement read_wear_columns(const RowSource& row, const WearRules& rules);

// A note ("note: PATH: ...") naming the library defaults the file's rows
// take because the header has no column for them (mu, and G and nu unless
// L1..L3 are columns), skipping the inputs in `given_elsewhere` (options);
// "" when none.
std::string defaults_note(const RowHeader& header, const cw_params& defaults,
                          const std::string& path,
                          const std::vector<Input>& given_elsewhere = {});

} // namespace cwcli
