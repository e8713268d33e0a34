// APNG: our chunk layer (acTL/fcTL/fdAT) around libpng-coded frames.
#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>

#include "src/io/png_internal.hpp"
#include "ssfx/io/png.hpp"
#include "tests/support/test_support.hpp"

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

// ---- the streaming reader and writer -------------------------------------------------

namespace {
std::string tempPath(const std::string& name) {
    const std::string dir = std::string(SSFX_TEST_OUT_DIR) + "/apng";
    std::filesystem::create_directories(dir);
    return dir + "/" + name;
}
}  // namespace

TEST(ApngStream, ReaderGivesTheWholeFileReadersFramesFromMemoryAndFromAFile) {
    for (const auto& bytes : {handMadeApng(1, 1, {0, 0, 255, 128}), handMadeApng(0, 2, {9, 8, 7, 255})}) {
        const io::Animation whole = io::decodeApng(bytes, "x");
        const std::string path = tempPath("stream.png");
        io::writeFileAtomic(path, bytes);
        for (int source = 0; source < 2; ++source) {
            io::ApngReader r = source == 0 ? io::ApngReader(bytes, "mem") : io::ApngReader(path);
            EXPECT_TRUE(r.animated());
            EXPECT_EQ(r.frameCount(), 2u);
            EXPECT_EQ(r.width(), 4);
            std::size_t n = 0;
            while (const io::Frame* f = r.next()) {
                ASSERT_LT(n, whole.frames.size());
                EXPECT_EQ(f->image, whole.frames[n].image) << n;
                EXPECT_EQ(f->delayDen, whole.frames[n].delayDen);
                ++n;
            }
            EXPECT_EQ(n, 2u);
            EXPECT_EQ(r.next(), nullptr);
        }
    }
    // A still PNG is one frame.
    const auto img = test::noise(5, 3, 2);
    const auto stillBytes = io::encodePng(img.view());  // a memory reader reads them as it goes
    io::ApngReader still(stillBytes, "still");
    EXPECT_FALSE(still.animated());
    const io::Frame* f = still.next();
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->image, img);
    EXPECT_EQ(still.next(), nullptr);
}

TEST(ApngStream, WriterWritesWhatTheWholeFileEncoderWritesAndOnlyAtCommit) {
    io::Animation a;
    a.numPlays = 2;
    for (int i = 0; i < 3; ++i) a.frames.push_back({test::noise(6, 5, unsigned(i + 7)), std::uint16_t(i + 1), 30});
    const std::string path = tempPath("written.png");
    std::filesystem::remove(path);
    {
        io::ApngWriter w(path, 6, 5, 3, 2);
        for (const auto& fr : a.frames) w.add(fr.image.view(), fr.delayNum, fr.delayDen);
        EXPECT_FALSE(std::filesystem::exists(path));  // nothing at the target before the commit
        w.commit();
    }
    EXPECT_EQ(io::readFile(path, io::kMaxImageFileBytes, "PNG"), io::encodeApng(a));
    // Too few frames: commit() refuses, and an abandoned writer leaves the old file intact
    // and no temporary behind.
    {
        io::ApngWriter w(path, 6, 5, 3);
        w.add(a.frames[0].image.view());
        EXPECT_THROW(w.commit(), Error);
    }
    {
        io::ApngWriter w(path, 6, 5, 3);
        EXPECT_THROW(w.add(ImageRgba8(5, 5).view()), Error);  // wrong size
    }
    EXPECT_EQ(io::readFile(path, io::kMaxImageFileBytes, "PNG"), io::encodeApng(a));
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(path).parent_path()))
        files += e.path().filename().string().find("written") != std::string::npos;
    EXPECT_EQ(files, 1);
}

TEST(ApngStream, AncillaryChunksAreNotCopiedIntoEveryFrame) {
    // 4,000 1x1 frames after a 4 MB tEXt chunk (before the image data): the reader used to
    // wrap every frame with every chunk before IDAT, 16 GB of copying and CRCs (170 s); now
    // each frame's PNG is IHDR + its data + IEND, so the bytes handed to libpng stay a few
    // dozen per frame (counted by the reader's test hook, not timed).
    const int frames = 4000;
    std::vector<std::uint8_t> out(kPngSignature, kPngSignature + 8);
    const auto png = io::encodePng(ImageRgba8(1, 1, Rgba8{1, 2, 3, 255}).view());
    const auto chunks = parseChunks(png, "f");
    appendChunk(out, "IHDR", chunks[0].data);
    std::vector<std::uint8_t> actl;
    appendBe32(actl, frames), appendBe32(actl, 0);
    appendChunk(out, "acTL", actl);
    std::vector<std::uint8_t> text(std::size_t(4) << 20, 'a');
    text[7] = 0;  // keyword "aaaaaaa", then the text
    appendChunk(out, "tEXt", text);
    std::uint32_t seq = 0;
    for (int i = 0; i < frames; ++i) {
        std::vector<std::uint8_t> f;
        appendBe32(f, seq++), appendBe32(f, 1), appendBe32(f, 1), appendBe32(f, 0), appendBe32(f, 0);
        appendBe16(f, 1), appendBe16(f, 25), f.push_back(0), f.push_back(0);
        appendChunk(out, "fcTL", f);
        for (const auto& c : chunks)
            if (c.is("IDAT")) {
                if (i == 0) {
                    appendChunk(out, "IDAT", c.data);
                } else {
                    std::vector<std::uint8_t> d;
                    appendBe32(d, seq++);
                    d.insert(d.end(), c.data.begin(), c.data.end());
                    appendChunk(out, "fdAT", d);
                }
            }
    }
    appendChunk(out, "IEND", {});
    const std::uint64_t before = apngBytesDecoded();
    const io::Animation a = io::decodeApng(out, "text.png");
    ASSERT_EQ(a.frames.size(), std::size_t(frames));
    EXPECT_EQ(a.frames.back().image(0, 0), (Rgba8{1, 2, 3, 255}));
    const std::uint64_t perFrame = (apngBytesDecoded() - before) / frames;
    EXPECT_LE(perFrame, 100u);
}

TEST(ApngStream, FrameCountAboveTheLimitIsRefusedFromTheHeader) {
    auto bytes = handMadeApng(0, 0, {0, 0, 255, 255});
    // acTL payload: after signature (8) + IHDR (25) + acTL length/type (8).
    const std::uint32_t n = io::kMaxApngFrames + 1;
    for (int i = 0; i < 4; ++i) bytes[8 + 25 + 8 + std::size_t(i)] = std::uint8_t(n >> (24 - 8 * i));
    const uLong crc = crc32(crc32(0, Z_NULL, 0), &bytes[8 + 25 + 4], 12);
    for (int i = 0; i < 4; ++i) bytes[8 + 25 + 16 + std::size_t(i)] = std::uint8_t(crc >> (24 - 8 * i));
    try {
        io::ApngReader r(bytes, "many.png");
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("limit of 100000"), std::string::npos) << e.what();
    }
}

TEST(ApngStream, ErrorsAfterSomeFramesLeaveTheEarlierFramesComplete) {
    // Cut the file inside frame 1's data: frame 0 comes out whole, then a clear error.
    const auto full = handMadeApng(0, 0, {0, 0, 255, 255});
    const std::vector<std::uint8_t> cut(full.begin(), full.end() - 20);
    io::ApngReader r(cut, "cut.png");
    const io::Frame* f = r.next();
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->image, ImageRgba8(4, 4, Rgba8{255, 0, 0, 255}));
    try {
        r.next();
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cut.png"), std::string::npos) << e.what();
    }
}
