#include "journal.hpp"

#include <cerrno>
#include <cstddef>
#include <cstring>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace cwcampaign {

namespace {

// The last digit is the record format (wire.cpp): 3 since the rows carry
// their temperature and damage results (--temperature, --k-yield) beside
// their wear placement and the chunks' wear profiles (--wear).
constexpr char kMagic[8] = {'C', 'W', 'C', 'K', 'P', 'T', '3', '\0'};
constexpr uint32_t kRecordMagic = 0x43575243u; // "CRWC" little-endian

// Fixed header: written once, checked on resume.
struct Header {
    char magic[8];
    uint32_t sizeof_grid, sizeof_params, sizeof_result;
    int32_t library_version;
    uint32_t kind;
    uint32_t reserved;
    uint64_t input_hash;
    uint64_t rows;
    uint64_t checksum; // of the bytes above
};

Header make_header(const JournalIdentity& id)
{
    Header h;
    std::memset(&h, 0, sizeof h);
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.sizeof_grid = sizeof(cw_grid);
    h.sizeof_params = sizeof(cw_params);
    h.sizeof_result = sizeof(cw_result);
    h.library_version = cw_version_number();
    h.kind = id.kind;
    h.input_hash = id.input_hash;
    h.rows = id.rows;
    h.checksum = fnv1a(&h, offsetof(Header, checksum));
    return h;
}

std::string sys_error(const std::string& what, const std::string& path)
{
    return what + " " + path + ": " + std::strerror(errno);
}

void write_all(int fd, const void* data, size_t size, uint64_t offset, const std::string& path)
{
    const auto* p = static_cast<const unsigned char*>(data);
    while (size > 0) {
        const ssize_t n = pwrite(fd, p, size, static_cast<off_t>(offset));
        if (n < 0) {
            if (errno == EINTR) continue;
            throw JournalError(sys_error("cannot write the checkpoint", path));
        }
        p += n;
        size -= static_cast<size_t>(n);
        offset += static_cast<uint64_t>(n);
    }
}

// Reads exactly size bytes at offset; false at a short read (end of file).
bool read_all(int fd, void* data, size_t size, uint64_t offset)
{
    auto* p = static_cast<unsigned char*>(data);
    while (size > 0) {
        const ssize_t n = pread(fd, p, size, static_cast<off_t>(offset));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        size -= static_cast<size_t>(n);
        offset += static_cast<uint64_t>(n);
    }
    return true;
}

} // namespace

// An exclusive lock for the journal's lifetime: a second campaign started on
// the same directory while one runs must not write into its checkpoint.
static void lock_or_throw(int fd, const std::string& path)
{
    if (flock(fd, LOCK_EX | LOCK_NB) != 0)
        throw JournalError(path + " is in use by a running campaign");
}

Journal Journal::create(const std::string& path, const JournalIdentity& id)
{
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw JournalError(sys_error("cannot create the checkpoint", path));
    Journal j(fd, path);
    lock_or_throw(fd, path);
    if (ftruncate(fd, 0) != 0) throw JournalError(sys_error("cannot truncate the checkpoint", path));
    const Header h = make_header(id);
    write_all(fd, &h, sizeof h, 0, path);
    if (fdatasync(fd) != 0) throw JournalError(sys_error("cannot sync the checkpoint", path));
    j.end_ = sizeof h;
    return j;
}

Journal Journal::open_existing(const std::string& path, const JournalIdentity& id)
{
    const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) throw JournalError(sys_error("cannot open the checkpoint", path));
    Journal j(fd, path);
    lock_or_throw(fd, path);
    Header h;
    if (!read_all(fd, &h, sizeof h, 0) || std::memcmp(h.magic, kMagic, 6) != 0 ||
        h.checksum != fnv1a(&h, offsetof(Header, checksum)))
        throw JournalError(path + " is not a creepwork checkpoint (or its header is damaged)");
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0)
        throw JournalError(path + " was written by another version of creepwork campaign "
                                  "(checkpoint format " + std::string(1, h.magic[6]) +
                           ", this one " + kMagic[6] + "); its results cannot be mixed with "
                           "this build's");
    const Header want = make_header(id);
    if (h.sizeof_grid != want.sizeof_grid || h.sizeof_params != want.sizeof_params ||
        h.sizeof_result != want.sizeof_result || h.library_version != want.library_version)
        throw JournalError(path + " was written by another build of creepwork (library " +
                           std::to_string(h.library_version) + ", this one " +
                           std::to_string(want.library_version) +
                           "); its results cannot be mixed with this build's");
    if (h.kind != want.kind)
        throw JournalError(path + " belongs to a " + (h.kind ? "creep-force table" : "campaign") +
                           ", not to a " + (want.kind ? "creep-force table" : "campaign"));
    if (h.input_hash != want.input_hash || h.rows != want.rows)
        throw JournalError(path + " belongs to another input or other --wear options (" +
                           std::to_string(h.rows) +
                           " rows, hash " + std::to_string(h.input_hash) + "; this input: " +
                           std::to_string(want.rows) + " rows, hash " +
                           std::to_string(want.input_hash) + ")");
    j.end_ = sizeof h;
    j.rows_ = id.rows;
    j.scan();
    return j;
}

bool Journal::in_use(const std::string& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool locked = flock(fd, LOCK_EX | LOCK_NB) != 0;
    ::close(fd);
    return locked;
}

Journal::Journal(Journal&& other) noexcept
    : fd_(other.fd_), path_(std::move(other.path_)), end_(other.end_), rows_(other.rows_),
      records_(std::move(other.records_)), dropped_tail_(other.dropped_tail_)
{
    other.fd_ = -1;
}

Journal::~Journal()
{
    if (fd_ >= 0) ::close(fd_);
}

void Journal::scan()
{
    uint64_t pos = end_;
    for (;;) {
        uint32_t magic = 0;
        uint64_t length = 0, checksum = 0;
        if (!read_all(fd_, &magic, sizeof magic, pos)) break;
        if (magic != kRecordMagic || !read_all(fd_, &length, sizeof length, pos + 4) ||
            length > (uint64_t(1) << 40)) {
            dropped_tail_ = true;
            break;
        }
        Bytes payload(length);
        if (!read_all(fd_, payload.data(), length, pos + 12) ||
            !read_all(fd_, &checksum, sizeof checksum, pos + 12 + length) ||
            checksum != fnv1a(payload.data(), payload.size())) {
            dropped_tail_ = true;
            break;
        }
        ChunkResult r;
        try {
            r = decode_result(payload);
        } catch (const WireError&) {
            dropped_tail_ = true;
            break;
        }
        if (r.outcomes.empty() || r.first_row + r.outcomes.size() > rows_)
            throw JournalError(path_ + " holds a chunk outside its input's rows (damaged?)");
        records_.push_back(Record{r.first_row, r.outcomes.size(), pos + 12, length});
        pos += 12 + length + 8;
    }
    end_ = pos;
    // Anything after the last good record is a torn append: cut it off so
    // the next append starts on a record boundary.
    if (ftruncate(fd_, static_cast<off_t>(end_)) != 0)
        throw JournalError(sys_error("cannot truncate the checkpoint", path_));
}

void Journal::append(uint64_t first_row, uint64_t count, const Bytes& encoded_result)
{
    const uint64_t length = encoded_result.size();
    Bytes record(12 + length + 8);
    std::memcpy(record.data(), &kRecordMagic, 4);
    std::memcpy(record.data() + 4, &length, 8);
    std::memcpy(record.data() + 12, encoded_result.data(), length);
    const uint64_t checksum = fnv1a(encoded_result.data(), length);
    std::memcpy(record.data() + 12 + length, &checksum, 8);
    write_all(fd_, record.data(), record.size(), end_, path_);
    records_.push_back(Record{first_row, count, end_ + 12, length});
    end_ += record.size();
}

void Journal::sync()
{
    if (fdatasync(fd_) != 0) throw JournalError(sys_error("cannot sync the checkpoint", path_));
}

ChunkResult Journal::read(const Record& r) const
{
    Bytes payload(r.length);
    if (!read_all(fd_, payload.data(), r.length, r.offset))
        throw JournalError("cannot read back the checkpoint " + path_);
    return decode_result(payload);
}

} // namespace cwcampaign
