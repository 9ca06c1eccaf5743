#include "wire.hpp"

#include <cstring>
#include <memory>
#include <string>
#include <type_traits>

namespace cwcampaign {

namespace {

// Message kinds: the first byte of every encoded buffer.
constexpr unsigned char kChunkTag = 'C', kStopTag = 'S', kResultTag = 'R';
// Per-case marker: a contact to solve, or a row the reader rejected.
constexpr unsigned char kCaseContact = 0, kCaseRejected = 1;

class Writer {
public:
    explicit Writer(unsigned char tag) { bytes_.push_back(tag); }

    template <class T> void put(const T& v)
    {
        static_assert(std::is_trivially_copyable_v<T>, "raw bytes only for plain data");
        const auto* p = reinterpret_cast<const unsigned char*>(&v);
        bytes_.insert(bytes_.end(), p, p + sizeof(T));
    }
    void put_string(const std::string& s)
    {
        put<uint32_t>(static_cast<uint32_t>(s.size()));
        bytes_.insert(bytes_.end(), s.begin(), s.end());
    }
    void put_doubles(const std::vector<double>& v)
    {
        put<uint32_t>(static_cast<uint32_t>(v.size()));
        const auto* p = reinterpret_cast<const unsigned char*>(v.data());
        bytes_.insert(bytes_.end(), p, p + v.size() * sizeof(double));
    }
    // Words as runs: (zeros, count, count literal words)... A wear profile's
    // state is mostly zero words (the nodes no patch of the chunk touched),
    // so a chunk's record grows with the nodes its rows wore, not the grid.
    void put_words(const std::vector<uint64_t>& v)
    {
        put<uint64_t>(v.size());
        size_t k = 0;
        while (k < v.size()) {
            size_t zeros = 0, count = 0;
            while (k + zeros < v.size() && v[k + zeros] == 0) ++zeros;
            while (k + zeros + count < v.size() && v[k + zeros + count] != 0) ++count;
            put<uint64_t>(zeros);
            put<uint64_t>(count);
            const auto* p = reinterpret_cast<const unsigned char*>(v.data() + k + zeros);
            bytes_.insert(bytes_.end(), p, p + count * sizeof(uint64_t));
            k += zeros + count;
        }
    }
    Bytes take() { return std::move(bytes_); }

private:
    Bytes bytes_;
};

class Reader {
public:
    Reader(const Bytes& bytes, unsigned char tag, const char* what) : bytes_(bytes), what_(what)
    {
        if (bytes_.empty() || bytes_[0] != tag) throw WireError(std::string(what) + ": wrong kind");
        pos_ = 1;
    }

    template <class T> T get()
    {
        static_assert(std::is_trivially_copyable_v<T>, "raw bytes only for plain data");
        need(sizeof(T));
        T v;
        std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
        pos_ += sizeof(T);
        return v;
    }
    std::string get_string()
    {
        const uint32_t n = get<uint32_t>();
        need(n);
        std::string s(reinterpret_cast<const char*>(bytes_.data() + pos_), n);
        pos_ += n;
        return s;
    }
    std::vector<double> get_doubles()
    {
        const uint32_t n = get<uint32_t>();
        need(static_cast<size_t>(n) * sizeof(double));
        std::vector<double> v(n);
        if (n) std::memcpy(v.data(), bytes_.data() + pos_, n * sizeof(double));
        pos_ += n * sizeof(double);
        return v;
    }
    std::vector<uint64_t> get_words()
    {
        const uint64_t n = get<uint64_t>();
        // A profile state has 35 + 20 n words, n <= 1e6 nodes (--profile-step):
        // a larger count is damage, not a reason to allocate gigabytes.
        if (n > (uint64_t(1) << 26)) throw WireError(std::string(what_) + ": malformed words");
        std::vector<uint64_t> v(n, 0);
        uint64_t k = 0;
        while (k < n) {
            const uint64_t zeros = get<uint64_t>(), count = get<uint64_t>();
            if (zeros + count == 0 || zeros > n - k || count > n - k - zeros)
                throw WireError(std::string(what_) + ": malformed words");
            k += zeros;
            need(count * sizeof(uint64_t));
            if (count) std::memcpy(v.data() + k, bytes_.data() + pos_, count * sizeof(uint64_t));
            pos_ += count * sizeof(uint64_t);
            k += count;
        }
        return v;
    }
    void finish() const
    {
        if (pos_ != bytes_.size()) throw WireError(std::string(what_) + ": trailing bytes");
    }

private:
    void need(size_t n) const
    {
        if (bytes_.size() - pos_ < n) throw WireError(std::string(what_) + ": truncated");
    }
    const Bytes& bytes_;
    const char* what_;
    size_t pos_ = 0;
};

} // namespace

Bytes encode_chunk(const Chunk& chunk)
{
    Writer w(kChunkTag);
    w.put(chunk.id);
    w.put(chunk.first_row);
    w.put<int32_t>(chunk.mode);
    // The gap files' values once per chunk, whatever the number of its rows
    // on them; a case names its table by index (-1: none).
    std::vector<const std::vector<double>*> tables;
    std::vector<int32_t> table_of(chunk.cases.size(), -1);
    for (size_t k = 0; k < chunk.cases.size(); ++k) {
        const std::vector<double>* values = chunk.cases[k].gap_values.get();
        if (!values || !chunk.cases[k].rejected.empty()) continue;
        size_t t = 0;
        while (t < tables.size() && tables[t] != values) ++t;
        if (t == tables.size()) tables.push_back(values);
        table_of[k] = static_cast<int32_t>(t);
    }
    w.put<uint32_t>(static_cast<uint32_t>(tables.size()));
    for (const std::vector<double>* values : tables) w.put_doubles(*values);
    w.put<uint32_t>(static_cast<uint32_t>(chunk.cases.size()));
    for (size_t k = 0; k < chunk.cases.size(); ++k) {
        const ContactCase& c = chunk.cases[k];
        if (!c.rejected.empty()) {
            w.put(kCaseRejected);
            w.put(c.rejected_status);
            w.put_string(c.rejected);
        } else {
            w.put(kCaseContact);
            w.put(c.grid);
            w.put(c.params);
            w.put(c.wear);
            w.put(table_of[k]);
        }
    }
    return w.take();
}

Chunk decode_chunk(const Bytes& bytes)
{
    Reader r(bytes, kChunkTag, "chunk message");
    Chunk chunk;
    chunk.id = r.get<uint64_t>();
    chunk.first_row = r.get<uint64_t>();
    chunk.mode = r.get<int32_t>();
    std::vector<std::shared_ptr<const std::vector<double>>> tables(r.get<uint32_t>());
    for (auto& t : tables) t = std::make_shared<const std::vector<double>>(r.get_doubles());
    const uint32_t n = r.get<uint32_t>();
    chunk.cases.resize(n);
    for (ContactCase& c : chunk.cases) {
        const auto kind = r.get<unsigned char>();
        if (kind == kCaseRejected) {
            c.rejected_status = r.get<int32_t>();
            c.rejected = r.get_string();
            if (c.rejected.empty() || c.rejected_status == CW_OK)
                throw WireError("chunk message: a rejected row without status or message");
        } else if (kind == kCaseContact) {
            c.grid = r.get<cw_grid>();
            c.params = r.get<cw_params>();
            c.wear = r.get<RowWear>();
            const int32_t table = r.get<int32_t>();
            if (table < -1 || table >= static_cast<int32_t>(tables.size()))
                throw WireError("chunk message: a gap table out of range");
            if (table >= 0) c.gap_values = tables[static_cast<size_t>(table)];
            // The pointer's bits are the sender's: the solver sets it.
            c.params.gap = nullptr;
        } else {
            throw WireError("chunk message: unknown case kind");
        }
    }
    r.finish();
    return chunk;
}

Bytes encode_stop() { return Bytes{kStopTag}; }

bool is_stop(const Bytes& bytes) { return bytes.size() == 1 && bytes[0] == kStopTag; }

Bytes encode_result(const ChunkResult& result)
{
    Writer w(kResultTag);
    w.put(result.id);
    w.put(result.first_row);
    w.put(result.seconds);
    w.put<uint32_t>(static_cast<uint32_t>(result.outcomes.size()));
    for (const Outcome& o : result.outcomes) {
        w.put<int32_t>(o.status);
        if (o.status == CW_OK)
            w.put(o.result);
        else
            w.put_string(o.message);
        w.put_doubles(o.wear);
        w.put_doubles(o.surface);
    }
    for (const std::vector<uint64_t>& state : result.wear_states) w.put_words(state);
    return w.take();
}

ChunkResult decode_result(const Bytes& bytes)
{
    Reader r(bytes, kResultTag, "result message");
    ChunkResult result;
    result.id = r.get<uint64_t>();
    result.first_row = r.get<uint64_t>();
    result.seconds = r.get<double>();
    const uint32_t n = r.get<uint32_t>();
    result.outcomes.resize(n);
    for (Outcome& o : result.outcomes) {
        o.status = r.get<int32_t>();
        if (o.status == CW_OK) {
            o.result = r.get<cw_result>();
        } else {
            cw_result_init(&o.result);
            o.message = r.get_string();
        }
        o.wear = r.get_doubles();
        o.surface = r.get_doubles();
    }
    for (std::vector<uint64_t>& state : result.wear_states) state = r.get_words();
    r.finish();
    return result;
}

uint64_t fnv1a(const void* data, size_t size, uint64_t seed)
{
    const auto* p = static_cast<const unsigned char*>(data);
    uint64_t h = seed;
    for (size_t i = 0; i < size; ++i) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

} // namespace cwcampaign
