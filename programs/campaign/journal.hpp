// The checkpoint: an append-only file of completed chunks, so a killed
// campaign resumes without redoing them. Rank 0 appends each chunk's
// encoded results (wire.hpp) as one record -- length, payload, checksum --
// as it arrives, and syncs the file to disk about once a second (a sync per
// chunk would make rank 0 of a large job wait on the file system). A kill
// can leave at most a torn last record; resuming drops it (and so redoes
// only that chunk). The header ties the file to its input (hash and row count) and to
// the build (struct sizes and library version): results of another input
// or another build are never mixed into a campaign. The journal holds an
// exclusive lock (flock) while open, so two runs cannot share one.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "campaign_types.hpp"
#include "wire.hpp"

namespace cwcampaign {

class JournalError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// What a journal belongs to.
struct JournalIdentity {
    uint32_t kind = 0;       // 0 = campaign of a CSV input, 1 = creep-force table
    uint64_t input_hash = 0; // of the input file, or of the table's definition
    uint64_t rows = 0;
};

class Journal {
public:
    struct Record {
        uint64_t first_row = 0, count = 0;
        uint64_t offset = 0, length = 0; // of the payload in the file
    };

    // A new, empty journal at path (an existing file is replaced).
    static Journal create(const std::string& path, const JournalIdentity& id);
    // Whether a running campaign holds the journal at path (its lock).
    static bool in_use(const std::string& path);
    // An existing journal: checks its header against id (JournalError
    // saying what differs), reads its records, drops a torn tail.
    static Journal open_existing(const std::string& path, const JournalIdentity& id);

    Journal(Journal&& other) noexcept;
    Journal& operator=(Journal&&) = delete;
    Journal(const Journal&) = delete;
    ~Journal();

    // Appends a chunk's encoded result (rows first_row .. first_row+count-1)
    // (JournalError on failure). Once written, the chunk survives the
    // process being killed; sync() makes it survive the machine failing too.
    void append(uint64_t first_row, uint64_t count, const Bytes& encoded_result);
    void sync();
    const std::vector<Record>& records() const { return records_; }
    ChunkResult read(const Record& r) const;
    // True when the tail of an interrupted append was dropped on opening.
    bool dropped_torn_tail() const { return dropped_tail_; }

private:
    Journal(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
    void scan();

    int fd_ = -1;
    std::string path_;
    uint64_t end_ = 0; // offset after the last good record
    uint64_t rows_ = 0;
    std::vector<Record> records_;
    bool dropped_tail_ = false;
};

} // namespace cwcampaign
