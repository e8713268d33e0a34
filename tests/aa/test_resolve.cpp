#include <gtest/gtest.h>

#include "ssfx/aa/resolve.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

TEST(Mitchell, KernelValuesFromTheFormula) {
    const float B = 1.0f / 3, C = 1.0f / 3;
    EXPECT_NEAR(aa::mitchell(0, B, C), (6 - 2 * B) / 6, 1e-6f);  // 8/9
    EXPECT_NEAR(aa::mitchell(1, B, C), B / 6, 1e-6f);            // 1/18
    EXPECT_NEAR(aa::mitchell(-1, B, C), B / 6, 1e-6f);
    EXPECT_EQ(aa::mitchell(2.5f, B, C), 0.0f);
    EXPECT_NEAR(aa::mitchell(2, B, C), 0.0f, 1e-6f);
    EXPECT_LT(aa::mitchell(1.5f, B, C), 0.0f);  // the negative lobe
}

TEST(Mitchell, PartitionOfUnity) {
    for (float t : {0.0f, 0.1f, 0.25f, 0.5f, 0.77f})
        EXPECT_NEAR(aa::mitchell(t - 2, 1.f / 3, 1.f / 3) + aa::mitchell(t - 1, 1.f / 3, 1.f / 3) +
                        aa::mitchell(t, 1.f / 3, 1.f / 3) + aa::mitchell(t + 1, 1.f / 3, 1.f / 3) +
                        aa::mitchell(t + 2, 1.f / 3, 1.f / 3),
                    1.0f, 1e-6f);
}

TEST(Resolve, FlatImagesStayFlat) {
    const Rgba8 c{37, 140, 251, 255};
    const ImageRgba8 flat8(16, 8, c);
    EXPECT_EQ(aa::ssaax2(flat8.view()), ImageRgba8(8, 4, c));
    EXPECT_EQ(aa::ssaax4(flat8.view()), ImageRgba8(4, 2, c));
    EXPECT_EQ(aa::upscaleMitchell(flat8.view(), 8), ImageRgba8(128, 64, c));
    EXPECT_EQ(aa::downscaleMitchell(flat8.view(), 2), ImageRgba8(8, 4, c));
}

TEST(Resolve, SsaaOfAVerticalStepIsSymmetric) {
    // Left half black, right half white at 2x: the resolved columns mirror each other.
    ImageRgba8 img(8, 4, Rgba8{0, 0, 0, 255});
    for (int y = 0; y < 4; ++y)
        for (int x = 4; x < 8; ++x) img(x, y) = {255, 255, 255, 255};
    for (const auto& out : {aa::ssaax2(img.view()), aa::downscaleMitchell(img.view(), 2)}) {
        ASSERT_EQ(out.width(), 4);
        EXPECT_NEAR(out(1, 0).r + out(2, 0).r, 255, 1);
        EXPECT_LT(out(1, 0).r, 40);  // mostly black, with some white from the kernel
        EXPECT_GT(out(2, 0).r, 215);
    }
}

TEST(Resolve, UpscaleInterpolatesBetweenTexelCentres) {
    ImageRgba8 img(2, 1, Rgba8{0, 0, 0, 255});
    img(1, 0) = {255, 255, 255, 255};
    const auto up = aa::upscaleMitchell(img.view(), 8);
    ASSERT_EQ(up.width(), 16);
    // Monotone ramp between the two texel centres (output pixels 4..11), symmetric around 127.5.
    for (int x = 4; x < 11; ++x) EXPECT_LE(up(x, 0).r, up(x + 1, 0).r);
    EXPECT_NEAR(up(7, 0).r + up(8, 0).r, 255, 1);
}
