// Ground-Truth Ambient Occlusion (see gtao.hpp; spec gtao.md). The per-pixel code of every
// pass is in gtao_pixel.hpp.
#include "ssfx/ao/gtao.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <utility>
#include <vector>

#include "src/ao/gtao_pixel.hpp"
#include "src/ao/gtao_simd.hpp"
#include "ssfx/core/error.hpp"

namespace ssfx::ao {

namespace detail {
GtaoTexelPath& gtaoTexelPathForTest() {
    static GtaoTexelPath path = GtaoTexelPath::Auto;
    return path;
}
bool gtaoNoisePlanes(const GtaoParams& p, GtaoNoisePlanes& planes) {
    using P = GtaoNoisePlanes;
    const int S = p.sliceCount, J = p.stepsPerSlice;
    const float power = p.sampleDistributionPower;
    if (S * (J + 2) > P::kMaxPlanes) return false;
    if (planes.slices == S && planes.steps == J && planes.power == power) return true;
    planes.values.assign(std::size_t(S * (J + 2)) * P::kPlaneFloats, 0.0f);
    for (int row = 0; row < 64; ++row)
        for (int col = 0; col < 64; ++col) {
            const std::array<float, 2> noise = gtaoNoise(col, row);
            float* at = planes.values.data() + std::size_t(row * P::kStride + col);
            for (int k = 0; k < S; ++k) {
                const float phi = gtaoSliceAngle(k, S, noise[0]);
                at[std::size_t(2 * k) * P::kPlaneFloats] = std::cos(phi);
                at[std::size_t(2 * k + 1) * P::kPlaneFloats] = std::sin(phi);
                for (int j = 0; j < J; ++j)
                    at[std::size_t(2 * S + k * J + j) * P::kPlaneFloats] = gtaoStepSpacing(k, j, J, power, noise[1]);
            }
        }
    for (std::size_t q = 0; q < std::size_t(S * (J + 2)); ++q)  // each row's copy of its first cells
        for (int row = 0; row < 64; ++row) {
            float* r = planes.values.data() + q * P::kPlaneFloats + std::size_t(row * P::kStride);
            std::copy(r, r + (P::kStride - 64), r + 64);
        }
    planes.slices = S, planes.steps = J, planes.power = power;
    return true;
}
bool& gtaoNoisePlanesForTest() {
    static bool use = true;
    return use;
}
bool& gtaoClampEverywhereForTest() {
    static bool clamp = false;
    return clamp;
}
}  // namespace detail

GtaoParams gtaoPreset(const std::string& name) {
    GtaoParams p;
    // XeGTAO's quality presets (vaGTAO.hlsl): slices x steps per side.
    if (name == "low") {
        p.sliceCount = 1, p.stepsPerSlice = 2;
    } else if (name == "medium") {
        p.sliceCount = 2, p.stepsPerSlice = 2;
    } else if (name == "high") {
        p.sliceCount = 3, p.stepsPerSlice = 3;
    } else if (name == "ultra") {
        p.sliceCount = 9, p.stepsPerSlice = 3;
    } else if (name == "ideal") {  // spec section 12: the definition's estimator
        p.radiusMultiplier = 1.0f, p.finalValuePower = 1.0f, p.falloffRange = 0.02f;
        p.projectedNormalLift = false, p.nearFade = false;
    } else if (name == "paper") {  // spec section 11 (full resolution; see gtao.hpp)
        p.sliceCount = 1, p.stepsPerSlice = 6;
        p.horizonStart = HorizonStart::MinusOne, p.thickness = 0.1f;
        p.radiusMultiplier = 1.0f, p.finalValuePower = 1.0f;
        p.projectedNormalLift = false, p.nearFade = false;
    } else {
        throw Error(fmt::format("gtao: unknown preset '{}' (presets: {})", name, fmt::join(kGtaoPresets, ", ")));
    }
    return p;
}

GtaoConstants gtaoConstants(const GtaoParams& p, const Projection& proj) {
    const float re = p.radius * p.radiusMultiplier, rp = 0.75f * re;
    return {re, rp, p.falloffRange * rp, p.falloffRange * re, re * (0.5f * float(proj.width) * proj.p00)};
}

Region gtaoGrown(Region out, int width, int height, int by) {
    const int x0 = std::max(0, out.x0 - by), y0 = std::max(0, out.y0 - by);
    const int x1 = std::min(width, out.x0 + out.width + by), y1 = std::min(height, out.y0 + out.height + by);
    return {x0, y0, x1 - x0, y1 - y0};
}

void validate(const GtaoParams& p) { validateParams(kGtaoParams, &p, "gtao"); }

void setParam(GtaoParams& p, const std::string& name, double v) { ssfx::setParam(kGtaoParams, &p, "gtao", name, v); }

int hilbertIndex(int x, int y) {
    // Spec section 7: a 64 x 64 Hilbert curve, the quadrant of each level from the top one.
    x &= 63, y &= 63;
    int index = 0;
    for (int s = 32; s > 0; s /= 2) {
        const int rx = (x & s) != 0, ry = (y & s) != 0;
        index += s * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) x = 63 - x, y = 63 - y;
            std::swap(x, y);
        }
    }
    return index;
}

std::array<float, 2> gtaoNoise(int x, int y, int frame) {
    const int i = hilbertIndex(x & 63, y & 63) + 288 * (frame & 63);
    // R2 sequence (spec section 7), in float: i is exact (< 2^24).
    const float a = 0.5f + float(i) * 0.75487766624669276f, b = 0.5f + float(i) * 0.56984029099805327f;
    return {a - std::floor(a), b - std::floor(b)};
}

float fastAcos(float x) { return detail::gtaoFastAcos(x); }

namespace {

using Clock = std::chrono::steady_clock;
double ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

// Pass 1 (spec section 4): level m + 1 from level m; the weights favour the farthest sample.
void chainLevel(ImageView<const float> finer, ImageView<float> coarser, float rp, float fRp, const Exec& exec) {
    parallelRows(coarser.height(), exec, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < coarser.width(); ++x) {
                const float t[4] = {finer.clamped(2 * x, 2 * y), finer.clamped(2 * x + 1, 2 * y),
                                    finer.clamped(2 * x, 2 * y + 1), finer.clamped(2 * x + 1, 2 * y + 1)};
                const float tmax = std::max(std::max(t[0], t[1]), std::max(t[2], t[3]));
                if (std::isinf(tmax)) {  // any sky in the block gives sky
                    coarser(x, y) = tmax;
                    continue;
                }
                float sum = 0.0f, wsum = 0.0f;
                for (float ti : t) {
                    const float w = std::clamp((rp - (tmax - ti)) / fRp, 0.0f, 1.0f);
                    sum += w * ti, wsum += w;
                }
                coarser(x, y) = sum / wsum;  // wsum >= 1: the farthest weighs 1
            }
    });
}

// Section 5.1 edges and section 6 normals of the work region. With `simd` (and no given
// normals), the interior of each row takes the vector code (gtao-inl.h: the same bits).
void edgesAndNormals(const detail::GtaoSetup& s, Region work, std::vector<std::uint8_t>& edges,
                     std::vector<Vec3>& normals, ImageView<const Vec3> given, const detail::GtaoSimdInput* simd,
                     const Exec& exec) {
    edges.assign(std::size_t(work.width) * std::size_t(work.height), 0);
    normals.assign(edges.size(), Vec3{0, 0, 0});
    parallelRows(work.height, exec, [&](int r0, int r1) {
        for (int j = r0; j < r1; ++j) {
            const int y = work.y0 + j;
            const std::size_t row = std::size_t(j) * std::size_t(work.width);
            auto pixel = [&](int x) {
                const std::size_t k = row + std::size_t(x - work.x0);
                float e[4];
                detail::gtaoEdges(s.t0, x, y, e);
                edges[k] = detail::quantiseEdges(e);
                if (std::isinf(s.t0(x, y))) return;
                normals[k] = given.empty() ? detail::gtaoNormalFromDepth(s, x, y, e) : detail::unitOrZero(given(x, y));
            };
            const int end = work.x0 + work.width;
            int x = work.x0;
            if (simd && given.empty()) {  // vector chunks: 1 <= x, x + N <= W - 1
                const int first = std::min(std::max(work.x0, 1), end), last = std::min(end, s.width - 1);
                for (; x < first; ++x) pixel(x);
                if (first < last) {
                    const std::size_t k = row + std::size_t(first - work.x0);
                    x = detail::gtaoEdgesNormalsRowSimd(*simd, y, first, last, &edges[k], &normals[k].x);
                }
            }
            for (; x < end; ++x) pixel(x);
        }
    });
}

// The 8-bit storage of xegtaoStorage: A / 1.5 as UNORM8.
float xegtaoStore(float a) { return std::nearbyint(std::clamp(a / 1.5f, 0.0f, 1.0f) * 255.0f) / 255.0f * 1.5f; }

struct Workspace {
    ZPyramid chain;
    detail::GtaoNoisePlanes noisePlanes;
    std::vector<std::uint8_t> edges;
    std::vector<Vec3> normals;
    ImageF a, b;
    Image<Vec3> bentA, bentB;
};

ImageF gtaoImpl(ImageView<const float> depth, const Camera& camera, const GtaoParams& p, const Exec& exec,
                const GtaoBuffers& buffers, GtaoStages* stages, GtaoTimings* timings, bool scalar = false) {
    validate(p);
    const int g = p.guardBand;
    const int W = depth.width(), H = depth.height();
    if (W <= 2 * g || H <= 2 * g)
        throw Error(fmt::format("gtao: a {}x{} depth buffer has no pixels inside a guard band of {}", W, H, g));
    if (!buffers.normals.empty() && (buffers.normals.width() != W || buffers.normals.height() != H))
        throw Error(fmt::format("gtao: the normal buffer is {}x{}, the depth buffer {}x{} (they must match)",
                                buffers.normals.width(), buffers.normals.height(), W, H));
    const auto c0 = Clock::now();
    const Projection proj = projection(camera, W, H);
    // Buffers kept per calling thread, reused while the sizes stay. A reference: the workers
    // of the parallel loops must see the caller's, not their own thread_local.
    thread_local Workspace perThread;
    Workspace& ws = perThread;
    ws.chain.shape(W, H, detail::kGtaoChainLevels - 1);
    depthToZ(depth, camera, ws.chain.level(0), exec);
    {
        float* t = ws.chain.data.data();  // t = -z > 0; sky -infinity -> +infinity
        for (std::int64_t i = 0, n = std::int64_t(W) * H; i < n; ++i) t[i] = -t[i];
    }
    const auto c1 = Clock::now();
    const detail::GtaoSetup s(ws.chain, proj, p);
    for (int m = 1; m < detail::kGtaoChainLevels; ++m)
        chainLevel(std::as_const(ws.chain).level(m - 1), ws.chain.level(m), s.rp, s.fRp, exec);
    const auto c2 = Clock::now();

    const Region out{g, g, W - 2 * g, H - 2 * g};
    const int passes = p.denoisePasses;
    auto grown = [&](int by) { return gtaoGrown(out, W, H, by); };
    const Region work = grown(passes);
    {  // Edges and normals: the vector code for all but the scalar reference.
        detail::GtaoSimdInput levelZero{};
        levelZero.chain = ws.chain.data.data(), levelZero.width = W, levelZero.height = H;
        levelZero.ax = s.pos.ax, levelZero.bx = s.pos.bx, levelZero.ay = s.pos.ay, levelZero.by = s.pos.by;
        edgesAndNormals(s, work, ws.edges, ws.normals, buffers.normals, scalar ? nullptr : &levelZero, exec);
    }
    const bool bent = buffers.bentNormals != nullptr;
    if (ws.a.width() != work.width || ws.a.height() != work.height) ws.a = ImageF(work.width, work.height);
    if (bent) ws.bentA = Image<Vec3>(work.width, work.height);
    detail::GtaoMain main(s, work, ws.normals.data());
    // The vector path (gtao-inl.h) where it applies: not for the scalar reference, nor with
    // bent normals or a sampleDistributionPower other than 2 (the scalar loop does those).
    const bool simd = !scalar && !bent && p.sampleDistributionPower == 2.0f;
    detail::GtaoSimdInput in{};
    if (simd) {
        static_assert(sizeof(Vec3) == 3 * sizeof(float));
        in = {ws.chain.data.data(),
              ws.chain.offset.data(),
              ws.chain.width.data(),
              s.texelX.data(),
              s.texelY.data(),
              W,
              H,
              g,
              s.pos.ax,
              s.pos.bx,
              s.pos.ay,
              s.pos.by,
              reinterpret_cast<const float*>(ws.normals.data()),
              work.x0,
              work.y0,
              work.width,
              s.noiseS.data(),
              s.noiseT.data(),
              s.rNum,
              s.re,
              s.fRe,
              s.mipOffset,
              s.toc1,
              s.thickness,
              s.finalPower,
              s.slices,
              s.steps,
              s.lift,
              s.nearFade,
              s.fastAcos,
              s.discard,
              s.minusOne};
        for (int l = 0; l < 16; ++l) {
            const int m = std::min(l, ws.chain.levels() - 1);
            in.levelStart16[l] = ws.chain.offset[std::size_t(m)];
            in.levelWidth16[l] = ws.chain.width[std::size_t(m)];
            in.levelHeight16[l] = ws.chain.height[std::size_t(m)];
            in.levelStartF16[l] = float(in.levelStart16[l]), in.levelWidthF16[l] = float(in.levelWidth16[l]);
        }
        const std::int64_t side = std::max(W, H);
        in.arithmeticTexels = (2 * side + 2) * side < (std::int64_t(1) << 30);
        // The one-product texel where it gives the table's entry for every p and level
        // (checked here, W + H entries a level: the vector pass then skips the correction).
        in.floatTexels = true;
        for (int m = 0; m < detail::kGtaoChainLevels; ++m) {
            const float sx = float(double(ws.chain.width[std::size_t(m)]) / (2.0 * W));
            const float sy = float(double(ws.chain.height[std::size_t(m)]) / (2.0 * H));
            for (int l = m; l < 16; l += detail::kGtaoChainLevels) in.texelScaleX16[l] = sx, in.texelScaleY16[l] = sy;
            for (int x = 0; x < W && in.floatTexels; ++x)
                in.floatTexels = int(float(2 * x + 1) * sx) == s.texelX[std::size_t(m * W + x)];
            for (int y = 0; y < H && in.floatTexels; ++y)
                in.floatTexels = int(float(2 * y + 1) * sy) == s.texelY[std::size_t(m * H + y)];
        }
        in.floatIndex = in.floatTexels && ws.chain.data.size() < (std::size_t(1) << 23);
        switch (detail::gtaoTexelPathForTest()) {
            case detail::GtaoTexelPath::Auto: break;
            case detail::GtaoTexelPath::Product: SSFX_ASSERT(in.floatIndex); break;
            case detail::GtaoTexelPath::ProductIntegerIndex:
                SSFX_ASSERT(in.floatTexels);
                in.floatIndex = false;
                break;
            case detail::GtaoTexelPath::Arithmetic:
                SSFX_ASSERT(in.arithmeticTexels);
                in.floatTexels = in.floatIndex = false;
                break;
            case detail::GtaoTexelPath::Tables: in.floatTexels = in.floatIndex = in.arithmeticTexels = false; break;
        }
        in.lodScale = float(std::exp2(2.0 - 2.0 * double(s.mipOffset)));
        if (detail::gtaoNoisePlanesForTest() && detail::gtaoNoisePlanes(p, ws.noisePlanes))
            in.noisePlanes = ws.noisePlanes.values.data();
        in.clampEverywhere = detail::gtaoClampEverywhereForTest();
    }
    parallelRows(work.height, exec, [&](int r0, int r1) {
        for (int j = r0; j < r1; ++j) {
            const int y = work.y0 + j;
            float* row = &ws.a(0, j);
            int i = 0;
            if (simd) i = detail::gtaoRowSimd(in, y, work.x0, work.x0 + work.width, row) - work.x0;
            for (; i < work.width; ++i) row[i] = main.pixel(work.x0 + i, y, bent ? &ws.bentA(i, j) : nullptr);
        }
    });
    if (p.xegtaoStorage) {
        float* a = ws.a.data();
        for (std::int64_t i = 0; i < ws.a.pixelCount(); ++i) a[i] = xegtaoStore(a[i]);
    }
    if (stages) {
        *stages = GtaoStages{};
        for (int m = 0; m < detail::kGtaoChainLevels; ++m) {
            const ImageView<const float> l = std::as_const(ws.chain).level(m);
            stages->chain.push_back(ImageF::copyOf(l));
        }
        stages->work = work;
        stages->edges = ImageF(work.width, work.height);
        stages->normals = Image<Vec3>(work.width, work.height);
        for (int j = 0; j < work.height; ++j)
            for (int i = 0; i < work.width; ++i) {
                const std::size_t k = std::size_t(j) * std::size_t(work.width) + std::size_t(i);
                stages->edges(i, j) = float(ws.edges[k]), stages->normals(i, j) = ws.normals[k];
            }
        stages->raw = ws.a;
    }
    const auto c3 = Clock::now();

    // Pass 3 (section 8): max(1, passes) ping-ponged 3x3 passes; 0 passes: A itself.
    ImageF result(out.width, out.height);
    Image<Vec3> bentOut;
    if (bent) bentOut = Image<Vec3>(out.width, out.height);
    if (passes == 0) {
        for (int y = 0; y < out.height; ++y)
            for (int x = 0; x < out.width; ++x) {
                const int i = x + out.x0 - work.x0, j = y + out.y0 - work.y0;
                result(x, y) = std::clamp(ws.a(i, j), 0.0f, 1.0f);
                if (bent) bentOut(x, y) = detail::unitOrZero(ws.bentA(i, j));
            }
    } else {
        for (int pass = 0; pass < passes; ++pass) {
            const bool last = pass == passes - 1;
            const Region r = grown(passes - 1 - pass);
            const float beta = last ? 1.2f : 1.2f / 5.0f;  // XeGTAO's DenoiseBlurBeta and its fifth
            if (ws.b.width() != work.width || ws.b.height() != work.height) ws.b = ImageF(work.width, work.height);
            if (bent && (ws.bentB.width() != work.width || ws.bentB.height() != work.height))
                ws.bentB = Image<Vec3>(work.width, work.height);
            detail::GtaoDenoise den{s.t0, work, ws.edges.data(), beta};
            // The vector denoiser (gtao-inl.h: the same bits) for the interior of each row of
            // the region where its neighbours are in the work region; not for the reference,
            // nor with bent normals.
            const detail::GtaoDenoiseInput vin{
                ws.chain.data.data(), W, ws.edges.data(), ws.a.data(), work.x0, work.y0, work.width, work.height, beta};
            const bool vector = !scalar && !bent;
            parallelRows(r.height, exec, [&](int r0, int r1) {
                for (int j = r0; j < r1; ++j) {
                    const int y = r.y0 + j, wj = y - work.y0;
                    auto finish = [&](float a) {
                        if (last) return std::clamp(a, 0.0f, 1.0f);
                        return p.xegtaoStorage ? xegtaoStore(a) : a;
                    };
                    auto pixel = [&](int x) {
                        const int wi = x - work.x0;
                        ws.b(wi, wj) =
                            finish(den.pixel(ws.a.view(), x, y, bent ? ws.bentA.view() : ImageView<const Vec3>{},
                                             bent ? &ws.bentB(wi, wj) : nullptr));
                    };
                    const int end = r.x0 + r.width;
                    int x = r.x0;
                    if (vector) {  // vector chunks: work.x0 + 1 <= x, x + N <= work's last column
                        const int first = std::min(std::max(r.x0, work.x0 + 1), end);
                        const int stop = std::min(end, work.x0 + work.width - 1);
                        for (; x < first; ++x) pixel(x);
                        if (first < stop) {
                            float* row = &ws.b(first - work.x0, wj);
                            x = detail::gtaoDenoiseRowSimd(vin, y, first, stop, row);
                            for (float* v = row; v < row + (x - first); ++v) *v = finish(*v);
                        }
                    }
                    for (; x < end; ++x) pixel(x);
                }
            });
            std::swap(ws.a, ws.b);
            if (bent) std::swap(ws.bentA, ws.bentB);
        }
        for (int y = 0; y < out.height; ++y)
            for (int x = 0; x < out.width; ++x) {
                const int i = x + out.x0 - work.x0, j = y + out.y0 - work.y0;
                result(x, y) = ws.a(i, j);
                if (bent) bentOut(x, y) = detail::unitOrZero(ws.bentA(i, j));
            }
    }
    if (bent) {  // sky: the view vector
        for (int y = 0; y < out.height; ++y)
            for (int x = 0; x < out.width; ++x)
                if (std::isinf(s.t0(x + out.x0, y + out.y0))) bentOut(x, y) = main.viewVector(x + out.x0, y + out.y0);
        *buffers.bentNormals = std::move(bentOut);
    }
    const auto c4 = Clock::now();
    if (timings) *timings = {ms(c0, c1), ms(c1, c2), ms(c2, c3), ms(c3, c4), ms(c0, c4)};
    if (stages) stages->result = result;
    return result;
}

}  // namespace

ImageF gtao(ImageView<const float> depth, const Camera& camera, const GtaoParams& params, const Exec& exec,
            const GtaoBuffers& buffers) {
    return gtaoImpl(depth, camera, params, exec, buffers, nullptr, nullptr);
}

ImageF gtao(ImageView<const float> depth, const Camera& camera, const GtaoParams& params, const Exec& exec,
            const GtaoBuffers& buffers, GtaoStages* stages) {
    if (!stages) throw Error("gtao: stages is null");
    return gtaoImpl(depth, camera, params, exec, buffers, stages, nullptr);
}

ImageF gtao(ImageView<const float> depth, const Camera& camera, const GtaoParams& params, const Exec& exec,
            GtaoTimings* timings) {
    return gtaoImpl(depth, camera, params, exec, {}, nullptr, timings);
}

ImageF gtaoReference(ImageView<const float> depth, const Camera& camera, const GtaoParams& params,
                     const GtaoBuffers& buffers) {
    return gtaoImpl(depth, camera, params, Exec{1}, buffers, nullptr, nullptr, true);
}

}  // namespace ssfx::ao
