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

// The header's attributes checked against the file before OpenEXR reads them (OpenEXR
// allocates what an attribute's size field claims: 5 KB of file could ask for 2 GiB). The
// layout (OpenEXR file layout, "Header"): magic, version (bit 12: multi-part), then per
// header a list of attributes, name\0 type\0 int32 size, value, ended by an empty name;
// a multi-part file has headers until an empty one.
void checkHeaderSizes(std::span<const std::uint8_t> b, const std::string& name) {
    if (b.size() < 8 || std::memcmp(b.data(), kExrMagic, 4) != 0)
        throw Error(fmt::format("{}: not an EXR file (wrong signature)", name));
    const bool multiPart = (b[5] & 0x10) != 0;  // version field bit 12
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
            if (multiPart && header > 0) return;
            throw Error(fmt::format("{}: corrupt EXR (an empty header)", name));
        }
        while (true) {
            const std::string attr = string("attribute name");
            if (attr.empty()) break;
            const std::string type = string("attribute type");
            if (b.size() - pos < 4) throw Error(fmt::format("{}: file is truncated (in attribute '{}')", name, attr));
            const std::int32_t size = std::int32_t(std::uint32_t(b[pos]) | std::uint32_t(b[pos + 1]) << 8 |
                                                   std::uint32_t(b[pos + 2]) << 16 | std::uint32_t(b[pos + 3]) << 24);
            pos += 4;
            if (size < 0 || std::uint64_t(size) > b.size() - pos)
                throw Error(
                    fmt::format("{}: header attribute '{}' ({}) claims {} bytes, more than the {} left in the "
                                "file",
                                name, attr, type, size, b.size() - pos));
            pos += std::size_t(size);
        }
        if (!multiPart) return;
    }
}

}  // namespace

ImageF decodeExr(std::span<const std::uint8_t> bytes, const std::string& name, const std::string& channel,
                 std::string* channelUsed) {
    checkHeaderSizes(bytes, name);
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
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(fb);
        file.writePixels(h);
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
