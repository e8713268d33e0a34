// Scalable Ambient Obscurance (see sao.hpp; spec sao.md).
#include "ssfx/ao/sao.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <chrono>
#include <cmath>
#include <utility>

#include "src/ao/ao_sampling.hpp"
#include "ssfx/core/error.hpp"

namespace ssfx::ao {

namespace {

// The paper's updated falloff (appendix, June 2012):
// A = max(0, 1 - 5 / (r^6 s) * sum max(r^2 - v.v, 0)^3 * max((v.n - beta) / (v.v + eps), 0)) ^ intensity.
// With linearIntensity (the released shader): A = max(0, 1 - ((sum * (intensity / r^6)) * (5 / s))),
// and no exponent. `exponent` is 1 then, and scale2 is 1 for the default (one factor).
struct SaoEstimator {
    float r2, bias, epsilon, scale, scale2, exponent;
    float term(float vv, float vn, float) const {
        const float f = std::max(r2 - vv, 0.0f);
        return f * f * f * std::max((vn - bias) / (vv + epsilon), 0.0f);
    }
    float finish(float sum) const { return post(std::max(0.0f, 1.0f - sum * scale * scale2)); }
    float post(float a) const { return exponent == 1.0f ? a : std::pow(a, exponent); }
    void fill(detail::SimdSampleInput& in) const {
        in.estimator = 0, in.r2 = r2, in.bias = bias, in.epsilon = epsilon, in.scale = scale, in.scale2 = scale2;
    }
};

// The released blur's Gaussian table (sigma = 2 taps; AmbientOcclusion_blur.pix, June 2012).
constexpr float kReleasedGaussian[5] = {0.153170f, 0.144893f, 0.122649f, 0.092902f, 0.062970f};

}  // namespace

int spiralTurnsFor(int s) {
    // Discrepancy-minimising turns for s = 1..30 (spec sao.md, from the released demo code).
    static constexpr int kTurns[30] = {1, 1, 2, 3, 2, 5, 2, 3, 2, 3, 3, 5, 5, 3, 4,
                                       7, 5, 5, 7, 9, 8, 5, 5, 7, 7, 7, 8, 5, 8, 11};
    if (s < 1 || s > 30) throw Error(fmt::format("sao: no spiral-turn table entry for {} samples (1..30)", s));
    return kTurns[s - 1];
}

float releasedTapAngle(int k, int numSamples, int numSpiralTurns, double spiralTurnAngle, float phi) {
    const float alpha = (float(k) + 0.5f) * (1.0f / float(numSamples));
    const float turnsAngle = float(numSpiralTurns) * float(spiralTurnAngle);  // GLSL folds it in float
    return alpha * turnsAngle + phi;  // two roundings: contraction is off (CMakeLists.txt)
}

float hashAngle(int x, int y) {
    // (3 * x) ^ (y + x * y): in C, + and * bind tighter than ^ (paper eq. 8 as released).
    return 10.0f * float((3 * x) ^ (y + x * y));
}

void validate(const SaoParams& p) {
    validateParams(kSaoParams, &p, "sao");
    detail::checkBilateral("sao", p.blur);
    if (p.releasedPacking && !p.packBlurInput) throw Error("sao: releasedPacking needs packBlurInput = 1");
}

SaoParams saoPreset(const std::string& name) {
    SaoParams p;
    if (name == "paper") return p;
    if (name != "released")
        throw Error(fmt::format("sao: unknown preset '{}' (presets: {})", name, fmt::join(saoPresetNames(), ", ")));
    // The released shaders (AmbientOcclusion_AO.pix, AmbientOcclusion_blur.pix) and their host
    // code's defaults, G3D 9, June 2012.
    p.numSamples = 11, p.numSpiralTurns = 7;         // NUM_SAMPLES, NUM_SPIRAL_TURNS
    p.spiralTurnAngle = 6.28, p.spinInFloat = true;  // tapLocation()
    p.linearIntensity = true;
    p.radius = 0.7f, p.bias = 0.012f, p.intensity = 0.7f;  // host defaults (the paper's demo: 1, 0.012, 1)
    p.blur.blurRadius = 4, p.blur.blurStride = 2;          // R, SCALE
    p.blur.blurReleasedWeights = true, p.blur.blurEpsilon = 1e-4f, p.blur.blurZeroOutside = true;
    p.blur.edgeSharpness = 2000.0f;                                          // EDGE_SHARPNESS 1 x 2000, on the key
    p.packBlurInput = true, p.releasedPacking = true, p.packZMin = -300.0f;  // RGB8, FAR_PLANE_Z
    return p;
}

std::vector<std::string> saoPresetNames() { return {"paper", "released"}; }

float releasedKey(float z, float zMin) {
    if (std::isinf(z)) return z;
    // CSZToKey, packKey, 8-bit storage of both channels, unpackKey (the released shaders).
    const float key = std::clamp(z * (1.0f / zMin), 0.0f, 1.0f);
    const float t = std::floor(key * 256.0f);
    const float g = std::nearbyint(t * (1.0f / 256.0f) * 255.0f) / 255.0f;
    const float b = std::nearbyint((key * 256.0f - t) * 255.0f) / 255.0f;
    return g * (256.0f / 257.0f) + b * (1.0f / 257.0f);
}

float packAo(float a) { return std::nearbyint(std::clamp(a, 0.0f, 1.0f) * 255.0f) / 255.0f; }

float packZ(float z, float zMin) {
    if (std::isinf(z)) return z;  // sky is told apart by the depth test, not by the key
    // key in [0, 1]; hi = floor(key * 256) / 256 and lo = key * 256 - floor(key * 256), each
    // stored as an 8-bit unorm (hi is a multiple of 1/256, so it survives exactly up to 255/256).
    const float key = std::clamp(z / zMin, 0.0f, 1.0f);
    const float t = std::floor(key * 256.0f);
    const float hi = std::nearbyint(std::min(t, 255.0f) / 256.0f * 255.0f) / 255.0f;
    const float lo = std::nearbyint((key * 256.0f - std::min(t, 255.0f)) * 255.0f) / 255.0f;
    const float k = std::nearbyint(hi * 256.0f) / 256.0f + lo / 256.0f;  // unpack
    return k * zMin;
}

void setParam(SaoParams& p, const std::string& name, double v) { ssfx::setParam(kSaoParams, &p, "sao", name, v); }

namespace {
void samplePassImpl(const ZPyramid& pyramid, const Projection& proj, Region region, const SaoParams& p,
                    const Exec& exec, bool vector, ImageF& out);
ImageF saoImpl(ImageView<const float> depth, const Camera& camera, const SaoParams& p, const Exec& exec,
               SaoTimings* timings, bool vector, AoStages* stages = nullptr);
}  // namespace

ImageF saoSamplePass(const std::vector<ImageF>& pyramid, const Projection& proj, Region region, const SaoParams& p,
                     const Exec& exec) {
    if (pyramid.empty()) throw Error("sao: empty z pyramid");
    thread_local ZPyramid flat;
    detail::copyPyramid(pyramid, flat);
    return saoSamplePass(flat, proj, region, p, exec);
}

ImageF saoSamplePass(const ZPyramid& pyramid, const Projection& proj, Region region, const SaoParams& p,
                     const Exec& exec) {
    if (pyramid.levels() == 0) throw Error("sao: empty z pyramid");
    ImageF out;
    samplePassImpl(pyramid, proj, region, p, exec, true, out);
    return out;
}

ImageF saoReference(ImageView<const float> depth, const Camera& camera, const SaoParams& p) {
    return saoImpl(depth, camera, p, Exec{1}, nullptr, false);
}

namespace {
detail::SampleSetup sampleSetup(const SaoParams& p, bool vector) {
    return {p.numSamples, p.numSpiralTurns,  p.logQ,       p.maxMip, p.radius, p.usePyramid,
            vector,       p.spiralTurnAngle, p.spinInFloat};
}

void samplePassImpl(const ZPyramid& pyramid, const Projection& proj, Region region, const SaoParams& p,
                    const Exec& exec, bool vector, ImageF& out) {
    const SampleConstants k = sampleConstants(p);
    const SaoEstimator est{k.r2, k.bias, k.epsilon, k.scale, k.scale2, k.exponent};
    detail::samplePass(pyramid, proj, region, sampleSetup(p, vector), est, exec, out);
}
}  // namespace

SampleConstants sampleConstants(const SaoParams& p) {
    validate(p);
    SampleConstants k;
    k.r2 = p.radius * p.radius, k.bias = p.bias, k.epsilon = p.epsilon;
    if (p.linearIntensity) {
        // The released host's intensityDivR6 = intensity / pow(radius, 6) (float), times the
        // shader's constant 5.0 / NUM_SAMPLES; no exponent.
        k.scale = p.intensity / std::pow(p.radius, 6.0f), k.scale2 = 5.0f / float(p.numSamples), k.exponent = 1.0f;
    } else {
        k.scale = 5.0f / (k.r2 * k.r2 * k.r2 * float(p.numSamples)), k.scale2 = 1.0f, k.exponent = p.intensity;
    }
    detail::spiral(sampleSetup(p, false), k.alpha, k.dirX, k.dirY, k.tapAngle);
    return k;
}

PositionFactors positionFactors(const Projection& p) {
    return {float((1.0 - 1.0 / p.width) / p.p00), float(-2.0 / (double(p.width) * p.p00)),
            float((1.0 / p.height - 1.0) / p.p11), float(2.0 / (double(p.height) * p.p11))};
}

BilateralTaps bilateralTaps(const BilateralParams& p) {
    // Section 2.4's spatial weights in summation order: t = -R..R with exp(-t^2 / (2 sigma^2))
    // (the centre 1), or the released blur's order and weights (the centre first with
    // gaussian[0], then t = -R..-1, 1..R with 0.3 + gaussian[|t|]).
    const int R = p.blurRadius;
    BilateralTaps taps;
    if (p.blurReleasedWeights) {
        if (R > 4) throw Error(fmt::format("bilateralPass: blurReleasedWeights needs blurRadius <= 4 (got {})", R));
        taps.offset.push_back(0), taps.weight.push_back(kReleasedGaussian[0]);
        for (int t = -R; t <= R; ++t)
            if (t != 0) taps.offset.push_back(t), taps.weight.push_back(0.3f + kReleasedGaussian[std::abs(t)]);
    } else {
        for (int t = -R; t <= R; ++t)
            taps.offset.push_back(t),
                taps.weight.push_back(std::exp(-float(t * t) / (2.0f * p.blurSigma * p.blurSigma)));
    }
    return taps;
}

namespace {}  // namespace

std::vector<Vec3> faceNormals(ImageView<const float> z, const Projection& proj, const Exec& exec) {
    if (z.width() != proj.width || z.height() != proj.height)
        throw Error(fmt::format("faceNormals: z is {}x{}, the projection {}x{}", z.width(), z.height(), proj.width,
                                proj.height));
    std::vector<Vec3> out(std::size_t(z.width()) * std::size_t(z.height()), Vec3{0, 0, 0});
    const detail::PositionTables pos(proj);
    parallelRows(z.height(), exec, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < z.width(); ++x) {
                Vec3 n;
                if (!std::isinf(z(x, y)) && detail::faceNormal(z, pos, x, y, n))
                    out[std::size_t(y) * std::size_t(z.width()) + std::size_t(x)] = n;
            }
    });
    return out;
}

void quadBilateral(ImageF& a, ImageView<const float> z, Region region, float threshold, const Exec& exec) {
    // A GPU does this with derivatives inside each 2x2 quad: A -= dFdx(A) * ((x & 1) - 0.5)
    // where |dFdx(z)| < threshold, then the same in y on the result: the average of the
    // pair. Pairs with a partner outside the region are left alone. Both members of a pair
    // get the same value (a + b == b + a), and pairs are disjoint, so it runs in place; a
    // row pair depends on nothing outside it, so row pairs run in parallel.
    if (region.width <= 0 || region.height <= 0) return;
    const int yEnd = region.y0 + region.height, xEnd = region.x0 + region.width;
    auto near = [&](float za, float zb) { return std::fabs(za - zb) < threshold; };  // false for sky (NaN, inf)
    auto horizontalPass = [&](int y) {
        float* row = &a(0, y - region.y0);
        for (int x = std::max(region.x0, (region.x0 + 1) & ~1); x + 1 < xEnd; x += 2)
            if (near(z(x, y), z(x + 1, y))) {
                const int i = x - region.x0;
                row[i] = row[i + 1] = (row[i] + row[i + 1]) * 0.5f;
            }
    };
    const int firstPair = region.y0 >> 1, pairs = ((yEnd - 1) >> 1) - firstPair + 1;
    parallelRows(pairs, exec, [&](int q0, int q1) {
        for (int q = q0; q < q1; ++q) {
            const int y0 = 2 * (firstPair + q), y1 = y0 + 1;
            const bool has0 = y0 >= region.y0, has1 = y1 < yEnd;
            if (has0) horizontalPass(y0);
            if (has1) horizontalPass(y1);
            if (!has0 || !has1) continue;  // the partner row is outside the region
            float* __restrict r0 = &a(0, y0 - region.y0);
            float* __restrict r1 = &a(0, y1 - region.y0);
            const float* z0 = &z(region.x0, y0);
            const float* z1 = &z(region.x0, y1);
            for (int i = 0; i < region.width; ++i)
                if (near(z0[i], z1[i])) r0[i] = r1[i] = (r0[i] + r1[i]) * 0.5f;
        }
    });
}

ImageF bilateralPass(const ImageF& a, ImageView<const float> z, Region region, const BilateralParams& p,
                     bool horizontal, const Exec& exec) {
    ImageF out;
    bilateralPass(a, z, region, p, horizontal, out, exec);
    return out;
}

void bilateralPass(const ImageF& a, ImageView<const float> z, Region region, const BilateralParams& p, bool horizontal,
                   ImageF& out, const Exec& exec) {
    // Section 2.4: spatial weights times max(0, 1 - k |dz|); sky does not contribute. Taps in
    // summation order with their spatial weights (bilateralTaps).
    const int W = region.width, H = region.height, R = p.blurRadius, S = p.blurStride;
    const BilateralTaps tapList = bilateralTaps(p);
    const std::vector<int>& order = tapList.offset;
    const std::vector<float>& weight = tapList.weight;
    const int taps = int(order.size());
    if (out.width() != region.width || out.height() != region.height) out = ImageF(region.width, region.height);
    // blurZeroOutside: a vertical tap beyond the region reads these rows (a key of -inf weighs
    // 0, for any k), a horizontal one is skipped; else taps clamp to the region's edge.
    const std::vector<float> outsideZ(p.blurZeroOutside ? std::size_t(W) : 0, -HUGE_VALF),
        outsideA(outsideZ.size(), 1.0f);
    // Taps of pixel i are i + t S. A row goes to the vector kernel (bilateral-inl.h: each
    // pixel sums its taps in order, the same float operations as the per-pixel loop below); in
    // the horizontal pass the pixels within R S of the row's ends reach past it and take the
    // per-pixel loop.
    parallelRows(region.height, exec, [&](int r0, int r1) {
        detail::BilateralRowInput row{};
        row.taps = taps;
        row.edgeSharpness = p.edgeSharpness;
        row.epsilon = p.blurEpsilon;
        for (int k = 0; k < taps; ++k) row.gauss[k] = weight[std::size_t(k)];
        for (int j = r0; j < r1; ++j) {
            const float* zc = &z(region.x0, region.y0 + j);
            const int lo = horizontal ? std::min(W, R * S) : 0, hi = horizontal ? std::max(lo, W - R * S) : W;
            row.zCentre = zc;
            for (int k = 0; k < taps; ++k) {
                const int t = order[std::size_t(k)];
                if (!horizontal && p.blurZeroOutside && (j + t * S < 0 || j + t * S >= H)) {
                    row.zTap[k] = outsideZ.data(), row.aTap[k] = outsideA.data();
                    continue;
                }
                const int tj = horizontal ? j : std::clamp(j + t * S, 0, H - 1);
                const int shift = horizontal ? t * S : 0;
                row.zTap[k] = &z(region.x0, region.y0 + tj) + shift;
                row.aTap[k] = &a(0, tj) + shift;
            }
            float* o = &out(0, j);
            detail::bilateralRowSimd(row, lo, hi, o);
            // The ends of a horizontal row, pixel by pixel.
            for (int i = 0; i < W; ++i) {
                if (i == lo) i = std::max(i, hi);
                if (i >= W) break;
                if (std::isinf(zc[i])) {
                    o[i] = 1.0f;
                    continue;
                }
                float s = 0, ws = 0;
                for (int k = 0; k < taps; ++k) {
                    const int at = i + order[std::size_t(k)] * S;
                    if (p.blurZeroOutside && (at < 0 || at >= W)) continue;  // weight 0
                    const int ti = std::clamp(at, 0, W - 1);
                    const float w =
                        weight[std::size_t(k)] * std::max(0.0f, 1.0f - p.edgeSharpness * std::fabs(zc[ti] - zc[i]));
                    s += w * a(ti, j);
                    ws += w;
                }
                o[i] = s / (ws + p.blurEpsilon);  // the centre tap has weight > 0
            }
        }
    });
}

ImageF sao(ImageView<const float> depth, const Camera& camera, const SaoParams& p, const Exec& exec) {
    return saoImpl(depth, camera, p, exec, nullptr, true);
}

ImageF sao(ImageView<const float> depth, const Camera& camera, const SaoParams& p, const Exec& exec,
           SaoTimings* timings) {
    return saoImpl(depth, camera, p, exec, timings, true);
}

ImageF sao(ImageView<const float> depth, const Camera& camera, const SaoParams& p, const Exec& exec, AoStages* stages) {
    if (!stages) throw Error("sao: no AoStages to fill");
    return saoImpl(depth, camera, p, exec, nullptr, true, stages);
}

namespace {
// A copy of the region r of `img`.
ImageF cropped(ImageView<const float> img, Region r) {
    ImageF out(r.width, r.height);
    for (int y = 0; y < r.height; ++y)
        std::copy(img.row(r.y0 + y) + r.x0, img.row(r.y0 + y) + r.x0 + r.width, &out(0, y));
    return out;
}

ImageF saoImpl(ImageView<const float> depth, const Camera& camera, const SaoParams& p, const Exec& exec,
               SaoTimings* timings, bool vector, AoStages* stages) {
    validate(p);
    const int g = p.guardBand;
    if (depth.width() <= 2 * g || depth.height() <= 2 * g)
        throw Error(fmt::format("sao: a {}x{} depth buffer has no pixels inside a guard band of {}", depth.width(),
                                depth.height(), g));
    using Clock = std::chrono::steady_clock;
    auto ms = [](Clock::time_point a, Clock::time_point b) {
        return std::chrono::duration<double, std::milli>(b - a).count();
    };
    const auto t0 = Clock::now();
    const Projection proj = projection(camera, depth.width(), depth.height());
    // Buffers kept per calling thread and reused while the sizes stay (a frame loop then
    // allocates only its output).
    thread_local struct Workspace {
        ZPyramid pyr;  // z is its level 0
        ImageF a, h, v, zp;
    } ws;
    const int levels = p.usePyramid ? p.maxMip : 0;
    ws.pyr.shape(depth.width(), depth.height(), levels);
    depthToZ(depth, camera, ws.pyr.level(0), exec);
    const ImageView<const float> z = std::as_const(ws.pyr).level(0);
    const auto t1 = Clock::now();
    for (int m = 1; m <= levels; ++m)
        zPyramidLevel(std::as_const(ws.pyr).level(m - 1), ws.pyr.level(m), p.pyramidFilter, exec);
    const auto t2 = Clock::now();
    const Region out{g, g, depth.width() - 2 * g, depth.height() - 2 * g};
    const Region work = quadAligned(out, depth.width(), depth.height());
    samplePassImpl(ws.pyr, proj, work, p, exec, vector, ws.a);
    if (stages) {
        *stages = AoStages{};
        stages->z = cropped(z, {0, 0, z.width(), z.height()});
        for (int m = 1; m <= levels; ++m) {
            const ImageView<const float> l = std::as_const(ws.pyr).level(m);
            stages->pyramid.push_back(cropped(l, {0, 0, l.width(), l.height()}));
        }
        stages->work = work;
        stages->raw = ws.a;
    }
    quadBilateral(ws.a, z, work, p.quadThreshold, exec);
    const auto t3 = Clock::now();
    ImageView<const float> zBlur = z;
    if (p.packBlurInput) {
        // What the blur would read from the packed buffer (the bandwidth option).
        if (ws.zp.width() != z.width() || ws.zp.height() != z.height()) ws.zp = ImageF(z.width(), z.height());
        for (int y = work.y0; y < work.y0 + work.height; ++y)
            for (int x = work.x0; x < work.x0 + work.width; ++x)
                ws.zp(x, y) = p.releasedPacking ? releasedKey(z(x, y), p.packZMin) : packZ(z(x, y), p.packZMin);
        float* av = ws.a.data();
        for (std::int64_t i = 0; i < ws.a.pixelCount(); ++i) av[i] = packAo(av[i]);
        zBlur = ws.zp.view();
    }
    if (stages) {
        stages->quad = ws.a;
        if (p.packBlurInput) stages->zBlur = cropped(zBlur, work);
    }
    bilateralPass(ws.a, zBlur, work, p.blur, true, ws.h, exec);
    if (p.releasedPacking) {  // the horizontal pass's output is stored in 8 bits too
        float* hv = ws.h.data();
        for (std::int64_t i = 0; i < ws.h.pixelCount(); ++i) hv[i] = packAo(hv[i]);
    }
    if (stages) stages->horizontal = ws.h;
    ImageF result(out.width, out.height);
    if (work.x0 == out.x0 && work.y0 == out.y0 && work.width == out.width && work.height == out.height) {
        bilateralPass(ws.h, zBlur, work, p.blur, false, result, exec);  // the usual case: even sizes
    } else {  // the work region has an extra row or column (odd sizes): crop it
        bilateralPass(ws.h, zBlur, work, p.blur, false, ws.v, exec);
        const ImageF& v = ws.v;
        for (int y = 0; y < out.height; ++y)
            for (int x = 0; x < out.width; ++x) result(x, y) = v(x + out.x0 - work.x0, y + out.y0 - work.y0);
    }
    const auto t4 = Clock::now();
    if (timings) *timings = {ms(t0, t1), ms(t1, t2), ms(t2, t3), ms(t3, t4), ms(t0, t4)};
    if (stages) stages->result = result;
    return result;
}
}  // namespace

}  // namespace ssfx::ao
