#include "output_dir.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <stdlib.h>   // mkdtemp (POSIX)
#include <sys/stat.h> // umask

#include "cli_error.hpp"

namespace fs = std::filesystem;

namespace cwcli {

const char* const kOutputMarker = ".creepwork-output";

namespace {

// "out/fig6/" names the same directory as "out/fig6".
fs::path without_trailing_slash(const std::string& target)
{
    std::string t = target;
    while (t.size() > 1 && t.back() == '/') t.pop_back();
    return fs::path(t);
}

fs::path parent_of(const fs::path& target)
{
    const fs::path parent = target.parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

} // namespace

void check_output_target(const std::string& target, const std::string& option, bool force)
{
    std::error_code ec;
    const fs::path t = without_trailing_slash(target);
    if (t.filename().empty() || t.filename() == "." || t.filename() == "..")
        throw usage_error(
            option, "'" + target + "' must name a new or creepwork-made directory, not . .. or /");
    // Missing parents are created (like mkdir -p), but only below a directory.
    fs::path ancestor = parent_of(t);
    while (!fs::exists(ancestor, ec) && ancestor.has_parent_path() &&
           ancestor != ancestor.parent_path())
        ancestor = ancestor.parent_path();
    if (fs::exists(ancestor, ec) && !fs::is_directory(ancestor, ec))
        throw usage_error(option, "'" + ancestor.string() + "' is not a directory");
    if (!fs::exists(t, ec)) return;
    if (!fs::is_directory(t, ec))
        throw usage_error(option, "'" + target + "' exists and is not a directory");
    if (fs::is_empty(t, ec)) return;
    if (!fs::exists(t / kOutputMarker, ec))
        throw usage_error(option, "'" + target + "' exists and was not written by creepwork (no " +
                                      kOutputMarker + "); refusing to replace it");
    if (!force)
        throw usage_error(option, "'" + target +
                                      "' holds an earlier creepwork output; add --force to "
                                      "replace it, or choose another directory");
}

StagedOutput::StagedOutput(const std::string& target, const std::string& option, bool force)
    : target_(without_trailing_slash(target).string())
{
    check_output_target(target, option, force);
    const fs::path t(target_);
    std::error_code ec;
    fs::create_directories(parent_of(t), ec);
    if (ec)
        throw CliError(kExitFailure,
                       "cannot create the parent of '" + target + "': " + ec.message());
    std::string templ = (parent_of(t) / ("." + t.filename().string() + ".tmp-XXXXXX")).string();
    if (!mkdtemp(templ.data()))
        throw CliError(kExitFailure, "cannot create a staging directory beside '" + target + "'");
    staging_ = templ;
    // mkdtemp makes the directory private (0700); give it the usual mode.
    const mode_t mask = umask(0);
    umask(mask);
    fs::permissions(staging_, static_cast<fs::perms>(0777 & ~mask), ec);
    std::ofstream marker(path(kOutputMarker));
    marker << "Written by the creepwork command-line program; it may replace this directory.\n";
    if (!marker) throw CliError(kExitFailure, "cannot write into " + staging_);
}

StagedOutput::~StagedOutput()
{
    if (committed_ || staging_.empty()) return;
    std::error_code ec;
    fs::remove_all(staging_, ec);
}

std::string StagedOutput::path(const std::string& relative) const
{
    return relative.empty() ? staging_ : (fs::path(staging_) / relative).string();
}

void StagedOutput::commit()
{
    std::error_code ec;
    const fs::path t(target_);
    fs::path old;
    if (fs::exists(t, ec)) {
        // Move the previous result aside first: rename() cannot replace a
        // non-empty directory, and this keeps the swap to two renames.
        std::string templ = (parent_of(t) / ("." + t.filename().string() + ".old-XXXXXX")).string();
        if (!mkdtemp(templ.data()))
            throw CliError(kExitFailure, "cannot replace '" + target_ + "'");
        old = fs::path(templ) / "previous";
        fs::rename(t, old, ec);
        if (ec) throw CliError(kExitFailure, "cannot replace '" + target_ + "': " + ec.message());
    }
    fs::rename(staging_, t, ec);
    if (ec) {
        std::error_code restore;
        if (!old.empty()) fs::rename(old, t, restore);
        throw CliError(kExitFailure, "cannot move results to '" + target_ + "': " + ec.message());
    }
    committed_ = true;
    if (!old.empty()) fs::remove_all(old.parent_path(), ec);
    long files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(t, ec))
        files += entry.is_regular_file(ec) && entry.path().filename() != kOutputMarker;
    std::fprintf(stderr, "creepwork: wrote %ld files to %s\n", files, target_.c_str());
}

} // namespace cwcli
