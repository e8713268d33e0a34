// Metrics and the x8 Mitchell upscale of the quality protocol, against values computed by
// hand from the definitions (metrics.hpp; spec ppaa.md "ssaax2, ssaax4" and section 3).
#include <gtest/gtest.h>

#include <cmath>

#include "ssfx/aa/resolve.hpp"
#include "ssfx/eval/metrics.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

TEST(Metrics, MseAndPsnrByHand) {
    // Two pixels; differences 51 (= 0.2) in R of one and 102 (= 0.4) in G and B of the
    // other: mse = (0.04 + 0.16 + 0.16) / (2 * 3) = 0.06, psnr = 10 log10(1 / 0.06).
    ImageRgba8 a(2, 1, Rgba8{0, 0, 0, 255}), b = a;
    b(0, 0).r = 51;
    b(1, 0).g = 102;
    b(1, 0).b = 102;
    EXPECT_NEAR(eval::mse(a.view(), b.view()), 0.06, 1e-12);
    EXPECT_NEAR(eval::psnr(a.view(), b.view()), 12.218487496163564, 1e-9);
    // Alpha is not compared; identical images have infinite PSNR.
    b = a;
    b(0, 0).a = 0;
    EXPECT_TRUE(std::isinf(eval::psnr(a.view(), b.view())));
}

TEST(Metrics, SsimByHand) {
    constexpr double c1 = 1e-4, c2 = 9e-4;
    // Equal constant windows: 1.
    const auto grey = test::solid(8, 8, {128, 128, 128, 255});
    EXPECT_DOUBLE_EQ(eval::ssim(grey.view(), grey.view()), 1.0);
    // Constant x = 0.2 vs y = 0.6 (51 and 153): no variance, so SSIM = (2xy + C1) / (x^2 + y^2 + C1).
    const auto a = test::solid(8, 8, {51, 51, 51, 255}), b = test::solid(8, 8, {153, 153, 153, 255});
    EXPECT_NEAR(eval::ssim(a.view(), b.view()), (2 * 0.2 * 0.6 + c1) / (0.04 + 0.36 + c1), 1e-12);
    // Top half black, bottom white vs its inverse: means 0.5, variances 0.25, covariance
    // -0.25: SSIM = (0.5 + C1) / (0.5 + C1) * (-0.5 + C2) / (0.5 + C2).
    ImageRgba8 h(8, 8, Rgba8{0, 0, 0, 255}), inv(8, 8, Rgba8{255, 255, 255, 255});
    for (int y = 4; y < 8; ++y)
        for (int x = 0; x < 8; ++x) h(x, y) = {255, 255, 255, 255}, inv(x, y) = {0, 0, 0, 255};
    EXPECT_NEAR(eval::ssim(h.view(), inv.view()), (-0.5 + c2) / (0.5 + c2), 1e-12);
    // Two windows side by side (16x8, the extra column beyond 16 ignored): the mean of both.
    ImageRgba8 wa(17, 8, Rgba8{51, 51, 51, 255}), wb(17, 8, Rgba8{51, 51, 51, 255});
    for (int y = 0; y < 8; ++y)
        for (int x = 8; x < 17; ++x) wb(x, y) = {153, 153, 153, 255};
    EXPECT_NEAR(eval::ssim(wa.view(), wb.view()), (1.0 + (0.24 + c1) / (0.4 + c1)) / 2, 1e-12);
}

TEST(Metrics, RejectMismatchedOrTinyImages) {
    const auto a = test::solid(8, 8, {0, 0, 0, 255}), b = test::solid(8, 9, {0, 0, 0, 255});
    EXPECT_THROW(eval::mse(a.view(), b.view()), Error);
    EXPECT_THROW(eval::ssim(a.view(), b.view()), Error);
    const auto tiny = test::solid(7, 8, {0, 0, 0, 255});
    EXPECT_THROW(eval::ssim(tiny.view(), tiny.view()), Error);
}

TEST(Metrics, IndependentOfThreadCount) {
    const auto a = test::noise(301, 203, 1), b = test::noise(301, 203, 2);
    EXPECT_EQ(eval::mse(a.view(), b.view(), Exec{1}), eval::mse(a.view(), b.view(), Exec{4}));
    EXPECT_EQ(eval::ssim(a.view(), b.view(), Exec{1}), eval::ssim(a.view(), b.view(), Exec{4}));
}

TEST(Metrics, MitchellX8UpscaleByHand) {
    // A 2x1 image, black then white, magnified x8. Output pixel x has its centre at
    // f = (x + 0.5) / 8 source pixels; the even 4-tap kernel takes texels round(f) - 2 ..
    // round(f) + 1 (clamped to the image) with weights k(i + 0.5 - f), B = C = 1/3,
    // normalised by their sum. Worked out with the spec's k(t), e.g. x = 4: f = 0.5625,
    // taps -1, 0, 1, 2 with weights 0.02747, 0.88136, 0.09238, -0.00121:
    // 255 * (0.09238 - 0.00121) / 1.0 = 23.249 -> 23.
    ImageRgba8 img(2, 1, Rgba8{0, 0, 0, 255});
    img(1, 0) = {255, 255, 255, 255};
    const auto up = aa::upscaleMitchell(img.view(), 8);
    ASSERT_EQ(up.width(), 16);
    ASSERT_EQ(up.height(), 8);
    const int expected[16] = {0, 0, 0, 7, 23, 47, 77, 110, 145, 178, 208, 232, 248, 255, 255, 255};
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) EXPECT_EQ(up(x, y).r, expected[x]) << "x=" << x << " y=" << y;
}
