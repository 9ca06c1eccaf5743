// A file that appears complete or not at all: written to NAME.tmp, synced,
// then renamed over NAME. A killed run leaves at most the .tmp behind, never
// a truncated results file that looks finished.
#pragma once

#include <cstdio>
#include <string>

namespace cwcampaign {

class AtomicFile {
public:
    explicit AtomicFile(const std::string& path); // throws std::runtime_error naming path
    ~AtomicFile();                                 // removes the .tmp unless committed
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    void write(const std::string& text);
    void commit();

private:
    [[noreturn]] void fail(const char* what) const;

    std::string path_, tmp_;
    std::FILE* f_ = nullptr;
};

// The whole of text as path, atomically.
void write_file_atomically(const std::string& path, const std::string& text);

} // namespace cwcampaign
