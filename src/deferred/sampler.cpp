// Texture sampling with explicit derivatives (see sampler.hpp).
#include "ssfx/deferred/sampler.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ssfx::deferred {

glm::vec4 textureBilinear(const scene::TextureArray& t, int layer, int level, glm::vec2 uv) {
    const ImageRgba8& img = t.layers[std::size_t(layer)][std::size_t(level)];
    const int size = img.width();
    const float x = uv.x * float(size) - 0.5f, y = uv.y * float(size) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    // Repeat addressing on integer texel indices: size is a power of two, so the mask wraps
    // negative indices too (two's complement).
    const int x0 = int(std::int64_t(fx) & (size - 1)), y0 = int(std::int64_t(fy) & (size - 1));
    const int x1 = (x0 + 1) & (size - 1), y1 = (y0 + 1) & (size - 1);
    auto texel = [&](int xx, int yy) {
        const Rgba8 c = img(xx, yy);
        return glm::vec4(c.r, c.g, c.b, c.a) * (1.0f / 255.0f);
    };
    const glm::vec4 top = texel(x0, y0) * (1.0f - ax) + texel(x1, y0) * ax;
    const glm::vec4 bottom = texel(x0, y1) * (1.0f - ax) + texel(x1, y1) * ax;
    return top * (1.0f - ay) + bottom * ay;
}

glm::vec4 textureLod(const scene::TextureArray& t, int layer, glm::vec2 uv, float lod) {
    const float maxLevel = float(t.levelCount() - 1);
    lod = std::clamp(std::isfinite(lod) ? lod : maxLevel, 0.0f, maxLevel);
    const int l0 = int(std::floor(lod));
    const float f = lod - float(l0);
    const glm::vec4 a = textureBilinear(t, layer, l0, uv);
    if (f == 0.0f) return a;
    return a * (1.0f - f) + textureBilinear(t, layer, l0 + 1, uv) * f;
}

glm::vec4 textureGrad(const scene::TextureArray& t, int layer, glm::vec2 uv, glm::vec2 dx, glm::vec2 dy,
                      int maxAnisotropy) {
    const float size = float(t.size);
    const float px = glm::length(dx) * size, py = glm::length(dy) * size;  // footprint axes in texels
    const float pMax = std::max(px, py), pMin = std::min(px, py);
    if (!(pMax > 0.0f)) return textureLod(t, layer, uv, 0.0f);
    const int n = std::clamp(int(std::ceil(pMax / std::max(pMin, 1e-20f))), 1, maxAnisotropy);
    const float lod = std::log2(pMax / float(n));
    if (n == 1) return textureLod(t, layer, uv, lod);
    const glm::vec2 major = px >= py ? dx : dy;
    glm::vec4 sum(0.0f);
    for (int i = 0; i < n; ++i) sum += textureLod(t, layer, uv + major * ((float(i) + 0.5f) / float(n) - 0.5f), lod);
    return sum / float(n);
}

}  // namespace ssfx::deferred
