// The end of a campaign: rank 0 reads the checkpoint's chunks in input
// order and writes DIR/results.csv, one line per input row. Going through
// the rows in input order is also the campaign's one fixed reduction order:
// the chunks' wear profiles (--wear) are added here, in that order (and,
// being exact sums, they would give the same bits in any other).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "input_csv.hpp"
#include "journal.hpp"
#include "wear_output.hpp"

namespace cwcampaign {

struct MergeSummary {
    uint64_t rows = 0, ok = 0, failed = 0;
    std::vector<std::string> first_failures; // up to three "id X: line L: message"
    uint64_t warned = 0;                     // solved rows with warnings
    std::vector<std::string> first_warnings; // up to three "id X: line L: warning"
};

// The header of results.csv (the optional s0, distance columns only when
// the input has them; the groups of extra).
std::vector<std::string> results_columns(const CampaignInput& in,
                                         const ResultColumns& extra = {});

// Writes path (via a temporary file renamed into place). Throws JournalError
// when the checkpoint does not cover every row exactly once, and
// std::runtime_error when the file cannot be written.
// wear (--wear; else nullptr) receives every chunk, in input order; extra
// says which optional columns to write (its wear: whether wear is given).
MergeSummary write_results_csv(const Journal& journal, const CampaignInput& in,
                               const std::string& path, WearProfiles* wear = nullptr,
                               ResultColumns extra = {});

// Calls visit(row, outcome) for every row in input order, reading one chunk
// at a time. Throws JournalError unless the checkpoint covers [0, rows)
// exactly once.
// chunk_visit, when given, is called with each chunk before its rows.
void for_each_row_in_order(const Journal& journal, uint64_t rows,
                           const std::function<void(uint64_t, const Outcome&)>& visit,
                           const std::function<void(const ChunkResult&)>& chunk_visit = nullptr);

} // namespace cwcampaign
