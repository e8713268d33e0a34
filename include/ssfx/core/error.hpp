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

//! `v` as an int when it is a whole number in [lo, hi]: a parameter or file value that must be
//! an integer is never rounded, truncated or wrapped (10.4, nan, 4294967297 are errors).
//! Throws Error "WHAT = V is not an integer" (with " in [LO, HI]" when a range is given).
int wholeNumber(double v, const std::string& what, double lo = -2147483648.0, double hi = 2147483647.0);

[[noreturn]] void assertFailed(const char* expr, const char* file, int line);

}  // namespace ssfx

//! Our own invariants (never caller input). Always on: they guard cheap, non-hot checks.
#define SSFX_ASSERT(cond) ((cond) ? static_cast<void>(0) : ::ssfx::assertFailed(#cond, __FILE__, __LINE__))
