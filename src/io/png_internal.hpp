// PNG chunk layer shared by the APNG reader and writer (PNG spec, section 5).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ssfx/io/png.hpp"

namespace ssfx::io::detail {

inline constexpr const auto& kPngSignature = ssfx::io::kPngMagic;

struct Chunk {
    char type[5] = {};                   //!< four letters, NUL-terminated
    std::span<const std::uint8_t> data;  //!< payload (without length, type and CRC)
    bool is(const char* t) const { return type[0] == t[0] && type[1] == t[1] && type[2] == t[2] && type[3] == t[3]; }
};

//! Splits a PNG file into chunks, checking the signature, lengths and every CRC. Stops
//! after IEND. Throws ssfx::Error naming `name` on any defect.
std::vector<Chunk> parseChunks(std::span<const std::uint8_t> bytes, const std::string& name);

std::uint32_t readBe32(const std::uint8_t* p);
std::uint16_t readBe16(const std::uint8_t* p);
void appendBe32(std::vector<std::uint8_t>& out, std::uint32_t v);
void appendBe16(std::vector<std::uint8_t>& out, std::uint16_t v);
//! Bytes of the per-frame PNGs that the APNG reader has handed to libpng on this thread (a
//! test hook: decoding stays linear in the file size when no chunk is copied per frame).
std::uint64_t& apngBytesDecoded();

//! Appends length, type, payload and CRC.
void appendChunk(std::vector<std::uint8_t>& out, const char* type, std::span<const std::uint8_t> data);

}  // namespace ssfx::io::detail
