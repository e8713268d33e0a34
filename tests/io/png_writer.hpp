// Writes PNGs of any colour type and bit depth with libpng's low-level API, so the tests
// can feed the reader inputs that ssfx itself never writes.
#pragma once

#include <png.h>

#include <cstdint>
#include <vector>

namespace ssfx::test {

struct RawPng {
    int width, height, bitDepth, colorType;
    std::vector<std::uint8_t> data;            //!< packed rows, big-endian 16-bit samples
    std::vector<png_color> palette = {};       //!< PLTE entries
    std::vector<std::uint8_t> trnsAlpha = {};  //!< tRNS for palettes
    bool trnsColor = false;                    //!< tRNS colour key (grey/RGB)
    png_color_16 trnsKey{};
};

inline std::vector<std::uint8_t> writeRawPng(const RawPng& p) {
    std::vector<std::uint8_t> out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_set_write_fn(
        png, &out,
        [](png_structp s, png_bytep d, png_size_t n) {
            auto* v = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(s));
            v->insert(v->end(), d, d + n);
        },
        nullptr);
    png_set_IHDR(png, info, png_uint_32(p.width), png_uint_32(p.height), p.bitDepth, p.colorType, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (!p.palette.empty()) png_set_PLTE(png, info, p.palette.data(), int(p.palette.size()));
    if (!p.trnsAlpha.empty())
        png_set_tRNS(png, info, const_cast<png_bytep>(p.trnsAlpha.data()), int(p.trnsAlpha.size()), nullptr);
    if (p.trnsColor) png_set_tRNS(png, info, nullptr, 0, const_cast<png_color_16p>(&p.trnsKey));
    png_write_info(png, info);
    const std::size_t rowBytes = p.data.size() / std::size_t(p.height);
    for (int y = 0; y < p.height; ++y)
        png_write_row(png, const_cast<png_bytep>(p.data.data() + rowBytes * std::size_t(y)));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return out;
}

}  // namespace ssfx::test
