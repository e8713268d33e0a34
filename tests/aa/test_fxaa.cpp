#include <gtest/gtest.h>

#include "src/aa/luma_planes.hpp"
#include "ssfx/aa/ddaa.hpp"
#include "ssfx/aa/fxaa.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

namespace {
// Black region below row 8 for x >= start, white elsewhere: a horizontal edge that ends
// (to the left) at x = start.
ImageRgba8 edgeEndingAt(int start) {
    ImageRgba8 img(64, 16, Rgba8{255, 255, 255, 255});
    for (int y = 8; y < 16; ++y)
        for (int x = start; x < 64; ++x) img(x, y) = {0, 0, 0, 255};
    return img;
}
}  // namespace

// fxaa3d skips pixels after its fifth read (1, 2, 3, 4, 5, 6.5, ...): an edge ending 6 or 7
// pixels away is found by the same read (6.5) and gives the same result, while ddaa2,
// which steps one pixel at a time, tells them apart (DDAA paper section 2.4).
TEST(Fxaa3d, PixelSkippingCannotTellEdgeEndsSixAndSevenApart) {
    const int px = 40, py = 8;                                      // black pixel under the edge
    const auto a = edgeEndingAt(px - 5), b = edgeEndingAt(px - 6);  // first white column 6 / 7 px away
    const auto fa = aa::fxaa3d(a.view()), fb = aa::fxaa3d(b.view());
    EXPECT_EQ(fa(px, py), fb(px, py));
    EXPECT_NE(fa(px, py), a(px, py));  // and it did anti-alias the pixel
    const auto da = aa::ddaa2(a.view()), db = aa::ddaa2(b.view());
    EXPECT_NE(da(px, py), db(px, py));
}

// fxaa3d's vector path replaces its walk reads by plane lookups only where provably exact;
// it must hold for the sizes people use (both search variants), or it never runs.
TEST(Fxaa3d, WalkReadsArePlaneReadsForRealisticSizes) {
    for (auto [w, h] : {std::pair{1920, 1080}, std::pair{600, 600}, std::pair{480, 480}, std::pair{3840, 2160},
                        std::pair{1280, 720}, std::pair{61, 29}, std::pair{1, 1}}) {
        const ImageRgba8 img(w, h);
        const Texture tex(img.view(), Filtering::Gpu);
        EXPECT_TRUE(aa::detail::walkReadsArePlaneReads(tex, true)) << w << "x" << h;
        EXPECT_TRUE(aa::detail::walkReadsArePlaneReads(tex, false)) << w << "x" << h;
        EXPECT_TRUE(aa::detail::centresAreTexels(tex)) << w << "x" << h;  // the final read's lerp
    }
}

TEST(Fxaa3d, FastPathMatchesTheReference) {
    for (const auto& img : {test::noise(61, 29, 8), edgeEndingAt(20)}) {
        EXPECT_EQ(aa::fxaa3d(img.view()), aa::fxaa3dReference(img.view()));
        aa::Fxaa3dParams lottes;
        lottes.paperSearchQuirk = false;
        EXPECT_EQ(aa::fxaa3d(img.view(), lottes), aa::fxaa3dReference(img.view(), lottes));
    }
}

// With subpix = 1, a bright pixel whose cross neighbours are mid-grey (the side ahead a
// little darker) and whose corners are black reads a whole pixel across, towards the side
// ahead: past the lerp between the two texels around the pixel, so its vector chunk takes
// the gathered read. Both must give the reference's bytes.
TEST(Fxaa3d, FinalReadAWholePixelAcrossMatchesTheReference) {
    ImageRgba8 img(40, 12, Rgba8{0, 0, 0, 255});
    auto grey = [](int g) { return Rgba8{std::uint8_t(g), std::uint8_t(g), std::uint8_t(g), 255}; };
    for (int x : {10, 25}) {  // two orientations: the darker side below, or to the right
        const bool vertical = x == 25;
        img(x, 5) = grey(255);
        img(x, 4) = grey(110), img(x - 1, 5) = grey(105), img(x + 1, 5) = grey(vertical ? 100 : 105);
        img(x, 6) = grey(vertical ? 105 : 100);
        if (vertical) img(x, 4) = grey(105), img(x - 1, 5) = grey(110);
    }
    aa::Fxaa3dParams full;
    full.subpix = 1.0f;
    const ImageRgba8 expected = aa::fxaa3dReference(img.view(), full);
    EXPECT_NE(expected(10, 5), img(10, 5));
    EXPECT_EQ(aa::fxaa3d(img.view(), full), expected);
}

TEST(Fxaa3d, EarlyExitLeavesLowContrastUntouched) {
    // Two greys with a luma contrast below edgeThresholdMin = 0.0625: sqrt(100/255) vs sqrt(110/255).
    ImageRgba8 img(8, 8, Rgba8{100, 100, 100, 255});
    for (int y = 4; y < 8; ++y)
        for (int x = 0; x < 8; ++x) img(x, y) = {110, 110, 110, 255};
    EXPECT_EQ(aa::fxaa3d(img.view()), img);
    EXPECT_EQ(aa::fxaa3c(img.view()), img);
    // The same step at a high contrast is processed.
    for (int y = 4; y < 8; ++y)
        for (int x = 0; x < 8; ++x) img(x, y) = {200, 200, 200, 255};
    EXPECT_NE(aa::fxaa3d(img.view()), img);
}

TEST(Fxaa3d, LottesSearchDiffersFromThePaperQuirkOnlyOnSideTwo) {
    const auto img = edgeEndingAt(20);
    aa::Fxaa3dParams lottes;
    lottes.paperSearchQuirk = false;
    const auto q = aa::fxaa3d(img.view()), l = aa::fxaa3d(img.view(), lottes);
    EXPECT_NE(q, l);
    EXPECT_LE(test::maxAbsDiff(q, l), 255);
}

TEST(Fxaa3c, DirectionalTapsSoftenADiagonalStep) {
    const auto img = test::ascii({
        "........",
        "#.......",
        "##......",
        "###.....",
        "####....",
        "#####...",
        "######..",
        "#######.",
    });
    const auto out = aa::fxaa3c(img.view());
    // Pixels on the staircase become grey; far from it nothing changes.
    EXPECT_GT(out(3, 3).r, 0);
    EXPECT_LT(out(3, 3).r, 255);
    EXPECT_EQ(out(7, 0), img(7, 0));
    EXPECT_EQ(out(0, 7), img(0, 7));
}
