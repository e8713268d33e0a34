// The GPU sampling model against hand-computed values (spec ppaa.md section 1).
#include <gtest/gtest.h>

#include <limits>

#include "ssfx/core/sample.hpp"

using namespace ssfx;

namespace {
ImageRgba8 row(std::initializer_list<std::uint8_t> values) {
    ImageRgba8 img(int(values.size()), 1);
    int x = 0;
    for (auto v : values) img(x++, 0) = {v, v, v, 255};
    return img;
}
}  // namespace

TEST(Sample, CentreReadReturnsThePixel) {
    const auto img = row({10, 200, 30});
    for (Filtering f : {Filtering::Gpu, Filtering::Exact}) {
        const Texture t(img.view(), f);
        EXPECT_EQ(t.sample(t.centreU(1), t.centreV(0)).r, 200.0f / 255.0f);
    }
}

TEST(Sample, MidpointIsHalfWayAndOnTheSixteenthGrid) {
    const auto img = row({0, 255});
    const Texture t(img.view(), Filtering::Gpu);
    // u = 0.5 is the boundary between the texels: fraction 0.5 -> weight 128/256.
    EXPECT_EQ(t.sample(0.5f, 0.5f).r, 2040.0f / 4080.0f);
}

TEST(Sample, FractionRoundsToEightBitsAndSumToSixteenthLevels) {
    const auto img = row({0, 1});
    const Texture t(img.view(), Filtering::Gpu);
    // Position 0.3 px right of texel 0's centre: fraction 0.3 -> round(76.8) = 77/256.
    // Sum = 77 * 256 * 1 (in 1/65536 level units) = 19712 -> (19712 + 2048) >> 12 = 5 sixteenths.
    const float u = (0.5f + 0.3f) / 2.0f;
    EXPECT_EQ(t.sample(u, 0.5f).r, 5.0f / 4080.0f);
    // The exact model keeps the unrounded fraction.
    const Texture e(img.view(), Filtering::Exact);
    EXPECT_NEAR(e.sample(u, 0.5f).r, 0.3f / 255.0f, 1e-7f);
}

TEST(Sample, ClampToEdgeOutsideTheImage) {
    const auto img = row({40, 80});
    const Texture t(img.view(), Filtering::Gpu);
    EXPECT_EQ(t.sample(-3.0f, 0.5f).r, 40.0f / 255.0f);
    EXPECT_EQ(t.sample(5.0f, 0.5f).r, 80.0f / 255.0f);
    EXPECT_EQ(t.sample(0.5f, -9.0f, 7, 3).r, 80.0f / 255.0f);  // texel offsets clamp too
}

TEST(Sample, NonFiniteCoordinatesReadTheEdgeWithoutUndefinedBehaviour) {
    const auto img = row({40, 80});
    const Texture t(img.view(), Filtering::Gpu);
    EXPECT_EQ(t.sample(std::nanf(""), 0.5f).r, 40.0f / 255.0f);
    EXPECT_EQ(t.sample(std::numeric_limits<float>::infinity(), 0.5f).r, 80.0f / 255.0f);
}

TEST(Sample, IntegerOffsetIsAddedAfterTheFloor) {
    const auto img = row({0, 100, 200, 250});
    const Texture t(img.view(), Filtering::Gpu);
    EXPECT_EQ(t.sample(t.centreU(0), 0.5f, 2, 0).r, 200.0f / 255.0f);
    // Half-way between texels 1 and 2, then +1: half-way between 2 and 3 = 225.
    EXPECT_EQ(t.sample(0.5f, 0.5f, 1, 0).r, 225.0f / 255.0f);
}

// Reads at pixel centres plus integer offsets must land exactly on texels for every
// realistic width, since the methods replace them by luma-plane lookups.
TEST(Sample, CentreReadsAreExactForAllWidthsUpTo4096) {
    for (int w : {1, 2, 3, 7, 480, 600, 1080, 1920, 1200, 3840, 4095, 4096}) {
        ImageRgba8 img(w, 1);
        for (int x = 0; x < w; ++x) img(x, 0) = {std::uint8_t(x * 7), 0, 0, 255};
        const Texture t(img.view(), Filtering::Gpu);
        for (int x = 0; x < w; ++x)
            for (int o : {-1, 0, 1}) {
                const int src = std::clamp(x + o, 0, w - 1);
                ASSERT_EQ(t.sample(t.centreU(x), 0.5f, o, 0).r, kUnorm8[std::uint8_t(src * 7)]) << w << " " << x;
            }
    }
}
