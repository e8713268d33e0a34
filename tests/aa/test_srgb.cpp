// The sRGB-texture mode of the PPAA methods (-p texture=srgb): every read decoded to linear
// light (IEC 61966-2-1), filtered, the result encoded back with round-to-nearest; luma
// thresholds on the decoded values' luma.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "src/aa/luma_planes.hpp"
#include "ssfx/aa/registry.hpp"
#include "ssfx/core/color.hpp"
#include "ssfx/core/sample.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

namespace {

// Every method that reads a texture: the PPAA methods and the resolves.
const char* kPpaa[] = {"blur", "fxaa3c", "fxaa3d", "ddaa1", "ddaa2", "ddaa2p", "ssaax2", "ssaax4"};
const char* kThresholdMethods[] = {"fxaa3c", "fxaa3d", "ddaa1", "ddaa2"};

MethodSettings srgb(Filtering filtering = Filtering::Gpu) {
    MethodSettings s;
    s.params = {{"texture", 1.0}};
    s.filtering = filtering;
    return s;
}

// A disc of `inside` on `outside`, aliased (each pixel one or the other).
ImageRgba8 disc(int size, Rgba8 inside, Rgba8 outside) {
    ImageRgba8 img(size, size, outside);
    const double c = size / 2.0, r = size / 3.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            if ((x + 0.5 - c) * (x + 0.5 - c) + (y + 0.3 - c) * (y + 0.3 - c) < r * r) img(x, y) = inside;
    return img;
}

// round(255 * linearToSrgb(v)) in double: the definition encodeSrgb8 must meet.
int encodeInDouble(double v) { return int(std::floor(255.0 * linearToSrgb(std::clamp(v, 0.0, 1.0)) + 0.5)); }

}  // namespace

TEST(SrgbTransfer, DecodeTableIsTheStandardCurve) {
    EXPECT_EQ(kSrgb8[0], 0.0f);
    EXPECT_EQ(kSrgb8[255], 1.0f);
    // Published values of the sRGB curve: code 128 is 21.586 % linear, code 10 (below the
    // 0.04045 knee) 10/255/12.92.
    EXPECT_NEAR(kSrgb8[128], 0.215861, 1e-6);
    EXPECT_FLOAT_EQ(kSrgb8[10], float(10.0 / 255.0 / 12.92));
    for (int k = 1; k < 256; ++k) EXPECT_LT(kSrgb8[k - 1], kSrgb8[k]) << k;
}

TEST(SrgbTransfer, EncodeInvertsDecodeAndRoundsToNearest) {
    for (int k = 0; k < 256; ++k) EXPECT_EQ(encodeSrgb8(kSrgb8[k]), k) << k;
    // 50 % linear light is sRGB 188 (0.7354 * 255 = 187.52).
    EXPECT_EQ(encodeSrgb8(0.5f), 188);
    EXPECT_EQ(encodeSrgb8(-1.0f), 0);
    EXPECT_EQ(encodeSrgb8(2.0f), 255);
    EXPECT_EQ(encodeSrgb8(std::nanf("")), 0);
    // Against the formula in double on a fine grid, skipping values within 1e-9 of a half
    // level (where a double pow() may round either way; encodeSrgb8's thresholds decide).
    int compared = 0;
    for (int i = 0; i <= 200000; ++i) {
        const float v = float(i) / 200000.0f;
        const double e = 255.0 * linearToSrgb(double(v));
        if (std::fabs(e - std::floor(e) - 0.5) < 1e-9) continue;
        ASSERT_EQ(encodeSrgb8(v), encodeInDouble(v)) << v;
        ++compared;
    }
    EXPECT_GT(compared, 199000);
}

// The float thresholds the GPU passes' exact encode searches (srgbEncodeThresholds):
// element k is the smallest float above the double half-level t_k = decode((k + 0.5) / 255),
// so the float just below it encodes to k and the threshold itself to k + 1.
TEST(SrgbTransfer, EncodeThresholdsAreTheFirstFloatsAboveTheHalfLevels) {
    const std::array<float, 255>& t = srgbEncodeThresholds();
    for (int k = 0; k < 255; ++k) {
        const double half = srgbToLinear((k + 0.5) / 255.0);
        const float f = t[std::size_t(k)];
        EXPECT_GT(double(f), half) << k;
        EXPECT_LE(double(std::nextafter(f, 0.0f)), half) << k;
        EXPECT_EQ(encodeSrgb8(f), k + 1) << k;
        EXPECT_EQ(encodeSrgb8(std::nextafter(f, 0.0f)), k) << k;
    }
}

// encodeSrgb8's table (two loads) against its defining rule, the number of thresholds <= v,
// on every 61st float in [0, 1] (17 million, every bucket many times) and on the 4 floats
// either side of each threshold and of each bucket boundary.
TEST(SrgbTransfer, EncodeTableFollowsTheThresholdRule) {
    const std::array<float, 255>& t = srgbEncodeThresholds();
    auto rule = [&](float v) {
        if (!(v > 0.0f)) return 0;
        if (v >= 1.0f) return 255;
        return int(std::upper_bound(t.begin(), t.end(), v) - t.begin());
    };
    std::int64_t wrong = 0;
    const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
    for (std::uint32_t b = 0; b <= one; b += 61)
        wrong += encodeSrgb8(std::bit_cast<float>(b)) != rule(std::bit_cast<float>(b));
    auto around = [&](std::uint32_t centre) {
        for (std::uint32_t b = centre - 4; b <= centre + 4; ++b)
            wrong += encodeSrgb8(std::bit_cast<float>(b)) != rule(std::bit_cast<float>(b));
    };
    for (const float f : t) around(std::bit_cast<std::uint32_t>(f));
    using T = detail::SrgbEncodeTable;
    for (std::uint32_t j = 0; j <= T::kBuckets; ++j) around(T::kLowBits + (j << T::kShift));
    EXPECT_EQ(wrong, 0);
}

TEST(SrgbTexture, FiltersDecodedTexels) {
    ImageRgba8 img(2, 1);
    img(0, 0) = {0, 0, 0, 255};
    img(1, 0) = {128, 255, 0, 255};
    for (Filtering f : {Filtering::Gpu, Filtering::Exact}) {
        const Texture u(img.view(), f), s(img.view(), f, TextureFormat::Srgb);
        EXPECT_EQ(s.texel(1, 0).r, kSrgb8[128]);
        // Halfway between the texels (u = 0.5): the mean of the decoded values.
        const Rgb a = s.sample(0.5f, 0.5f), b = u.sample(0.5f, 0.5f);
        EXPECT_FLOAT_EQ(a.r, kSrgb8[128] * 0.5f);
        EXPECT_FLOAT_EQ(a.g, 0.5f);
        EXPECT_NEAR(b.r, 64.0f / 255.0f, 1.0f / 4080.0f);  // unorm: 128 / 255 halved, on the 1/16 grid
        // A quarter of the way (u = 0.375, texel position 0.25): weights 0.75 / 0.25.
        EXPECT_FLOAT_EQ(s.sample(0.375f, 0.5f).r, 0.25f * kSrgb8[128]);
    }
}

// The vector kernels' luma planes (luma_planes.hpp) hold the lumas of the reads half-way
// between two texels (H, V) and four (Q); an sRGB texture's must be its own reads bit for
// bit (the decoded texels weighted 1/2 or 1/4 in Texture::sampleGpuDecoded's order), the
// clamped borders included. 40 px wide: the vector loops and their scalar tails both run.
TEST(SrgbTexture, LumaPlanesHoldTheTexturesHalfWayReads) {
    const int w = 40, h = 7;
    const auto img = test::noise(w, h, 5);
    const Texture tex(img.view(), Filtering::Gpu, TextureFormat::Srgb);
    // Row 3 with reach 3: plane rows 0 .. 7, all of them.
    const aa::detail::LumaPlanes planes =
        aa::detail::planeRowsFor(img.view(), aa::detail::newPlaneCall(), 3, 3, true, TextureFormat::Srgb);
    int checked = 0;
    for (int r = 0; r <= h; ++r)
        for (int c = 0; c <= w; ++c) {
            const float u = float(c) / float(w), v = float(r) / float(h);  // texel corners
            ASSERT_EQ(tex.axisU(u).w, 128);
            ASSERT_EQ(tex.axisV(v).w, 128);
            ASSERT_EQ(planes.data[planes.rowQ(r) + std::size_t(c)], luma(tex.sample(u, v))) << "Q " << c << "," << r;
            if (c < w) {  // between rows r - 1 and r
                ASSERT_EQ(planes.data[planes.rowH(r) + std::size_t(c)], luma(tex.sample(tex.centreU(c), v)))
                    << "H " << c << "," << r;
            }
            if (r < h) {  // between columns c - 1 and c
                ASSERT_EQ(planes.data[planes.rowV(r) + std::size_t(c)], luma(tex.sample(u, tex.centreV(r))))
                    << "V " << c << "," << r;
            }
            ++checked;
        }
    EXPECT_EQ(checked, (w + 1) * (h + 1));
}

TEST(SrgbMode, EveryTextureReadingMethodHasTheParameter) {
    for (const char* id : kPpaa) {
        const MethodInfo& m = methodById(id);
        const ParamInfo& p = findParam(m.params, id, "texture");
        EXPECT_EQ(p.kind, ParamKind::Choice) << id;
        ASSERT_EQ(p.choices.size(), 2u) << id;
        EXPECT_EQ(p.choices[0], "unorm") << id;
        EXPECT_EQ(p.choices[1], "srgb") << id;
        EXPECT_EQ(p.initial(), 0.0) << id << ": unorm must stay the default";
    }
}

TEST(SrgbMode, FlatImagesUnchanged) {
    const auto flat = test::solid(24, 24, {90, 140, 200, 255});
    for (const char* id : kPpaa) {
        const MethodInfo& m = methodById(id);
        const auto in = test::solid(24 * m.inputScale, 24 * m.inputScale, {90, 140, 200, 255});
        EXPECT_EQ(m.run(in.view(), srgb(), {}), flat) << id;
    }
}

TEST(SrgbMode, ThresholdsApplyToTheDecodedLuma) {
    // Codes 5 and 20: unorm luma sqrt(5/255) = 0.140 vs 0.280, a contrast of 0.14 (above
    // edgeThresholdMin 0.0625): an edge. Decoded, 0.00152 and 0.00700: luma 0.039 vs 0.084,
    // 0.045: below it, so an sRGB-texture shader leaves every pixel as it is.
    const auto img = disc(40, {20, 20, 20, 255}, {5, 5, 5, 255});
    for (const char* id : kThresholdMethods) {
        const MethodInfo& m = methodById(id);
        EXPECT_NE(m.run(img.view(), {}, {}), img) << id << ": unorm should see the edge";
        EXPECT_EQ(m.run(img.view(), srgb(), {}), img) << id;
    }
}

TEST(SrgbMode, BlackAndWhiteEdgesAreTheUnormFilterEncodedAsSrgb) {
    // On texels 0 and 255 both formats read 0 and 1, so with exact filtering a method
    // computes the same linear values v in both modes and only the encoding differs: unorm
    // writes u = round(255 v), sRGB round(255 srgb(v)). So every sRGB channel lies in
    // [encode((u - 0.5) / 255), encode((u + 0.5) / 255)], is >= u (the curve is above the
    // diagonal), and equals u where u is 0 or 255.
    for (const char* id : kPpaa) {
        const MethodInfo& m = methodById(id);
        const auto img = disc(48 * m.inputScale, {255, 255, 255, 255}, {0, 0, 0, 255});
        MethodSettings exact;
        exact.filtering = Filtering::Exact;
        const auto u = m.run(img.view(), exact, {});
        const auto s = m.run(img.view(), srgb(Filtering::Exact), {});
        int between = 0;
        for (int y = 0; y < u.height(); ++y)
            for (int x = 0; x < u.width(); ++x)
                for (auto c : {&Rgba8::r, &Rgba8::g, &Rgba8::b}) {
                    const int uc = u(x, y).*c, sc = s(x, y).*c;
                    ASSERT_GE(sc, encodeSrgb8(float((uc - 0.5) / 255.0))) << id << " at " << x << "," << y;
                    ASSERT_LE(sc, encodeSrgb8(float((uc + 0.5) / 255.0))) << id << " at " << x << "," << y;
                    ASSERT_GE(sc, uc) << id;
                    between += uc > 0 && uc < 255;
                }
        EXPECT_GT(between, 30) << id << ": the test needs anti-aliased pixels";
        EXPECT_NE(u, s) << id;
    }
}

TEST(SrgbMode, BlurMatchesAnOracleInDouble) {
    // The 3x3 Gaussian of decoded neighbours (clamp to edge), in double, encoded in double.
    // The library sums in float32: a result within ~1e-7 of a half level may round the other
    // way, so at most one level apart and almost always equal.
    const auto img = test::noise(32, 32, 7);
    const auto out = methodById("blur").run(img.view(), srgb(), {});
    const double w1 = std::exp(-1.0 / (2.0 * 0.6 * 0.6)), w2 = w1 * w1;
    int mismatches = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            for (auto c : {&Rgba8::r, &Rgba8::g, &Rgba8::b}) {
                double sum = 0, wsum = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const double w = dx == 0 && dy == 0 ? 1.0 : (dx == 0 || dy == 0 ? w1 : w2);
                        sum += w * srgbToLinear(img.view().clamped(x + dx, y + dy).*c / 255.0);
                        wsum += w;
                    }
                const int want = encodeInDouble(sum / wsum), got = out(x, y).*c;
                ASSERT_LE(std::abs(want - got), 1) << x << "," << y;
                mismatches += want != got;
            }
    EXPECT_LE(mismatches, 32 * 32 * 3 / 100);
}

TEST(SrgbMode, SameBytesForAnyThreadCountAndTheReference) {
    for (const char* id : kPpaa) {
        const MethodInfo& m = methodById(id);
        const auto img = test::noise(70 * m.inputScale, 50 * m.inputScale, 3);
        const auto one = m.run(img.view(), srgb(), Exec{1});
        EXPECT_EQ(m.run(img.view(), srgb(), Exec{0}), one) << id;
        EXPECT_EQ(m.run(img.view(), srgb(), Exec{3}), one) << id;
        EXPECT_EQ(m.reference(img.view(), srgb(), Exec{1}), one) << id;
    }
}
