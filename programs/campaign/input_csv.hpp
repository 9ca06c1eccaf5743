// A campaign's input: a CSV file with a header, one contact state per row,
// in the schema every CLI door shares (../cli/contact_rows.hpp,
// doc/input-schema.md): the same columns, defaults, checks and warnings as
// `creepwork solve` and `creepwork wear`. A problem with the file itself
// (missing, no header, a missing or unknown column) is an InputError naming
// the file and column; a problem with one row (a value that is not a
// number, a wrong field count, a value out of range) rejects that row -- it
// gets a status and a message in the results -- and the campaign goes on.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "../cli/contact_rows.hpp"
#include "campaign_types.hpp"

namespace cwcampaign {

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

using cwcli::WearRules;

struct CampaignInput {
    std::vector<ContactCase> cases; // one per data row, in file order
    std::vector<std::string> ids;   // the id column, one per row
    std::vector<long> lines;        // line of the file where each row starts
    // The row's plausibility warnings, "; "-joined ("" for none): written to
    // its message in results.csv (with --strict the row is rejected instead).
    std::vector<std::string> warnings;
    // The s0 and distance columns, carried through to results.csv; NaN where
    // a row leaves them empty. Empty vectors when the file has no column.
    std::vector<double> s0, distance;
    bool has_s0 = false, has_distance = false;
    std::vector<std::string> notes; // about the file, for stderr ("note: ...")
    uint64_t hash = 0; // of the file's bytes: the campaign's identity on resume
    // Of the gap files the rows name (gap_rows.hpp), 0 when none: also part
    // of the identity, so that a resume refuses a changed gap file.
    uint64_t gap_hash = 0;
};

// wear: nullptr without --wear. With it, the file must have an s0 column,
// and each row's wear columns are checked and resolved into ContactCase::wear
// (a bad one rejects the row). strict (--strict): a row with a plausibility
// warning is rejected (kStatusRowImplausible) instead of solved.
CampaignInput read_campaign_csv(const std::string& path, const WearRules* wear = nullptr,
                                bool strict = false);

} // namespace cwcampaign
