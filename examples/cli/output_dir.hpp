// All-or-nothing output directories. Everything is written into a fresh
// staging directory beside the target; only when every file is complete is
// the staging directory renamed onto the target, so a failure never leaves a
// half-written result there (an interrupted run can leave only a hidden
// .NAME.tmp-* directory beside it). An existing target is replaced only if
// it is empty or was made by creepwork (it holds the marker file), so a
// mistyped --out cannot delete someone's data.
#pragma once

#include <string>

namespace cwcli {

class StagedOutput {
public:
    // Checks the target (throws CliError naming option) and creates the
    // staging directory.
    StagedOutput(const std::string& target, const std::string& option);
    ~StagedOutput(); // removes the staging directory unless committed
    StagedOutput(const StagedOutput&) = delete;
    StagedOutput& operator=(const StagedOutput&) = delete;

    // Path of a file inside the staging directory ("" = the directory).
    std::string path(const std::string& relative = "") const;
    // Moves the finished directory into place.
    void commit();

    const std::string& target() const { return target_; }

private:
    std::string target_, staging_;
    bool committed_ = false;
};

// Throws CliError(kExitUsage) when target cannot become an output directory;
// cheap, so commands call it before their (longer) computations.
void check_output_target(const std::string& target, const std::string& option);

extern const char* const kOutputMarker; // ".creepwork-output"

} // namespace cwcli
