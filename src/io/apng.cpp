// APNG: our chunk layer over libpng (APNG 1.0 specification, Mozilla 2008: acTL, fcTL, fdAT).
// Each frame is re-wrapped as a standalone PNG (IHDR with the frame's size, the shared
// pre-IDAT chunks, its data as IDAT) and decoded by libpng; frames are then composed onto
// the canvas with the frame's blend and dispose operations.
#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "png_internal.hpp"
#include "ssfx/io/png.hpp"

namespace ssfx::io {

namespace detail {

std::uint32_t readBe32(const std::uint8_t* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) | p[3];
}
std::uint16_t readBe16(const std::uint8_t* p) { return std::uint16_t((p[0] << 8) | p[1]); }
void appendBe32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) out.push_back(std::uint8_t(v >> s));
}
void appendBe16(std::vector<std::uint8_t>& out, std::uint16_t v) {
    out.push_back(std::uint8_t(v >> 8));
    out.push_back(std::uint8_t(v));
}

void appendChunk(std::vector<std::uint8_t>& out, const char* type, std::span<const std::uint8_t> data) {
    appendBe32(out, std::uint32_t(data.size()));
    const std::size_t typePos = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    const uLong crc = crc32(crc32(0L, Z_NULL, 0), out.data() + typePos, uInt(4 + data.size()));
    appendBe32(out, std::uint32_t(crc));
}

std::vector<Chunk> parseChunks(std::span<const std::uint8_t> bytes, const std::string& name) {
    if (bytes.size() < 8 || std::memcmp(bytes.data(), kPngSignature, 8) != 0)
        throw Error(fmt::format("{}: not a PNG file (wrong signature)", name));
    std::vector<Chunk> chunks;
    std::size_t pos = 8;
    while (true) {
        if (bytes.size() - pos < 12) throw Error(fmt::format("{}: file is truncated (no IEND chunk)", name));
        const std::uint32_t len = readBe32(&bytes[pos]);
        if (len > 0x7FFFFFFFu || len > bytes.size() - pos - 12)
            throw Error(fmt::format("{}: file is truncated or has a corrupt chunk length at byte {}", name, pos));
        Chunk c;
        std::memcpy(c.type, &bytes[pos + 4], 4);
        for (int i = 0; i < 4; ++i)
            if (!std::isalpha(static_cast<unsigned char>(c.type[i])))
                throw Error(fmt::format("{}: corrupt chunk type at byte {}", name, pos));
        c.data = bytes.subspan(pos + 8, len);
        const uLong crc = crc32(crc32(0L, Z_NULL, 0), &bytes[pos + 4], uInt(len + 4));
        if (std::uint32_t(crc) != readBe32(&bytes[pos + 8 + len]))
            throw Error(fmt::format("{}: CRC error in chunk {} at byte {}", name, c.type, pos));
        chunks.push_back(c);
        pos += 12 + std::size_t(len);
        if (c.is("IEND")) return chunks;
    }
}

}  // namespace detail

using namespace detail;

namespace {

struct FrameControl {
    std::uint32_t width, height, x, y;
    std::uint16_t delayNum, delayDen;
    std::uint8_t dispose, blend;
};

enum : std::uint8_t { kDisposeNone = 0, kDisposeBackground = 1, kDisposePrevious = 2 };
enum : std::uint8_t { kBlendSource = 0, kBlendOver = 1 };

// Non-premultiplied "over" (APNG spec, APNG_BLEND_OP_OVER), rounded to 8 bits.
Rgba8 over(Rgba8 src, Rgba8 dst) {
    if (src.a == 255 || dst.a == 0) return src;
    if (src.a == 0) return dst;
    const double sa = src.a / 255.0, da = dst.a / 255.0 * (1.0 - sa);
    const double a = sa + da;
    auto c = [&](std::uint8_t s, std::uint8_t d) {
        return std::uint8_t(std::lround((s * sa + d * da) / a));
    };
    return {c(src.r, dst.r), c(src.g, dst.g), c(src.b, dst.b), std::uint8_t(std::lround(a * 255.0))};
}

}  // namespace

bool isApng(std::span<const std::uint8_t> bytes) {
    try {
        for (const Chunk& c : parseChunks(bytes, "")) {
            if (c.is("acTL")) return true;
            if (c.is("IDAT")) return false;
        }
    } catch (const Error&) {
    }
    return false;
}

Animation decodeApng(std::span<const std::uint8_t> bytes, const std::string& name) {
    const std::vector<Chunk> chunks = parseChunks(bytes, name);
    if (chunks.empty() || !chunks[0].is("IHDR") || chunks[0].data.size() != 13)
        throw Error(fmt::format("{}: corrupt PNG (first chunk is not a valid IHDR)", name));
    const std::uint8_t* ihdr = chunks[0].data.data();
    const std::uint32_t canvasW = readBe32(ihdr), canvasH = readBe32(ihdr + 4);
    checkDimensions(canvasW, canvasH, name);

    // Locate acTL; without one (before IDAT) this is a still PNG.
    std::uint32_t numFrames = 0, numPlays = 0;
    bool animated = false;
    for (const Chunk& c : chunks) {
        if (c.is("IDAT")) break;
        if (c.is("acTL")) {
            if (c.data.size() != 8) throw Error(fmt::format("{}: corrupt acTL chunk", name));
            numFrames = readBe32(c.data.data());
            numPlays = readBe32(c.data.data() + 4);
            animated = true;
        }
    }
    if (!animated) {
        Animation a;
        a.frames.push_back(Frame{decodePng(bytes, name), 1, 25});
        return a;
    }
    if (numFrames == 0) throw Error(fmt::format("{}: APNG declares 0 frames", name));
    // Memory guard: all composed frames together stay under the pixel limit.
    if (std::int64_t(numFrames) * canvasW * canvasH > kMaxPixels)
        throw Error(fmt::format("{}: APNG with {} frames of {}x{} exceeds the limit of {} pixels in all", name,
                                numFrames, canvasW, canvasH, kMaxPixels));

    // Collect frames: their control chunk and their data chunks.
    struct RawFrame {
        FrameControl fc;
        std::vector<std::span<const std::uint8_t>> data;
    };
    std::vector<RawFrame> raw;
    std::vector<const Chunk*> shared;  // PLTE, tRNS, ... copied into every frame's PNG
    bool seenIdat = false, idatIsFrame = false;
    std::uint32_t nextSeq = 0;
    for (const Chunk& c : chunks) {
        if (c.is("IHDR") || c.is("acTL") || c.is("IEND")) continue;
        if (c.is("fcTL")) {
            if (c.data.size() != 26) throw Error(fmt::format("{}: corrupt fcTL chunk", name));
            const std::uint8_t* p = c.data.data();
            if (readBe32(p) != nextSeq++)
                throw Error(fmt::format("{}: APNG sequence numbers out of order at fcTL", name));
            FrameControl fc{readBe32(p + 4), readBe32(p + 8), readBe32(p + 12), readBe32(p + 16),
                            readBe16(p + 20), readBe16(p + 22), p[24], p[25]};
            if (fc.width == 0 || fc.height == 0 || fc.x > canvasW || fc.y > canvasH || fc.width > canvasW - fc.x ||
                fc.height > canvasH - fc.y)
                throw Error(fmt::format("{}: APNG frame {} ({}x{} at {},{}) does not fit the {}x{} canvas", name,
                                        raw.size(), fc.width, fc.height, fc.x, fc.y, canvasW, canvasH));
            if (fc.dispose > 2 || fc.blend > 1)
                throw Error(fmt::format("{}: APNG frame {} has an invalid dispose/blend op", name, raw.size()));
            if (!seenIdat && raw.empty() && (fc.x != 0 || fc.y != 0 || fc.width != canvasW || fc.height != canvasH))
                throw Error(fmt::format("{}: APNG first frame {}x{} differs from the image size {}x{}", name,
                                        fc.width, fc.height, canvasW, canvasH));
            if (!seenIdat) idatIsFrame = true;
            if (raw.size() >= numFrames)
                throw Error(fmt::format("{}: APNG has more frames than the {} its acTL declares", name, numFrames));
            raw.push_back({fc, {}});
        } else if (c.is("IDAT")) {
            seenIdat = true;
            if (idatIsFrame) raw.back().data.push_back(c.data);
        } else if (c.is("fdAT")) {
            if (c.data.size() < 4) throw Error(fmt::format("{}: corrupt fdAT chunk", name));
            if (readBe32(c.data.data()) != nextSeq++)
                throw Error(fmt::format("{}: APNG sequence numbers out of order at fdAT", name));
            if (raw.empty() || (idatIsFrame && raw.size() == 1))
                throw Error(fmt::format("{}: fdAT chunk without its fcTL", name));
            raw.back().data.push_back(c.data.subspan(4));
        } else if (!seenIdat) {
            shared.push_back(&c);
        }
    }
    if (raw.size() != numFrames)
        throw Error(fmt::format("{}: APNG declares {} frames but has {}", name, numFrames, raw.size()));

    Animation anim;
    anim.numPlays = numPlays;
    ImageRgba8 canvas{int(canvasW), int(canvasH)};
    for (std::size_t i = 0; i < raw.size(); ++i) {
        const FrameControl& fc = raw[i].fc;
        if (raw[i].data.empty()) throw Error(fmt::format("{}: APNG frame {} has no image data", name, i));
        std::vector<std::uint8_t> png(kPngSignature, kPngSignature + 8);
        std::vector<std::uint8_t> hdr(ihdr, ihdr + 13);
        hdr[0] = std::uint8_t(fc.width >> 24), hdr[1] = std::uint8_t(fc.width >> 16);
        hdr[2] = std::uint8_t(fc.width >> 8), hdr[3] = std::uint8_t(fc.width);
        hdr[4] = std::uint8_t(fc.height >> 24), hdr[5] = std::uint8_t(fc.height >> 16);
        hdr[6] = std::uint8_t(fc.height >> 8), hdr[7] = std::uint8_t(fc.height);
        appendChunk(png, "IHDR", hdr);
        for (const Chunk* c : shared) appendChunk(png, c->type, c->data);
        for (const auto& d : raw[i].data) appendChunk(png, "IDAT", d);
        appendChunk(png, "IEND", {});
        const ImageRgba8 sub = decodePng(png, fmt::format("{} (frame {})", name, i));

        const ImageRgba8 before = fc.dispose == kDisposePrevious ? canvas : ImageRgba8();
        for (std::uint32_t y = 0; y < fc.height; ++y)
            for (std::uint32_t x = 0; x < fc.width; ++x) {
                Rgba8& d = canvas(int(fc.x + x), int(fc.y + y));
                d = fc.blend == kBlendOver ? over(sub(int(x), int(y)), d) : sub(int(x), int(y));
            }
        anim.frames.push_back(Frame{canvas, fc.delayNum, fc.delayDen});
        // The first frame's "previous" is the cleared canvas (APNG spec).
        if (fc.dispose == kDisposeBackground || (fc.dispose == kDisposePrevious && i == 0)) {
            for (std::uint32_t y = 0; y < fc.height; ++y)
                for (std::uint32_t x = 0; x < fc.width; ++x) canvas(int(fc.x + x), int(fc.y + y)) = Rgba8{};
        } else if (fc.dispose == kDisposePrevious) {
            canvas = before;
        }
    }
    return anim;
}

std::vector<std::uint8_t> encodeApng(const Animation& anim) {
    if (anim.frames.empty()) throw Error("APNG output: no frames");
    const int w = anim.width(), h = anim.height();
    std::vector<std::uint8_t> out(kPngSignature, kPngSignature + 8);
    std::uint32_t seq = 0;
    for (std::size_t i = 0; i < anim.frames.size(); ++i) {
        const Frame& f = anim.frames[i];
        if (f.image.width() != w || f.image.height() != h)
            throw Error(fmt::format("APNG output: frame {} is {}x{}, frame 0 is {}x{}", i, f.image.width(),
                                    f.image.height(), w, h));
        const std::vector<std::uint8_t> png = encodePng(f.image);
        const std::vector<Chunk> chunks = parseChunks(png, "APNG output");
        if (i == 0) {
            appendChunk(out, "IHDR", chunks[0].data);
            std::vector<std::uint8_t> actl;
            appendBe32(actl, std::uint32_t(anim.frames.size()));
            appendBe32(actl, anim.numPlays);
            appendChunk(out, "acTL", actl);
        }
        std::vector<std::uint8_t> fctl;
        appendBe32(fctl, seq++);
        appendBe32(fctl, std::uint32_t(w));
        appendBe32(fctl, std::uint32_t(h));
        appendBe32(fctl, 0);
        appendBe32(fctl, 0);
        appendBe16(fctl, f.delayNum);
        appendBe16(fctl, f.delayDen);
        fctl.push_back(kDisposeNone);
        fctl.push_back(kBlendSource);
        appendChunk(out, "fcTL", fctl);
        for (const Chunk& c : chunks) {
            if (!c.is("IDAT")) continue;
            if (i == 0) {
                appendChunk(out, "IDAT", c.data);
            } else {
                std::vector<std::uint8_t> fdat;
                appendBe32(fdat, seq++);
                fdat.insert(fdat.end(), c.data.begin(), c.data.end());
                appendChunk(out, "fdAT", fdat);
            }
        }
    }
    appendChunk(out, "IEND", {});
    return out;
}

Animation readApng(const std::string& path) {
    const auto bytes = readFile(path);
    return decodeApng(bytes, path);
}

void writeApng(const std::string& path, const Animation& animation) {
    writeFileAtomic(path, encodeApng(animation));
}

}  // namespace ssfx::io
