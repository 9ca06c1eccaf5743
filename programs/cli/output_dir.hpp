// All-or-nothing output directories. Everything is written into a fresh
// staging directory beside the target; only when every file is complete is
// the staging directory is renamed onto the target, so a failure never leaves a
// half-written result there (an interrupted run can leave only a hidden
// .NAME.tmp-* directory beside it). An existing non-empty target is replaced
// only if creepwork made it (it holds the marker file), so a mistyped --out
// cannot delete someone's data, and only with --force, so a second run
// cannot silently overwrite the first.
#pragma once

#include <string>

namespace cwcli {

class StagedOutput {
public:
    // Checks the target (throws CliError naming option) and creates the
    // staging directory.
    StagedOutput(const std::string& target, const std::string& option, bool force);
    ~StagedOutput(); // removes the staging directory unless committed
    StagedOutput(const StagedOutput&) = delete;
    StagedOutput& operator=(const StagedOutput&) = delete;

    // Path of a file inside the staging directory ("" = the directory).
    std::string path(const std::string& relative = "") const;
    // Moves the finished directory into place and says so on stderr
    // ("creepwork: wrote 14 files to out/fig6"; stdout may be JSON).
    void commit();

    const std::string& target() const { return target_; }

private:
    std::string target_, staging_;
    bool committed_ = false;
};

// Throws CliError(kExitUsage) when target cannot become an output directory
// (or holds an earlier output and force is false); cheap, so commands call
// it before their (longer) computations.
void check_output_target(const std::string& target, const std::string& option, bool force);

extern const char* const kOutputMarker; // ".creepwork-output"

} // namespace cwcli
