// Adaptive supersampling for deferred shading (see adaptive.hpp; paper sections 3-4).
#include "ssfx/deferred/adaptive.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ssfx/core/color.hpp"
#include "ssfx/core/error.hpp"

namespace ssfx::deferred {

namespace {

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void checkM(const scene::GBuffer& g) {
    if (g.m < 1 || g.m > 4) throw Error(fmt::format("deferred: G-buffer supersampling m = {} is not in 1..4", g.m));
}

float lumaOf(const glm::vec3& c) {
    const glm::vec3 v = glm::clamp(c, 0.0f, 1.0f);
    return luma(v.r, v.g, v.b);  // the PPAA methods' luma (ppaa.md section 1)
}

}  // namespace

void validate(const AdaptiveParams& p) { validateParams(kAdaptiveParams, &p, "adaptive"); }

std::vector<int> ditherMatrix(int m) {
    // Bayer (1973) index matrices as printed in the paper's Figure 3 (rows top to bottom).
    switch (m) {
        case 1: return {0};
        case 2: return {0, 2, 3, 1};
        case 3: return {2, 6, 3, 5, 0, 8, 1, 7, 4};
        case 4: return {1, 8, 2, 10, 12, 4, 14, 6, 3, 11, 0, 9, 15, 7, 13, 5};
        default: throw Error(fmt::format("dither matrix: m = {} is not in 1..4", m));
    }
}

std::vector<std::array<int, 2>> ditherOrder(int m) {
    const auto matrix = ditherMatrix(m);
    std::vector<std::array<int, 2>> order(matrix.size());
    for (int y = 0; y < m; ++y)
        for (int x = 0; x < m; ++x) order[std::size_t(matrix[std::size_t(y * m + x)])] = {x, y};
    return order;
}

float depthMetric(const float* d, int n, float c) {
    if (n <= 0) return 0.0f;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        sum += d[i];
        sum2 += double(d[i]) * d[i];
    }
    const double mean = sum / n;
    return float(c * std::max(0.0, sum2 / n - mean * mean));
}

float normalMetric(const glm::vec3* normals, int n, float c) {
    if (n <= 0) return 0.0f;
    glm::vec3 mean(0.0f);
    for (int i = 0; i < n; ++i) mean += normals[i];
    const float len = glm::length(mean);
    if (!(len > 0.0f)) return c;  // normals cancel out: a maximal cone
    mean /= len;
    float minDot = 1.0f;
    for (int i = 0; i < n; ++i) minDot = std::min(minDot, std::abs(glm::dot(mean, normals[i])));
    return c * std::sqrt(std::max(0.0f, 1.0f - minDot));
}

float shadingMetric(float centre, float north, float south, float west, float east, float c, float tMin, float tEdge) {
    const float lMax = std::max({centre, north, south, west, east}),
                lMin = std::min({centre, north, south, west, east});
    const float r = lMax - lMin;
    return r < std::max(tMin, lMax * tEdge) ? 0.0f : c * r;  // FXAA's early exit (ppaa.md section 1)
}

DeferredResult adaptiveSupersampling(const scene::Scene& scene, const scene::GBuffer& g, const AdaptiveParams& p,
                                     const Exec& exec) {
    validate(p);
    checkM(g);
    const SampleShader shader(scene, g, p.shading);
    const int m = g.m, n = m * m, w = g.width, h = g.height;
    const auto order = ditherOrder(m);
    DeferredResult r;
    r.image = ImageRgbF(w, h);
    r.samples = Image<std::uint8_t>(w, h);
    r.kDepth = ImageF(w, h);
    r.kNormal = ImageF(w, h);
    r.kShading = ImageF(w, h);
    r.possible = std::int64_t(w) * h * n;

    // ShadeFirstSample: dither index 0 of every window, standing for the whole pixel.
    auto t0 = std::chrono::steady_clock::now();
    ImageRgbF first(w, h);
    parallelRows(h, exec, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) first(x, y) = shader.shade(m * x + order[0][0], m * y + order[0][1], 1.0f);
    });
    r.firstMs = msSince(t0);

    // Evaluate: k per pixel from the geometry and shading metrics.
    t0 = std::chrono::steady_clock::now();
    ImageF lumas(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) lumas(x, y) = lumaOf(first(x, y));
    const ImageView<const float> lumasView = lumas.view();
    parallelRows(h, exec, [&](int y0, int y1) {
        std::vector<float> depths(static_cast<std::size_t>(n));
        std::vector<glm::vec3> normals(static_cast<std::size_t>(n));
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) {
                int geometry = 0;
                for (int j = 0; j < m; ++j)
                    for (int i = 0; i < m; ++i) {
                        const int sx = m * x + i, sy = m * y + j;
                        const float d = shader.linearDepth(sx, sy);
                        depths[std::size_t(j * m + i)] = std::isinf(d) ? kBackgroundDepth : d;
                        if (!std::isinf(d)) normals[std::size_t(geometry++)] = g.normal[g.index(sx, sy)];
                    }
                const float kd = depthMetric(depths.data(), n, p.cDepth);
                const float kn = normalMetric(normals.data(), geometry, p.cNormal);
                const float ks = shadingMetric(lumas(x, y), lumasView.clamped(x, y - 1), lumasView.clamped(x, y + 1),
                                               lumasView.clamped(x - 1, y), lumasView.clamped(x + 1, y), p.cShading,
                                               p.tMin, p.tEdge);
                r.kDepth(x, y) = kd;
                r.kNormal(x, y) = kn;
                r.kShading(x, y) = ks;
                const float k = std::max({kd, kn, ks});
                r.samples(x, y) = std::uint8_t(std::clamp(std::lround(std::min(k, 1e6f)), 1L, long(n)));
            }
    });
    r.evaluateMs = msSince(t0);

    // ShadeRestAdaptively: k - 1 more samples in dither order, each standing for 1/k of the pixel.
    // Returns the samples shaded beyond the first.
    auto shadePixel = [&](int x, int y) -> std::int64_t {
        const int k = r.samples(x, y);
        if (k == 1) {
            r.image(x, y) = first(x, y);
            return 0;
        }
        std::int64_t shaded = k - 1;
        const float footprint = 1.0f / std::sqrt(float(k));
        const int fx = m * x + order[0][0], fy = m * y + order[0][1];
        glm::vec3 sum = first(x, y);
        if (shader.textured(fx, fy)) {
            sum = shader.shade(fx, fy, footprint);  // its albedo depends on the footprint
            ++shaded;
        }
        for (int s = 1; s < k; ++s)
            sum += shader.shade(m * x + order[std::size_t(s)][0], m * y + order[std::size_t(s)][1], footprint);
        r.image(x, y) = sum / float(k);
        return shaded;
    };
    t0 = std::chrono::steady_clock::now();
    if (!p.tiled) {
        std::vector<std::int64_t> rowShaded(std::size_t(h), 0);
        parallelRows(h, exec, [&](int y0, int y1) {
            for (int y = y0; y < y1; ++y) {
                std::int64_t shaded = w;  // the first samples
                for (int x = 0; x < w; ++x) shaded += shadePixel(x, y);
                rowShaded[std::size_t(y)] = shaded;
            }
        });
        for (auto s : rowShaded) r.shaded += s;
    } else {
        // The paper's future work: per tile, the pixels grouped by sample count (a counting
        // sort), then shaded group by group. Same pixels, same samples, another order.
        constexpr int kTile = 8;
        const int tilesX = (w + kTile - 1) / kTile, tilesY = (h + kTile - 1) / kTile;
        std::vector<std::int64_t> bandShaded(std::size_t(tilesY), 0);
        parallelRows(tilesY, exec, [&](int t0y, int t1y) {
            std::vector<std::array<int, 2>> sorted(kTile * kTile);
            std::vector<int> start(std::size_t(n) + 2);
            for (int ty = t0y; ty < t1y; ++ty) {
                const int y0 = ty * kTile, y1 = std::min(h, y0 + kTile);
                std::int64_t shaded = std::int64_t(w) * (y1 - y0);
                for (int tx = 0; tx < tilesX; ++tx) {
                    const int x0 = tx * kTile, x1 = std::min(w, x0 + kTile);
                    std::fill(start.begin(), start.end(), 0);
                    for (int y = y0; y < y1; ++y)
                        for (int x = x0; x < x1; ++x) ++start[std::size_t(r.samples(x, y)) + 1];
                    for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
                    for (int y = y0; y < y1; ++y)
                        for (int x = x0; x < x1; ++x) sorted[std::size_t(start[r.samples(x, y)]++)] = {x, y};
                    for (int i = 0; i < (x1 - x0) * (y1 - y0); ++i)
                        shaded += shadePixel(sorted[std::size_t(i)][0], sorted[std::size_t(i)][1]);
                }
                bandShaded[std::size_t(ty)] = shaded;
            }
        });
        for (auto b : bandShaded) r.shaded += b;
    }
    r.restMs = msSince(t0);
    return r;
}

DeferredResult bruteForceSupersampling(const scene::Scene& scene, const scene::GBuffer& g, const ShadingParams& p,
                                       const Exec& exec) {
    checkM(g);
    const SampleShader shader(scene, g, p);
    const int m = g.m, n = m * m, w = g.width, h = g.height;
    const auto order = ditherOrder(m);
    const float footprint = 1.0f / float(m);
    DeferredResult r;
    r.image = ImageRgbF(w, h);
    r.samples = Image<std::uint8_t>(w, h, std::uint8_t(n));
    r.possible = r.shaded = std::int64_t(w) * h * n;
    const auto t0 = std::chrono::steady_clock::now();
    parallelRows(h, exec, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) {
                // Sample 0 with the whole pixel's footprint when m = 1 (as the method's first
                // sample), else in dither order with the 1/m footprint (the method's k = n case).
                glm::vec3 sum(0.0f);
                for (int s = 0; s < n; ++s)
                    sum += shader.shade(m * x + order[std::size_t(s)][0], m * y + order[std::size_t(s)][1], footprint);
                r.image(x, y) = sum / float(n);
            }
    });
    r.restMs = msSince(t0);
    return r;
}

}  // namespace ssfx::deferred
