// EXR and camera JSON files.
#include <gtest/gtest.h>

#include <cstring>

#include <algorithm>

#include <cmath>

#include <fmt/format.h>

#include "ssfx/io/camera.hpp"
#include "ssfx/io/exr.hpp"
#include "tests/support/test_support.hpp"

using namespace ssfx;

TEST(Exr, RoundTripIsExactAndKeepsTheChannel) {
    ImageF img(7, 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) img(x, y) = float(x) * 0.125f - float(y) * 3.0f + 1e-7f * float(x * y);
    img(6, 4) = -INFINITY;
    const auto bytes = io::encodeExr(img.view(), "Z");
    std::string used;
    const ImageF back = io::decodeExr(bytes, "mem.exr", "", &used);
    EXPECT_EQ(used, "Z");
    EXPECT_EQ(back, img);
    EXPECT_THROW(io::decodeExr(bytes, "mem.exr", "Q"), Error);
}

TEST(Exr, TruncatedAndCorruptFilesAreErrorsNamingTheFile) {
    const ImageF img(16, 16, 0.5f);
    auto bytes = io::encodeExr(img.view());
    for (std::size_t n : {std::size_t(0), std::size_t(3), std::size_t(40), bytes.size() / 2, bytes.size() - 1}) {
        std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + std::ptrdiff_t(n));
        try {
            io::decodeExr(cut, "cut.exr");
            ADD_FAILURE() << "no error at " << n << " bytes";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("cut.exr"), std::string::npos) << e.what();
        }
    }
    bytes[bytes.size() / 2] ^= 0xff;
    bytes[bytes.size() / 2 + 1] ^= 0xff;
    try {
        const ImageF f = io::decodeExr(bytes, "flip.exr");  // a flipped byte in ZIP data may still decode
        EXPECT_EQ(f.width(), 16);
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("flip.exr"), std::string::npos);
    }
}

TEST(Exr, AHeaderAttributeClaimingMoreThanTheFileIsRefusedBeforeOpenExrAllocates) {
    // A valid file with one attribute's size field patched to 2 GiB - 1: OpenEXR would
    // allocate that before finding the file truncated; the header check refuses it first.
    ImageF img(8, 8, 0.5f);
    auto bytes = io::encodeExr(img.view(), "Z");
    const std::string attr = "compression";
    const auto at = std::search(bytes.begin(), bytes.end(), attr.begin(), attr.end());
    ASSERT_NE(at, bytes.end());
    std::size_t p = std::size_t(at - bytes.begin()) + attr.size() + 1;  // past "compression\0"
    while (bytes[p] != 0) ++p;                                          // past the type name
    ++p;
    for (int i = 0; i < 4; ++i) bytes[p + std::size_t(i)] = i == 3 ? 0x7F : 0xFF;  // int32 0x7FFFFFFF
    const std::string m = test::errorOf([&] { io::decodeExr(bytes, "claim.exr"); });
    EXPECT_NE(m.find("claim.exr"), std::string::npos) << m;
    EXPECT_NE(m.find("'compression'"), std::string::npos) << m;
    EXPECT_NE(m.find("2147483647 bytes"), std::string::npos) << m;
    EXPECT_EQ(io::decodeExr(io::encodeExr(img.view(), "Z"), "ok.exr"), img);  // an intact file still reads
}

TEST(Exr, AHugeDataWindowIsRefusedBeforeOpenExrAllocates) {
    // The fuzzer's find (make test's fuzz run, 2026-12-06): a 140-byte ZIP-compressed header
    // whose data window is 33423368 x 16 pixels. Opening it, OpenEXR allocated a 2 GiB
    // scan-line buffer; the header check now refuses the size first, naming the limit.
    const char* base64 =
        "di8xAQIAAABjaGFubmVscwBjaGxpc3QAEwAAAFoAAgAAAAAAAAABAAAAAQAAAABjbwBjb21wcmVzc2lvbgABAAAAA2RhdGFXaW5kb3cA"
        "Ym94MmkAEAAAAAAAAAAAAAAABwD+AQ8AAAAFAAAAAAAAAAALAABkaXNwbGF5V2luZCqjwveCqBAAbQRgK8A=";
    std::vector<std::uint8_t> bytes;
    std::uint32_t acc = 0;
    int bits = 0;
    for (const char* c = base64; *c && *c != '='; ++c) {
        const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        acc = acc << 6 | std::uint32_t(std::strchr(table, *c) - table);
        if ((bits += 6) >= 8) bytes.push_back(std::uint8_t(acc >> (bits -= 8)));
    }
    ASSERT_EQ(bytes.size(), 140u);
    const std::string m = test::errorOf([&] { io::decodeExr(bytes, "huge.exr"); });
    EXPECT_NE(m.find("huge.exr"), std::string::npos) << m;
    // "(data window)": the header check's message, not the one after OpenEXR opened the file.
    EXPECT_NE(m.find("huge.exr (data window): size 33423368x16 exceeds"), std::string::npos) << m;
}

TEST(Camera, JsonRoundTripAndErrors) {
    Camera c;
    c.fovY = 0.8;
    c.zNear = -0.25;
    c.zFar = -300;
    const Camera back = io::parseCameraJson(io::cameraJson(c), "c.json");
    EXPECT_NEAR(back.fovY, 0.8, 1e-9);
    EXPECT_EQ(back.zNear, -0.25);
    EXPECT_EQ(back.zFar, -300);
    EXPECT_TRUE(std::isinf(io::parseCameraJson(R"({"fov_y_deg": 60, "z_near": -0.1, "z_far": null})", "c").zFar));
    EXPECT_TRUE(std::isinf(io::parseCameraJson(R"({"fov_y_deg": 60, "z_near": -0.1, "z_far": "-inf"})", "c").zFar));
    for (const char* bad :
         {"[1]", "{", R"({"fov": 60})", R"({"z_near": 0.1})", R"({"fov_y_deg": 200})", R"({"z_near": "a"})",
          R"({"z_near": -1, "z_far": -0.5})", "{}", R"({"fov_y_deg": 60, "z_near": -0.1})"})
        EXPECT_THROW(io::parseCameraJson(bad, "c.json"), Error) << bad;
    // Messages name the file and the key as the file spells it.
    auto message = [](const char* text) {
        try {
            io::parseCameraJson(text, "cam.json");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_NE(message("{}").find("cam.json: missing key 'fov_y_deg'"), std::string::npos) << message("{}");
    const std::string near = message(R"({"fov_y_deg": 60, "z_near": 0.1, "z_far": null})");
    EXPECT_NE(near.find("cam.json: z_near"), std::string::npos) << near;
}

// The line offset table is written (OpenEXR writes it from the output file's destructor,
// after the pixels): the one block of a small file is where the table says. Files written
// before this was fixed had a zeroed table, which readers must rebuild.
TEST(Exr, TheLineOffsetTableIsWritten) {
    const ImageF img(8, 4, 0.25f);
    const std::vector<std::uint8_t> b = io::encodeExr(img.view(), "Z");
    auto le64 = [&](std::size_t at) {
        std::uint64_t v = 0;
        for (int i = 7; i >= 0; --i) v = v << 8 | b[at + std::size_t(i)];
        return v;
    };
    bool found = false;
    for (std::size_t at = 8; at + 16 <= b.size() && !found; ++at)
        found = le64(at) == at + 8 && (le64(at + 8) >> 32) == b.size() - at - 16;  // y = 0, then the size
    EXPECT_TRUE(found);
}

// Issue #35 item 8: a file whose table is whole but whose blocks claim more pixels than they
// can hold is refused before the image is allocated (the CLI test crafts 16384^2 in 33 KB).
TEST(Exr, BlocksThatCannotHoldTheClaimedPixelsAreRefused) {
    const ImageF img(8, 4, 0.25f);
    std::vector<std::uint8_t> b = io::encodeExr(img.view(), "Z");
    const std::string key("dataWindow\0box2i\0", 17);
    const auto at = std::search(b.begin(), b.end(), key.begin(), key.end()) - b.begin() + 17 + 4;
    b[std::size_t(at) + 8] = 0xFF, b[std::size_t(at) + 9] = 0x0F;  // xMax = 4095: one block claims 64 KiB
    const std::string m = test::errorOf([&] { io::decodeExr(b, "wide.exr"); });
    EXPECT_NE(m.find("wide.exr: corrupt EXR (scan-line block 0 packs"), std::string::npos) << m;
    b.resize(b.size() - 4);  // and cut short
    const std::string cut = test::errorOf([&] { io::decodeExr(b, "cut.exr"); });
    EXPECT_NE(cut.find("cut.exr"), std::string::npos) << cut;
}

TEST(Camera, TheFieldOfViewIsCheckedInTheFilesDegrees) {
    for (const char* fov : {"180", "0", "-5", "200"}) {
        const std::string m = test::errorOf([&] {
            io::parseCameraJson(fmt::format(R"({{"fov_y_deg": {}, "z_near": -0.1, "z_far": null}})", fov), "c.json");
        });
        EXPECT_NE(m.find(fmt::format("c.json: 'fov_y_deg' {} is not in (0, 180) degrees", fov)), std::string::npos)
            << m;
    }
}
