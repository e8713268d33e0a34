// Ray-traced ground truth (see raytraced.hpp).
#include "ssfx/ao/raytraced.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>

#include "ssfx/core/error.hpp"

namespace ssfx::ao {

namespace {

Vec3d normalize(Vec3d v) {
    const double l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return {v.x / l, v.y / l, v.z / l};
}

// Radical inverse in base 2 (the Hammersley set's second coordinate).
double radicalInverse2(std::uint32_t i) {
    i = (i << 16) | (i >> 16);
    i = ((i & 0x55555555u) << 1) | ((i & 0xAAAAAAAAu) >> 1);
    i = ((i & 0x33333333u) << 2) | ((i & 0xCCCCCCCCu) >> 2);
    i = ((i & 0x0F0F0F0Fu) << 4) | ((i & 0xF0F0F0F0u) >> 4);
    i = ((i & 0x00FF00FFu) << 8) | ((i & 0xFF00FF00u) >> 8);
    return double(i) * (1.0 / 4294967296.0);
}

// A per-pixel hash in [0, 1)^2 (integer mixing of Bob Jenkins / Thomas Wang style), the
// Cranley-Patterson rotation that decorrelates neighbouring pixels' ray sets.
void pixelShift(int x, int y, double& u, double& v) {
    auto mix = [](std::uint32_t h) {
        h ^= h >> 16, h *= 0x7feb352du, h ^= h >> 15, h *= 0x846ca68bu, h ^= h >> 16;
        return h;
    };
    const std::uint32_t a = mix(std::uint32_t(x) * 0x9e3779b9u ^ mix(std::uint32_t(y) + 0x632be5abu));
    u = double(a) / 4294967296.0;
    v = double(mix(a ^ 0x85ebca6bu)) / 4294967296.0;
}

}  // namespace

Vec3d primaryRay(const Projection& proj, float px, float py) {
    const Vec3 p = reconstructPosition(proj, px, py, -1.0f);
    return normalize({p.x, p.y, p.z});
}

void validate(const RaytracedParams& p) { validateParams(kRaytracedParams, &p, "raytraced"); }

std::vector<ImageF> raytracedSet(const RayScene& scene, const Camera& camera, int width, int height,
                                 std::span<const RaytracedParams> truths, const Exec& exec,
                                 const ProgressFn& progress) {
    if (truths.empty()) throw Error("raytraced: no truths asked for");
    for (const RaytracedParams& p : truths) {
        validate(p);
        if (p.raysPerPixel != truths[0].raysPerPixel || p.guardBand != truths[0].guardBand)
            throw Error("raytraced: truths from one ray set share raysPerPixel and guardBand");
    }
    const RaytracedParams& p0 = truths[0];
    if (width <= 2 * p0.guardBand || height <= 2 * p0.guardBand)
        throw Error(
            fmt::format("raytraced: no pixels inside a guard band of {} in {}x{}", p0.guardBand, width, height));
    const Projection proj = projection(camera, width, height);
    const int g = p0.guardBand, w = width - 2 * g, h = height - 2 * g;
    const double n = p0.raysPerPixel;
    double rMax = 0;
    for (const RaytracedParams& p : truths) rMax = std::max(rMax, double(p.radius));
    std::vector<ImageF> out;
    for (std::size_t k = 0; k < truths.size(); ++k) out.emplace_back(w, h);
    std::atomic<std::int64_t> rowsDone{0};
    parallelRows(h, exec, [&](int r0, int r1) {
        std::vector<double> occlusion(truths.size());
        for (int j = r0; j < r1; ++j)
            for (int i = 0; i < w; ++i) {
                const int x = i + g, y = j + g;
                const Vec3d dir = primaryRay(proj, float(x) + 0.5f, float(y) + 0.5f);
                const RayHit hit = scene.intersect({0, 0, 0}, dir, 0.0, INFINITY);
                // No hit, or a hit at or beyond a finite far plane, which a rasteriser clips:
                // nothing drawn there, sky, as the depth-buffer methods see it (depth 1).
                if (!std::isfinite(hit.t) || dir.z * hit.t <= camera.zFar) {
                    for (ImageF& o : out) o(i, j) = 1.0f;
                    continue;
                }
                const Vec3d c{dir.x * hit.t, dir.y * hit.t, dir.z * hit.t};
                const Vec3d nn = hit.normal;
                // An orthonormal frame around the normal (Duff et al. 2017, "Building an
                // orthonormal basis, revisited").
                const double sign = std::copysign(1.0, nn.z);
                const double a = -1.0 / (sign + nn.z), b = nn.x * nn.y * a;
                const Vec3d t1{1.0 + sign * nn.x * nn.x * a, sign * b, -sign * nn.x};
                const Vec3d t2{b, sign + nn.y * nn.y * a, -nn.y};
                // Start rays a little off the surface, scaled with distance (the hit point
                // carries the intersection's rounding).
                const double eps = scene.surfaceOffset() * std::max(1.0, hit.t);
                const Vec3d o{c.x + nn.x * eps, c.y + nn.y * eps, c.z + nn.z * eps};
                double su, sv;
                pixelShift(x, y, su, sv);
                std::fill(occlusion.begin(), occlusion.end(), 0.0);
                for (int k = 0; k < p0.raysPerPixel; ++k) {
                    // Hammersley point, rotated, mapped to a cosine-weighted direction.
                    double u1 = (k + 0.5) / n + su, u2 = radicalInverse2(std::uint32_t(k)) + sv;
                    u1 -= std::floor(u1), u2 -= std::floor(u2);
                    const double rad = std::sqrt(u1), phi = 2 * std::numbers::pi * u2;
                    const double lx = rad * std::cos(phi), ly = rad * std::sin(phi),
                                 lz = std::sqrt(std::max(0.0, 1 - u1));
                    const Vec3d d{t1.x * lx + t2.x * ly + nn.x * lz, t1.y * lx + t2.y * ly + nn.y * lz,
                                  t1.z * lx + t2.z * ly + nn.z * lz};
                    // The nearest hit within the largest radius is the nearest within any
                    // smaller one whenever it is closer than that one: one cast serves all.
                    const RayHit s = scene.intersect(o, d, 0.0, rMax);
                    for (std::size_t t = 0; t < truths.size(); ++t) {
                        const double r = truths[t].radius;
                        if (s.t < r) {
                            const double q = 1.0 - (s.t / r) * (s.t / r);
                            occlusion[t] += truths[t].visibility == Visibility::Binary ? 1.0 : q * q * q;
                        }
                    }
                }
                for (std::size_t t = 0; t < truths.size(); ++t) out[t](i, j) = float(1.0 - occlusion[t] / n);
            }
        if (progress) progress({"ray tracing", rowsDone += r1 - r0, h, "rows"});
    });
    return out;
}

ImageF raytraced(const RayScene& scene, const Camera& camera, int width, int height, const RaytracedParams& p,
                 const Exec& exec, const ProgressFn& progress) {
    return std::move(raytracedSet(scene, camera, width, height, std::span(&p, 1), exec, progress)[0]);
}

}  // namespace ssfx::ao
