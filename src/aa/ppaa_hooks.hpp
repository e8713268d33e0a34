// Test hooks for ppaa-inl.h (defined in luma_planes.cpp).
#pragma once

#include <cstdint>

namespace ssfx::aa::detail {

//! How many levels k in [0, 4080] get a ByteOfLevel other than toUnorm8(k / 4080), on the
//! SIMD target this machine dispatches to.
std::int64_t levelByteMismatches();
//! How many pairs of levels (ka, kb) get a ByteOfMeanLevel other than
//! toUnorm8((ka / 4080 + kb / 4080) * 0.5f) in float, likewise (all 4081^2 pairs).
std::int64_t meanLevelByteMismatches();

}  // namespace ssfx::aa::detail
