// Frame sequences as the post-processing of rendered animation keeps them: numbered files
// (frame.%04d.png), folders of PNGs, and raw RGBA8 streams (ffmpeg's `-f rawvideo -pix_fmt
// rgba`, through pipes). The CLI's `ssfx aa` runs a method over them (ssfx aa --help).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "ssfx/core/image.hpp"

namespace ssfx::io {

//! "A-B" (A <= B) or "A": frames A to B inclusive, each 0..999999999.
struct FrameRange {
    int first = 0, last = 0;
    static FrameRange parse(const std::string& text);
    std::int64_t count() const { return std::int64_t(last) - first + 1; }
};

//! A numbered file name: exactly one printf-style `%d` or `%0Nd` (N = 1..9), `%%` for a
//! literal percent sign. Throws ssfx::Error naming the problem for any other pattern.
class FramePattern {
public:
    explicit FramePattern(std::string pattern);
    //! Whether `path` holds a frame conversion (a '%' not part of "%%").
    static bool isPattern(std::string_view path);
    //! A path that is not a pattern, with each "%%" read as one '%' (so that `ssfx aa` can
    //! name a file "100%.png" as "100%%.png" beside its numbered patterns).
    static std::string plain(std::string_view path);

    const std::string& pattern() const { return pattern_; }
    std::string path(int frame) const;
    //! The frame number that the file name `name` (no folder) has under this pattern, or -1
    //! when the pattern does not name it (%04d names "0007" and "12345", not "7" or "+007").
    int frameOf(std::string_view name) const;
    //! The numbers of the existing files that the pattern names, in order (frame numbers
    //! 0..999999999); empty when there are none.
    std::vector<int> existing() const;
    //! The frames to process: every frame of `range` (each must exist) or, with no range,
    //! every existing one. Time and memory follow the folder's entries, not the range's
    //! length (--frames 0-999999999 costs one listing). Throws ssfx::Error for no matching
    //! file, for missing frames ("N of M frames are missing, the first: PATH"), and for a
    //! frame that is not a regular file (a FIFO, a device, a folder: refused by name, not
    //! opened, so a FIFO cannot block the run).
    std::vector<int> select(const FrameRange* range) const;

private:
    std::string pattern_, prefix_, suffix_;
    int width_ = 0;  //!< zero-padded digits, 0 = as many as needed
};

//! The PNG files (*.png, any case) of a folder, by name; throws ssfx::Error when `dir` is not
//! a folder or holds none.
std::vector<std::string> pngFilesIn(const std::string& dir);

//! Raw frames of width x height RGBA8 pixels (4 bytes each, rows top to bottom, no padding)
//! read one after another from a stream (stdin, a pipe, a file).
class RawFrameReader {
public:
    //! `name` for messages ("stdin", the path). Does not own or close `stream`.
    RawFrameReader(std::FILE* stream, int width, int height, std::string name);
    //! The size is checked against the pixel limit (--max-pixels) as every decoder's is.
    //! The next frame into `frame` (resized as needed); false at the end of the stream. A
    //! frame cut short is an ssfx::Error naming its index and how many bytes it had.
    bool read(ImageRgba8& frame);
    int framesRead() const { return frames_; }
    std::size_t frameBytes() const { return std::size_t(width_) * std::size_t(height_) * 4; }

private:
    std::FILE* stream_;
    int width_, height_, frames_ = 0;
    std::string name_;
};

class AtomicFile;

//! Raw RGBA8 frames written one after another into an AtomicFile (png.hpp): into a pipe or
//! standard output ("-") frame by frame, each whole and flushed; into a regular file, which
//! appears at the AtomicFile's commit. A failed write is an ssfx::Error.
class RawFrameWriter {
public:
    explicit RawFrameWriter(AtomicFile& out) : out_(&out) {}
    void write(ImageView<const Rgba8> frame);
    int framesWritten() const { return frames_; }

private:
    AtomicFile* out_;
    int frames_ = 0;
};

}  // namespace ssfx::io
