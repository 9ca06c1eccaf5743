#include "atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <unistd.h>

namespace cwcampaign {

AtomicFile::AtomicFile(const std::string& path) : path_(path), tmp_(path + ".tmp")
{
    f_ = std::fopen(tmp_.c_str(), "wb");
    if (!f_) fail("cannot create");
}

AtomicFile::~AtomicFile()
{
    if (!f_) return;
    std::fclose(f_);
    std::remove(tmp_.c_str());
}

void AtomicFile::write(const std::string& text)
{
    if (std::fwrite(text.data(), 1, text.size(), f_) != text.size()) fail("cannot write");
}

void AtomicFile::commit()
{
    if (std::fflush(f_) != 0 || fsync(fileno(f_)) != 0) fail("cannot write");
    const int rc = std::fclose(f_);
    f_ = nullptr;
    if (rc != 0) fail("cannot write");
    if (std::rename(tmp_.c_str(), path_.c_str()) != 0) fail("cannot rename into");
}

void AtomicFile::fail(const char* what) const
{
    throw std::runtime_error(std::string(what) + " " + path_ + ": " + std::strerror(errno));
}

void write_file_atomically(const std::string& path, const std::string& text)
{
    AtomicFile f(path);
    f.write(text);
    f.commit();
}

} // namespace cwcampaign
