// Files as the CLI and campaign tests read and write them. The CSV reader is
// the tests' own (RFC 4180: quotes, "" escapes, no trimming), independent of
// the programs' reader, so a bug there cannot hide itself.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace cwtest {

// The whole file, or "" if it cannot be read.
std::string slurp(const std::string& path);
// Throws std::runtime_error when the file cannot be written.
void write_text(const std::string& path, const std::string& text);
bool exists(const std::string& path);

// Records of a whole CSV file.
std::vector<std::vector<std::string>> read_csv(const std::string& path);
// The records after the header, each cell read with strtod (the CLI writes
// exact doubles).
std::vector<std::vector<double>> read_numbers(const std::string& path);
// Index of each name in a header record.
std::map<std::string, size_t> header_index(const std::vector<std::string>& header);

} // namespace cwtest
