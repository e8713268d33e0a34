// Still PNG through libpng. libpng reports errors by longjmp; each phase that can fail runs
// in a function whose frame holds no C++ objects, so no destructor is skipped.
#include <fmt/format.h>
#include <png.h>

#include <csetjmp>
#include <cstring>

#include "ssfx/io/png.hpp"

namespace ssfx::io {

namespace {

struct ReadState {
    const std::uint8_t* data;
    std::size_t size;
    std::size_t pos;
    char message[256];
};

void readCallback(png_structp png, png_bytep out, png_size_t n) {
    auto* s = static_cast<ReadState*>(png_get_io_ptr(png));
    if (n > s->size - s->pos) png_error(png, "file is truncated");
    std::memcpy(out, s->data + s->pos, n);
    s->pos += n;
}

void errorCallback(png_structp png, png_const_charp msg) {
    auto* s = static_cast<ReadState*>(png_get_error_ptr(png));
    std::snprintf(s->message, sizeof s->message, "%s", msg);
    png_longjmp(png, 1);
}
void warningCallback(png_structp, png_const_charp) {}  // warnings (e.g. iCCP) are not errors

// Phase 1: header and transforms. Returns false on a libpng error (message in state).
bool readHeader(png_structp png, png_infop info, png_uint_32* w, png_uint_32* h) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_user_limits(png, kMaxDimension, kMaxDimension);
    png_read_info(png, info);
    *w = png_get_image_width(png, info);
    *h = png_get_image_height(png, info);
    const int colorType = png_get_color_type(png, info);
    const int bitDepth = png_get_bit_depth(png, info);
    // The conversion rule documented in png.hpp.
    if (bitDepth == 16) png_set_scale_16(png);
    if (colorType == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (colorType == PNG_COLOR_TYPE_GRAY && bitDepth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
    if (colorType == PNG_COLOR_TYPE_GRAY || colorType == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
    png_set_filler(png, 0xFF, PNG_FILLER_AFTER);  // adds alpha = 255 where there is none
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    return png_get_rowbytes(png, info) == *w * 4u;
}

// Phase 2: pixels.
bool readPixels(png_structp png, png_infop info, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, info);
    return true;
}

struct WriteState {
    std::vector<std::uint8_t>* out;
    char message[256];
};
void writeCallback(png_structp png, png_bytep data, png_size_t n) {
    auto* s = static_cast<WriteState*>(png_get_io_ptr(png));
    s->out->insert(s->out->end(), data, data + n);
}
void flushCallback(png_structp) {}
void writeErrorCallback(png_structp png, png_const_charp msg) {
    auto* s = static_cast<WriteState*>(png_get_error_ptr(png));
    std::snprintf(s->message, sizeof s->message, "%s", msg);
    png_longjmp(png, 1);
}

bool writeAll(png_structp png, png_infop info, int w, int h, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_IHDR(png, info, png_uint_32(w), png_uint_32(h), 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // Level 6 is libpng's default trade-off; outputs here are test data, not archives.
    png_set_compression_level(png, 6);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, info);
    return true;
}

}  // namespace

ImageRgba8 decodePng(std::span<const std::uint8_t> bytes, const std::string& name) {
    if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0)
        throw Error(fmt::format("{}: not a PNG file (wrong signature)", name));
    ReadState state{bytes.data(), bytes.size(), 0, {}};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, errorCallback, warningCallback);
    if (!png) throw Error(fmt::format("{}: libpng initialisation failed", name));
    png_infop info = png_create_info_struct(png);
    struct Guard {
        png_structp* p;
        png_infop* i;
        ~Guard() { png_destroy_read_struct(p, i, nullptr); }
    } guard{&png, &info};
    if (!info) throw Error(fmt::format("{}: libpng initialisation failed", name));
    png_set_read_fn(png, &state, readCallback);

    png_uint_32 w = 0, h = 0;
    if (!readHeader(png, info, &w, &h))
        throw Error(fmt::format("{}: corrupt or unsupported PNG ({})", name, state.message));
    checkInputDimensions(w, h, name);
    ImageRgba8 image{int(w), int(h)};
    std::vector<png_bytep> rows(h);
    for (png_uint_32 y = 0; y < h; ++y) rows[y] = reinterpret_cast<png_bytep>(image.view().row(int(y)));
    if (!readPixels(png, info, rows.data()))
        throw Error(fmt::format("{}: corrupt or truncated PNG ({})", name, state.message));
    return image;
}

std::vector<std::uint8_t> encodePng(ImageView<const Rgba8> image) {
    checkDimensions(image.width(), image.height(), "PNG output");
    std::vector<std::uint8_t> out;
    WriteState state{&out, {}};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, writeErrorCallback, warningCallback);
    if (!png) throw Error("PNG output: libpng initialisation failed");
    png_infop info = png_create_info_struct(png);
    struct Guard {
        png_structp* p;
        png_infop* i;
        ~Guard() { png_destroy_write_struct(p, i); }
    } guard{&png, &info};
    if (!info) throw Error("PNG output: libpng initialisation failed");
    png_set_write_fn(png, &state, writeCallback, flushCallback);
    std::vector<png_bytep> rows(std::size_t(image.height()));
    for (int y = 0; y < image.height(); ++y)
        rows[std::size_t(y)] = reinterpret_cast<png_bytep>(const_cast<Rgba8*>(image.row(y)));
    if (!writeAll(png, info, image.width(), image.height(), rows.data()))
        throw Error(fmt::format("PNG output: encoding failed ({})", state.message));
    return out;
}

std::vector<std::uint8_t> readPngFile(const std::string& path) {
    // Chunk by chunk (PNG spec, section 5.3: length, type, data, CRC) until IEND; the CRCs
    // and the chunks' order are the decoder's to check.
    const std::uint64_t limit = pngFileLimit();
    InputFile f(path, "PNG");
    std::vector<std::uint8_t> bytes = f.signature(kPngMagic, "PNG");
    while (true) {
        const std::size_t at = bytes.size();
        if (f.append(bytes, 8) < 8) break;  // truncated: the decoder says so
        const std::uint64_t len = (std::uint64_t(bytes[at]) << 24) | (std::uint64_t(bytes[at + 1]) << 16) |
                                  (std::uint64_t(bytes[at + 2]) << 8) | bytes[at + 3];
        if (len > 0x7FFFFFFFu) break;  // corrupt: the decoder names it
        if (at + 12 + len > limit)
            throw Error(fmt::format("{}: more than {} bytes before the PNG's end (IEND), the limit for a PNG file{}",
                                    path, limit,
                                    maxPixels() < kMaxPixels ? fmt::format(" at --max-pixels {}", maxPixels()) : ""));
        const bool end = std::memcmp(&bytes[at + 4], "IEND", 4) == 0;
        if (f.append(bytes, len + 4) < len + 4) break;
        if (end) break;
    }
    f.checkError();
    return bytes;
}

ImageRgba8 readPng(const std::string& path) {
    const auto bytes = readPngFile(path);
    return decodePng(bytes, path);
}

void writePng(const std::string& path, ImageView<const Rgba8> image) {
    const auto bytes = encodePng(image);
    writeFileAtomic(path, bytes);
}

}  // namespace ssfx::io
