// PNG and APNG files. The only place (with exr.hpp, later) that knows file formats.
//
// Reading converts every PNG colour type to RGBA8 by one documented rule:
//  - 16-bit samples are scaled to 8 bits with rounding: v8 = round(v16 * 255 / 65535);
//  - grey (1, 2, 4, 8, 16 bit) becomes R = G = B = grey; palette entries are expanded;
//  - alpha comes from the alpha channel, or from tRNS (palette or single colour key),
//    else it is 255;
//  - stored values are kept as they are: no gamma or colour-space conversion.
// Dimensions are checked against kMaxPixels / kMaxDimension before any pixel buffer is
// allocated. Every failure throws ssfx::Error naming the file and the problem.
//
// APNG (animated PNG): the acTL/fcTL/fdAT chunk layer is ours (Debian's libpng has no APNG
// support); each frame's data is decoded or encoded by libpng. Reading composes every
// frame onto the full canvas (dispose and blend ops applied), so callers see whole frames.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ssfx/core/image.hpp"

namespace ssfx::io {

// ---- whole files --------------------------------------------------------------------
std::vector<std::uint8_t> readFile(const std::string& path);
//! Writes to a temporary file in the same directory and renames it over `path`, so
//! `path` is never left half-written (an existing file stays intact on failure).
void writeFileAtomic(const std::string& path, std::span<const std::uint8_t> bytes);

// ---- still PNG ----------------------------------------------------------------------
//! `name` is used in error messages (usually the file path).
ImageRgba8 decodePng(std::span<const std::uint8_t> bytes, const std::string& name);
std::vector<std::uint8_t> encodePng(ImageView<const Rgba8> image);
ImageRgba8 readPng(const std::string& path);
void writePng(const std::string& path, ImageView<const Rgba8> image);

// ---- animated PNG -------------------------------------------------------------------
struct Frame {
    ImageRgba8 image;              //!< the whole canvas after this frame
    std::uint16_t delayNum = 1;    //!< frame delay = delayNum / delayDen seconds
    std::uint16_t delayDen = 25;   //!< 0 means 1/100 s as in the APNG spec
    double delaySeconds() const { return double(delayNum) / (delayDen == 0 ? 100.0 : delayDen); }
};
struct Animation {
    std::vector<Frame> frames;
    std::uint32_t numPlays = 0;  //!< 0 = loop forever
    int width() const { return frames.empty() ? 0 : frames[0].image.width(); }
    int height() const { return frames.empty() ? 0 : frames[0].image.height(); }
};

//! True when the bytes are a PNG with an acTL chunk before the first IDAT.
bool isApng(std::span<const std::uint8_t> bytes);
//! Decodes an APNG (all frames, composed); a still PNG gives one frame.
Animation decodeApng(std::span<const std::uint8_t> bytes, const std::string& name);
//! Encodes all frames (same size, each stored whole: dispose none, blend source).
std::vector<std::uint8_t> encodeApng(const Animation& animation);
Animation readApng(const std::string& path);
void writeApng(const std::string& path, const Animation& animation);

}  // namespace ssfx::io
