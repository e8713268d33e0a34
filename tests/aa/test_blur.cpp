#include <gtest/gtest.h>

#include <cmath>

#include "ssfx/aa/blur.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

TEST(Blur, SinglePixelSpreadsWithGaussianWeights) {
    ImageRgba8 img(5, 5, Rgba8{0, 0, 0, 255});
    img(2, 2) = {255, 255, 255, 255};
    const auto out = aa::blur(img.view());
    // Weights from the spec: 1, w1 = exp(-1/(2*0.36)) = 0.2493522, w1^2, normalised by their sum.
    const double w1 = 0.2493522, sum = 1 + 4 * w1 + 4 * w1 * w1;
    EXPECT_EQ(out(2, 2).r, int(std::lround(255 / sum)));            // 127.8 -> 128
    EXPECT_EQ(out(1, 2).r, int(std::lround(255 * w1 / sum)));       // 31.9 -> 32
    EXPECT_EQ(out(1, 1).r, int(std::lround(255 * w1 * w1 / sum)));  // 7.9 -> 8
    EXPECT_EQ(out(0, 0).r, 0);
    EXPECT_EQ(out(2, 2).a, 255);
}

TEST(Blur, StaysWithinTheNeighbourhoodRange) {
    const auto img = test::noise(23, 19, 5);
    const auto out = aa::blur(img.view());
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            int lo = 255, hi = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int v = img.view().clamped(x + dx, y + dy).g;
                    lo = std::min(lo, v), hi = std::max(hi, v);
                }
            ASSERT_GE(out(x, y).g, lo);
            ASSERT_LE(out(x, y).g, hi);
        }
}

TEST(Blur, SimdRowsMatchTheScalarReferenceAtEveryWidth) {
    // Widths 1 .. 2 * 16 + 1 run every SIMD tail length for up to 16 lanes.
    for (int w = 1; w <= 33; ++w) {
        const auto img = test::noise(w, 3, unsigned(w));
        ASSERT_EQ(aa::blur(img.view()), aa::blurReference(img.view())) << "width " << w;
    }
}
