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
    const Image<std::uint8_t> mask = eval::differenceMask(a.view(), test::noise(301, 203, 3).view());
    const eval::ErrorStats e1 = eval::errorStats(a.view(), b.view(), {mask.view(), 1}, Exec{1});
    const eval::ErrorStats e4 = eval::errorStats(a.view(), b.view(), {mask.view(), 1}, Exec{4});
    EXPECT_EQ(e1.pixels, e4.pixels);
    EXPECT_EQ(e1.psnr, e4.psnr);
    EXPECT_EQ(e1.p99Error, e4.p99Error);
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

TEST(Metrics, ErrorStatsByHand) {
    // 100 pixels, e = max(|dR|, |dG|, |dB|): 97 exact, then 3, 10 and 40 levels. Nearest rank
    // 99: the 99th smallest e is 10; the largest is 40.
    ImageRgba8 a(10, 10, Rgba8{100, 100, 100, 255}), b = a;
    b(0, 0) = {103, 100, 99, 255};  // e = 3 (dR 3, dB 1)
    b(5, 5) = {100, 90, 100, 255};  // e = 10
    b(9, 9) = {60, 100, 100, 255};  // e = 40
    const eval::ErrorStats all = eval::errorStats(a.view(), b.view());
    EXPECT_EQ(all.pixels, 100);
    EXPECT_EQ(all.maxError, 40);
    EXPECT_EQ(all.p99Error, 10);
    // PSNR from the same squares as psnr(): (9 + 1 + 100 + 1600) / 255^2 / 300.
    EXPECT_NEAR(all.psnr, 10 * std::log10(1 / (1710.0 / (255.0 * 255.0) / 300.0)), 1e-9);
    EXPECT_DOUBLE_EQ(all.psnr, eval::psnr(a.view(), b.view()));
    // A mask of the left column (x = 0): 10 pixels, one of them off by 3.
    Image<std::uint8_t> mask(10, 10);
    for (int y = 0; y < 10; ++y) mask(0, y) = 1;
    const eval::ErrorStats left = eval::errorStats(a.view(), b.view(), {mask.view(), 1});
    EXPECT_EQ(left.pixels, 10);
    EXPECT_EQ(left.maxError, 3);
    EXPECT_EQ(left.p99Error, 3);  // rank ceil(9.9) = 10: the largest of ten
    // An empty mask counts nothing: NaN figures.
    const Image<std::uint8_t> none(10, 10);
    const eval::ErrorStats empty = eval::errorStats(a.view(), b.view(), {none.view(), 1});
    EXPECT_EQ(empty.pixels, 0);
    EXPECT_TRUE(std::isnan(empty.psnr) && std::isnan(empty.maxError) && std::isnan(empty.p99Error));
    // A mask at scale 5 over the same image: the 2x2 mask pixel (1, 1) covers [5, 10) x [5, 10).
    Image<std::uint8_t> coarse(2, 2);
    coarse(1, 1) = 1;
    const eval::ErrorStats block = eval::errorStats(a.view(), b.view(), {coarse.view(), 5});
    EXPECT_EQ(block.pixels, 25);
    EXPECT_EQ(block.maxError, 40);
    // A mask that does not cover the images is an error naming both sizes.
    const std::string e = test::errorOf([&] { eval::errorStats(a.view(), b.view(), {coarse.view(), 4}); });
    EXPECT_NE(e.find("2x2 mask at scale 4"), std::string::npos) << e;
    EXPECT_NE(e.find("10x10"), std::string::npos) << e;
}

TEST(Metrics, MaskedSsimAveragesTheWindowsWithACountedPixel) {
    // Two 8x8 windows side by side: the left one equal (SSIM 1), the right constant 51 vs 153.
    ImageRgba8 a(16, 8, Rgba8{51, 51, 51, 255}), b = a;
    for (int y = 0; y < 8; ++y)
        for (int x = 8; x < 16; ++x) b(x, y) = {153, 153, 153, 255};
    const double right = (2 * 0.2 * 0.6 + 1e-4) / (0.04 + 0.36 + 1e-4);
    EXPECT_NEAR(eval::ssim(a.view(), b.view()), (1 + right) / 2, 1e-12);
    Image<std::uint8_t> mask(16, 8);
    mask(9, 3) = 1;  // one pixel of the right window
    EXPECT_NEAR(eval::ssim(a.view(), b.view(), {mask.view(), 1}), right, 1e-12);
    mask(0, 0) = 1;  // and one of the left
    EXPECT_NEAR(eval::ssim(a.view(), b.view(), {mask.view(), 1}), (1 + right) / 2, 1e-12);
    const Image<std::uint8_t> none(16, 8);
    EXPECT_TRUE(std::isnan(eval::ssim(a.view(), b.view(), {none.view(), 1})));
}

TEST(Metrics, DifferenceMaskMarksPixelsThatDifferInRgbOnly) {
    ImageRgba8 a(3, 1, Rgba8{10, 10, 10, 255}), b = a;
    b(1, 0).g = 11;
    b(2, 0).a = 0;  // alpha does not count
    const Image<std::uint8_t> m = eval::differenceMask(a.view(), b.view());
    EXPECT_EQ(m.pixels(), (std::vector<std::uint8_t>{0, 1, 0}));
}
