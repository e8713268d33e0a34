// OpenEXR files for float buffers (depth, AO), through OpenEXR (libopenexr). With png.hpp
// the only place that knows file formats.
//
// Reading takes one channel of a scanline or tiled EXR as float32 (HALF and UINT samples
// converted): `channel` if given, else the first of "Z", "Y", "R", "A" that exists, else
// the file's only channel. The data window's size is checked against kMaxPixels before
// anything is allocated; every failure (truncated or corrupt file, missing channel)
// throws ssfx::Error naming the file. Writing stores one FLOAT channel, ZIP compressed,
// through writeFileAtomic (no partial file on failure).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ssfx/core/image.hpp"

namespace ssfx::io {

ImageF decodeExr(std::span<const std::uint8_t> bytes, const std::string& name, const std::string& channel = "",
                 std::string* channelUsed = nullptr);
ImageF readExr(const std::string& path, const std::string& channel = "", std::string* channelUsed = nullptr);

std::vector<std::uint8_t> encodeExr(ImageView<const float> image, const std::string& channel = "Y");

//! Several FLOAT channels of the same size in one file (e.g. a G-buffer: N.X, N.Y, N.Z, ...).
struct ExrChannel {
    std::string name;
    ImageView<const float> image;
};
std::vector<std::uint8_t> encodeExr(const std::vector<ExrChannel>& channels);
void writeExr(const std::string& path, const std::vector<ExrChannel>& channels);
void writeExr(const std::string& path, ImageView<const float> image, const std::string& channel = "Y");

}  // namespace ssfx::io
