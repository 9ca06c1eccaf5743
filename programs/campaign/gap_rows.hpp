// Campaign rows that solve a contact of any shape: a row with a gap_file
// cell takes its grid and undeformed distance from that file (the CSV of
// `creepwork solve --gap`, ../cli/gap_input.hpp), relative to the input CSV's
// directory unless absolute. Rank 0 reads each file once while it reads the
// input, so that a missing or malformed file rejects its rows (naming the
// file and its line) before any solve; the rows of a file share its values,
// which travel with their chunks (wire.hpp): the other ranks read no file.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "../cli/contact_rows.hpp"
#include "campaign_types.hpp"

namespace cwcampaign {

// The gap files the reader has met, each read once.
class GapFiles {
public:
    struct File {
        cw_grid grid;
        std::shared_ptr<const std::vector<double>> h; // [i + j*nx] [m]
        uint64_t hash = 0;
        std::string error; // read_gap_file's message ("" when the file is good)
    };
    // path: as resolved (absolute).
    const File& load(const std::string& path);
    // Of every good file's hash, in the order the rows first named them
    // (0 when none): a part of the campaign's identity on resume.
    uint64_t hash() const { return hash_; }

private:
    std::map<std::string, File> files_;
    uint64_t hash_ = 0;
};

// A row with a gap_file: checks the columns (a, b and the ellipse's grid
// and pressure must be empty; N or approach, not both; model exact (the
// default) or fastsim; normal_method exact or semi-hertz), reads the
// contact's other inputs as every door does, and loads the file (dir: the
// input CSV's directory). Fills c (c.gap_values; params.gap stays nullptr:
// the solver points it at them) and appends the row's plausibility
// warnings. Throws RowError naming the line and the column.
void read_gap_row(const cwcli::RowSource& row, const std::string& dir, GapFiles& files,
                  ContactCase& c, std::vector<std::string>& warnings);

// An elliptic row: approach and normal_method belong to gap_file rows only
// (throws RowError).
void refuse_gap_columns(const cwcli::RowSource& row);

} // namespace cwcampaign
