// The evaluation's Cairo test images: sizes, determinism, scale consistency, the features
// the issue asks for.
#include <gtest/gtest.h>

#include <cmath>

#include "ssfx/aa/resolve.hpp"
#include "ssfx/core/color.hpp"
#include "ssfx/eval/metrics.hpp"
#include "ssfx/eval/test_images.hpp"

using namespace ssfx;

namespace {
double darkFraction(const ImageRgba8& img) {
    std::int64_t n = 0;
    for (const auto& p : img.pixels()) n += (p.r + p.g + p.b) < 3 * 128;
    return double(n) / double(img.pixelCount());
}
int distinctColours(const ImageRgba8& img) {
    std::vector<std::uint32_t> c;
    for (const auto& p : img.pixels()) c.push_back(std::uint32_t(p.r) << 16 | std::uint32_t(p.g) << 8 | p.b);
    std::sort(c.begin(), c.end());
    return int(std::unique(c.begin(), c.end()) - c.begin());
}
}  // namespace

TEST(TestImages, SizesAtEveryScale) {
    for (const auto& t : eval::testImages())
        for (int s : {1, 2}) {
            const auto img = eval::drawTestImage(t.name, s);
            EXPECT_EQ(img.width(), t.width * s) << t.name;
            EXPECT_EQ(img.height(), t.height * s) << t.name;
        }
    EXPECT_EQ(eval::testImageByName("animated").frames, 32);
    EXPECT_EQ(eval::testImageByName("animated").fps, 25);
}

TEST(TestImages, DeterministicAndAliased) {
    for (const auto& t : eval::testImages()) {
        const auto a = eval::drawTestImage(t.name, 1), b = eval::drawTestImage(t.name, 1);
        EXPECT_EQ(a, b) << t.name;
        // No antialiasing: only the drawing's own colours appear (a handful, not a ramp).
        EXPECT_LE(distinctColours(a), 16) << t.name;
    }
}

TEST(TestImages, SameGeometryAtEveryScale) {
    // The x8 render shrunk to 1x is close to the 1x render (same drawing), and the share
    // of ink is about the same at every scale.
    for (const auto& name : {"lines", "circles", "plot"}) {
        const auto x1 = eval::drawTestImage(name, 1), x4 = eval::drawTestImage(name, 4);
        EXPECT_NEAR(darkFraction(x1), darkFraction(x4), 0.02) << name;
        const auto down = aa::downscaleMitchell(x4.view(), 4);
        EXPECT_GT(eval::psnr(down.view(), x1.view()), 14.0) << name;
    }
}

TEST(TestImages, CirclesHaveAColourOfTheBackgroundsLuma) {
    // The paper's green-on-grey case (spec ppaa.md section 4): in the bottom-left quadrant
    // the green disc's luma is within 0.002 of the background's.
    const auto img = eval::drawTestImage("circles", 1);
    const Rgba8 bg = img(2, 478), green = img(120, 360);  // quadrant corner; centre of the green disc
    EXPECT_EQ(green, (Rgba8{0, 255, 0, 255}));
    auto luma = [](Rgba8 p) { return std::sqrt(0.299 * p.r / 255 + 0.587 * p.g / 255 + 0.114 * p.b / 255); };
    EXPECT_NEAR(luma(bg), luma(green), 0.002);
}

TEST(TestImages, AnimationMovesAndLoops) {
    const auto f0 = eval::drawTestImage("animated", 1, 0), f1 = eval::drawTestImage("animated", 1, 1);
    EXPECT_NE(f0, f1);
    // The last frame leads back to the first: it differs from frame 0 about as much as
    // frame 1 does (no jump at the loop point).
    const auto last = eval::drawTestImage("animated", 1, 31);
    const double step = eval::mse(f0.view(), f1.view()), wrap = eval::mse(last.view(), f0.view());
    EXPECT_LT(wrap, 2.0 * step);
    EXPECT_GT(wrap, 0.5 * step);
}

TEST(TestImages, PlotHasText) {
    // Text is real glyphs: the title row band contains many small dark runs.
    const auto img = eval::drawTestImage("plot", 1);
    int transitions = 0;
    for (int x = 1; x < img.width(); ++x) transitions += (img(x, 24).r < 128) != (img(x - 1, 24).r < 128);
    EXPECT_GT(transitions, 20);
}

TEST(TestImages, BadArguments) {
    EXPECT_THROW(eval::drawTestImage("nope", 1), Error);
    EXPECT_THROW(eval::drawTestImage("lines", 0), Error);
    EXPECT_THROW(eval::drawTestImage("lines", 1, 1), Error);
    EXPECT_THROW(eval::drawTestImage("animated", 1, 32), Error);
}
