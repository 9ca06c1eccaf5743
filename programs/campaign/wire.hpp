// Byte encoding of chunks and chunk results, shared by the MPI messages and
// the checkpoint journal. Every rank runs the same executable (checked at
// start-up, campaign_main.cpp), so the library's structs travel as their
// bytes; decoding checks every length and throws WireError on a short or
// malformed buffer instead of reading past it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "campaign_types.hpp"

namespace cwcampaign {

class WireError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

using Bytes = std::vector<unsigned char>;

Bytes encode_chunk(const Chunk& chunk);
Chunk decode_chunk(const Bytes& bytes);
// An empty chunk message tells a worker to stop.
Bytes encode_stop();
bool is_stop(const Bytes& bytes);

Bytes encode_result(const ChunkResult& result);
ChunkResult decode_result(const Bytes& bytes);

// 64-bit FNV-1a, for the journal's record checksums and the input's hash.
uint64_t fnv1a(const void* data, size_t size, uint64_t seed = 14695981039346656037ull);

} // namespace cwcampaign
