// The blur's per-pixel formula, shared by the scalar reference and the SIMD row kernel's
// borders. Float operations in one fixed order so that every path gives the same bits.
#pragma once

#include "src/aa/ppaa_common.hpp"
#include "ssfx/aa/blur.hpp"

namespace ssfx::aa::detail {

// (BlurWeights and blurWeights() are public: ssfx/aa/blur.hpp.)

//! Sum order: centre, then the direct neighbours W, E, S, N, then the corners.
inline float blurChannel(float c, float w, float e, float s, float n, float sw, float se, float nw, float ne,
                         const BlurWeights& k) {
    const float direct = ((w + e) + (s + n)) * k.w1;
    const float corner = ((sw + se) + (nw + ne)) * k.w2;
    return ((c + direct) + corner) * k.norm;
}

//! `format`: an sRGB texture's texels are decoded (kSrgb8) and the result encoded back.
inline Rgba8 blurPixel(ImageView<const Rgba8> in, int x, int y, const BlurWeights& k,
                       TextureFormat format = TextureFormat::Unorm) {
    const float* d = decodeTable(format);
    const Rgba8 c = in(x, y), w = in.clamped(x - 1, y), e = in.clamped(x + 1, y);
    const Rgba8 s = in.clamped(x, y - 1), n = in.clamped(x, y + 1);
    const Rgba8 sw = in.clamped(x - 1, y - 1), se = in.clamped(x + 1, y - 1);
    const Rgba8 nw = in.clamped(x - 1, y + 1), ne = in.clamped(x + 1, y + 1);
    auto ch = [&](std::uint8_t Rgba8::*m) {
        return encode8(
            blurChannel(d[c.*m], d[w.*m], d[e.*m], d[s.*m], d[n.*m], d[sw.*m], d[se.*m], d[nw.*m], d[ne.*m], k),
            format);
    };
    return {ch(&Rgba8::r), ch(&Rgba8::g), ch(&Rgba8::b), c.a};
}

}  // namespace ssfx::aa::detail
