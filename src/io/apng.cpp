// APNG: our chunk layer over libpng (APNG 1.0 specification, Mozilla 2008: acTL, fcTL, fdAT).
// Frames are read one at a time (ApngReader): each is re-wrapped as a standalone PNG (IHDR
// with the frame's size, the PLTE and tRNS chunks that decoding needs, its data as IDAT) and
// decoded by libpng, then composed onto the canvas with the frame's blend and dispose
// operations. Other ancillary chunks (tEXt, iCCP, ...) are checked and skipped, never
// copied per frame, so the time is linear in the file size.
#include <fmt/format.h>
#include <zlib.h>

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "src/io/png_internal.hpp"
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

std::uint64_t& apngBytesDecoded() {
    thread_local std::uint64_t n = 0;
    return n;
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
    auto c = [&](std::uint8_t s, std::uint8_t d) { return std::uint8_t(std::lround((s * sa + d * da) / a)); };
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

// ---- the streaming reader ------------------------------------------------------------

namespace {

struct OwnedChunk {
    char type[5] = {};
    std::vector<std::uint8_t> data;
    std::uint64_t at = 0;  //!< byte offset of the chunk in the file
    bool is(const char* t) const { return std::memcmp(type, t, 4) == 0; }
};

}  // namespace

struct ApngReader::Impl {
    std::string name;
    std::FILE* file = nullptr;             // a file source, or
    std::span<const std::uint8_t> memory;  // a memory source
    std::uint64_t pos = 0;                 // bytes consumed
    std::uint64_t size = UINT64_MAX;       // known size (memory, regular files), else unbounded
    std::uint8_t ihdr[13] = {};
    std::uint32_t canvasW = 0, canvasH = 0, numFrames = 1, numPlays = 0;
    bool animated = false;
    std::vector<OwnedChunk> decodeChunks;  // PLTE and tRNS: all that decodePng() reads besides IHDR/IDAT
    OwnedChunk pending;                    // read ahead: the chunk that starts the next frame
    bool hasPending = false, seenIdat = false, idatIsFrame = false, ended = false;
    std::uint32_t nextSeq = 0, framesSeen = 0;  // fcTL chunks so far
    Frame current;                              // current.image is the canvas
    ImageRgba8 before;                          // the canvas before a dispose-previous frame
    FrameControl last{};
    bool haveLast = false;

    ~Impl() {
        if (file) std::fclose(file);
    }

    // Reads up to n bytes; returns how many (fewer only at the end of the source).
    std::size_t read(std::uint8_t* dst, std::size_t n) {
        std::size_t got;
        if (file) {
            got = std::fread(dst, 1, n, file);
            if (got < n && std::ferror(file)) throw Error(fmt::format("{}: read error", name));
        } else {
            got = std::size_t(std::min<std::uint64_t>(n, memory.size() - pos));
            std::memcpy(dst, memory.data() + pos, got);
        }
        pos += got;
        return got;
    }

    // One chunk with its CRC checked (the messages of parseChunks()). The payload grows as
    // it arrives, in 1 MiB steps, so a corrupt length costs no more memory than the bytes
    // that are really there.
    void readChunk(OwnedChunk& c) {
        const std::uint64_t at = pos;
        std::uint8_t head[8];
        if (size - pos < 12 || read(head, 8) < 8)
            throw Error(fmt::format("{}: file is truncated (no IEND chunk)", name));
        const std::uint32_t len = readBe32(head);
        if (len > 0x7FFFFFFFu || len > size - at - 12)
            throw Error(fmt::format("{}: file is truncated or has a corrupt chunk length at byte {}", name, at));
        std::memcpy(c.type, head + 4, 4);
        c.at = at;
        for (int i = 0; i < 4; ++i)
            if (!std::isalpha(static_cast<unsigned char>(c.type[i])))
                throw Error(fmt::format("{}: corrupt chunk type at byte {}", name, at));
        c.data.clear();
        for (std::uint32_t done = 0; done < len;) {
            const std::uint32_t step = std::min<std::uint32_t>(len - done, 1u << 20);
            c.data.resize(done + step);
            if (read(c.data.data() + done, step) < step)
                throw Error(fmt::format("{}: file is truncated or has a corrupt chunk length at byte {}", name, at));
            done += step;
        }
        std::uint8_t crcBytes[4];
        if (read(crcBytes, 4) < 4) throw Error(fmt::format("{}: file is truncated (no IEND chunk)", name));
        uLong crc = crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(c.type), 4);
        if (!c.data.empty()) crc = crc32(crc, c.data.data(), uInt(c.data.size()));  // a null buffer would reset it
        if (std::uint32_t(crc) != readBe32(crcBytes))
            throw Error(fmt::format("{}: CRC error in chunk {} at byte {}", name, c.type, at));
    }

    OwnedChunk nextChunk() {
        if (hasPending) {
            hasPending = false;
            return std::move(pending);
        }
        OwnedChunk c;
        readChunk(c);
        return c;
    }

    void open() {
        std::uint8_t sig[8];
        if (read(sig, 8) < 8 || std::memcmp(sig, kPngSignature, 8) != 0)
            throw Error(fmt::format("{}: not a PNG file (wrong signature)", name));
        OwnedChunk c;
        readChunk(c);
        if (!c.is("IHDR") || c.data.size() != 13)
            throw Error(fmt::format("{}: corrupt PNG (first chunk is not a valid IHDR)", name));
        std::memcpy(ihdr, c.data.data(), 13);
        canvasW = readBe32(ihdr), canvasH = readBe32(ihdr + 4);
        checkInputDimensions(canvasW, canvasH, name);
        // The chunks before the image data: acTL makes it an APNG; keep PLTE and tRNS.
        while (true) {
            readChunk(c);
            if (c.is("IDAT") || c.is("fcTL")) break;
            if (c.is("IEND")) throw Error(fmt::format("{}: no image data (IDAT) before IEND", name));
            if (c.is("acTL")) {
                if (c.data.size() != 8) throw Error(fmt::format("{}: corrupt acTL chunk", name));
                numFrames = readBe32(c.data.data());
                numPlays = readBe32(c.data.data() + 4);
                animated = true;
            } else if (c.is("PLTE") || c.is("tRNS")) {
                decodeChunks.push_back(std::move(c));
                c = OwnedChunk{};
            }
        }
        pending = std::move(c), hasPending = true;
        if (!animated) numFrames = 1;
        if (animated && numFrames == 0) throw Error(fmt::format("{}: APNG declares 0 frames", name));
        if (numFrames > kMaxApngFrames)
            throw Error(
                fmt::format("{}: APNG declares {} frames, more than the limit of {}", name, numFrames, kMaxApngFrames));
        current.image = ImageRgba8(int(canvasW), int(canvasH));
    }

    // A standalone PNG of one frame's data, decoded by libpng.
    ImageRgba8 decodeFrame(std::uint32_t w, std::uint32_t h, const std::vector<OwnedChunk>& data, std::size_t index) {
        std::vector<std::uint8_t> png(kPngSignature, kPngSignature + 8);
        std::vector<std::uint8_t> hdr(ihdr, ihdr + 13);
        for (int k = 0; k < 4; ++k)
            hdr[std::size_t(k)] = std::uint8_t(w >> (24 - 8 * k)),
            hdr[std::size_t(4 + k)] = std::uint8_t(h >> (24 - 8 * k));
        appendChunk(png, "IHDR", hdr);
        for (const OwnedChunk& c : decodeChunks) appendChunk(png, c.type, c.data);
        for (const OwnedChunk& d : data) appendChunk(png, "IDAT", d.data);
        appendChunk(png, "IEND", {});
        apngBytesDecoded() += png.size();
        return decodePng(png, animated ? fmt::format("{} (frame {})", name, index) : name);
    }

    const Frame* nextStill() {
        std::vector<OwnedChunk> data;
        bool dataEnded = false;  // PNG: the IDAT chunks are consecutive
        while (true) {
            OwnedChunk c = nextChunk();
            if (c.is("IEND")) break;
            if (c.is("IDAT")) {
                if (dataEnded) throw Error(fmt::format("{}: IDAT chunks are not consecutive", name));
                data.push_back(std::move(c));
            } else {
                dataEnded = !data.empty();
            }
        }
        ended = true;
        current.image = decodeFrame(canvasW, canvasH, data, 0);
        current.delayNum = 1, current.delayDen = 25;
        return &current;
    }

    const Frame* next() {
        if (ended) return nullptr;
        if (!animated) return nextStill();
        // Dispose of the frame returned last (APNG: after it was shown, before the next one).
        ImageRgba8& canvas = current.image;
        if (haveLast) {
            const FrameControl& fc = last;
            // The first frame's "previous" is the cleared canvas (APNG spec).
            if (fc.dispose == kDisposeBackground || (fc.dispose == kDisposePrevious && framesSeen == 1)) {
                for (std::uint32_t y = 0; y < fc.height; ++y)
                    for (std::uint32_t x = 0; x < fc.width; ++x) canvas(int(fc.x + x), int(fc.y + y)) = Rgba8{};
            } else if (fc.dispose == kDisposePrevious) {
                canvas = std::move(before);
            }
        }
        // This frame's fcTL, skipping what precedes it (an IDAT that is not part of the animation).
        FrameControl fc{};
        bool haveFc = false;
        std::vector<OwnedChunk> data;
        while (true) {
            OwnedChunk c = nextChunk();
            if (c.is("IEND")) {
                if (framesSeen != numFrames)
                    throw Error(fmt::format("{}: APNG declares {} frames but has {}", name, numFrames, framesSeen));
                ended = true;
                if (!haveFc) return nullptr;
                break;
            }
            if (c.is("fcTL")) {
                if (haveFc) {  // the next frame starts: read ahead
                    pending = std::move(c), hasPending = true;
                    break;
                }
                if (c.data.size() != 26) throw Error(fmt::format("{}: corrupt fcTL chunk", name));
                const std::uint8_t* p = c.data.data();
                if (readBe32(p) != nextSeq++)
                    throw Error(fmt::format("{}: APNG sequence numbers out of order at fcTL", name));
                fc = {readBe32(p + 4),
                      readBe32(p + 8),
                      readBe32(p + 12),
                      readBe32(p + 16),
                      readBe16(p + 20),
                      readBe16(p + 22),
                      p[24],
                      p[25]};
                const std::uint32_t index = framesSeen;
                if (fc.width == 0 || fc.height == 0 || fc.x > canvasW || fc.y > canvasH || fc.width > canvasW - fc.x ||
                    fc.height > canvasH - fc.y)
                    throw Error(fmt::format("{}: APNG frame {} ({}x{} at {},{}) does not fit the {}x{} canvas", name,
                                            index, fc.width, fc.height, fc.x, fc.y, canvasW, canvasH));
                if (fc.dispose > 2 || fc.blend > 1)
                    throw Error(fmt::format("{}: APNG frame {} has an invalid dispose/blend op", name, index));
                if (!seenIdat && index == 0 && (fc.x != 0 || fc.y != 0 || fc.width != canvasW || fc.height != canvasH))
                    throw Error(fmt::format("{}: APNG first frame {}x{} differs from the image size {}x{}", name,
                                            fc.width, fc.height, canvasW, canvasH));
                if (!seenIdat) idatIsFrame = true;
                if (index >= numFrames)
                    throw Error(fmt::format("{}: APNG has more frames than the {} its acTL declares", name, numFrames));
                ++framesSeen;
                haveFc = true;
            } else if (c.is("IDAT")) {
                seenIdat = true;
                if (idatIsFrame && haveFc && framesSeen == 1) data.push_back(std::move(c));
            } else if (c.is("fdAT")) {
                if (c.data.size() < 4) throw Error(fmt::format("{}: corrupt fdAT chunk", name));
                if (readBe32(c.data.data()) != nextSeq++)
                    throw Error(fmt::format("{}: APNG sequence numbers out of order at fdAT", name));
                if (!haveFc || (idatIsFrame && framesSeen == 1))
                    throw Error(fmt::format("{}: fdAT chunk without its fcTL", name));
                c.data.erase(c.data.begin(), c.data.begin() + 4);
                data.push_back(std::move(c));
            } else if (!seenIdat && (c.is("PLTE") || c.is("tRNS"))) {
                decodeChunks.push_back(std::move(c));
            }
        }
        const std::size_t index = framesSeen - 1;
        if (data.empty()) throw Error(fmt::format("{}: APNG frame {} has no image data", name, index));
        if (fc.width == canvasW && fc.height == canvasH && fc.blend == kBlendSource && fc.dispose != kDisposePrevious) {
            // The frame replaces the whole canvas: free it first, so that one canvas-sized
            // image is in memory at a time (a 4800x4800 frame is 92 MB).
            canvas = ImageRgba8();
            canvas = decodeFrame(fc.width, fc.height, data, index);
            current.delayNum = fc.delayNum, current.delayDen = fc.delayDen;
            last = fc, haveLast = true;
            return &current;
        }
        const ImageRgba8 sub = decodeFrame(fc.width, fc.height, data, index);
        if (fc.dispose == kDisposePrevious) before = canvas;
        for (std::uint32_t y = 0; y < fc.height; ++y)
            for (std::uint32_t x = 0; x < fc.width; ++x) {
                Rgba8& d = canvas(int(fc.x + x), int(fc.y + y));
                d = fc.blend == kBlendOver ? over(sub(int(x), int(y)), d) : sub(int(x), int(y));
            }
        current.delayNum = fc.delayNum, current.delayDen = fc.delayDen;
        last = fc, haveLast = true;
        return &current;
    }
};

ApngReader::ApngReader(const std::string& path) : impl_(std::make_unique<Impl>()) {
    impl_->name = path;
    checkPath(path);
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw Error(fmt::format("{}: is a directory, not a PNG file", path));
    impl_->file = std::fopen(path.c_str(), "rb");
    if (!impl_->file) throw Error(fmt::format("{}: cannot open for reading ({})", path, std::strerror(errno)));
    struct stat st {};
    if (::fstat(::fileno(impl_->file), &st) == 0 && S_ISREG(st.st_mode)) impl_->size = std::uint64_t(st.st_size);
    impl_->open();
}

ApngReader::ApngReader(std::span<const std::uint8_t> bytes, const std::string& name) : impl_(std::make_unique<Impl>()) {
    impl_->name = name;
    impl_->memory = bytes;
    impl_->size = bytes.size();
    impl_->open();
}

ApngReader::~ApngReader() = default;
ApngReader::ApngReader(ApngReader&&) noexcept = default;
ApngReader& ApngReader::operator=(ApngReader&&) noexcept = default;
int ApngReader::width() const { return int(impl_->canvasW); }
int ApngReader::height() const { return int(impl_->canvasH); }
bool ApngReader::animated() const { return impl_->animated; }
std::uint32_t ApngReader::frameCount() const { return impl_->numFrames; }
std::uint32_t ApngReader::numPlays() const { return impl_->numPlays; }
const Frame* ApngReader::next() { return impl_->next(); }

namespace {

// The whole-file readers: every frame in memory, so all frames together stay under the
// pixel limit (checked from the header, before any frame is decoded).
Animation readAll(ApngReader& r, const std::string& name) {
    if (r.animated() && std::int64_t(r.frameCount()) * r.width() * r.height() > maxPixels())
        throw Error(fmt::format("{}: APNG with {} frames of {}x{} exceeds the limit of {} pixels in all", name,
                                r.frameCount(), r.width(), r.height(), maxPixels()));
    Animation anim;
    anim.numPlays = r.numPlays();
    while (const Frame* f = r.next())
        anim.frames.push_back(Frame{ImageRgba8::copyOf(f->image.view()), f->delayNum, f->delayDen});
    return anim;
}

}  // namespace

Animation decodeApng(std::span<const std::uint8_t> bytes, const std::string& name) {
    ApngReader r(bytes, name);
    return readAll(r, name);
}

namespace {

// The signature, IHDR (8-bit RGBA, as encodePng() writes it) and acTL of an APNG.
std::vector<std::uint8_t> apngHeader(int width, int height, std::uint32_t frames, std::uint32_t numPlays) {
    std::vector<std::uint8_t> out(kPngSignature, kPngSignature + 8), ihdr, actl;
    appendBe32(ihdr, std::uint32_t(width)), appendBe32(ihdr, std::uint32_t(height));
    for (std::uint8_t b : {8, 6, 0, 0, 0}) ihdr.push_back(b);  // depth 8, RGBA, deflate, filter 0, no interlace
    appendChunk(out, "IHDR", ihdr);
    appendBe32(actl, frames), appendBe32(actl, numPlays);
    appendChunk(out, "acTL", actl);
    return out;
}

// One frame stored whole (dispose none, blend source): its fcTL, then its data as IDAT for
// the first frame and as fdAT after; `seq` is the next sequence number.
void appendFrame(std::vector<std::uint8_t>& out, ImageView<const Rgba8> image, std::uint16_t delayNum,
                 std::uint16_t delayDen, bool first, std::uint32_t& seq) {
    const std::vector<std::uint8_t> png = encodePng(image);
    std::vector<std::uint8_t> fctl;
    appendBe32(fctl, seq++);
    appendBe32(fctl, std::uint32_t(image.width())), appendBe32(fctl, std::uint32_t(image.height()));
    appendBe32(fctl, 0), appendBe32(fctl, 0);
    appendBe16(fctl, delayNum), appendBe16(fctl, delayDen);
    fctl.push_back(kDisposeNone), fctl.push_back(kBlendSource);
    appendChunk(out, "fcTL", fctl);
    for (const Chunk& c : parseChunks(png, "APNG output")) {
        if (!c.is("IDAT")) continue;
        if (first) {
            appendChunk(out, "IDAT", c.data);
        } else {
            std::vector<std::uint8_t> fdat;
            appendBe32(fdat, seq++);
            fdat.insert(fdat.end(), c.data.begin(), c.data.end());
            appendChunk(out, "fdAT", fdat);
        }
    }
}

}  // namespace

std::vector<std::uint8_t> encodeApng(const Animation& anim) {
    if (anim.frames.empty()) throw Error("APNG output: no frames");
    const int w = anim.width(), h = anim.height();
    std::vector<std::uint8_t> out = apngHeader(w, h, std::uint32_t(anim.frames.size()), anim.numPlays);
    std::uint32_t seq = 0;
    for (std::size_t i = 0; i < anim.frames.size(); ++i) {
        const Frame& f = anim.frames[i];
        if (f.image.width() != w || f.image.height() != h)
            throw Error(fmt::format("APNG output: frame {} is {}x{}, frame 0 is {}x{}", i, f.image.width(),
                                    f.image.height(), w, h));
        appendFrame(out, f.image.view(), f.delayNum, f.delayDen, i == 0, seq);
    }
    appendChunk(out, "IEND", {});
    return out;
}

Animation readApng(const std::string& path) {
    ApngReader r(path);
    return readAll(r, path);
}

void writeApng(const std::string& path, const Animation& animation) { writeFileAtomic(path, encodeApng(animation)); }

// ---- the streaming writer ------------------------------------------------------------

ApngWriter::ApngWriter(const std::string& path, int width, int height, std::uint32_t frames, std::uint32_t numPlays)
    : file_(path), width_(width), height_(height), frames_(frames) {
    checkDimensions(width, height, path);
    if (frames < 1 || frames > kMaxApngFrames)
        throw Error(fmt::format("{}: an APNG of {} frames (1..{})", path, frames, kMaxApngFrames));
    file_.write(apngHeader(width, height, frames, numPlays));
}

ApngWriter::~ApngWriter() = default;

void ApngWriter::add(ImageView<const Rgba8> image, std::uint16_t delayNum, std::uint16_t delayDen) {
    if (image.width() != width_ || image.height() != height_)
        throw Error(fmt::format("{}: frame {} is {}x{}, the animation {}x{}", file_.path(), added_, image.width(),
                                image.height(), width_, height_));
    if (added_ >= frames_) throw Error(fmt::format("{}: more than the {} frames declared", file_.path(), frames_));
    std::vector<std::uint8_t> out;
    appendFrame(out, image, delayNum, delayDen, added_ == 0, seq_);
    file_.write(out);
    ++added_;
}

void ApngWriter::commit() {
    if (added_ != frames_)
        throw Error(fmt::format("{}: {} of the {} declared frames were written", file_.path(), added_, frames_));
    std::vector<std::uint8_t> out;
    appendChunk(out, "IEND", {});
    file_.write(out);
    file_.commit();
}

}  // namespace ssfx::io
