// OpenEXR reading and writing (see exr.hpp), through in-memory streams so that reads see
// exactly the bytes given and writes go through writeFileAtomic.
#include "ssfx/io/exr.hpp"

#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <exception>

#include "ssfx/io/png.hpp"

namespace ssfx::io {

namespace {

class MemoryIStream : public Imf::IStream {
public:
    MemoryIStream(std::span<const std::uint8_t> bytes, const std::string& name)
        : Imf::IStream(name.c_str()), b_(bytes) {}
    bool read(char c[], int n) override {
        // Written so that it cannot overflow: a corrupt offset table can seek to any 64-bit
        // position, and pos_ + n would wrap around to a small number.
        if (n < 0 || pos_ > b_.size() || std::uint64_t(n) > b_.size() - pos_)
            throw IEX_NAMESPACE::InputExc("file is truncated");
        std::memcpy(c, b_.data() + pos_, std::size_t(n));
        pos_ += std::uint64_t(n);
        return pos_ < b_.size();
    }
    std::uint64_t tellg() override { return pos_; }
    void seekg(std::uint64_t pos) override { pos_ = pos; }

private:
    std::span<const std::uint8_t> b_;
    std::uint64_t pos_ = 0;
};

class MemoryOStream : public Imf::OStream {
public:
    MemoryOStream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {
        if (pos_ + std::uint64_t(n) > out.size()) out.resize(std::size_t(pos_) + std::size_t(n));
        std::memcpy(out.data() + pos_, c, std::size_t(n));
        pos_ += std::uint64_t(n);
    }
    std::uint64_t tellp() override { return pos_; }
    void seekp(std::uint64_t pos) override { pos_ = pos; }
    std::vector<std::uint8_t> out;

private:
    std::uint64_t pos_ = 0;
};

// What checkHeader() learns of a single-part scanline file for checkChunks().
struct HeaderFacts {
    std::size_t end = 0;     // the first byte after the header: the line offset table
    bool scanlines = false;  // single part, not tiled, not deep: the table is checkable
    int compression = -1;    // the "compression" attribute (OpenEXR's enum order)
    std::int64_t width = 0, height = 0;
    std::int64_t bytesPerPixel = 0;  // full-resolution channels only (a lower bound)
};

std::int32_t le32(const std::uint8_t* p) {
    return std::int32_t(std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
                        std::uint32_t(p[3]) << 24);
}

// The header's attributes checked against the file before OpenEXR reads them (OpenEXR
// allocates what an attribute's size field claims: 5 KB of file could ask for 2 GiB). The
// layout (OpenEXR file layout, "Header"): magic, version (bit 9: tiled, 11: deep, 12:
// multi-part), then per header a list of attributes, name\0 type\0 int32 size, value,
// ended by an empty name; a multi-part file has headers until an empty one.
HeaderFacts checkHeader(std::span<const std::uint8_t> b, const std::string& name) {
    if (b.size() < 8 || std::memcmp(b.data(), kExrMagic, 4) != 0)
        throw Error(fmt::format("{}: not an EXR file (wrong signature)", name));
    const bool tiled = (b[5] & 0x02) != 0, deep = (b[5] & 0x08) != 0, multiPart = (b[5] & 0x10) != 0;
    HeaderFacts facts;
    facts.scanlines = !tiled && !deep && !multiPart;
    std::size_t pos = 8;
    auto string = [&](const char* what) {
        const std::size_t start = pos;
        while (pos < b.size() && b[pos] != 0) ++pos;
        if (pos >= b.size()) throw Error(fmt::format("{}: file is truncated (in the header's {})", name, what));
        return std::string(reinterpret_cast<const char*>(&b[start]), pos++ - start);
    };
    for (int header = 0;; ++header) {
        if (pos >= b.size()) throw Error(fmt::format("{}: file is truncated (in the header)", name));
        if (b[pos] == 0) {  // an empty header ends a multi-part file's list
            if (multiPart && header > 0) return facts;
            throw Error(fmt::format("{}: corrupt EXR (an empty header)", name));
        }
        while (true) {
            const std::string attr = string("attribute name");
            if (attr.empty()) break;
            const std::string type = string("attribute type");
            if (b.size() - pos < 4) throw Error(fmt::format("{}: file is truncated (in attribute '{}')", name, attr));
            const std::int32_t size = le32(&b[pos]);
            pos += 4;
            if (size < 0 || std::uint64_t(size) > b.size() - pos)
                throw Error(
                    fmt::format("{}: header attribute '{}' ({}) claims {} bytes, more than the {} left in the "
                                "file",
                                name, attr, type, size, b.size() - pos));
            const std::uint8_t* v = &b[pos];
            if (attr == "compression" && type == "compression" && size == 1) facts.compression = v[0];
            if (attr == "dataWindow" && type == "box2i" && size == 16) {
                facts.width = std::int64_t(le32(v + 8)) - le32(v) + 1;
                facts.height = std::int64_t(le32(v + 12)) - le32(v + 4) + 1;
                // Before OpenEXR sees it: opening the file allocates a scan-line block's buffer
                // for the data window's width (a 140-byte file asked for 2 GiB).
                checkInputDimensions(facts.width, facts.height, name + " (data window)");
            }
            if (attr == "channels" && type == "chlist") {
                // name\0, int32 pixel type (UINT 4, HALF 2, FLOAT 4 bytes), 4 bytes, int32 x and y sampling.
                for (std::size_t c = 0; c < std::size_t(size) && v[c] != 0;) {
                    while (c < std::size_t(size) && v[c] != 0) ++c;
                    if (std::size_t(size) - c < 17) break;
                    const std::int32_t pixelType = le32(v + c + 1);
                    if (le32(v + c + 9) == 1 && le32(v + c + 13) == 1) facts.bytesPerPixel += pixelType == 1 ? 2 : 4;
                    c += 17;
                }
            }
            pos += std::size_t(size);
        }
        if (!multiPart) {
            facts.end = pos;
            return facts;
        }
    }
}

// A scanline file's line offset table checked against the file before any pixel memory is
// allocated (OpenEXR file layout, "Line Offset Tables" and "Scan Line Blocks"): every block
// must lie inside the file, and a block that claims more pixel bytes than its compression
// can produce from its packed size is refused, so that a short file claiming 16384^2 pixels
// costs its own size, not 1 GiB. The ratios are the codecs' ceilings: none 1; RLE 64
// (OpenEXR's runs: 2 bytes for at most 128); ZIP/ZIPS deflate's 1032 (258 bytes per
// 2-bit code), rounded up to 1100. PIZ, PXR24, B44 and DWA are only checked to lie in the file.
void checkChunks(std::span<const std::uint8_t> b, const HeaderFacts& h, const std::string& name) {
    if (!h.scanlines || h.width < 1 || h.height < 1 || h.compression < 0 || h.compression > 9) return;
    static constexpr int kLines[10] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};  // scan lines per block
    static constexpr std::int64_t kRatio[10] = {1, 64, 1100, 1100, 0, 0, 0, 0, 0, 0};
    const int lines = kLines[h.compression];
    const std::int64_t blocks = (h.height + lines - 1) / lines;
    const std::uint64_t tableBytes = std::uint64_t(blocks) * 8;
    if (h.end > b.size() || tableBytes > b.size() - h.end)
        throw Error(
            fmt::format("{}: file is truncated ({} scan-line blocks of {}x{} pixels need an offset table of {} "
                        "bytes; the file has {} after its header)",
                        name, blocks, h.width, h.height, tableBytes, b.size() - std::min(b.size(), h.end)));
    // The table's offsets, or, where an entry is unset (a file whose writer stopped early, or
    // one written before ssfx's table fix), the blocks one after another from the table's
    // end, as OpenEXR reconstructs such a table.
    auto offset = [&](std::int64_t k) {
        const std::uint8_t* e = &b[h.end + std::size_t(k) * 8];
        std::uint64_t at = 0;
        for (int i = 7; i >= 0; --i) at = at << 8 | e[i];
        return at;
    };
    bool table = true;
    for (std::int64_t k = 0; k < blocks && table; ++k) table = offset(k) >= h.end + tableBytes && offset(k) < b.size();
    std::uint64_t next = h.end + tableBytes;
    for (std::int64_t k = 0; k < blocks; ++k) {
        const std::uint64_t at = table ? offset(k) : next;
        const bool inside = at <= b.size() && b.size() - at >= 8;
        const std::int32_t packed = inside ? le32(&b[at + 4]) : -1;
        if (!inside || packed < 0 || std::uint64_t(packed) > b.size() - at - 8)
            throw Error(
                fmt::format("{}: file is truncated or corrupt (scan-line block {} of {} lies past the end of "
                            "the file's {} bytes)",
                            name, k, blocks, b.size()));
        next = at + 8 + std::uint64_t(packed);
        const std::int64_t rows = std::min<std::int64_t>(lines, h.height - k * lines);
        const std::int64_t raw = h.width * rows * h.bytesPerPixel;
        if (kRatio[h.compression] > 0 && std::int64_t(packed) * kRatio[h.compression] < raw)
            throw Error(
                fmt::format("{}: corrupt EXR (scan-line block {} packs {} bytes of pixels into {}, more than "
                            "its compression can)",
                            name, k, raw, packed));
    }
}

}  // namespace

ImageF decodeExr(std::span<const std::uint8_t> bytes, const std::string& name, const std::string& channel,
                 std::string* channelUsed) {
    const HeaderFacts facts = checkHeader(bytes, name);
    // The blocks too, before OpenEXR opens the file (it sizes its buffers by the header).
    checkChunks(bytes, facts, name);
    try {
        MemoryIStream stream(bytes, name);
        Imf::InputFile file(stream);
        const Imath::Box2i dw = file.header().dataWindow();
        const std::int64_t w = std::int64_t(dw.max.x) - dw.min.x + 1, h = std::int64_t(dw.max.y) - dw.min.y + 1;
        checkInputDimensions(w, h, name);
        const Imf::ChannelList& channels = file.header().channels();
        std::string pick = channel;
        if (pick.empty()) {
            for (const char* c : {"Z", "Y", "R", "A"})
                if (channels.findChannel(c)) {
                    pick = c;
                    break;
                }
            if (pick.empty()) {
                auto it = channels.begin();
                if (it != channels.end() && ++Imf::ChannelList::ConstIterator(it) == channels.end()) pick = it.name();
            }
            if (pick.empty()) throw Error(fmt::format("{}: no Z, Y, R or A channel, and more than one channel", name));
        } else if (!channels.findChannel(pick)) {
            throw Error(fmt::format("{}: no channel '{}'", name, pick));
        }
        const Imf::Channel* ch = channels.findChannel(pick);
        if (ch->xSampling != 1 || ch->ySampling != 1)
            throw Error(fmt::format("{}: channel '{}' is subsampled, which is not supported", name, pick));
        ImageF img{int(w), int(h)};
        Imf::FrameBuffer fb;
        // The slice's base is the address of pixel (0, 0) of the data window's coordinate system.
        char* base = reinterpret_cast<char*>(img.data()) -
                     (std::ptrdiff_t(dw.min.x) + std::ptrdiff_t(dw.min.y) * w) * std::ptrdiff_t(sizeof(float));
        fb.insert(pick, Imf::Slice(Imf::FLOAT, base, sizeof(float), std::size_t(w) * sizeof(float)));
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        if (channelUsed) *channelUsed = pick;
        return img;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(fmt::format("{}: corrupt or unreadable EXR ({})", name, e.what()));
    }
}

ImageF readExr(const std::string& path, const std::string& channel, std::string* channelUsed) {
    const auto bytes = readFile(path, kMaxExrFileBytes, "EXR", kExrMagic);
    return decodeExr(bytes, path, channel, channelUsed);
}

std::vector<std::uint8_t> encodeExr(ImageView<const float> image, const std::string& channel) {
    return encodeExr(std::vector<ExrChannel>{{channel, image}});
}

std::vector<std::uint8_t> encodeExr(const std::vector<ExrChannel>& channels) {
    if (channels.empty()) throw Error("EXR encoding: no channels");
    const int w = channels[0].image.width(), h = channels[0].image.height();
    checkDimensions(w, h, "EXR image");
    for (const auto& c : channels)
        if (c.image.width() != w || c.image.height() != h)
            throw Error(fmt::format("EXR encoding: channel '{}' is {}x{}, not {}x{}", c.name, c.image.width(),
                                    c.image.height(), w, h));
    try {
        Imf::Header header(w, h);
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::FrameBuffer fb;
        for (const auto& c : channels) {
            if (header.channels().findChannel(c.name))
                throw Error(fmt::format("EXR encoding: channel '{}' twice", c.name));
            header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
            fb.insert(c.name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(c.image.data())),
                                         sizeof(float), std::size_t(c.image.stride()) * sizeof(float)));
        }
        MemoryOStream stream;
        {
            // The file's destructor writes the line offset table (seeking back to it): the
            // bytes are complete only after it has run.
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(fb);
            file.writePixels(h);
        }
        return std::move(stream.out);
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(fmt::format("EXR encoding failed ({})", e.what()));
    }
}

void writeExr(const std::string& path, ImageView<const float> image, const std::string& channel) {
    // Encode fully before touching the file: an error leaves any existing file intact.
    const auto bytes = encodeExr(image, channel);
    writeFileAtomic(path, bytes);
}

void writeExr(const std::string& path, const std::vector<ExrChannel>& channels) {
    writeFileAtomic(path, encodeExr(channels));
}

}  // namespace ssfx::io
