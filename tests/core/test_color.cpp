#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <hwy/targets.h>

#include "src/core/exact_div_hooks.hpp"
#include "ssfx/core/color.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

TEST(Color, LumaOfBlackWhiteAndPrimaries) {
    EXPECT_EQ(luma(0, 0, 0), 0.0f);
    EXPECT_NEAR(luma(1, 1, 1), 1.0f, 1e-7f);
    EXPECT_NEAR(luma(1, 0, 0), std::sqrt(0.299f), 1e-7f);
    EXPECT_NEAR(luma(0, 1, 0), std::sqrt(0.587f), 1e-7f);
}

TEST(Color, ToUnorm8RoundsTheExactProduct) {
    EXPECT_EQ(toUnorm8(0.0f), 0);
    EXPECT_EQ(toUnorm8(1.0f), 255);
    EXPECT_EQ(toUnorm8(-0.5f), 0);
    EXPECT_EQ(toUnorm8(7.0f), 255);
    EXPECT_EQ(toUnorm8(std::nanf("")), 0);
    EXPECT_EQ(toUnorm8(100.0f / 255.0f), 100);
    // 0.672549009f * 255 is 171.49999...(exact) but 171.5 after a float32 multiply; the
    // reference GPU output is 171 (measured on circles_ddaa2.png).
    EXPECT_EQ(toUnorm8(0.672549009f), 171);
    EXPECT_EQ(toUnorm8(171.5f / 255.0f + 1e-6f), 172);
}

TEST(Color, LumaPlaneMatchesPerPixelLuma) {
    const auto img = test::noise(37, 5, 3);
    const ImageF L = lumaPlane(img.view());
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const Rgba8 p = img(x, y);
            ASSERT_EQ(L(x, y), luma(kUnorm8[p.r], kUnorm8[p.g], kUnorm8[p.b])) << x << "," << y;
        }
}

// The kernels' reciprocal-and-correction division (src/core/exact_div-inl.h) is only
// claimed exact for the integer ranges they divide; check every integer of each range, on
// every SIMD target this binary has and this machine runs (the FMA targets take the fast
// form, the others divide).
TEST(Color, ExactDivisionIsIeeeDivisionForEveryInteger) {
    struct Range {
        float divisor;
        int kMax;
    };
    // 255: a channel byte; 4080 = 255 x 16: a GPU-model bilinear sum (sample.cpp); 510 and
    // 1020: sums of two and four bytes (the half-way luma planes of the PPAA searches).
    const Range ranges[] = {{255.0f, 255}, {4080.0f, 4080}, {510.0f, 510}, {1020.0f, 1020}};
    const auto targets = hwy::SupportedAndGeneratedTargets();
    ASSERT_FALSE(targets.empty());
    for (const std::int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        for (const Range& r : ranges)
            EXPECT_EQ(detail::divExactMismatches(r.divisor, r.kMax), 0)
                << hwy::TargetName(target) << ": k / " << r.divisor << " for k <= " << r.kMax;
    }
    hwy::SetSupportedTargetsForTest(0);
}

// The kernels' row decode (src/core/srgb_encode-inl.h: a lookup in registers on AVX-512,
// gathers elsewhere) gives kSrgb8's floats: rows of 1 to 40 texels (the vector loops and
// their tails) and of 1000 (every byte value in every channel, at many positions), on every
// SIMD target.
TEST(Color, SrgbRowDecodeGivesTheTablesFloats) {
    const auto targets = hwy::SupportedAndGeneratedTargets();
    ASSERT_FALSE(targets.empty());
    for (const std::int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        for (int w = 1; w <= 40; ++w) EXPECT_EQ(detail::decodeSrgbRowMismatches(w), 0) << hwy::TargetName(target) << w;
        EXPECT_EQ(detail::decodeSrgbRowMismatches(1000), 0) << hwy::TargetName(target);
    }
    hwy::SetSupportedTargetsForTest(0);
}

// The vector kernels' sRGB encode (src/core/srgb_encode-inl.h: on AVX-512 a polynomial whose
// ambiguous lanes take the table, elsewhere one gather of the packed bucket word) against
// encodeSrgb8 (whose table SrgbTransfer.EncodeTableFollowsTheThresholdRule holds to the
// defining rule): every float in [2^-14, 1] and 1024 either side (117 million: where the
// polynomial is used, so this is its proof), every 61st float in [0, 1], the 4 floats either
// side of each threshold and of each bucket boundary, and the out-of-range inputs, on every
// SIMD target.
TEST(Color, VectorSrgbEncodeGivesTheScalarLevels) {
    using T = detail::SrgbEncodeTable;
    std::vector<float> v;
    const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
    for (std::uint32_t b = 0; b <= one + 64; b += 61) v.push_back(std::bit_cast<float>(b));
    auto around = [&](std::uint32_t centre) {
        for (std::uint32_t b = centre - 4; b <= centre + 4; ++b) v.push_back(std::bit_cast<float>(b));
    };
    for (const float f : srgbEncodeThresholds()) around(std::bit_cast<std::uint32_t>(f));
    for (std::uint32_t j = 0; j <= T::kBuckets; ++j) around(T::kLowBits + (j << T::kShift));
    for (const float f :
         {-1.0f, -0.0f, 2.0f, std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
          std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::denorm_min()})
        v.push_back(f);
    const auto targets = hwy::SupportedAndGeneratedTargets();
    ASSERT_FALSE(targets.empty());
    for (const std::int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        EXPECT_EQ(detail::encodeSrgb8Mismatches(v.data(), std::int64_t(v.size())), 0) << hwy::TargetName(target);
        EXPECT_EQ(detail::encodeSrgb8RangeMismatches(T::kLowBits - 1024, one + 1024), 0) << hwy::TargetName(target);
    }
    hwy::SetSupportedTargetsForTest(0);
}
