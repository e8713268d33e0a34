#include <gtest/gtest.h>

#include "ssfx/core/image.hpp"

using namespace ssfx;

TEST(Image, AllocatesAndIndexesRowMajor) {
    ImageRgba8 img(3, 2, Rgba8{1, 2, 3, 4});
    EXPECT_EQ(img.width(), 3);
    EXPECT_EQ(img.height(), 2);
    img(2, 1) = {9, 9, 9, 9};
    EXPECT_EQ(img.data()[5], (Rgba8{9, 9, 9, 9}));  // row 1, column 2
    EXPECT_EQ(img.view().row(1)[2], (Rgba8{9, 9, 9, 9}));
}

TEST(Image, ClampedAccessReadsTheNearestEdge) {
    ImageF img(2, 2);
    img(0, 0) = 1, img(1, 0) = 2, img(0, 1) = 3, img(1, 1) = 4;
    const auto v = img.view();
    EXPECT_EQ(v.clamped(-5, -5), 1);
    EXPECT_EQ(v.clamped(7, 0), 2);
    EXPECT_EQ(v.clamped(-1, 9), 3);
    EXPECT_EQ(v.clamped(3, 3), 4);
}

TEST(Image, SubViewWithStride) {
    ImageF img(4, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) img(x, y) = float(10 * y + x);
    ImageView<const float> sub(img.data() + 1 + 4, 2, 2, 4);  // starts at (1, 1)
    EXPECT_EQ(sub(0, 0), 11);
    EXPECT_EQ(sub(1, 1), 22);
    EXPECT_EQ(ImageF::copyOf(sub)(1, 0), 12);
}

TEST(Image, RejectsZeroNegativeAndHugeSizesBeforeAllocating) {
    EXPECT_THROW(ImageRgba8(0, 5), Error);
    EXPECT_THROW(ImageRgba8(5, -1), Error);
    EXPECT_THROW(checkDimensions(kMaxDimension + 1, 1, "x"), Error);
    EXPECT_THROW(checkDimensions(1 << 15, 1 << 14, "x"), Error);  // 2^29 pixels > 2^28
    EXPECT_NO_THROW(checkDimensions(1 << 14, 1 << 14, "x"));
    try {
        checkDimensions(0, 3, "photo.png");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("photo.png"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("0x3"), std::string::npos);
    }
}
