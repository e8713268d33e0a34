// Cairo image surface -> ImageRgba8, shared by the test images and the charts.
#pragma once

#include <cairo.h>

#include <cstdint>

#include "ssfx/core/image.hpp"

namespace ssfx::eval::detail {

//! Copies an opaque CAIRO_FORMAT_RGB24 surface (one native-endian uint32 per pixel,
//! 0x00RRGGBB) into an RGBA8 image with alpha 255.
inline ImageRgba8 imageFromCairo(cairo_surface_t* s) {
    cairo_surface_flush(s);
    const int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
    const int stride = cairo_image_surface_get_stride(s);
    const unsigned char* data = cairo_image_surface_get_data(s);
    ImageRgba8 out(w, h);
    for (int y = 0; y < h; ++y) {
        const auto* row = reinterpret_cast<const std::uint32_t*>(data + std::ptrdiff_t(y) * stride);
        for (int x = 0; x < w; ++x) {
            const std::uint32_t p = row[x];
            out(x, y) = {std::uint8_t(p >> 16), std::uint8_t(p >> 8), std::uint8_t(p), 255};
        }
    }
    return out;
}

}  // namespace ssfx::eval::detail
