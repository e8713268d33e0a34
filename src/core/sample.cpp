#include "ssfx/core/sample.hpp"

#include "ssfx/core/color.hpp"

namespace ssfx {

namespace {
std::array<float, 4081> makeSixteenths() {
    std::array<float, 4081> t{};
    for (int k = 0; k <= 4080; ++k) t[std::size_t(k)] = static_cast<float>(k) / 4080.0f;
    return t;
}
std::array<float, 256> makeSrgbTable() {
    std::array<float, 256> t{};
    for (int k = 0; k < 256; ++k) t[std::size_t(k)] = static_cast<float>(srgbToLinear(k / 255.0));
    return t;
}
}  // namespace

const std::array<float, 4081> kSixteenthLevels = makeSixteenths();
const std::array<float, 256> kSrgb8 = makeSrgbTable();

Rgb Texture::sampleGpu(const AxisPos& ax, const AxisPos& ay, int ox, int oy) const {
    const auto [t00, t10, t01, t11] = fetch(ax, ay, ox, oy);
    // Exact weights in 1/65536 units; the sum is at most 65536 * 255 (fits in int32).
    const int w00 = (256 - ax.w) * (256 - ay.w), w10 = ax.w * (256 - ay.w);
    const int w01 = (256 - ax.w) * ay.w, w11 = ax.w * ay.w;
    auto channel = [&](std::uint8_t a, std::uint8_t b, std::uint8_t c, std::uint8_t d) {
        const int sum = w00 * a + w10 * b + w01 * c + w11 * d;
        const int k = (sum + 2048) >> 12;         // round half up to 1/16 level (4096 units)
        return kSixteenthLevels[std::size_t(k)];  // k / (255 * 16)
    };
    return {channel(t00.r, t10.r, t01.r, t11.r), channel(t00.g, t10.g, t01.g, t11.g),
            channel(t00.b, t10.b, t01.b, t11.b)};
}

Rgb Texture::sampleGpuDecoded(const AxisPos& ax, const AxisPos& ay, int ox, int oy) const {
    const auto [t00, t10, t01, t11] = fetch(ax, ay, ox, oy);
    // The same 8-bit sub-texel weights as sampleGpu, applied to decoded texels in float32
    // (the weights are exact: multiples of 1/65536), summed in this order.
    const float w00 = float((256 - ax.w) * (256 - ay.w)) * (1.0f / 65536.0f);
    const float w10 = float(ax.w * (256 - ay.w)) * (1.0f / 65536.0f);
    const float w01 = float((256 - ax.w) * ay.w) * (1.0f / 65536.0f);
    const float w11 = float(ax.w * ay.w) * (1.0f / 65536.0f);
    const float* d = decode_;
    auto channel = [&](std::uint8_t a, std::uint8_t b, std::uint8_t c, std::uint8_t e) {
        return ((w00 * d[a] + w10 * d[b]) + w01 * d[c]) + w11 * d[e];
    };
    return {channel(t00.r, t10.r, t01.r, t11.r), channel(t00.g, t10.g, t01.g, t11.g),
            channel(t00.b, t10.b, t01.b, t11.b)};
}

Rgb Texture::sampleExact(const AxisPos& ax, const AxisPos& ay, int ox, int oy) const {
    const auto [t00, t10, t01, t11] = fetch(ax, ay, ox, oy);
    const float fx = ax.frac, fy = ay.frac;
    auto channel = [&](std::uint8_t a, std::uint8_t b, std::uint8_t c, std::uint8_t d) {
        const float* t = decode_;
        const float top = t[a] + (t[b] - t[a]) * fx;
        const float bottom = t[c] + (t[d] - t[c]) * fx;
        return top + (bottom - top) * fy;
    };
    return {channel(t00.r, t10.r, t01.r, t11.r), channel(t00.g, t10.g, t01.g, t11.g),
            channel(t00.b, t10.b, t01.b, t11.b)};
}

}  // namespace ssfx
