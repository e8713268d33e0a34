// Test hooks for exact_div-inl.h and srgb_encode-inl.h (defined in color.cpp).
#pragma once

#include <cstdint>

namespace ssfx::detail {

//! How many integers k in [0, kMax] get a DivExact(k, divisor) other than the IEEE
//! quotient float(k) / divisor, on the SIMD target this machine dispatches to.
std::int64_t divExactMismatches(float divisor, int kMax);

//! How many of the given floats get an EncodeSrgb8 (the vector encode) other than
//! encodeSrgb8 (the scalar one), on the SIMD target this machine dispatches to.
std::int64_t encodeSrgb8Mismatches(const float* values, std::int64_t count);
//! The same for every float whose bits lie in [lowBits, highBits).
std::int64_t encodeSrgb8RangeMismatches(std::uint32_t lowBits, std::uint32_t highBits);

//! How many channel values of a row of w texels (every byte value in every channel, at
//! every position mod 32) get a DecodeSrgbRowPlanar other than kSrgb8 of the byte, on the
//! SIMD target this machine dispatches to.
std::int64_t decodeSrgbRowMismatches(int w);

}  // namespace ssfx::detail
