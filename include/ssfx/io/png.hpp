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
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ssfx/core/image.hpp"

namespace ssfx::io {

// ---- whole files --------------------------------------------------------------------
//! Caps on whole-file reads, derived from the pixel limit (kMaxPixels = 2^28), so that a
//! wrong input (a device, an endless FIFO, a huge file) costs a bounded read and a clear
//! error instead of all the memory:
//!  - PNG/APNG and texture images: 5 bytes a pixel at the limit (RGBA even stored without
//!    compression, plus filter bytes, zlib's block headers and the chunks): 1.25 GiB;
//!  - EXR: 17 bytes a pixel (four float32 channels uncompressed, plus headers and the
//!    offset tables): 4.25 GiB;
//!  - JSON (cameras, scene files): 16 MiB.
inline constexpr std::uint64_t kMaxImageFileBytes = 5 * std::uint64_t(kMaxPixels);
inline constexpr std::uint64_t kMaxExrFileBytes = 17 * std::uint64_t(kMaxPixels);
inline constexpr std::uint64_t kMaxJsonFileBytes = std::uint64_t(16) << 20;
inline constexpr std::uint8_t kPngMagic[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
inline constexpr std::uint8_t kExrMagic[4] = {0x76, 0x2F, 0x31, 0x01};

//! Reads a whole file of `kind` ("PNG", "EXR", "JSON", ...): its first bytes are checked
//! against `signature` before anything else is read, and the read stops with an error
//! past `maxBytes`. Errors name the file: a directory, a missing file, a wrong signature,
//! a file above the cap.
std::vector<std::uint8_t> readFile(const std::string& path, std::uint64_t maxBytes, const char* kind,
                                   std::span<const std::uint8_t> signature = {});
//! A file opened for reading, closed at the end of its scope: the checks and messages of
//! readFile() (a NUL in the path, a directory, a missing file), then reads of known sizes.
class InputFile {
public:
    InputFile(const std::string& path, const char* kind);
    ~InputFile();
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;
    //! The file's first magic.size() bytes, which must be `magic` ("not a KIND file" otherwise).
    std::vector<std::uint8_t> signature(std::span<const std::uint8_t> magic, const char* kind);
    //! Appends up to n bytes to `bytes` (fewer at the end of the file); returns how many.
    std::uint64_t append(std::vector<std::uint8_t>& bytes, std::uint64_t n);
    //! Throws ssfx::Error when a read failed (as opposed to reaching the end).
    void checkError() const;

private:
    std::string path_;
    std::FILE* file_ = nullptr;
};

//! Refuses a path with a NUL byte in it (the C library would read it as a shorter path and
//! open another file): an ssfx::Error. Every function here that takes a path checks it.
void checkPath(const std::string& path);
//! A PNG or APNG file's bytes up to and including its IEND chunk: what follows IEND is not
//! read and is ignored (a stream that goes on after the image, `(cat a.png; cat /dev/zero)`,
//! costs one image). The read stops with an error past pngFileLimit() bytes; a file that
//! ends before IEND is returned as it is, for the decoder to report as truncated.
std::vector<std::uint8_t> readPngFile(const std::string& path);
//! The most bytes readPngFile() reads: 5 a pixel at maxPixels() (below) plus 16 MiB for
//! ancillary chunks, at most kMaxImageFileBytes; so --max-pixels lowers it too.
std::uint64_t pngFileLimit();
//! Writes through an AtomicFile (below): `path` is never left half-written, an existing file
//! stays intact on failure, links are followed, devices and FIFOs written into, "-" is stdout.
void writeFileAtomic(const std::string& path, std::span<const std::uint8_t> bytes);
//! The same for text (JSON, Markdown, HTML).
void writeTextAtomic(const std::string& path, std::string_view text);

//! Creates the output directory `dir` (and its parents) unless it exists; an ssfx::Error
//! naming it when it is a file or cannot be created (a user's mistake: exit 2, not 1).
void makeDirectories(const std::string& dir);

//! The output folder of a run that may fail: the constructor creates `dir` and its missing
//! parents (as makeDirectories); unless keep() is called, the destructor removes the
//! folders it created that are still empty, deepest first. A failed run so leaves no empty
//! folder behind, and never removes a file it wrote (frames before a bad one stay) or
//! anything that was there before.
class OutputFolder {
public:
    explicit OutputFolder(const std::string& dir);
    ~OutputFolder();
    OutputFolder(const OutputFolder&) = delete;
    OutputFolder& operator=(const OutputFolder&) = delete;
    void keep() { created_.clear(); }

private:
    std::vector<std::string> created_;  //!< outermost first
};

//! Outputs that belong together (a render's depth.exr, z.exr, camera.json, color.png,
//! gbuffer.exr): while a set is open on this thread, each AtomicFile's commit() finishes
//! its temporary but leaves it beside its target; the set's commit() moves them all into
//! place at the end, and a set destroyed without commit() (an error on the way) removes
//! them, so a failed run leaves none of its new files and every old one intact. Sets do not
//! nest: an inner set joins the outer one.
class OutputSet {
public:
    OutputSet();
    ~OutputSet();
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;
    void commit();

private:
    friend class AtomicFile;
    struct Pending {
        std::string tmp, target, path;
        int slot;
    };
    std::vector<Pending> pending_;
    OutputSet* outer_ = nullptr;
};

//! An output written piece by piece with the same guarantee: the pieces go to a temporary
//! file beside `path`, commit() syncs it and renames it over `path`; destroyed without a
//! commit (an error on the way), it removes the temporary and `path` is untouched. What
//! `path` names decides how:
//!  - a regular file (or none yet): replaced atomically; an existing file keeps its mode, a
//!    new one gets 0666 less the umask; a read-only one (no write bit, or not writable by
//!    us) is refused with an ssfx::Error and left alone. The replacement is a new file owned
//!    by this process's user and group (ownership is not kept; a set-user-ID or set-group-ID
//!    bit is dropped where the owner or group changes), and a hard link to the old file is
//!    split: its other names keep the old content;
//!  - a symbolic link: followed, and its target replaced in the target's directory (the
//!    link stays a link);
//!  - a device, FIFO or socket: written into directly (never replaced by a regular file);
//!  - one of this process's descriptors: "-" (standard output), /dev/stdout, /dev/stderr,
//!    /dev/fd/N, /proc/self/fd/N (or a link to one of these), and a regular file that is
//!    our standard output or error (`-o log >> log`): written into through the descriptor,
//!    at its offset (appending where the shell opened it with >>), never truncated or
//!    replaced.
//! The temporary is named .ssfx-XXXXXXXX.tmp (any name that fits the directory fits it) and
//! is removed on SIGINT and SIGTERM too (the signal then ends the program as before).
class AtomicFile {
public:
    explicit AtomicFile(const std::string& path);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;
    void write(std::span<const std::uint8_t> bytes);
    //! Hands what was written on (to a pipe's reader, say); the commit still decides.
    void flush();
    void commit();
    const std::string& path() const { return path_; }
    //! Written into as it comes (a descriptor, a device, a FIFO), not replaced at commit().
    bool direct() const { return direct_; }

private:
    void openDescriptor(int fd);  //!< direct writes into this process's descriptor fd
    std::string path_, target_, tmp_;
    std::FILE* file_ = nullptr;
    bool direct_ = false;    //!< written into (stdout, a device, a FIFO): no temporary
    bool keepMode_ = false;  //!< an existing regular file's mode is given to the replacement
    int slot_ = -1;          //!< the temporary's entry in the signal handler's table
};

// ---- the decoders' pixel limit --------------------------------------------------------
//! Every decoder (PNG, each APNG frame and all of a whole-file APNG's frames together, EXR)
//! refuses an image larger than this many pixels from its header, before allocating it.
//! It is kMaxPixels (2^28) unless lowered, process-wide, for batch work (`ssfx --max-pixels
//! N`): a 74-byte PNG claiming 16384x16384 then costs nothing instead of 1 GiB. Throws
//! ssfx::Error unless 1 <= n <= kMaxPixels.
void setMaxPixels(std::int64_t n);
std::int64_t maxPixels();
//! checkDimensions() and maxPixels(), with a message naming `what` and the limit.
void checkInputDimensions(std::int64_t width, std::int64_t height, const std::string& what);

// ---- still PNG ----------------------------------------------------------------------
//! `name` is used in error messages (usually the file path).
ImageRgba8 decodePng(std::span<const std::uint8_t> bytes, const std::string& name);
std::vector<std::uint8_t> encodePng(ImageView<const Rgba8> image);
ImageRgba8 readPng(const std::string& path);
void writePng(const std::string& path, ImageView<const Rgba8> image);

// ---- animated PNG -------------------------------------------------------------------
struct Frame {
    ImageRgba8 image;             //!< the whole canvas after this frame
    std::uint16_t delayNum = 1;   //!< frame delay = delayNum / delayDen seconds
    std::uint16_t delayDen = 25;  //!< 0 means 1/100 s as in the APNG spec
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

//! At most this many frames in one APNG (an hour at 25 fps is 90,000): the streaming
//! reader's bound on the work a file can ask for, separate from the pixel limits.
inline constexpr std::uint32_t kMaxApngFrames = 100000;

//! Reads an APNG (or a still PNG: one frame) one frame at a time, from a file or from
//! memory, holding one composed canvas, one frame's compressed data and the few chunks that
//! decoding needs (PLTE, tRNS), never the whole file: memory is about one frame whatever
//! the frame count, and time is linear in the file size. Each frame's size is checked
//! against kMaxPixels / kMaxDimension, the declared frame count against kMaxApngFrames.
//! decodeApng() and readApng() are built on it (they add the all-frames pixel limit).
//! Errors throw ssfx::Error naming the file (and the frame) as decodeApng() does; frames
//! already returned were complete and correct.
class ApngReader {
public:
    explicit ApngReader(const std::string& path);
    //! From memory: the bytes are read as the frames are asked for, so they must outlive the reader.
    ApngReader(std::span<const std::uint8_t> bytes, const std::string& name);
    ~ApngReader();
    ApngReader(ApngReader&&) noexcept;
    ApngReader& operator=(ApngReader&&) noexcept;
    int width() const;
    int height() const;
    bool animated() const;             //!< false: a still PNG
    std::uint32_t frameCount() const;  //!< as the acTL chunk declares it (1 for a still PNG)
    std::uint32_t numPlays() const;
    //! The next frame, composed onto the canvas (dispose and blend applied), or nullptr after
    //! the last one (then the file's end has been checked). Valid until the next call.
    const Frame* next();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

//! Writes an APNG one frame at a time (each frame stored whole: dispose none, blend
//! source) through an AtomicFile: `path` appears, complete, only at commit(), which
//! checks that exactly `frames` frames were added.
class ApngWriter {
public:
    ApngWriter(const std::string& path, int width, int height, std::uint32_t frames, std::uint32_t numPlays = 0);
    ~ApngWriter();
    void add(ImageView<const Rgba8> image, std::uint16_t delayNum = 1, std::uint16_t delayDen = 25);
    void commit();

private:
    AtomicFile file_;
    int width_, height_;
    std::uint32_t frames_, added_ = 0, seq_ = 0;
};

}  // namespace ssfx::io
