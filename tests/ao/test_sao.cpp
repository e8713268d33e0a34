// SAO (src/ao/sao.cpp, ao_simd.cpp) and the AlchemyAO baseline on analytic depth buffers
// (planes computed in the test). Depth and the pyramid: test_depth.cpp; the ray tracer:
// test_raytraced.cpp.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <utility>

#include "ssfx/ao/alchemy.hpp"
#include "ssfx/ao/depth.hpp"
#include "ssfx/ao/raytraced.hpp"
#include "ssfx/ao/sao.hpp"
#include "ssfx/scene/analytic.hpp"

using namespace ssfx;
using namespace ssfx::ao;

namespace {

// Casts a ray through each pixel centre and stores the depth of the nearest hit of
// `hit(dir) -> t` (t along a ray whose z component is -1, so camera-space z = -t), or
// 1 (sky, with an infinite far plane) for no hit (t <= 0 or infinite).
ImageF castDepth(int w, int h, const Camera& cam, const std::function<double(Vec3)>& hit) {
    const Projection p = projection(cam, w, h);
    ImageF d(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Vec3 dir = reconstructPosition(p, float(x) + 0.5f, float(y) + 0.5f, -1.0f);
            const double t = hit(dir);
            d(x, y) = (t > 0 && std::isfinite(t)) ? float(zToDepth(-t, cam)) : 1.0f;
        }
    return d;
}

// Floor y = -1 and a back wall z = -5 (an inside corner along y = -1, z = -5).
double cornerHit(Vec3 dir) {
    double t = 5.0;  // the wall
    if (dir.y < 0) t = std::min(t, -1.0 / dir.y);
    return t;
}

}  // namespace

TEST(Sao, HashAndSpiralByHand) {
    // phi = 10 * ((3x) ^ (y + x y)): (2, 3): 6 ^ 9 = 15; (5, 1): 15 ^ 6 = 9; (0, 0): 0.
    EXPECT_EQ(hashAngle(2, 3), 150.0f);
    EXPECT_EQ(hashAngle(5, 1), 90.0f);
    EXPECT_EQ(hashAngle(0, 0), 0.0f);
    EXPECT_EQ(spiralTurnsFor(9), 2);
    EXPECT_EQ(spiralTurnsFor(1), 1);
    EXPECT_EQ(spiralTurnsFor(30), 11);
    EXPECT_THROW(spiralTurnsFor(31), Error);
}

TEST(Sao, FrontoParallelPlaneIsUnoccluded) {
    Camera cam;
    const ImageF d = castDepth(96, 64, cam, [](Vec3) { return 3.0; });  // the plane z = -3
    for (bool pyramid : {true, false}) {
        SaoParams p;
        p.usePyramid = pyramid;
        const ImageF a = sao(d.view(), cam, p);
        for (float v : a.pixels()) ASSERT_NEAR(v, 1.0f, 1e-6f);
    }
    const ImageF b = alchemy(d.view(), cam);
    for (float v : b.pixels()) ASSERT_NEAR(v, 1.0f, 1e-6f);
}

TEST(Sao, InsideCornerIsOccludedAndSkyStaysOne) {
    Camera cam;
    const int w = 160, h = 120;
    // The corner scene, with sky above the wall's top edge at y = +1.5.
    const ImageF d = castDepth(w, h, cam, [](Vec3 dir) {
        const double t = cornerHit(dir);
        return t * dir.y > 1.5 ? INFINITY : t;
    });
    SaoParams p;
    p.radius = 1.0f;
    const ImageF a = sao(d.view(), cam, p);
    const Projection proj = projection(cam, w, h);
    // Pixel rows: the corner line y = -1 at z = -5 projects to row h/2 + S/5.
    const int cornerRow = int(h / 2 + proj.pixelsPerMeter / 5.0f);
    double nearCorner = 0, openWall = 0, skyMin = 1;
    for (int x = 40; x < 120; ++x) {
        nearCorner += a(x, cornerRow - 2) / 80.0;  // on the wall, just above the corner
        openWall += a(x, h / 2 - 5) / 80.0;        // the wall about 1 m above the floor
    }
    for (int x = 0; x < w; ++x) skyMin = std::min<double>(skyMin, a(x, 0));
    EXPECT_LT(nearCorner, 0.85);  // the floor occludes the wall's foot
    EXPECT_GT(openWall, 0.97);    // nothing within 1 m occludes the open wall
    EXPECT_EQ(skyMin, 1.0);       // sky pixels stay 1
    for (float v : a.pixels()) ASSERT_TRUE(v >= 0.0f && v <= 1.0f);
    // The baseline sees the same corner.
    const ImageF b = alchemy(d.view(), cam);
    double bCorner = 0;
    for (int x = 40; x < 120; ++x) bCorner += b(x, cornerRow - 2) / 80.0;
    EXPECT_LT(bCorner, 0.9);
}

TEST(Sao, SameBytesForAnyThreadCountAndGuardBand) {
    Camera cam;
    const ImageF d = castDepth(130, 90, cam, cornerHit);
    SaoParams p;
    p.guardBand = 13;
    const ImageF a1 = sao(d.view(), cam, p, Exec{1}), a4 = sao(d.view(), cam, p, Exec{4});
    EXPECT_EQ(a1, a4);
    EXPECT_EQ(a1.width(), 130 - 26);
    EXPECT_EQ(a1.height(), 90 - 26);
    EXPECT_EQ(alchemy(d.view(), cam, {}, Exec{1}), alchemy(d.view(), cam, {}, Exec{3}));
}

TEST(Sao, BadInputsAreClearErrors) {
    Camera cam;
    ImageF d(16, 16, 0.5f);
    auto expectError = [&](const ImageF& depth, const SaoParams& p, const std::string& text) {
        try {
            sao(depth.view(), cam, p);
            ADD_FAILURE() << "no error for " << text;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
        }
    };
    ImageF bad = d;
    bad(3, 5) = NAN;
    expectError(bad, {}, "pixel (3, 5)");
    bad(3, 5) = 1.5f;
    expectError(bad, {}, "not in [0, 1]");
    bad(3, 5) = INFINITY;
    expectError(bad, {}, "pixel (3, 5)");
    SaoParams p;
    p.guardBand = 8;
    expectError(d, p, "guard band");
    p = {};
    p.radius = -1;
    expectError(d, p, "radius");
    p = {};
    p.numSamples = 0;
    expectError(d, p, "numSamples");
    Camera badCam;
    badCam.zNear = 0.1;
    EXPECT_THROW(sao(d.view(), badCam), Error);
    badCam = {};
    badCam.fovY = 4;
    EXPECT_THROW(sao(d.view(), badCam), Error);
}

TEST(Sao, InsideCornerMatchesTheRaytracedValue) {
    // Where the floor meets the wall, SAO's estimate is within 0.1 of the ray-traced truth
    // (measured: 0.49 vs 0.50 at 320x240); AlchemyAO's estimator is scaled differently.
    Camera cam;
    const int w = 320, h = 240;
    const auto scene = scene::cornerScene();
    const auto geo = scene::castGeometry(scene, cam, w, h);
    const ImageF s = sao(geo.depth.view(), cam);
    const ImageF t = raytraced(scene, cam, w, h);
    // The last wall row above the floor (the corner line) in the middle column.
    int row = -1;
    for (int y = h / 2; y < h; ++y)
        if (geo.z(160, y) <= -4.999f) row = y;
    ASSERT_GT(row, 0);
    EXPECT_NEAR(s(160, row), t(160, row), 0.1);
    EXPECT_LT(t(160, row), 0.6);
    // Away from the corner, on the open wall, both are near 1.
    EXPECT_NEAR(s(160, row - 40), t(160, row - 40), 0.05);
}

TEST(Sao, VectorKernelMatchesTheScalarReference) {
    // Tolerance: the vector kernel takes the hash angle's sine and cosine from float
    // approximations (the reference: double), so a tap whose truncated offset sits on a
    // pixel boundary can move by one pixel; that changes A by a few 1e-4 in rare pixels
    // (measured on the room at 640x360: SAO max 1e-7, AlchemyAO max 4e-4 in 7 pixels).
    // Bound: every pixel within 2e-3, mean difference below 1e-6.
    Camera cam;
    const auto geo = scene::castGeometry(scene::roomScene(), cam, 320 + 32, 180 + 32);
    auto compare = [](const ImageF& a, const ImageF& r, const char* what) {
        ASSERT_EQ(a.width(), r.width());
        double mx = 0, sum = 0;
        for (std::size_t i = 0; i < a.pixels().size(); ++i) {
            const double d = std::abs(double(a.pixels()[i]) - r.pixels()[i]);
            mx = std::max(mx, d), sum += d;
        }
        EXPECT_LE(mx, 2e-3) << what;
        EXPECT_LE(sum / double(a.pixels().size()), 1e-6) << what;
    };
    SaoParams sp;
    sp.guardBand = 16;
    compare(sao(geo.depth.view(), cam, sp), saoReference(geo.depth.view(), cam, sp), "sao");
    sp.radius = 3.0f;
    sp.intensity = 2.0f;
    compare(sao(geo.depth.view(), cam, sp), saoReference(geo.depth.view(), cam, sp), "sao r=3 intensity 2");
    AlchemyParams ap;
    ap.guardBand = 16;
    compare(alchemy(geo.depth.view(), cam, ap), alchemyReference(geo.depth.view(), cam, ap), "alchemy");
    // Odd sizes: the last column's quad partner is clamped, the scalar loop finishes rows.
    const auto odd = scene::castGeometry(scene::cornerScene(), cam, 101, 77);
    compare(sao(odd.depth.view(), cam), saoReference(odd.depth.view(), cam), "sao odd size");
    // An odd guard band: vectors start on odd columns, so the quad-pair normal gathers its
    // partners (even starts take them from the vector's own lanes).
    sp = SaoParams{};
    sp.guardBand = 13;
    ap.guardBand = 13;
    compare(sao(geo.depth.view(), cam, sp), saoReference(geo.depth.view(), cam, sp), "sao odd guard band");
    compare(alchemy(geo.depth.view(), cam, ap), alchemyReference(geo.depth.view(), cam, ap), "alchemy odd guard band");
}

TEST(Sao, PackedBlurInputByHandAndItsEffect) {
    // A to 8 bits: 0.5 * 255 = 127.5 rounds to even, 128.
    EXPECT_FLOAT_EQ(packAo(0.5f), 128.0f / 255.0f);
    EXPECT_EQ(packAo(1.0f), 1.0f);
    // z = -50 m with z_min = -200 m: key 0.25, key * 256 = 64 exactly: hi = 64/256, lo = 0.
    EXPECT_FLOAT_EQ(packZ(-50.0f, -200.0f), -50.0f);
    EXPECT_TRUE(std::isinf(packZ(-INFINITY, -200.0f)));
    // The fraction channel has 255 steps per 1/256 of the key: |error| <= 200 m * 0.5 / 255 / 256.
    for (float z = -0.1f; z > -199.0f; z *= 1.37f) EXPECT_LE(std::abs(packZ(z, -200.0f) - z), 1.54e-3f) << z;
    // On the room, the packed blur input changes A by little more than the 8-bit step.
    Camera cam;
    const auto geo = scene::castGeometry(scene::roomScene(), cam, 320 + 32, 180 + 32);
    SaoParams p;
    p.guardBand = 16;
    const ImageF a = sao(geo.depth.view(), cam, p);
    p.packBlurInput = true;
    const ImageF b = sao(geo.depth.view(), cam, p);
    double mx = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i)
        mx = std::max(mx, double(std::abs(a.pixels()[i] - b.pixels()[i])));
    EXPECT_GT(mx, 0.0);
    EXPECT_LT(mx, 0.02);
}

namespace {

// A random AO image over `r` and a z buffer with a few depth steps and sky pixels.
struct BlurInput {
    ImageF a, z;
};
BlurInput blurInput(int w, int h, Region r, unsigned seed) {
    BlurInput in{ImageF(r.width, r.height), ImageF(w, h)};
    unsigned s = seed;
    auto next = [&] { return (s = s * 1664525u + 1013904223u) >> 8; };
    for (std::int64_t i = 0; i < in.a.pixelCount(); ++i) in.a.data()[i] = float(next() % 1000) / 999.0f;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const unsigned k = next() % 100;
            in.z(x, y) = k < 5 ? -HUGE_VALF : (k < 30 ? -2.0f - float(x) * 1e-3f : -2.0004f - float(k) * 1e-4f);
        }
    return in;
}

}  // namespace

TEST(Sao, BlurPassIsThePerPixelFormula) {
    // The per-pixel definition of section 2.4 as the spec states it (taps i + t S clamped to
    // the region, weights g_t max(0, 1 - k |dz|), sky = 1), written out here; the pass (a
    // vector kernel plus a per-pixel loop at the clamped ends) must give the same bits: it
    // does the same float operations in the same order.
    const int w = 75, h = 41;
    const Region r{3, 2, 67, 37};
    const BlurInput in = blurInput(w, h, r, 7);
    for (float k : {0.0f, 300.0f, 2048.0f})
        for (int radius : {0, 1, 3, 8})
            for (bool horizontal : {true, false}) {
                BilateralParams p;
                p.blurRadius = radius;
                p.blurStride = radius == 8 ? 5 : 3;
                p.edgeSharpness = k;
                const ImageF out = bilateralPass(in.a, in.z.view(), r, p, horizontal, Exec{2});
                for (int j = 0; j < r.height; ++j)
                    for (int i = 0; i < r.width; ++i) {
                        const float zc = in.z(r.x0 + i, r.y0 + j);
                        float s = 0.0f, ws = 0.0f;
                        for (int t = -radius; t <= radius; ++t) {
                            const int ti = horizontal ? std::clamp(i + t * p.blurStride, 0, r.width - 1) : i;
                            const int tj = horizontal ? j : std::clamp(j + t * p.blurStride, 0, r.height - 1);
                            const float g = std::exp(-float(t * t) / (2.0f * p.blurSigma * p.blurSigma));
                            const float wt = g * std::max(0.0f, 1.0f - k * std::fabs(in.z(r.x0 + ti, r.y0 + tj) - zc));
                            s += wt * in.a(ti, tj);
                            ws += wt;
                        }
                        const float expect = std::isinf(zc) ? 1.0f : s / ws;
                        ASSERT_EQ(out(i, j), expect) << "pixel " << i << "," << j << " radius " << radius << " k " << k
                                                     << (horizontal ? " horizontal" : " vertical");
                    }
            }
}

TEST(Sao, QuadBilateralAveragesPairsOfTheBufferGrid) {
    // The 2x2 quad step as written in the spec (pairs x ^ 1, then y ^ 1 on the result, each
    // from a copy; partners outside the region left alone), against the in-place parallel
    // pass, for regions starting on even and odd buffer coordinates and odd sizes.
    const int w = 40, h = 31;
    for (const Region r : {Region{0, 0, 40, 31}, Region{3, 1, 33, 27}, Region{2, 5, 36, 20}, Region{1, 0, 1, 1}}) {
        BlurInput in = blurInput(w, h, r, 11);
        ImageF expect = in.a;
        for (bool horizontal : {true, false}) {
            const ImageF before = expect;
            for (int j = 0; j < r.height; ++j)
                for (int i = 0; i < r.width; ++i) {
                    const int x = r.x0 + i, y = r.y0 + j;
                    const int px = horizontal ? x ^ 1 : x, py = horizontal ? y : y ^ 1;
                    const int pi = px - r.x0, pj = py - r.y0;
                    if (pi < 0 || pj < 0 || pi >= r.width || pj >= r.height) continue;
                    if (std::fabs(in.z(px, py) - in.z(x, y)) < 0.01f)
                        expect(i, j) = (before(i, j) + before(pi, pj)) * 0.5f;
                }
        }
        quadBilateral(in.a, in.z.view(), r, 0.01f, Exec{3});
        EXPECT_EQ(in.a, expect) << r.x0 << "," << r.y0 << " " << r.width << "x" << r.height;
        if (r.width > 1)
            EXPECT_NE(in.a, blurInput(w, h, r, 11).a);  // it did average something
        else
            EXPECT_EQ(in.a, blurInput(w, h, r, 11).a);  // a lone pixel has no partner
    }
}

TEST(Sao, OneBufferPyramidGivesTheSameLevelsAndPasses) {
    // zPyramid into one buffer (the layout sao() uses) holds the same levels as the
    // level-by-level form, and the sample passes on either input give the same bits.
    Camera cam;
    const auto geo = scene::castGeometry(scene::roomScene(), cam, 161, 97);
    const ImageF z = depthToZ(geo.depth.view(), cam);
    const Projection proj = projection(cam, 161, 97);
    const auto levels = zPyramid(z.view(), 4);
    ZPyramid flat;
    zPyramid(z.view(), 4, PyramidFilter::RotatedGrid, flat, Exec{2});
    ASSERT_EQ(flat.levels(), 5);
    for (int m = 0; m < 5; ++m) {
        ASSERT_EQ(flat.level(m).width(), levels[std::size_t(m)].width());
        ASSERT_EQ(flat.level(m).height(), levels[std::size_t(m)].height());
        EXPECT_EQ(ImageF::copyOf(std::as_const(flat).level(m)), levels[std::size_t(m)]) << "level " << m;
    }
    const Region r{5, 4, 150, 88};
    EXPECT_EQ(saoSamplePass(flat, proj, r, {}), saoSamplePass(levels, proj, r, {}));
    EXPECT_EQ(alchemySamplePass(flat, proj, r, {}), alchemySamplePass(z.view(), proj, r, {}));
    EXPECT_THROW(zPyramid(z.view(), 17, PyramidFilter::Mean, flat), Error);
    EXPECT_THROW(saoSamplePass(ZPyramid{}, proj, r, {}), Error);
}
