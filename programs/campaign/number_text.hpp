// Doubles as text, exactly as `creepwork solve --format json` prints them
// (cwcli::shortest_exact: the shortest of %.15g, %.16g, %.17g that reads back
// as the same double), but through std::to_chars / std::from_chars, which
// the standard defines to give printf's digits in the "C" locale, at a
// fraction of the cost: a results file has ~30 numbers per row.
#pragma once

#include <string>

namespace cwcampaign {

// Appends the text of v to out.
void append_number(std::string& out, double v);
std::string number_text(double v);

} // namespace cwcampaign
