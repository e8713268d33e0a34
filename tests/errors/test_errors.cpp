// One test per bad-input class: each expects ssfx::Error with a message naming the problem.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>

#include "src/io/png_internal.hpp"
#include "ssfx/aa/blur.hpp"
#include "ssfx/aa/ddaa.hpp"
#include "ssfx/aa/fxaa.hpp"
#include "ssfx/aa/registry.hpp"
#include "ssfx/aa/resolve.hpp"
#include "ssfx/io/png.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

namespace {

// Runs f and checks it throws ssfx::Error whose message contains every fragment.
template <class F>
void expectError(F&& f, std::initializer_list<const char*> fragments) {
    try {
        f();
        ADD_FAILURE() << "no ssfx::Error thrown";
    } catch (const Error& e) {
        for (const char* frag : fragments)
            EXPECT_NE(std::string(e.what()).find(frag), std::string::npos) << "message: " << e.what();
    }
}

std::vector<std::uint8_t> validPng() { return io::encodePng(test::noise(8, 8, 2).view()); }

// Rewrites IHDR fields (width, height, bit depth) and fixes its CRC.
std::vector<std::uint8_t> patchIhdr(std::uint32_t w, std::uint32_t h, std::uint8_t depth) {
    auto b = validPng();
    for (int i = 0; i < 4; ++i)
        b[16 + i] = std::uint8_t(w >> (24 - 8 * i)), b[20 + i] = std::uint8_t(h >> (24 - 8 * i));
    b[24] = depth;
    const uLong crc = crc32(crc32(0, Z_NULL, 0), &b[12], 17);
    for (int i = 0; i < 4; ++i) b[29 + i] = std::uint8_t(crc >> (24 - 8 * i));
    return b;
}

}  // namespace

TEST(Errors, MissingFile) {
    expectError([] { io::readPng("/nonexistent/dir/none.png"); }, {"/nonexistent/dir/none.png", "cannot open"});
}

TEST(Errors, WrongSignature) {
    const std::vector<std::uint8_t> jpeg = {0xFF, 0xD8, 0xFF, 0xE0, 0, 0x10, 'J', 'F', 'I', 'F', 0};
    expectError([&] { io::decodePng(jpeg, "photo.jpg"); }, {"photo.jpg", "signature"});
    expectError([&] { io::decodeApng(jpeg, "photo.jpg"); }, {"photo.jpg", "signature"});
}

TEST(Errors, EmptyAndTruncatedFiles) {
    expectError([] { io::decodePng({}, "empty.png"); }, {"empty.png"});
    const auto b = validPng();
    for (std::size_t cut : {std::size_t(8), std::size_t(20), b.size() / 2, b.size() - 13}) {
        const std::vector<std::uint8_t> t(b.begin(), b.begin() + long(cut));
        expectError([&] { io::decodePng(t, "cut.png"); }, {"cut.png"});
        expectError([&] { io::decodeApng(t, "cut.png"); }, {"cut.png"});
    }
}

TEST(Errors, CorruptChunkCrc) {
    auto b = validPng();
    b[b.size() - 17] ^= 0x55;  // last IDAT payload byte (before its CRC and the 12-byte IEND)
    expectError([&] { io::decodeApng(b, "crc.png"); }, {"crc.png", "CRC"});
    expectError([&] { io::decodePng(b, "crc.png"); }, {"crc.png"});
}

TEST(Errors, ZeroDimensions) {
    expectError([] { io::decodePng(patchIhdr(0, 8, 8), "zero.png"); }, {"zero.png"});
    expectError([] { io::decodeApng(patchIhdr(8, 0, 8), "zero.png"); }, {"zero.png", "8x0"});
}

TEST(Errors, HugeDimensionsAreRefusedBeforeAllocating) {
    // Within libpng's own limits but 30000^2 = 9e8 pixels > 2^28: refused by our check.
    expectError([] { io::decodePng(patchIhdr(30000, 30000, 8), "huge.png"); }, {"huge.png", "30000x30000", "limit"});
    // Beyond the per-side limit: refused while reading the header.
    expectError([] { io::decodePng(patchIhdr(2000000, 1, 8), "wide.png"); }, {"wide.png"});
}

TEST(Errors, UnsupportedBitDepth) {
    expectError([] { io::decodePng(patchIhdr(8, 8, 3), "depth3.png"); }, {"depth3.png"});
}

TEST(Errors, ApngWithInconsistentFrameSizes) {
    io::Animation a;
    a.frames.push_back({ImageRgba8(4, 4), 1, 10});
    a.frames.push_back({ImageRgba8(5, 4), 1, 10});
    expectError([&] { io::encodeApng(a); }, {"frame 1", "5x4"});

    // A frame that does not fit the canvas: rewrite the second fcTL's width to 9.
    a.frames[1].image = ImageRgba8(4, 4);
    auto bytes = io::encodeApng(a);
    auto chunks = io::detail::parseChunks(bytes, "x");
    int seen = 0;
    for (const auto& c : chunks)
        if (c.is("fcTL") && seen++ == 1) {
            const std::size_t at = std::size_t(c.data.data() - bytes.data());
            bytes[at + 7] = 9;  // width low byte
            const uLong crc = crc32(crc32(0, Z_NULL, 0), &bytes[at - 4], uInt(c.data.size() + 4));
            for (int i = 0; i < 4; ++i) bytes[at + c.data.size() + std::size_t(i)] = std::uint8_t(crc >> (24 - 8 * i));
        }
    expectError([&] { io::decodeApng(bytes, "anim.png"); }, {"anim.png", "frame 1", "does not fit"});
}

TEST(Errors, ApngFrameCountMismatch) {
    io::Animation a;
    a.frames.assign(2, io::Frame{ImageRgba8(2, 2), 1, 10});
    auto bytes = io::encodeApng(a);
    // acTL payload starts after signature (8) + IHDR (25) + acTL length/type (8): num_frames = 3.
    bytes[8 + 25 + 8 + 3] = 3;
    const uLong crc = crc32(crc32(0, Z_NULL, 0), &bytes[8 + 25 + 4], 12);
    for (int i = 0; i < 4; ++i) bytes[8 + 25 + 16 + std::size_t(i)] = std::uint8_t(crc >> (24 - 8 * i));
    expectError([&] { io::decodeApng(bytes, "count.png"); }, {"count.png", "declares 3 frames but has 2"});
}

TEST(Errors, ParametersOutOfRangeOrNaNAreRejectedNotClamped) {
    const auto img = test::noise(8, 8, 1);
    aa::Ddaa2Params p;
    p.strength = 1000;
    expectError([&] { aa::ddaa2(img.view(), p); }, {"ddaa2", "strength", "1000"});
    p = {};
    p.edgeThreshold = std::nanf("");
    expectError([&] { aa::ddaa2(img.view(), p); }, {"edgeThreshold", "nan"});
    aa::Fxaa3dParams f;
    f.subpix = -0.1f;
    expectError([&] { aa::fxaa3d(img.view(), f); }, {"fxaa3d", "subpix"});
    aa::BlurParams b;
    b.sigma = 0;
    expectError([&] { aa::blur(img.view(), b); }, {"blur", "sigma"});
}

TEST(Errors, RegistryRejectsUnknownNamesAndBadOverrides) {
    expectError([] { methodById("smaa"); }, {"smaa", "ddaa2"});
    const auto img = test::noise(8, 8, 1);
    MethodSettings s;
    s.params = {{"strenght", 2.0}};
    expectError([&] { methodById("ddaa2").run(img.view(), s, {}); }, {"strenght", "strength"});
    s.params = {{"searchRounds", 2.5}};
    expectError([&] { methodById("ddaa2").run(img.view(), s, {}); }, {"searchRounds", "integer"});
    s.params = {};
    s.preset = aa::Preset::High;
    expectError([&] { methodById("blur").run(img.view(), s, {}); }, {"blur", "presets"});
}

TEST(Errors, WrongSizesAndAliasing) {
    auto img = test::noise(8, 8, 1);
    ImageRgba8 small(4, 4);
    expectError([&] { aa::ddaa1(img.view(), small.view()); }, {"ddaa1", "4x4", "8x8"});
    expectError([&] { aa::blur(img.view(), img.view()); }, {"overlap"});
    const auto odd = test::noise(7, 8, 1);
    expectError([&] { aa::ssaax2(odd.view()); }, {"ssaax2", "7x8", "divisible by 2"});
    const auto six = test::noise(6, 8, 1);
    expectError([&] { aa::ssaax4(six.view()); }, {"ssaax4", "divisible by 4"});
    expectError([&] { aa::ddaa2p(odd.view()); }, {"ddaa2p", "2x render"});
    expectError([&] { aa::resampleMitchell(img.view(), 0); }, {"factor 0"});
}
