// Test hook for exact_div-inl.h (defined in color.cpp).
#pragma once

#include <cstdint>

namespace ssfx::detail {

//! How many integers k in [0, kMax] get a DivExact(k, divisor) other than the IEEE
//! quotient float(k) / divisor, on the SIMD target this machine dispatches to.
std::int64_t divExactMismatches(float divisor, int kMax);

}  // namespace ssfx::detail
