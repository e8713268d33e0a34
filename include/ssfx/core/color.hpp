// Luma and 8-bit quantisation shared by the anti-aliasing methods (spec ppaa.md section 1).
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/sample.hpp"

namespace ssfx {

//! Perceptual luma of the PPAA methods: sqrt(0.299 r + 0.587 g + 0.114 b) on unorm values
//! (Rec. 601 weights; the square root approximates lightness). Evaluated left to right in
//! float32 without fused multiply-add, as the reference shaders are.
inline float luma(float r, float g, float b) { return std::sqrt(0.299f * r + 0.587f * g + 0.114f * b); }
inline float luma(const Rgb& c) { return luma(c.r, c.g, c.b); }

//! The opt-in colour-aware contrast measure of the luma-based PPAA methods (our extension
//! for the limitation of spec ppaa.md section 4): luma plus `chromaWeight` times the
//! chroma max(r,g,b) - min(r,g,b). Colours of equal luma but different saturation (the
//! paper's green on grey) then differ; greys (chroma 0) keep their luma exactly, and with
//! chromaWeight = 0 this is luma() bit for bit. Colours equal in both luma and chroma
//! (hue changes at constant lightness and saturation) remain invisible.
inline float edgeLuma(const Rgb& c, float chromaWeight) {
    const float l = luma(c);
    if (chromaWeight == 0.0f) return l;
    const float hi = c.r > c.g ? (c.r > c.b ? c.r : c.b) : (c.g > c.b ? c.g : c.b);
    const float lo = c.r < c.g ? (c.r < c.b ? c.r : c.b) : (c.g < c.b ? c.g : c.b);
    return l + chromaWeight * (hi - lo);
}

//! Float in [0, 1] (clamped; NaN gives 0) to the nearest 8-bit level. The product v * 255
//! is rounded exactly (in double, where it is exact), not after a float32 rounding: GPUs
//! convert this way, and a float32 product turns values just below k + 0.5 into ties.
inline std::uint8_t toUnorm8(float v) {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return static_cast<std::uint8_t>(double(v) * 255.0 + 0.5);
}

//! The sRGB transfer functions of IEC 61966-2-1 (Vulkan's "sRGB EOTF" and its inverse), in
//! double: encoded value in [0, 1] to linear light and back.
inline double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
inline double linearToSrgb(double l) { return l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055; }

//! encodeSrgb8's thresholds as floats: element k is the smallest float above the linear
//! value of the half-level (k + 0.5) / 255, so encodeSrgb8(v) is the number of elements <= v
//! for v in [0, 1) (the GPU passes' exact encode reads them: src/gpu/shaders/aa/ppaa.glsl).
const std::array<float, 255>& srgbEncodeThresholds();

namespace detail {
//! encodeSrgb8's count of thresholds <= v in two loads instead of a search. The floats in
//! [2^-14, 1) fall into buckets by their exponent and top 8 mantissa bits (a bucket spans
//! 2^-8 of its value, 0.39 %; consecutive thresholds are at least 0.9 % apart), so a bucket
//! holds at most one threshold: the level is its smallest float's level, plus one where v is
//! at or above the next threshold. Below 2^-14 the level is 0 (the first threshold is
//! 1.5e-4). The table checks the one-threshold property for every bucket when it is built.
//! `packed` holds both facts of a bucket in one word, so the CPU's encode is one load (one
//! gather a vector): a positive float is at or above a threshold in its bucket exactly when
//! its bits' offset in the bucket is at or above the threshold's.
struct SrgbEncodeTable {
    static constexpr std::uint32_t kShift = 15;            // 23 - 8 mantissa bits
    static constexpr std::uint32_t kLowBits = 113u << 23;  // 2^-14
    static constexpr std::uint32_t kBuckets = (127u - 113u) << 8;
    static constexpr std::uint32_t kOffsetMask = (1u << kShift) - 1;  //!< a float's offset in its bucket
    static constexpr std::uint32_t kNoThreshold = 1u << kShift;       //!< above every offset
    std::array<std::int32_t, kBuckets> first;                         //!< each bucket's smallest float's level
    std::array<float, 256> next;                                      //!< the threshold above level k (255: +infinity)
    //! first << 16 | the offset of the bucket's threshold (kNoThreshold where it holds none)
    std::array<std::int32_t, kBuckets> packed;
};
const SrgbEncodeTable& srgbEncodeTable();
//! kSrgb8's floats split into their low and high 16 bits: two 256-entry tables of 16-bit
//! words, which AVX-512 holds in registers and looks up 32 texels at a time (a table
//! lookup, so the same floats; src/core/srgb_encode-inl.h).
struct SrgbDecodeHalves {
    alignas(64) std::array<std::uint16_t, 256> low;
    alignas(64) std::array<std::uint16_t, 256> high;
};
const SrgbDecodeHalves& srgbDecodeHalves();
}  // namespace detail

//! Linear light in [0, 1] (clamped; NaN gives 0) to the nearest sRGB-encoded 8-bit level:
//! round(255 * linearToSrgb(v)) exactly, by comparing v with the 255 linear values where
//! that rounding changes (decoded half-levels, in double), so no pow() rounding can move a
//! result. encodeSrgb8(kSrgb8[k]) == k for every k.
inline std::uint8_t encodeSrgb8(float v) {
    using T = detail::SrgbEncodeTable;
    if (!(v > 0.0f)) return 0;  // and NaN
    if (v >= 1.0f) return 255;
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(v);
    if (bits < T::kLowBits) return 0;
    const T& t = detail::srgbEncodeTable();
    const std::uint32_t offset = bits - T::kLowBits;
    const auto e = static_cast<std::uint32_t>(t.packed[offset >> T::kShift]);
    return static_cast<std::uint8_t>((e >> 16) + ((offset & T::kOffsetMask) >= (e & 0xFFFFu) ? 1u : 0u));
}

//! A filtered channel back to its texture's 8-bit encoding (toUnorm8 or encodeSrgb8).
inline std::uint8_t encode8(float v, TextureFormat format) {
    return format == TextureFormat::Srgb ? encodeSrgb8(v) : toUnorm8(v);
}

//! Luma plane of an RGBA8 image (one float per pixel; reads at pixel centres become lookups).
//! SIMD and threaded; equal to luma() per pixel, bit for bit, of the texels as `format`
//! reads them (unorm: v / 255; sRGB: kSrgb8, the decoded linear values).
ImageF lumaPlane(ImageView<const Rgba8> image, const Exec& exec = {}, TextureFormat format = TextureFormat::Unorm);
//! The same into a caller's plane of the image's size.
void lumaPlane(ImageView<const Rgba8> image, ImageView<float> out, const Exec& exec = {},
               TextureFormat format = TextureFormat::Unorm);

}  // namespace ssfx
