// A worker's gap files: the values of the files its rows name, read on
// first use (read_gap_file, as the reader did) and kept for the next
// chunks, a few files at a time. A file that cannot be read again, or whose
// grid or values differ from what rank 0 read (gap_hash), fails its rows
// with a message naming it: a row is solved on exactly the contact the
// campaign checked, whatever rank solves it.
#pragma once

#include <cstdint>
#include <list>
#include <memory>
#include <string>
#include <vector>

#include "campaign_types.hpp"

namespace cwcampaign {

class GapValues {
public:
    explicit GapValues(size_t max_files) : max_files_(max_files < 1 ? 1 : max_files) {}

    // The values of c's gap file at [i + j*nx], or nullptr with the reason.
    // The pointer shares the values, so they outlive their eviction.
    std::shared_ptr<const std::vector<double>> values(const ContactCase& c, std::string& message);

private:
    struct Entry {
        std::string path;
        uint64_t hash = 0; // the reader's
        std::shared_ptr<const std::vector<double>> h; // nullptr: error
        std::string error;
    };
    size_t max_files_;
    std::list<Entry> files_; // most recently used first
};

} // namespace cwcampaign
