// The one error type the core throws. Only the C boundary (capi/) catches it
// and turns it into a status code plus the message, which always names the
// offending input.
#pragma once

#include <stdexcept>
#include <string>

namespace creepwork {

enum class ErrorKind {
    invalid_input,     // NaN/Inf, out-of-range or inconsistent parameter
    grid_out_of_range, // nx, ny or box scale outside the documented limits
    numeric_failure,   // a non-finite intermediate result (never returned)
    not_converged,     // an iterative model hit its iteration bound (never returned silently)
};

class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, const std::string& message)
        : std::runtime_error(message), kind_(kind) {}
    ErrorKind kind() const noexcept { return kind_; }

private:
    ErrorKind kind_;
};

} // namespace creepwork
