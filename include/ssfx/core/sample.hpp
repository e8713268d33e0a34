// Texture reads with clamp-to-edge addressing, as a GPU sampler does them.
//
// Coordinates are texture coordinates in [0, 1]: pixel (x, y) has its centre at
// ((x + 0.5) / W, (y + 0.5) / H) (spec ppaa.md section 1). A read may add an *integer texel
// offset* (the GPU's sample-with-offset), which is added to the texel index after the floor.
//
// Two filtering models:
//  - Filtering::Gpu (default): the filter unit of real GPUs. The texel-space position
//    u * W - 0.5 (float32) is split into floor and fraction; the fraction is rounded to the
//    nearest 1/256 (8 sub-texel bits; it may round up to 1); the four 8-bit texels are
//    weighted exactly and the sum is rounded half-up to 1/16 of an 8-bit level, so every
//    channel is k / (255 * 16) for an integer k. Exact in integer arithmetic; it reproduces
//    the reference GPU outputs bit for bit (spec ppaa.md, "GPU sampling model").
//  - Filtering::Exact: float32 bilinear interpolation with the unrounded fraction.
//
// Two texture formats: TextureFormat::Unorm (rgba8unorm, the paper's and its reference
// images') returns v / 255; TextureFormat::Srgb (rgba8unorm_srgb, what GPU plotting renderers
// post-process) decodes every texel to linear light first (IEC 61966-2-1, as Vulkan's sRGB
// formats do, "sRGB EOTF") and filters the decoded values: in the Gpu model with the same
// 8-bit sub-texel weights, the sum in float32 (no 1/16-level grid: that grid is the fixed-point
// filtering of unorm texels, and a decoded texel is not on an 8-bit grid).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>

#include "ssfx/core/image.hpp"

namespace ssfx {

enum class Filtering : std::uint8_t {
    Gpu,    //!< 8-bit sub-texel weights, 1/16-level results (default; matches GPUs)
    Exact,  //!< float32 bilinear weights, no quantisation
};

namespace detail {
constexpr std::array<float, 256> makeUnormTable() {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[i] = static_cast<float>(i) / 255.0f;
    return t;
}
}  // namespace detail

//! 8-bit unorm to float: v / 255 rounded to float32 (what a GPU returns for rgba8unorm).
inline constexpr std::array<float, 256> kUnorm8 = detail::makeUnormTable();

//! How a texture's 8-bit texels are read: as unorm (v / 255) or sRGB-decoded to linear.
enum class TextureFormat : std::uint8_t {
    Unorm,  //!< rgba8unorm (the default: the paper's and its reference images' textures)
    Srgb,   //!< rgba8unorm_srgb: every read decoded to linear light before filtering
};
inline constexpr std::array<std::string_view, 2> kTextureFormatNames{"unorm", "srgb"};

//! sRGB-encoded 8-bit value to linear light, IEC 61966-2-1 (c <= 0.04045: c / 12.92, else
//! ((c + 0.055) / 1.055)^2.4), computed in double and rounded to float32; 0 and 255 give 0
//! and 1 exactly.
extern const std::array<float, 256> kSrgb8;

//! The 256 values a texel channel of this format reads as (kUnorm8 or kSrgb8).
inline const float* decodeTable(TextureFormat format) {
    return format == TextureFormat::Srgb ? kSrgb8.data() : kUnorm8.data();
}

//! k / (255 * 16) rounded to float32, for k = 0 .. 4080: a GPU-model filtered channel.
//! A table lookup instead of a division; the same correctly rounded floats.
extern const std::array<float, 4081> kSixteenthLevels;

struct Rgb {
    float r = 0, g = 0, b = 0;
};

//! An RGBA8 image seen as a texture (RGB channels; alpha is never filtered in ssfx).
class Texture {
public:
    Texture(ImageView<const Rgba8> image, Filtering filtering, TextureFormat format = TextureFormat::Unorm)
        : img_(image),
          w_(image.width()),
          h_(image.height()),
          fw_(static_cast<float>(image.width())),
          fh_(static_cast<float>(image.height())),
          invW_(1.0f / static_cast<float>(image.width())),
          invH_(1.0f / static_cast<float>(image.height())),
          filtering_(filtering),
          format_(format),
          decode_(ssfx::decodeTable(format)) {}

    int width() const { return w_; }
    int height() const { return h_; }
    //! 1/W and 1/H rounded to float32 once (spec: offsets are added as `u + d * (1/W)`).
    float invW() const { return invW_; }
    float invH() const { return invH_; }
    Filtering filtering() const { return filtering_; }
    TextureFormat format() const { return format_; }
    //! The 256 values a texel channel reads as (kUnorm8 or kSrgb8).
    const float* decodeTable() const { return decode_; }
    ImageView<const Rgba8> image() const { return img_; }

    //! Texture coordinate of pixel x's centre: (x + 0.5) / W in float32.
    float centreU(int x) const { return (static_cast<float>(x) + 0.5f) / fw_; }
    float centreV(int y) const { return (static_cast<float>(y) + 0.5f) / fh_; }

    //! Exact texel value with clamp-to-edge (a read at a pixel centre).
    Rgb texel(int x, int y) const {
        const Rgba8 p = img_.clamped(x, y);
        return {decode_[p.r], decode_[p.g], decode_[p.b]};
    }

    //! Bilinear read at texture coordinate (u, v) plus an integer texel offset (ox, oy).
    Rgb sample(float u, float v, int ox = 0, int oy = 0) const { return sample(axisU(u), axisV(v), ox, oy); }

    //! A coordinate split into texel index and sub-texel weight along one axis. Reads that
    //! share a coordinate and differ by integer texel offsets (batched reads) split it once.
    struct AxisPos {
        int index;   //!< floor(coord * size - 0.5), clamped to [-4, size + 4]
        float frac;  //!< fraction (Exact model)
        int w;       //!< fraction rounded to 1/256, 0..256 (Gpu model)
    };
    AxisPos axisU(float u) const { return axis(u, fw_, w_); }
    AxisPos axisV(float v) const { return axis(v, fh_, h_); }
    //! The read at split coordinates plus integer texel offsets; same result as sample().
    Rgb sample(const AxisPos& ax, const AxisPos& ay, int ox, int oy) const {
        if (filtering_ == Filtering::Exact) return sampleExact(ax, ay, ox, oy);
        return format_ == TextureFormat::Unorm ? sampleGpu(ax, ay, ox, oy) : sampleGpuDecoded(ax, ay, ox, oy);
    }

private:
    static AxisPos axis(float coord, float size, int n) {
        const float t = coord * size - 0.5f;
        const float fl = std::floor(t);
        // Clamp before converting: coordinates far outside the texture read the edge anyway
        // (and NaN, which no valid caller produces, lands on -4).
        const float lim = static_cast<float>(n) + 4.0f;
        const float flc = fl >= -4.0f ? (fl < lim ? fl : lim) : -4.0f;
        const float frac = t - fl;
        // Round half up to 1/256. (NaN, from a caller bug, must not reach the int conversion.)
        return {static_cast<int>(flc), frac, frac >= 0.0f ? static_cast<int>(frac * 256.0f + 0.5f) : 0};
    }
    // Clamped texel pair along an axis of n texels.
    static void pair(int i, int n, int* i0, int* i1) {
        *i0 = i < 0 ? 0 : (i >= n ? n - 1 : i);
        *i1 = i + 1 < 0 ? 0 : (i + 1 >= n ? n - 1 : i + 1);
    }
    struct Quad {
        Rgba8 t00, t10, t01, t11;  // (x0,y0) (x1,y0) (x0,y1) (x1,y1)
    };
    Quad fetch(const AxisPos& ax, const AxisPos& ay, int ox, int oy) const {  // inline: hot in every read
        int x0, x1, y0, y1;
        pair(ax.index + ox, w_, &x0, &x1);
        pair(ay.index + oy, h_, &y0, &y1);
        const Rgba8* r0 = img_.row(y0);
        const Rgba8* r1 = img_.row(y1);
        return {r0[x0], r0[x1], r1[x0], r1[x1]};
    }
    Rgb sampleGpu(const AxisPos& ax, const AxisPos& ay, int ox, int oy) const;
    Rgb sampleGpuDecoded(const AxisPos& ax, const AxisPos& ay, int ox, int oy) const;
    Rgb sampleExact(const AxisPos& ax, const AxisPos& ay, int ox, int oy) const;

    ImageView<const Rgba8> img_;
    int w_, h_;
    float fw_, fh_, invW_, invH_;
    Filtering filtering_;
    TextureFormat format_;
    const float* decode_;
};

}  // namespace ssfx
