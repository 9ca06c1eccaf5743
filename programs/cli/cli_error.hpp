// The CLI's one error type. main() prints it as a single stderr line and
// exits with its status, so every failure path ends in the same place.
#pragma once

#include <stdexcept>
#include <string>

namespace cwcli {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1; // environment: cannot write, gnuplot failed
constexpr int kExitUsage = 2;   // bad input: options, values, library rejections

class CliError : public std::runtime_error {
public:
    CliError(int status, const std::string& message) : std::runtime_error(message), status_(status)
    {
    }
    int status() const { return status_; }

private:
    int status_;
};

// Bad input: "--opt: problem".
inline CliError usage_error(const std::string& option, const std::string& problem)
{
    return CliError(kExitUsage, option + ": " + problem);
}

} // namespace cwcli
