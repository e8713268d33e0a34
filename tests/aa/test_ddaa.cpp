#include <gtest/gtest.h>

#include <set>

#include "src/aa/ddaa_kernel.hpp"
#include "ssfx/aa/ddaa.hpp"
#include "ssfx/aa/fxaa.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

// Small-structure preservation (paper section 2.2, Fig. 6): a 1-pixel line is a ridge or
// valley (both neighbours across it brighter), so ddaa diffuses it less; without the rule
// (ridgeFactor = 0) it washes out, and fxaa3d lightens it most. Measured on a line of
// slope 1/3 as the sum of the line pixels' values (0 = the line kept fully black).
TEST(Ddaa, ThinLineIsPreservedByTheRidgeRule) {
    ImageRgba8 img(60, 40, Rgba8{255, 255, 255, 255});
    for (int x = 0; x < 60; ++x) img(x, 5 + x / 3) = {0, 0, 0, 255};
    auto lineSum = [](const ImageRgba8& out) {
        int s = 0;
        for (int x = 3; x < 57; ++x) s += out(x, 5 + x / 3).r;
        return s;
    };
    aa::Ddaa2Params off;
    off.ridgeFactor = 0;
    // ddaa1: the rule removes all diffusion across the line (min(|g1|,|g2|) = 1).
    EXPECT_EQ(lineSum(aa::ddaa1(img.view())), 0);
    EXPECT_GT(lineSum(aa::ddaa1(img.view(), off)), 54 * 40);
    // ddaa2: its edge search still shifts run ends, but much less than without the rule
    // or than fxaa3d (margins: about 1500 and 3700 here).
    const int kept = lineSum(aa::ddaa2(img.view())), washed = lineSum(aa::ddaa2(img.view(), off));
    EXPECT_LT(kept, washed - 1000);
    EXPECT_GT(lineSum(aa::fxaa3d(img.view())), kept * 18 / 10);
}

// A long near-horizontal step (1 px up every 24 px): ddaa2's edge search spreads it into a
// ramp of many grey levels along the edge; ddaa1 only diffuses +-0.51 px and cannot.
TEST(Ddaa, LongEdgeGetsARampFromDdaa2NotDdaa1) {
    ImageRgba8 img(120, 20, Rgba8{255, 255, 255, 255});
    for (int x = 0; x < 120; ++x)
        for (int y = 8 + x / 24; y < 20; ++y) img(x, y) = {0, 0, 0, 255};
    auto levels = [](const ImageRgba8& out) {
        std::set<int> s;
        for (int y = 6; y < 15; ++y)
            for (int x = 24; x < 96; ++x)
                if (out(x, y).r != 0 && out(x, y).r != 255) s.insert(out(x, y).r);
        return s.size();
    };
    const std::size_t l2 = levels(aa::ddaa2(img.view())), l1 = levels(aa::ddaa1(img.view()));
    EXPECT_GE(l2, 12u);
    EXPECT_LE(l1, 4u);
}

TEST(Ddaa, EarlyExitThresholdsFollowThePreset) {
    // A diagonal step between greys 120 and 140: luma contrast sqrt(140/255) - sqrt(120/255)
    // = 0.0550. The threshold is max(edgeThresholdMin, 0.741 * edgeThreshold): medium
    // max(0.0625, 0.123) and high max(0.0312, 0.0926) leave it; ultra max(0.0156, 0.0467)
    // and extreme max(0.0078, 0.0230) process it.
    ImageRgba8 img(8, 8, Rgba8{120, 120, 120, 255});
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < y; ++x) img(x, y) = {140, 140, 140, 255};
    EXPECT_EQ(aa::ddaa2(img.view(), aa::ddaa2ParamsFor(aa::Preset::Medium)), img);
    EXPECT_EQ(aa::ddaa2(img.view(), aa::ddaa2ParamsFor(aa::Preset::High)), img);
    EXPECT_NE(aa::ddaa2(img.view(), aa::ddaa2ParamsFor(aa::Preset::Ultra)), img);
    EXPECT_NE(aa::ddaa1(img.view(), aa::ddaa1ParamsFor(aa::Preset::Extreme)), img);
}

// The vector path of ddaa2 replaces its search reads by pair-plane lookups only where that
// is provably exact; it must hold for the sizes people use, or the fast path never runs.
TEST(Ddaa, SearchReadsArePairReadsForRealisticSizes) {
    for (auto [w, h] : {std::pair{1920, 1080}, std::pair{600, 600}, std::pair{480, 480}, std::pair{3840, 2160},
                        std::pair{1280, 720}, std::pair{61, 29}, std::pair{1, 1}, std::pair{7, 3}}) {
        const ImageRgba8 img(w, h);
        const Texture tex(img.view(), Filtering::Gpu);
        EXPECT_TRUE(aa::detail::searchReadsArePairReads(tex, 5)) << w << "x" << h;
    }
}

TEST(Ddaa, FastPathMatchesTheReference) {
    const auto img = test::noise(61, 29, 8);
    EXPECT_EQ(aa::ddaa1(img.view()), aa::ddaa1Reference(img.view()));
    EXPECT_EQ(aa::ddaa2(img.view()), aa::ddaa2Reference(img.view()));
}

// At maxDiffusion = 1, a vertical step edge diffuses a whole pixel along it (direction
// (0, +-1) at full strength): one of the two reads lands a texel further than the pixel's
// 3 x 3 texels, and the vector path gathers it. Same bytes as the reference either way.
TEST(Ddaa, DiffusionReadsAWholePixelAwayMatchTheReference) {
    ImageRgba8 img(40, 9, Rgba8{20, 20, 20, 255});
    for (int y = 0; y < 9; ++y)
        for (int x = 21; x < 40; ++x) img(x, y) = {230, 230, 230, 255};
    aa::Ddaa1Params far1;
    far1.maxDiffusion = 1.0f;
    aa::Ddaa2Params far2;
    far2.maxDiffusion = 1.0f;
    for (const auto& in : {img, test::noise(61, 29, 8)}) {
        EXPECT_EQ(aa::ddaa1(in.view(), far1), aa::ddaa1Reference(in.view(), far1));
        EXPECT_EQ(aa::ddaa2(in.view(), far2), aa::ddaa2Reference(in.view(), far2));
    }
}
