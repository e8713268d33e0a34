// Adaptive supersampling: dither order, metrics on hand-made windows, the texture sampler
// against analytic expectations, k = m^2 reproducing the reference exactly, bad parameters,
// and the whole method on a rendered G-buffer.
#include <gtest/gtest.h>

#include <cmath>

#include "ssfx/core/error.hpp"
#include "ssfx/deferred/adaptive.hpp"
#include "ssfx/deferred/registry.hpp"
#include "ssfx/deferred/sampler.hpp"
#include "tests/deferred/hand_made_gbuffer.hpp"
#include "tests/render/render_fixture.hpp"
#include "tests/support/param_tables.hpp"

namespace ssfx::test {
namespace {

using namespace ssfx::deferred;

TEST(Dither, MatricesAreThePapersAndPermutations) {
    EXPECT_EQ(ditherMatrix(2), (std::vector<int>{0, 2, 3, 1}));
    EXPECT_EQ(ditherMatrix(3), (std::vector<int>{2, 6, 3, 5, 0, 8, 1, 7, 4}));
    EXPECT_EQ(ditherMatrix(4), (std::vector<int>{1, 8, 2, 10, 12, 4, 14, 6, 3, 11, 0, 9, 15, 7, 13, 5}));
    for (int m = 1; m <= 4; ++m) {
        auto v = ditherMatrix(m);
        std::sort(v.begin(), v.end());
        for (int i = 0; i < m * m; ++i) EXPECT_EQ(v[std::size_t(i)], i);
    }
    // Index 0 first, then 1, 2, 3 at the positions the matrix gives them.
    const auto o2 = ditherOrder(2);
    EXPECT_EQ(o2, (std::vector<std::array<int, 2>>{{0, 0}, {1, 1}, {1, 0}, {0, 1}}));
    const auto o4 = ditherOrder(4);
    EXPECT_EQ(o4[0], (std::array<int, 2>{2, 2}));
    EXPECT_EQ(o4[1], (std::array<int, 2>{0, 0}));
    EXPECT_EQ(o4[15], (std::array<int, 2>{0, 3}));
    EXPECT_THROW(ditherMatrix(5), Error);
}

TEST(Metrics, FlatWindowsNeedOneSampleAndEdgesMore) {
    const AdaptiveParams p;
    const float flat[4] = {3, 3, 3, 3};
    EXPECT_EQ(depthMetric(flat, 4, p.cDepth), 0.0f);
    const float step[4] = {3, 3, 4, 4};  // a 1 m step: variance 0.25
    EXPECT_FLOAT_EQ(depthMetric(step, 4, p.cDepth), 0.25f * p.cDepth);
    EXPECT_GT(std::lround(depthMetric(step, 4, p.cDepth)), 1);
    const float sky[4] = {3, 3, kBackgroundDepth, kBackgroundDepth};
    EXPECT_GT(depthMetric(sky, 4, p.cDepth), 16.0f);
    const glm::vec3 same[4] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    EXPECT_NEAR(normalMetric(same, 4, p.cNormal), 0.0f, 1e-6f);
    // A 90-degree crease: mean at 45 degrees, min |dot| = cos 45, k_n = c sqrt(1 - 0.7071).
    const glm::vec3 crease[4] = {{0, 0, 1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}};
    EXPECT_NEAR(normalMetric(crease, 4, p.cNormal), p.cNormal * std::sqrt(1.0f - std::sqrt(0.5f)), 1e-4f);
    EXPECT_GT(std::lround(normalMetric(crease, 4, p.cNormal)), 1);
    EXPECT_EQ(normalMetric(crease, 0, p.cNormal), 0.0f);
    // Shading: FXAA's early exit; above it, c * range.
    EXPECT_EQ(shadingMetric(0.5f, 0.5f, 0.5f, 0.5f, 0.5f, p.cShading, p.tMin, p.tEdge), 0.0f);
    EXPECT_EQ(shadingMetric(0.5f, 0.55f, 0.5f, 0.5f, 0.5f, p.cShading, p.tMin, p.tEdge), 0.0f);  // 0.05 < 0.0625
    EXPECT_FLOAT_EQ(shadingMetric(0.2f, 0.6f, 0.2f, 0.2f, 0.2f, p.cShading, p.tMin, p.tEdge), p.cShading * 0.4f);
}

TEST(Sampler, ConstantTextureAndAnisotropicFootprints) {
    scene::TextureArray t;
    addTextureLayer(t, ImageRgba8(16, 16, Rgba8{51, 102, 153, 255}));
    ImageRgba8 columns(16, 16), rows(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const std::uint8_t c = (x % 2) ? 255 : 0, r = (y % 2) ? 255 : 0;
            columns(x, y) = {c, c, c, 255};
            rows(x, y) = {r, r, r, 255};
        }
    addTextureLayer(t, columns);
    addTextureLayer(t, rows);
    ASSERT_EQ(t.levelCount(), 5);
    for (glm::vec2 d : {glm::vec2(0.0f), glm::vec2(0.01f), glm::vec2(3.0f)}) {
        const glm::vec4 v = textureGrad(t, 0, {0.3f, 0.7f}, d, {d.y, -d.x});
        EXPECT_NEAR(v.r, 0.2f, 1e-5f);
        EXPECT_NEAR(v.g, 0.4f, 1e-5f);
        EXPECT_NEAR(v.b, 0.6f, 1e-5f);
    }
    // A grazing footprint: half a texel across (x), 8 texels along v (y). Stripes that vary
    // along u stay sharp; stripes that vary along v are averaged.
    const glm::vec2 dx(0.5f / 16.0f, 0.0f), dy(0.0f, 8.0f / 16.0f);
    for (int i = 0; i < 16; ++i) {
        const glm::vec2 uv((float(i) + 0.5f) / 16.0f, 0.37f);
        EXPECT_NEAR(textureGrad(t, 1, uv, dx, dy).r, (i % 2) ? 1.0f : 0.0f, 1e-5f) << i;
        EXPECT_NEAR(textureGrad(t, 2, uv, dx, dy).r, 0.5f, 0.07f) << i;
    }
    // Isotropic 2-texel footprint: level 1, where the 2x2 box filter made the stripes grey
    // ((0 + 255 + 0 + 255 + 2) / 4 = 128, rounded as the mip chain rounds).
    EXPECT_NEAR(textureGrad(t, 1, {0.5f / 16.0f, 0.5f}, {2.0f / 16.0f, 0.0f}, {0.0f, 2.0f / 16.0f}).r, 128.0f / 255.0f,
                1e-6f);
    // Repeat addressing.
    EXPECT_NEAR(textureBilinear(t, 1, 0, {1.0f + 1.5f / 16.0f, 0.5f}).r, 1.0f, 1e-6f);
    EXPECT_NEAR(textureBilinear(t, 1, 0, {-1.0f + 0.5f / 16.0f, 0.5f}).r, 0.0f, 1e-6f);
}

TEST(Adaptive, AllSamplesReproduceTheReferenceExactly) {
    const scene::Scene scene = scene::atrium();
    for (int m = 2; m <= 4; ++m) {
        const scene::GBuffer g = handMadeGBuffer(scene, 6, 5, m, true);
        AdaptiveParams p;
        p.cDepth = 1e9f;  // every window has depth variance: k = m^2 everywhere
        const auto a = adaptiveSupersampling(scene, g, p);
        const auto r = bruteForceSupersampling(scene, g, p.shading);
        for (auto k : a.samples.pixels()) ASSERT_EQ(k, m * m);
        EXPECT_EQ(a.image, r.image) << "m = " << m;  // bit for bit
        // Every sample, plus the first one again (textured: its footprint changed).
        EXPECT_EQ(a.shaded, std::int64_t(6 * 5) * (m * m + 1));
        EXPECT_EQ(r.shaded, std::int64_t(6 * 5) * m * m);
    }
}

TEST(Adaptive, FlatRegionsShadeOneSample) {
    const scene::Scene scene = scene::atrium();
    const scene::GBuffer g = handMadeGBuffer(scene, 8, 6, 4, false);
    AdaptiveParams p;
    p.cShading = 0.0f;  // the checker's own contrast would trigger the shading metric
    const auto a = adaptiveSupersampling(scene, g, p);
    for (auto k : a.samples.pixels()) EXPECT_EQ(k, 1);
    EXPECT_EQ(a.shaded, 8 * 6);
    EXPECT_DOUBLE_EQ(a.shadedPercent(), 100.0 / 16.0);
}

// GBuffer::ambientOcclusion multiplies the ambient term of each of a pixel's samples: 1
// leaves every bit as without it, 0 gives the image of a scene without ambient light, and
// what is not a width x height image of values in [0, 1] is refused by name.
TEST(Adaptive, AmbientOcclusionScalesTheAmbientTerm) {
    scene::Scene scene = scene::atrium();
    scene::GBuffer g = handMadeGBuffer(scene, 8, 6, 2, true);
    const AdaptiveParams p;
    const auto plain = adaptiveSupersampling(scene, g, p);
    const auto plainBrute = bruteForceSupersampling(scene, g, p.shading);
    g.ambientOcclusion = ImageF(8, 6, 1.0f);
    EXPECT_EQ(adaptiveSupersampling(scene, g, p).image, plain.image);
    EXPECT_EQ(bruteForceSupersampling(scene, g, p.shading).image, plainBrute.image);
    g.ambientOcclusion = ImageF(8, 6, 0.0f);
    const auto occluded = adaptiveSupersampling(scene, g, p);
    EXPECT_NE(occluded.image, plain.image);
    scene::Scene dark = scene;
    dark.ambient = glm::vec3(0.0f);
    scene::GBuffer noAo = g;
    noAo.ambientOcclusion = ImageF();
    EXPECT_EQ(occluded.image, adaptiveSupersampling(dark, noAo, p).image);
    // Per pixel: occluding one pixel changes that pixel only (k aside: S's luma feeds it).
    g.ambientOcclusion = ImageF(8, 6, 1.0f);
    g.ambientOcclusion(3, 2) = 0.25f;
    const auto one = bruteForceSupersampling(scene, g, p.shading);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x)
            EXPECT_EQ(one.image(x, y) == plainBrute.image(x, y), x != 3 || y != 2) << x << "," << y;
    for (const auto& [bad, what] : {std::pair{ImageF(7, 6, 1.0f), "7x6"}, std::pair{ImageF(8, 6, NAN), "nan"},
                                    std::pair{ImageF(8, 6, 1.5f), "1.5"}, std::pair{ImageF(8, 6, -0.1f), "-0.1"}}) {
        g.ambientOcclusion = bad;
        try {
            adaptiveSupersampling(scene, g, p);
            ADD_FAILURE() << "accepted " << what;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("ambient occlusion"), std::string::npos) << e.what();
        }
    }
}

TEST(Adaptive, ParamTable) {
    checkParamTable<deferred::AdaptiveParams>(deferred::kAdaptiveParams, "adaptive",
                                              [](const deferred::AdaptiveParams& p) { deferred::validate(p); });
}

TEST(Adaptive, BadParametersAreRejected) {
    AdaptiveParams p;
    p.cDepth = -1.0f;
    EXPECT_THROW(validate(p), Error);
    p = {};
    p.tEdge = 1.5f;
    EXPECT_THROW(validate(p), Error);
    p = {};
    p.shading.stall = -1;
    EXPECT_THROW(validate(p), Error);
    p = {};
    p.shading.maxAnisotropy = 17;
    EXPECT_THROW(validate(p), Error);
    p = {};
    p.shading.shininess = std::nanf("");
    EXPECT_THROW(validate(p), Error);
    const scene::Scene scene = scene::atrium();
    scene::GBuffer g = handMadeGBuffer(scene, 4, 4, 2, false);
    g.normal.pop_back();
    EXPECT_THROW(adaptiveSupersampling(scene, g, {}), Error);
    g = handMadeGBuffer(scene, 4, 4, 2, false);
    g.material[3] = 999;
    EXPECT_THROW(bruteForceSupersampling(scene, g, {}), Error);
}

// Properties of every method of the deferred registry (new ones are covered automatically):
// the same bytes for any thread count, every parameter outside its range refused, a NaN in
// the G-buffer refused with an error naming the sample.
TEST_F(RenderTest, EveryDeferredMethodIsDeterministicAndRefusesBadInput) {
    const scene::Scene scene = scene::cornellBox();
    const scene::GBuffer g =
        renderer().renderGBuffer(scene, scene.views.at(0).second, 40, 70, 2);  // several row blocks
    for (const deferred::DeferredMethodInfo& m : deferred::deferredMethods()) {
        SCOPED_TRACE(std::string(m.id));
        const deferred::DeferredParams p = m.defaults();
        const auto one = m.run(scene, g, p, Exec{1});
        EXPECT_EQ(m.run(scene, g, p, Exec{2}).image, one.image);
        EXPECT_EQ(m.run(scene, g, p, Exec{8}).image, one.image);
        EXPECT_GT(one.shaded, 0);
        for (const ParamInfo& row : m.params) {
            deferred::DeferredParams q = m.defaults();
            EXPECT_THROW(deferred::setParam(m, q, row.name, row.max + std::max(1.0, row.max * 1e-3)), Error)
                << row.name;
            EXPECT_THROW(deferred::setParam(m, q, row.name, std::nan("")), Error) << row.name;
        }
        for (int plane = 0; plane < 3; ++plane) {
            scene::GBuffer bad = g;
            const std::size_t i = bad.index(7, 5);
            if (plane == 0) bad.depth.data()[i] = std::nanf("");
            if (plane == 1) bad.normal[i].y = std::nanf("");
            if (plane == 2) bad.uv[i].x = INFINITY;
            try {
                m.run(scene, bad, p, Exec{1});
                ADD_FAILURE() << "plane " << plane << ": a NaN was shaded";
            } catch (const Error& e) {
                EXPECT_NE(std::string(e.what()).find("(7, 5)"), std::string::npos) << e.what();
            }
        }
    }
    EXPECT_THROW(deferred::deferredMethodById("taa"), Error);
}

TEST_F(RenderTest, AdaptiveOnARenderedGBufferIsCloseToTheReferenceWithFewerSamples) {
    const scene::Scene scene = scene::atrium();
    const scene::GBuffer g = renderer().renderGBuffer(scene, scene.view("nave"), 128, 96, 4);
    const AdaptiveParams p;
    const auto a1 = adaptiveSupersampling(scene, g, p, Exec{1});
    const auto a2 = adaptiveSupersampling(scene, g, p, Exec{2});
    EXPECT_EQ(a1.image, a2.image);  // deterministic for any thread count
    EXPECT_EQ(a1.shaded, a2.shaded);
    const auto r = bruteForceSupersampling(scene, g, p.shading, Exec{2});
    const double psnr = 10.0 * std::log10(1.0 / mse(a1.image, r.image));
    EXPECT_GT(psnr, 35.0);
    EXPECT_LT(a1.shadedPercent(), 75.0);
    EXPECT_GT(a1.shadedPercent(), 100.0 / 16.0);
    // The tile-grouped order gives the same image and count.
    AdaptiveParams tiled = p;
    tiled.tiled = true;
    const auto t = adaptiveSupersampling(scene, g, tiled, Exec{2});
    EXPECT_EQ(t.image, a1.image);
    EXPECT_EQ(t.shaded, a1.shaded);
    // Stall changes the cost, not the result.
    AdaptiveParams stalled = p;
    stalled.shading.stall = 50;
    EXPECT_EQ(adaptiveSupersampling(scene, g, stalled).image, a1.image);
}

}  // namespace
}  // namespace ssfx::test
