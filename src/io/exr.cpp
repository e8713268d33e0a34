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
    MemoryIStream(std::span<const std::uint8_t> bytes, const std::string& name) : Imf::IStream(name.c_str()), b_(bytes) {}
    bool read(char c[], int n) override {
        if (n < 0 || pos_ + std::uint64_t(n) > b_.size()) throw IEX_NAMESPACE::InputExc("file is truncated");
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

}  // namespace

ImageF decodeExr(std::span<const std::uint8_t> bytes, const std::string& name, const std::string& channel,
                 std::string* channelUsed) {
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
            if (header.channels().findChannel(c.name)) throw Error(fmt::format("EXR encoding: channel '{}' twice", c.name));
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

void writeExr(const std::string& path, const std::vector<ExrChannel>& channels) { writeFileAtomic(path, encodeExr(channels)); }

}  // namespace ssfx::io
