// ssfx::Error: the one exception type for caller mistakes (bad input, bad params).
// Internal bugs use SSFX_ASSERT, which aborts with a message (Halide's user_error /
// internal_assert split; see STYLE.md section 3).
#pragma once

#include <stdexcept>
#include <string>

namespace ssfx {

//! Thrown on invalid input: the message names the file/field, the value and what was allowed.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

[[noreturn]] void assertFailed(const char* expr, const char* file, int line);

}  // namespace ssfx

//! Our own invariants (never caller input). Always on: they guard cheap, non-hot checks.
#define SSFX_ASSERT(cond) \
    ((cond) ? static_cast<void>(0) : ::ssfx::assertFailed(#cond, __FILE__, __LINE__))
