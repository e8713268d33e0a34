#include "ssfx/core/sample.hpp"

namespace ssfx {

Rgb Texture::sampleGpu(float u, float v, int ox, int oy) const {
    const Axis ax = axis(u, fw_, w_, ox);
    const Axis ay = axis(v, fh_, h_, oy);
    const Rgba8* r0 = img_.row(ay.i0);
    const Rgba8* r1 = img_.row(ay.i1);
    const Rgba8 t00 = r0[ax.i0], t10 = r0[ax.i1], t01 = r1[ax.i0], t11 = r1[ax.i1];
    // Exact weights in 1/65536 units; the sum is at most 65536 * 255 (fits in int32).
    const int w00 = (256 - ax.w) * (256 - ay.w), w10 = ax.w * (256 - ay.w);
    const int w01 = (256 - ax.w) * ay.w, w11 = ax.w * ay.w;
    auto channel = [&](std::uint8_t a, std::uint8_t b, std::uint8_t c, std::uint8_t d) {
        const int sum = w00 * a + w10 * b + w01 * c + w11 * d;
        const int k = (sum + 2048) >> 12;  // round half up to 1/16 level (4096 units)
        return static_cast<float>(k) / 4080.0f;  // k / (255 * 16)
    };
    return {channel(t00.r, t10.r, t01.r, t11.r), channel(t00.g, t10.g, t01.g, t11.g),
            channel(t00.b, t10.b, t01.b, t11.b)};
}

Rgb Texture::sampleExact(float u, float v, int ox, int oy) const {
    const Axis ax = axis(u, fw_, w_, ox);
    const Axis ay = axis(v, fh_, h_, oy);
    const Rgba8* r0 = img_.row(ay.i0);
    const Rgba8* r1 = img_.row(ay.i1);
    const Rgba8 t00 = r0[ax.i0], t10 = r0[ax.i1], t01 = r1[ax.i0], t11 = r1[ax.i1];
    const float fx = ax.frac, fy = ay.frac;
    auto channel = [&](std::uint8_t a, std::uint8_t b, std::uint8_t c, std::uint8_t d) {
        const float top = kUnorm8[a] + (kUnorm8[b] - kUnorm8[a]) * fx;
        const float bottom = kUnorm8[c] + (kUnorm8[d] - kUnorm8[c]) * fx;
        return top + (bottom - top) * fy;
    };
    return {channel(t00.r, t10.r, t01.r, t11.r), channel(t00.g, t10.g, t01.g, t11.g),
            channel(t00.b, t10.b, t01.b, t11.b)};
}

}  // namespace ssfx
