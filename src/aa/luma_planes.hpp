// Luma planes of half-way reads, for the vector kernels' edge searches.
//
// A GPU-model read exactly half-way between two texels (weights 128/128 on one axis, 0 or
// 256 on the other) returns 8 (a + b) / 4080 per channel, and one half-way between four
// texels 4 (a + b + c + d) / 4080: functions of the texels alone. ddaa2's and fxaa3d's edge
// searches read only such positions (for every realistic image size; each method checks
// its own coordinate arithmetic per size), so their reads become plane lookups.
#pragma once

#include <cstddef>

#include "ssfx/core/color.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/sample.hpp"

namespace ssfx::aa::detail {

//! Layout, with clamp-to-edge folded in (index -1 and W/H stand for the edge texel twice):
//!  H: (H + 1) rows x W: row r, column x = half-way between pixels (x, r - 1) and (x, r);
//!  V: H rows x (W + 1): row y, column c = half-way between pixels (c - 1, y) and (c, y);
//!  Q (optional): (H + 1) x (W + 1): half-way between the four pixels around corner (c, r).
struct LumaPlanes {
    const float* data = nullptr;
    int width = 0, height = 0;
    bool quad = false;
    std::size_t sizeH() const { return std::size_t(height + 1) * std::size_t(width); }
    std::size_t sizeV() const { return std::size_t(height) * std::size_t(width + 1); }
    std::size_t rowH(int r) const { return std::size_t(r) * std::size_t(width); }
    std::size_t rowV(int y) const { return sizeH() + std::size_t(y) * std::size_t(width + 1); }
    std::size_t rowQ(int r) const { return sizeH() + sizeV() + std::size_t(r) * std::size_t(width + 1); }
    bool hasQuad() const { return quad; }
};

//! Luma of the GPU-model read half-way between texels a and b.
inline float pairLuma(const Rgba8& a, const Rgba8& b) {
    return luma(kSixteenthLevels[std::size_t(8 * (a.r + b.r))], kSixteenthLevels[std::size_t(8 * (a.g + b.g))],
                kSixteenthLevels[std::size_t(8 * (a.b + b.b))]);
}
//! Luma of the GPU-model read half-way between four texels.
inline float quadLuma(const Rgba8& a, const Rgba8& b, const Rgba8& c, const Rgba8& d) {
    return luma(kSixteenthLevels[std::size_t(4 * (a.r + b.r + c.r + d.r))],
                kSixteenthLevels[std::size_t(4 * (a.g + b.g + c.g + d.g))],
                kSixteenthLevels[std::size_t(4 * (a.b + b.b + c.b + d.b))]);
}

//! True when every read of fxaa3d's walk on an image of this size equals a plane value
//! (then its vector kernel runs; otherwise the scalar one). In fxaa3d.cpp.
bool walkReadsArePlaneReads(const Texture& tex, bool paperSearchQuirk);

//! The planes of `in` (SIMD, threaded) in a buffer kept per calling thread and reused
//! while the size stays the same. Valid until the next call on the same thread.
LumaPlanes scratchLumaPlanes(ImageView<const Rgba8> in, bool withQuad, const Exec& exec);

}  // namespace ssfx::aa::detail
