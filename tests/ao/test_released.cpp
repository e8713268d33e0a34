// The released-code configuration of SAO (issue: the authors' released shaders, G3D 9, June
// 2012, as an opt-in preset): each of its parameters by hand on small inputs, the preset,
// and the vector kernel against the scalar oracle in that configuration.
#include <gtest/gtest.h>

#include <cmath>

#include "ssfx/ao/alchemy.hpp"
#include "ssfx/ao/depth.hpp"
#include "ssfx/ao/sao.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/scene/analytic.hpp"

using namespace ssfx;
using namespace ssfx::ao;

TEST(Released, PresetSetsEveryReleasedValueAndPaperIsTheDefault) {
    const SaoParams d, paper = saoPreset("paper"), r = saoPreset("released");
    EXPECT_EQ(paper.numSamples, d.numSamples);
    EXPECT_EQ(paper.blur.blurRadius, d.blur.blurRadius);
    EXPECT_FALSE(paper.spinInFloat || paper.linearIntensity || paper.releasedPacking || paper.blur.blurReleasedWeights);
    EXPECT_EQ(r.numSamples, 11);
    EXPECT_EQ(r.numSpiralTurns, 7);
    EXPECT_EQ(r.spiralTurnAngle, 6.28);
    EXPECT_TRUE(r.spinInFloat);
    EXPECT_TRUE(r.linearIntensity);
    EXPECT_EQ(r.radius, 0.7f);
    EXPECT_EQ(r.bias, 0.012f);
    EXPECT_EQ(r.intensity, 0.7f);
    EXPECT_EQ(r.epsilon, 0.01f);
    EXPECT_EQ(r.quadThreshold, 0.02f);
    EXPECT_EQ(r.blur.blurRadius, 4);
    EXPECT_EQ(r.blur.blurStride, 2);
    EXPECT_TRUE(r.blur.blurReleasedWeights);
    EXPECT_TRUE(r.blur.blurZeroOutside);
    EXPECT_EQ(r.blur.blurEpsilon, 1e-4f);
    EXPECT_EQ(r.blur.edgeSharpness, 2000.0f);
    EXPECT_TRUE(r.packBlurInput);
    EXPECT_TRUE(r.releasedPacking);
    EXPECT_EQ(r.packZMin, -300.0f);
    validate(r);
    EXPECT_EQ(saoPresetNames(), (std::vector<std::string>{"paper", "released"}));
    try {
        saoPreset("shipped");
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("paper, released"), std::string::npos) << e.what();
    }
}

TEST(Released, ParametersByNameAndTheirChecks) {
    SaoParams p;
    setParam(p, "spiralTurnAngle", 6.28);
    setParam(p, "spinInFloat", 1);
    setParam(p, "linearIntensity", 1);
    setParam(p, "blurReleasedWeights", 1);
    setParam(p, "blurZeroOutside", 1);
    setParam(p, "blurEpsilon", 1e-4);
    setParam(p, "packBlurInput", 1);
    setParam(p, "releasedPacking", 1);
    EXPECT_EQ(p.spiralTurnAngle, 6.28);
    EXPECT_TRUE(p.spinInFloat && p.linearIntensity && p.blur.blurReleasedWeights && p.blur.blurZeroOutside &&
                p.releasedPacking);
    EXPECT_EQ(p.blur.blurEpsilon, 1e-4f);
    EXPECT_THROW(setParam(p, "spinInFloat", 0.5), Error);  // a flag is 0 or 1
    // Integers are whole numbers in range: never rounded, truncated or wrapped.
    for (double bad : {10.4, double(NAN), 4294967297.0, -0.5})
        for (const char* name : {"numSamples", "guardBand", "blurRadius", "logQ"})
            EXPECT_THROW(setParam(p, name, bad), Error) << name << " " << bad;
    AlchemyParams ap;
    EXPECT_THROW(setParam(ap, "numSamples", 12.5), Error);
    setParam(ap, "numSamples", 13);
    EXPECT_EQ(ap.numSamples, 13);
    SaoParams bad;
    bad.releasedPacking = true;  // needs packBlurInput
    EXPECT_THROW(validate(bad), Error);
    bad = {};
    bad.blur.blurReleasedWeights = true;
    bad.blur.blurRadius = 5;  // the table has 5 entries: |t| <= 4
    EXPECT_THROW(validate(bad), Error);
    bad = {};
    bad.spiralTurnAngle = 7;
    EXPECT_THROW(validate(bad), Error);
    bad = {};
    bad.blur.blurEpsilon = -1e-4f;
    EXPECT_THROW(validate(bad), Error);
}

TEST(Released, TapAngleIsSummedInFloat) {
    // s = 11, tau = 7, 6.28: alpha_0 = 0.5 * float(1/11) = 0.045454547, float(7 * 6.28) =
    // 43.960003, their product 1.9981821; with phi = hashAngle(2, 3) = 150 the float sum is
    // 151.99818 (the exact sum 151.9981818...; float's step there is 1.5e-5).
    EXPECT_EQ(releasedTapAngle(0, 11, 7, 6.28, 0.0f), 1.9981820583343506f);
    EXPECT_EQ(releasedTapAngle(0, 11, 7, 6.28, hashAngle(2, 3)), 151.99818420410156f);
    // Pixel (1000, 700): (3 * 1000) ^ (700 + 700000) = 3000 ^ 700700 = 703140, phi = 7031400 rad.
    // Tap 10's spiral angle 41.961823 is added to a float whose step is 0.5: the sum rounds
    // to phi + 42, turning that tap by 0.038 rad from the exact sum.
    const float phi = hashAngle(1000, 700);
    EXPECT_EQ(phi, 7031400.0f);
    EXPECT_EQ(releasedTapAngle(10, 11, 7, 6.28, phi), 7031442.0f);
    // With 2 pi per turn instead of 6.28 tap 10 has alpha (tau 2 pi) = 41.98...
    EXPECT_NEAR(releasedTapAngle(10, 11, 7, 2 * M_PI, 0.0f), 10.5 / 11 * 7 * 2 * M_PI, 1e-5);
}

TEST(Released, KeyAsTheReleasedShadersPackAndUnpackIt) {
    // z = -75 m, z_min = -300 m: key 0.25, 256 key = 64: G = round(64 / 256 * 255) / 255 =
    // 64 / 255, B = 0; read back 64/255 * 256/257 = 16384 / 65535.
    EXPECT_FLOAT_EQ(releasedKey(-75.0f, -300.0f), 16384.0f / 65535.0f);
    // z = -1 m: key 1/300, 256 key = 0.8533: G = 0, B = round(0.8533 * 255) = 218: 218 / (255 * 257).
    EXPECT_FLOAT_EQ(releasedKey(-1.0f, -300.0f), 218.0f / (255.0f * 257.0f));
    // Beyond z_min the key clamps to 1: G = 1, B = 0: 256 / 257 (below 1, the cleared sky's key).
    EXPECT_FLOAT_EQ(releasedKey(-400.0f, -300.0f), 256.0f / 257.0f);
    EXPECT_TRUE(std::isinf(releasedKey(-INFINITY, -300.0f)));
    // Monotone in depth, to within the 16-bit step.
    for (float z = -0.5f; z > -290.0f; z *= 1.1f) EXPECT_GE(releasedKey(z * 1.1f, -300.0f), releasedKey(z, -300.0f));
}

TEST(Released, BlurWeightsZeroOutsideAndEpsilonByHand) {
    // One row of 5 pixels, flat z, A = (0.2, 0, 1, 0, 0.4); radius 1, stride 1.
    const Region r{0, 0, 5, 1};
    ImageF a(5, 1), z(5, 1, -2.0f);
    const float av[5] = {0.2f, 0.0f, 1.0f, 0.0f, 0.4f};
    for (int i = 0; i < 5; ++i) a(i, 0) = av[i];
    BilateralParams p;
    p.blurRadius = 1, p.blurStride = 1, p.blurReleasedWeights = true, p.blurEpsilon = 1e-4f;
    const float w0 = 0.153170f, w1 = 0.3f + 0.144893f;  // centre gaussian[0], taps 0.3 + gaussian[1]
    // Centre first, then t = -1, +1 (the released loop's order), in float.
    auto expect = [&](float ac, float al, float ar, float wl, float wr) {
        const float s = ((w0 * ac + wl * al) + wr * ar), ws = ((w0 + wl) + wr);
        return s / (ws + 1e-4f);
    };
    ImageF out = bilateralPass(a, z.view(), r, p, true);
    EXPECT_EQ(out(2, 0), expect(1.0f, 0.0f, 0.0f, w1, w1));
    EXPECT_EQ(out(0, 0), expect(0.2f, 0.2f, 0.0f, w1, w1));  // clamped: the left tap reads pixel 0
    p.blurZeroOutside = true;
    out = bilateralPass(a, z.view(), r, p, true);
    EXPECT_EQ(out(0, 0), expect(0.2f, 0.0f, 0.0f, 0.0f, w1));  // the left tap weighs 0
    EXPECT_EQ(out(4, 0), expect(0.4f, 0.0f, 0.0f, w1, 0.0f));
    EXPECT_EQ(out(2, 0), expect(1.0f, 0.0f, 0.0f, w1, w1));
    // The same vertically (a 1 x 5 column) with zero outside.
    ImageF ac(1, 5), zc(1, 5, -2.0f);
    for (int i = 0; i < 5; ++i) ac(0, i) = av[i];
    const ImageF col = bilateralPass(ac, zc.view(), Region{0, 0, 1, 5}, p, false);
    EXPECT_EQ(col(0, 0), expect(0.2f, 0.0f, 0.0f, 0.0f, w1));
    EXPECT_EQ(col(0, 4), expect(0.4f, 0.0f, 0.0f, w1, 0.0f));
    // The edge weight on the key: k = 2000 and a key step of 2e-4 scale the right tap by
    // max(0, 1 - 2000 * 2e-4) = 0.6 (in float: 1 - 2000 * |k_r - k_c|).
    ImageF key(5, 1, 0.5f);
    key(3, 0) = 0.5002f;
    p.edgeSharpness = 2000.0f;
    out = bilateralPass(a, key.view(), r, p, true);
    const float edge = w1 * std::max(0.0f, 1.0f - 2000.0f * std::fabs(0.5002f - 0.5f));
    EXPECT_NEAR(edge / w1, 0.6f, 1e-4f);
    EXPECT_EQ(out(2, 0), expect(1.0f, 0.0f, 0.0f, w1, edge));
    // The order matters in float: with radius 2 the released sum (centre, -2, -1, +1, +2)
    // rounds differently from t order (-2 .. +2) for these levels.
    {
        const float lv[5] = {164, 254, 242, 58, 12};
        ImageF a2(5, 1), z2(5, 1, -2.0f);
        for (int i = 0; i < 5; ++i) a2(i, 0) = lv[i] / 255.0f;
        BilateralParams q;
        q.blurRadius = 2, q.blurStride = 1, q.blurReleasedWeights = true, q.blurEpsilon = 1e-4f;
        const float w2 = 0.3f + 0.122649f;
        const float wt[5] = {w2, w1, w0, w1, w2};
        auto sum = [&](std::initializer_list<int> order) {
            float s = 0, ws = 0;
            for (int i : order) s += wt[i] * a2(i, 0), ws += wt[i];
            return s / (ws + 1e-4f);
        };
        const float released = sum({2, 0, 1, 3, 4}), inOrder = sum({0, 1, 2, 3, 4});
        ASSERT_NE(released, inOrder);
        EXPECT_EQ(bilateralPass(a2, z2.view(), r, q, true)(2, 0), released);
    }
    // A sky centre stays 1, a sky tap weighs 0.
    key(1, 0) = -INFINITY;
    out = bilateralPass(a, key.view(), r, p, true);
    EXPECT_EQ(out(1, 0), 1.0f);
    EXPECT_EQ(out(2, 0), expect(1.0f, 0.0f, 0.0f, 0.0f, edge));
}

namespace {
const scene::GeometryBuffer& room() {
    static const scene::GeometryBuffer g = scene::castGeometry(scene::roomScene(), Camera{}, 192 + 32, 108 + 32);
    return g;
}
}  // namespace

TEST(Released, IntensityIsALinearFactor) {
    // linearIntensity: 1 - A = intensity (1 - A at intensity 1) wherever A > 0, up to the
    // float rounding of the two factors; the default raises A to the intensity instead.
    const Camera cam;
    const ZPyramid pyr = [&] {
        ZPyramid p;
        zPyramid(depthToZ(room().depth.view(), cam).view(), 5, PyramidFilter::RotatedGrid, p);
        return p;
    }();
    const Projection proj = projection(cam, room().depth.width(), room().depth.height());
    const Region all{16, 16, 192, 108};
    SaoParams p;
    p.linearIntensity = true;
    const ImageF one = saoSamplePass(pyr, proj, all, p);
    p.intensity = 0.7f;
    const ImageF lin = saoSamplePass(pyr, proj, all, p);
    p.linearIntensity = false;
    const ImageF expo = saoSamplePass(pyr, proj, all, p);
    int occluded = 0;
    for (std::size_t i = 0; i < one.pixels().size(); ++i) {
        const float a1 = one.pixels()[i];
        if (a1 <= 0.0f) continue;
        occluded += a1 < 0.9f;
        EXPECT_NEAR(1.0f - lin.pixels()[i], 0.7f * (1.0f - a1), 2e-6f) << i;
        EXPECT_NEAR(expo.pixels()[i], std::pow(a1, 0.7f), 2e-6f) << i;
    }
    EXPECT_GT(occluded, 200);
}

TEST(Released, VectorKernelMatchesTheScalarReferenceInTheReleasedConfiguration) {
    // Tolerance: as for the paper's configuration, the vector kernel's sine and cosine (now
    // of every tap's angle) are float approximations, so a truncated tap offset can move by a
    // pixel; the 8-bit storage between the passes then turns a small change into a whole
    // level in a few pixels. Bound: every pixel within 3/255, mean below 1e-4. (Measured on
    // the room at 960x540: no pixel differs; without the 8-bit storage 18 pixels differ, by
    // up to 1.9e-4.)
    const Camera cam;
    SaoParams p = saoPreset("released");
    p.guardBand = 16;
    const auto big = scene::castGeometry(scene::roomScene(), cam, 960 + 32, 540 + 32);
    const ImageF a = sao(big.depth.view(), cam, p), r = saoReference(big.depth.view(), cam, p);
    ASSERT_EQ(a.width(), r.width());
    double mx = 0, sum = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i) {
        const double d = std::abs(double(a.pixels()[i]) - r.pixels()[i]);
        mx = std::max(mx, d), sum += d;
    }
    EXPECT_LE(mx, 3.0 / 255.0);
    EXPECT_LE(sum / double(a.pixels().size()), 1e-4);
    // The same bytes for any thread count.
    EXPECT_EQ(sao(room().depth.view(), cam, p, Exec{1}), sao(room().depth.view(), cam, p, Exec{3}));
    // The released configuration differs from the paper's (it is not a no-op).
    SaoParams paper;
    paper.guardBand = 16;
    const ImageF b = sao(big.depth.view(), cam, paper);
    double diff = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i)
        diff = std::max(diff, double(std::abs(a.pixels()[i] - b.pixels()[i])));
    EXPECT_GT(diff, 0.05);
}
