// A campaign's input: a CSV file with a header, one contact state per row,
// in SI and with the CLI's spellings (doc/campaigns.md lists the columns).
// A problem with the file itself (missing, no header, a missing or unknown
// column) is an InputError naming the file and column; a problem with one
// row (a value that is not a number, a wrong field count, an unknown model)
// makes that row unreadable -- it gets an error line in the results -- and
// the campaign goes on.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "campaign_types.hpp"

namespace cwcampaign {

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct CampaignInput {
    std::vector<ContactCase> cases; // one per data row, in file order
    std::vector<std::string> ids;   // the id column, one per row
    std::vector<long> lines;        // line of the file where each row starts
    // The wear columns (used with --wear), carried through to results.csv; NaN where
    // a row leaves them empty. Empty vectors when the file has no column.
    std::vector<double> s0, distance;
    bool has_s0 = false, has_distance = false;
    uint64_t hash = 0; // of the file's bytes: the campaign's identity on resume
};

// What the reader needs to resolve a row's wear columns (--wear).
struct WearRules {
    int default_body = kRail; // --body
    double wheel_radius = 0;  // --wheel-radius [m]; 0: not given
    bool speed_given = false; // --speed
    bool archard = false;     // --law archard: a row needs a rolling speed
};

// Every column the reader knows, required first; the wear columns (body,
// contact_angle, passes, speed) only with --wear.
const std::vector<std::string>& required_columns();
const std::vector<std::string>& optional_columns();
const std::vector<std::string>& wear_columns();

// wear: nullptr without --wear. With it, the file must have an s0 column,
// and each row's wear columns are checked and resolved into ContactCase::wear
// (a bad one makes the row unreadable).
CampaignInput read_campaign_csv(const std::string& path, const WearRules* wear = nullptr);

} // namespace cwcampaign
