// Luma planes of half-way reads, for the vector kernels' edge searches.
//
// A GPU-model read exactly half-way between two texels (weights 128/128 on one axis, 0 or
// 256 on the other) returns 8 (a + b) / 4080 per channel, and one half-way between four
// texels 4 (a + b + c + d) / 4080: functions of the texels alone. ddaa2's and fxaa3d's edge
// searches read only such positions (for every realistic image size; each method checks
// its own coordinate arithmetic per size), so their reads become plane lookups.
#pragma once

#include <cstddef>
#include <cstdint>

#include "ssfx/core/color.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/sample.hpp"

namespace ssfx::aa::detail {

//! Layout, with clamp-to-edge folded in (index -1 and W/H stand for the edge texel twice):
//!  H: row r (0 <= r <= H), column x = half-way between pixels (x, r - 1) and (x, r);
//!  V: row y (0 <= y < H), column c (0 <= c <= W) = half-way between pixels (c - 1, y), (c, y);
//!  Q (optional): row r, column c = half-way between the four pixels around corner (c, r).
//! Rows live in a ring per plane, one plane after the other: plane row r in slot
//! r & ringMask of ringMask + 1 (a power of two). A thread walking down the image computes
//! each plane row once, just before its searches first reach it, and reads it from cache
//! while it is within reach (planeRowsFor()).
struct LumaPlanes {
    const float* data = nullptr;
    int width = 0, height = 0;  //!< of the image
    bool quad = false;
    int ringMask = 0;
    //! The texels as the texture reads them: an sRGB texture's planes hold the lumas of
    //! Texture::sampleGpuDecoded's half-way reads (its decoded texels weighted 1/2 or 1/4).
    TextureFormat format = TextureFormat::Unorm;
    //! The run of a method these rows belong to (newPlaneCall()): the same call, the same image.
    std::uint64_t call = 0;
    std::size_t ringRows() const { return std::size_t(ringMask) + 1; }
    std::size_t slot(int r) const { return std::size_t(r & ringMask); }
    std::size_t sizeH() const { return ringRows() * std::size_t(width); }
    std::size_t sizeV() const { return ringRows() * std::size_t(width + 1); }
    std::size_t rowH(int r) const { return slot(r) * std::size_t(width); }
    std::size_t rowV(int y) const { return sizeH() + slot(y) * std::size_t(width + 1); }
    std::size_t rowQ(int r) const { return sizeH() + sizeV() + slot(r) * std::size_t(width + 1); }
    std::size_t size() const { return sizeH() + sizeV() + (quad ? sizeV() : 0); }
    bool hasQuad() const { return quad; }
};

//! Image rows first .. first + count - 1 of an sRGB texture, decoded (kSrgb8) as three channel
//! rows (r, g, b) per image row, each `width` floats with one float of padding either side:
//! channel c of row y at data + ((y - first) * 3 + c) * (width + 2) + 1.
//! (The layout DecodeSrgbRowPadded writes, src/core/srgb_encode-inl.h.)
struct DecodedBand {
    const float* data = nullptr;
    int first = 0, count = 0;
    //! Floats per image row: three channel rows of width + 2.
    static std::size_t rowFloats(int width) { return 3 * (std::size_t(width) + 2); }
    bool holds(int y) const { return data != nullptr && y >= first && y < first + count; }
    //! Channel 0 of row y (held); channel c is c * (width + 2) floats on.
    const float* row(int y, int width) const { return data + std::size_t(y - first) * rowFloats(width) + 1; }
};

//! Largest ring (rows per plane): searches may reach up to (kMaxPlaneRing - 2) / 2 rows.
inline constexpr int kMaxPlaneRing = 64;

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

//! The vector kernels index the planes with int32 gather indices (at most three rings of
//! kMaxPlaneRing rows).
inline bool planesFitGatherIndices(int width) {
    return std::int64_t(width + 1) * kMaxPlaneRing * 3 < std::int64_t(INT32_MAX);
}

//! Runs check(n, inv, centre(i), split(coord)) for the x axis, then the y axis, of a
//! texture: the shape of the per-size exactness checks of the search/walk reads.
template <class AxisCheck>
bool forBothAxes(const Texture& tex, const AxisCheck& check) {
    return check(
               tex.width(), tex.invW(), [&](int x) { return tex.centreU(x); }, [&](float u) { return tex.axisU(u); }) &&
           check(
               tex.height(), tex.invH(), [&](int y) { return tex.centreV(y); }, [&](float v) { return tex.axisV(v); });
}

//! Half a pixel across from centre c of texel i (the steep side's offset, both ways) lands
//! exactly half-way between texels i - 1 and i, or i and i + 1 (clamped): GPU weight 128.
//! (ddaa2 writes the offset (+-1 * 0.5) * inv, fxaa3d (+-inv) * 0.5: both exact, equal.)
template <class Split>
bool acrossIsHalfWay(int n, float inv, float c, int i, const Split& split) {
    auto clampN = [n](int k) { return k < 0 ? 0 : (k >= n ? n - 1 : k); };
    for (int across : {-1, 1}) {
        const Texture::AxisPos a = split(c + (across < 0 ? -inv : inv) * 0.5f);
        const int first = across < 0 ? i - 1 : i;
        if (a.w != 128 || clampN(a.index) != clampN(first) || clampN(a.index + 1) != clampN(first + 1)) return false;
    }
    return true;
}

//! A pixel centre, split on its axis, is that texel alone: index i with weight 0 or index
//! i - 1 with weight 256 (clamped). Then a read at a pixel's centre on one axis and
//! anywhere on the other is a lerp between two texels of the pixel's row or column: this
//! is how fxaa3d's final read avoids gathers. True for every realistic size; O(W + H).
inline bool centresAreTexels(const Texture& tex) {
    return forBothAxes(tex, [](int n, float, auto centre, auto split) {
        for (int i = 0; i < n; ++i) {
            const Texture::AxisPos a = split(centre(i));
            const int lo = a.index < 0 ? 0 : (a.index >= n ? n - 1 : a.index);
            const int hi = a.index + 1 < 0 ? 0 : (a.index + 1 >= n ? n - 1 : a.index + 1);
            if (!((a.w == 0 && lo == i) || (a.w == 256 && hi == i))) return false;
        }
        return true;
    });
}

//! check() for an image size and a method option, remembered per calling thread for the
//! last size: the per-size exactness checks are O(W + H) but run once per frame otherwise
//! (a frame loop at one size then pays for them once).
template <class Check>
bool oncePerSize(int width, int height, int option, const Check& check) {
    thread_local struct {
        int w = -1, h = -1, option = 0;
        bool result = false;
    } last;
    if (last.w != width || last.h != height || last.option != option) last = {width, height, option, check()};
    return last.result;
}

//! True when every read of fxaa3d's walk on an image of this size equals a plane value
//! (then its vector kernel runs; otherwise the scalar one). In fxaa3d.cpp.
bool walkReadsArePlaneReads(const Texture& tex, bool paperSearchQuirk);

//! A new id for one run of a method over an image: the plane rings kept per thread hold
//! rows of the image of one call at a time.
std::uint64_t newPlaneCall();

//! The plane rows that pixel row y reads when its searches go at most `reach` rows away
//! (plane rows y - reach .. y + reach + 1, clamped), in a ring kept per calling thread:
//! rows already there from the same call (the row above, typically) are kept, the others
//! computed (SIMD). Valid until the next call on the same thread; reach <= 31. `format`:
//! the texture's encoding (LumaPlanes::format).
//! `band`: an sRGB texture's image rows that the caller already decoded (its band's
//! LumaRows::decoded), read instead of decoded again.
LumaPlanes planeRowsFor(ImageView<const Rgba8> in, std::uint64_t call, int y, int reach, bool withQuad,
                        TextureFormat format, const DecodedBand& band = {});

}  // namespace ssfx::aa::detail
