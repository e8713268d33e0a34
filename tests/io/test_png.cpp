// PNG reading: the conversion rule to RGBA8 (png.hpp) for every colour type and depth.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "ssfx/io/png.hpp"
#include "tests/io/png_writer.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;
using test::RawPng;
using test::writeRawPng;

TEST(Png, RoundTripRgbaIsLossless) {
    const auto img = test::noise(33, 17, 1);
    const auto bytes = io::encodePng(img.view());
    EXPECT_EQ(io::decodePng(bytes, "mem"), img);
}

TEST(Png, GreyBecomesEqualRgbWithOpaqueAlpha) {
    const auto bytes = writeRawPng({3, 1, 8, PNG_COLOR_TYPE_GRAY, {0, 128, 255}});
    const auto img = io::decodePng(bytes, "grey");
    EXPECT_EQ(img(1, 0), (Rgba8{128, 128, 128, 255}));
    EXPECT_EQ(img(2, 0), (Rgba8{255, 255, 255, 255}));
}

TEST(Png, LowBitGreyIsExpandedToFullRange) {
    // 2-bit grey: levels 0..3 -> 0, 85, 170, 255; one byte holds 4 pixels.
    const auto bytes = writeRawPng({4, 1, 2, PNG_COLOR_TYPE_GRAY, {0b00011011}});
    const auto img = io::decodePng(bytes, "grey2");
    EXPECT_EQ(img(0, 0).r, 0);
    EXPECT_EQ(img(1, 0).r, 85);
    EXPECT_EQ(img(2, 0).r, 170);
    EXPECT_EQ(img(3, 0).r, 255);
}

TEST(Png, GreyAlphaKeepsAlpha) {
    const auto bytes = writeRawPng({1, 1, 8, PNG_COLOR_TYPE_GRAY_ALPHA, {77, 99}});
    EXPECT_EQ(io::decodePng(bytes, "ga")(0, 0), (Rgba8{77, 77, 77, 99}));
}

TEST(Png, SixteenBitIsScaledWithRounding) {
    // v8 = round(v16 * 255 / 65535): 0x8080 -> 128, 0x7F7F -> 127, 0xFFFF -> 255, 0x0081 -> 1 (0.502).
    const auto bytes =
        writeRawPng({1, 1, 16, PNG_COLOR_TYPE_RGB_ALPHA, {0x80, 0x80, 0x7F, 0x7F, 0x00, 0x81, 0xFF, 0xFF}});
    EXPECT_EQ(io::decodePng(bytes, "rgba16")(0, 0), (Rgba8{128, 127, 1, 255}));
}

TEST(Png, PaletteWithTransparencyIsExpanded) {
    RawPng p{2, 1, 8, PNG_COLOR_TYPE_PALETTE, {1, 0}};
    p.palette = {{10, 20, 30}, {200, 100, 50}};
    p.trnsAlpha = {128};  // entry 0 half transparent, entry 1 opaque
    const auto img = io::decodePng(writeRawPng(p), "pal");
    EXPECT_EQ(img(0, 0), (Rgba8{200, 100, 50, 255}));
    EXPECT_EQ(img(1, 0), (Rgba8{10, 20, 30, 128}));
}

TEST(Png, RgbColourKeyBecomesTransparent) {
    RawPng p{2, 1, 8, PNG_COLOR_TYPE_RGB, {1, 2, 3, 4, 5, 6}};
    p.trnsColor = true;
    p.trnsKey.red = 4, p.trnsKey.green = 5, p.trnsKey.blue = 6;
    const auto img = io::decodePng(writeRawPng(p), "key");
    EXPECT_EQ(img(0, 0).a, 255);
    EXPECT_EQ(img(1, 0).a, 0);
}

TEST(Png, WriteIsAtomicAndReadable) {
    const std::string path = test::outDir() + "/atomic.png";
    const auto img = test::noise(5, 4, 9);
    io::writePng(path, img.view());
    EXPECT_EQ(io::readPng(path), img);
    // No temporary file is left beside it.
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(test::outDir()))
        if (e.path().filename().string().find("atomic.png") != std::string::npos) ++files;
    EXPECT_EQ(files, 1);
}

// Issue #35 item 8: a PNG is read up to its IEND chunk and no further, so that a stream that
// goes on after the image (a FIFO fed by `cat a.png /dev/zero`) costs one image; the read's
// cap follows --max-pixels.
TEST(Png, AFileIsReadUpToItsEndChunkAndNoFurther) {
    const std::string dir = test::outDir();
    ImageRgba8 img(5, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) img(x, y) = {std::uint8_t(x * 40), std::uint8_t(y * 70), 9, 255};
    const std::vector<std::uint8_t> png = io::encodePng(img.view());
    const std::string path = dir + "/trailing.png";
    {
        std::FILE* f = std::fopen(path.c_str(), "wb");
        std::fwrite(png.data(), 1, png.size(), f);
        const std::vector<std::uint8_t> junk(1 << 20, 0);
        std::fwrite(junk.data(), 1, junk.size(), f);
        std::fclose(f);
    }
    EXPECT_EQ(io::readPngFile(path), png);
    EXPECT_EQ(io::readPng(path), img);
    // A cut file comes back as it is, for the decoder to name.
    {
        std::FILE* f = std::fopen(path.c_str(), "wb");
        std::fwrite(png.data(), 1, png.size() - 5, f);
        std::fclose(f);
    }
    EXPECT_EQ(io::readPngFile(path).size(), png.size() - 5);
    EXPECT_NE(test::errorOf([&] { io::readPng(path); }).find("trailing.png"), std::string::npos);
}

TEST(Png, TheReadLimitFollowsMaxPixels) {
    EXPECT_EQ(io::pngFileLimit(), io::kMaxImageFileBytes);
    io::setMaxPixels(1000);
    EXPECT_EQ(io::pngFileLimit(), 5000u + (16u << 20));
    io::setMaxPixels(kMaxPixels);
    EXPECT_EQ(io::pngFileLimit(), io::kMaxImageFileBytes);
}

TEST(Png, APathWithANulByteIsRefusedNotCut) {
    const std::string dir = test::outDir();
    const std::string victim = dir + "/victim";
    { std::ofstream(victim) << "keep"; }
    const std::string withNul = victim + std::string(1, '\0') + ".png";
    const std::string m = test::errorOf([&] { io::writePng(withNul, ImageRgba8(2, 2).view()); });
    EXPECT_NE(m.find("victim\\0.png' contains a NUL byte"), std::string::npos) << m;
    EXPECT_NE(test::errorOf([&] { io::readPng(withNul); }).find("NUL byte"), std::string::npos);
    EXPECT_NE(test::errorOf([&] { io::makeDirectories(withNul); }).find("NUL byte"), std::string::npos);
    std::ifstream in(victim);
    std::string text;
    in >> text;
    EXPECT_EQ(text, "keep");
}
