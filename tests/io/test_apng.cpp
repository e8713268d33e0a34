// APNG: our chunk layer (acTL/fcTL/fdAT) around libpng-coded frames.
#include <gtest/gtest.h>

#include "../../src/io/png_internal.hpp"
#include "ssfx/io/png.hpp"
#include "support/test_support.hpp"

using namespace ssfx;
using namespace ssfx::io::detail;

TEST(Apng, RoundTripKeepsFramesDelaysAndPlays) {
    io::Animation a;
    a.numPlays = 3;
    for (int i = 0; i < 4; ++i) a.frames.push_back({test::noise(9, 7, unsigned(i)), std::uint16_t(i + 1), 25});
    const auto bytes = io::encodeApng(a);
    EXPECT_TRUE(io::isApng(bytes));
    const auto b = io::decodeApng(bytes, "anim");
    ASSERT_EQ(b.frames.size(), 4u);
    EXPECT_EQ(b.numPlays, 3u);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(b.frames[std::size_t(i)].image, a.frames[std::size_t(i)].image);
        EXPECT_EQ(b.frames[std::size_t(i)].delayNum, i + 1);
        EXPECT_EQ(b.frames[std::size_t(i)].delayDen, 25);
    }
    EXPECT_DOUBLE_EQ(b.frames[1].delaySeconds(), 2.0 / 25.0);
}

TEST(Apng, StillPngReadsAsOneFrame) {
    const auto img = test::noise(3, 3, 4);
    const auto bytes = io::encodePng(img.view());
    EXPECT_FALSE(io::isApng(bytes));
    const auto a = io::decodeApng(bytes, "still");
    ASSERT_EQ(a.frames.size(), 1u);
    EXPECT_EQ(a.frames[0].image, img);
}

namespace {
// Hand-assembles an APNG: a 4x4 canvas, frame 0 full red, frame 1 a 2x2 patch at (1,1).
std::vector<std::uint8_t> handMadeApng(std::uint8_t blend, std::uint8_t dispose0, Rgba8 patch) {
    const ImageRgba8 full(4, 4, Rgba8{255, 0, 0, 255});
    const ImageRgba8 part(2, 2, patch);
    const auto png0 = io::encodePng(full.view()), png1 = io::encodePng(part.view());  // chunks point into these
    const auto c0 = parseChunks(png0, "f0");
    const auto c1 = parseChunks(png1, "f1");
    std::vector<std::uint8_t> out(kPngSignature, kPngSignature + 8);
    appendChunk(out, "IHDR", c0[0].data);
    std::vector<std::uint8_t> actl;
    appendBe32(actl, 2), appendBe32(actl, 0);
    appendChunk(out, "acTL", actl);
    auto fctl = [&](std::uint32_t seq, std::uint32_t w, std::uint32_t h, std::uint32_t x, std::uint32_t y,
                    std::uint8_t dispose, std::uint8_t bl) {
        std::vector<std::uint8_t> f;
        appendBe32(f, seq), appendBe32(f, w), appendBe32(f, h), appendBe32(f, x), appendBe32(f, y);
        appendBe16(f, 1), appendBe16(f, 10);
        f.push_back(dispose), f.push_back(bl);
        appendChunk(out, "fcTL", f);
    };
    fctl(0, 4, 4, 0, 0, dispose0, 0);
    for (const auto& c : c0)
        if (c.is("IDAT")) appendChunk(out, "IDAT", c.data);
    fctl(1, 2, 2, 1, 1, 0, blend);
    std::uint32_t seq = 2;
    for (const auto& c : c1)
        if (c.is("IDAT")) {
            std::vector<std::uint8_t> d;
            appendBe32(d, seq++);
            d.insert(d.end(), c.data.begin(), c.data.end());
            appendChunk(out, "fdAT", d);
        }
    appendChunk(out, "IEND", {});
    return out;
}
}  // namespace

TEST(Apng, SubFramesAreComposedOntoTheCanvas) {
    const auto a = io::decodeApng(handMadeApng(0, 0, {0, 0, 255, 255}), "compose");
    ASSERT_EQ(a.frames.size(), 2u);
    EXPECT_EQ(a.frames[1].image(0, 0), (Rgba8{255, 0, 0, 255}));  // kept from frame 0
    EXPECT_EQ(a.frames[1].image(1, 1), (Rgba8{0, 0, 255, 255}));  // the patch
    EXPECT_EQ(a.frames[1].image(3, 3), (Rgba8{255, 0, 0, 255}));
}

TEST(Apng, BlendOverAndDisposeBackground) {
    // Frame 0 disposed to transparent black; frame 1 half-transparent blue blended over it.
    const auto a = io::decodeApng(handMadeApng(1, 1, {0, 0, 255, 128}), "over");
    EXPECT_EQ(a.frames[0].image(1, 1), (Rgba8{255, 0, 0, 255}));
    EXPECT_EQ(a.frames[1].image(0, 0), (Rgba8{0, 0, 0, 0}));
    EXPECT_EQ(a.frames[1].image(1, 1), (Rgba8{0, 0, 255, 128}));  // over transparent = source
}
