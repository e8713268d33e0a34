// Frame sequences: numbered files, folders, raw streams (see ssfx/io/sequence.hpp).
#include "ssfx/io/sequence.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "ssfx/core/error.hpp"
#include "ssfx/io/png.hpp"

namespace ssfx::io {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxFrame = 999999999;

// The printf conversion in `s` at `i` (s[i] == '%'): its length, and its zero-padded width
// (0 for plain %d); -1 when it is not %d / %0Nd.
int conversionAt(std::string_view s, std::size_t i, int& width) {
    std::size_t j = i + 1;
    width = 0;
    if (j < s.size() && s[j] == '0') {
        ++j;
        if (j >= s.size() || !std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '0') return -1;
        width = s[j] - '0';
        ++j;
    }
    if (j >= s.size() || s[j] != 'd') return -1;
    return int(j + 1 - i);
}

std::string unescape(std::string_view s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        out += s[i];
        if (s[i] == '%' && i + 1 < s.size() && s[i + 1] == '%') ++i;
    }
    return out;
}

}  // namespace

bool FramePattern::isPattern(std::string_view path) {
    for (std::size_t i = 0; i < path.size(); ++i)
        if (path[i] == '%') {
            if (i + 1 < path.size() && path[i + 1] == '%') {
                ++i;
                continue;
            }
            return true;
        }
    return false;
}

std::string FramePattern::plain(std::string_view path) { return unescape(path); }

FramePattern::FramePattern(std::string pattern) : pattern_(std::move(pattern)) {
    std::size_t at = std::string::npos, length = 0;
    for (std::size_t i = 0; i < pattern_.size(); ++i) {
        if (pattern_[i] != '%') continue;
        if (i + 1 < pattern_.size() && pattern_[i + 1] == '%') {
            ++i;
            continue;
        }
        int width = 0;
        const int n = conversionAt(pattern_, i, width);
        if (n < 0)
            throw Error(fmt::format("frame pattern '{}': only %d or %0Nd (N 1..9) name the frame number (%% for a %)",
                                    pattern_));
        if (at != std::string::npos)
            throw Error(fmt::format("frame pattern '{}': more than one frame number", pattern_));
        at = i, length = std::size_t(n), width_ = width;
        i += length - 1;
    }
    if (at == std::string::npos) throw Error(fmt::format("frame pattern '{}': no frame number (%d or %0Nd)", pattern_));
    if (pattern_.find('/', at) != std::string::npos)
        throw Error(
            fmt::format("frame pattern '{}': the frame number must be in the file name, not a folder", pattern_));
    prefix_ = unescape(std::string_view(pattern_).substr(0, at));
    suffix_ = unescape(std::string_view(pattern_).substr(at + length));
}

std::string FramePattern::path(int frame) const { return fmt::format("{}{:0{}d}{}", prefix_, frame, width_, suffix_); }

int FramePattern::frameOf(std::string_view name) const {
    // prefix_ may hold folders; the file name's own prefix is what follows the last '/'.
    const std::size_t slash = prefix_.rfind('/');
    const std::string_view stem =
        slash == std::string::npos ? std::string_view(prefix_) : std::string_view(prefix_).substr(slash + 1);
    if (name.size() <= stem.size() + suffix_.size() || name.substr(0, stem.size()) != stem ||
        name.substr(name.size() - suffix_.size()) != suffix_)
        return -1;
    const std::string_view digits = name.substr(stem.size(), name.size() - stem.size() - suffix_.size());
    if (digits.size() > 9 ||
        !std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); }))
        return -1;
    int n = 0;
    for (char c : digits) n = n * 10 + (c - '0');
    return fmt::format("{:0{}d}", n, width_) == digits ? n : -1;  // %04d: "0007", not "7"
}

std::vector<int> FramePattern::existing() const {
    // prefix_ = folder/ + stem: "in/frame." -> "in", "frame." -> ".".
    const std::size_t slash = prefix_.rfind('/');
    const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : prefix_.substr(0, slash);
    checkPath(dir);
    std::vector<int> frames;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec))
        if (const int n = frameOf(entry.path().filename().string()); n >= 0) frames.push_back(n);
    std::sort(frames.begin(), frames.end());
    return frames;
}

std::vector<int> FramePattern::select(const FrameRange* range) const {
    std::vector<int> frames = existing();
    if (range) {
        // The frames of the range that exist, then the first gap: no list of the range itself.
        const auto lo = std::lower_bound(frames.begin(), frames.end(), range->first);
        const auto hi = std::upper_bound(frames.begin(), frames.end(), range->last);
        frames = std::vector<int>(lo, hi);
        if (std::int64_t(frames.size()) < range->count()) {
            int missing = range->first;
            for (int n : frames) {
                if (n != missing) break;
                ++missing;
            }
            throw Error(fmt::format("{} of {} frames are missing, the first: {}",
                                    range->count() - std::int64_t(frames.size()), range->count(), path(missing)));
        }
    }
    if (frames.empty()) throw Error(fmt::format("{}: no files match the frame pattern", pattern_));
    for (int n : frames) {
        std::error_code ec;
        const fs::file_status st = fs::status(path(n), ec);
        if (!fs::is_regular_file(st))
            throw Error(fmt::format("{}: {}, not a regular file; every frame must be a PNG file", path(n),
                                    fs::is_fifo(st)        ? "a FIFO"
                                    : fs::is_directory(st) ? "a folder"
                                    : fs::is_socket(st)    ? "a socket"
                                    : fs::exists(st)       ? "a device"
                                                           : "a dangling link"));
    }
    return frames;
}

FrameRange FrameRange::parse(const std::string& text) {
    const auto bad = [&] {
        return Error(fmt::format("--frames '{}' is not A-B or A (frame numbers 0..{}, A <= B)", text, kMaxFrame));
    };
    auto number = [&](const std::string& s) {
        if (s.empty() || s.size() > 9 ||
            !std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); }))
            throw bad();
        return std::stoi(s);
    };
    const auto dash = text.find('-');
    FrameRange r;
    r.first = number(text.substr(0, dash));
    r.last = dash == std::string::npos ? r.first : number(text.substr(dash + 1));
    if (r.last < r.first) throw bad();
    return r;
}

std::vector<std::string> pngFilesIn(const std::string& dir) {
    checkPath(dir);
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw Error(fmt::format("{}: not a folder", dir));
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        std::string ext = entry.path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (ext == ".png" && entry.is_regular_file(ec)) files.push_back(entry.path().filename().string());
    }
    if (ec) throw Error(fmt::format("{}: cannot list the folder ({})", dir, ec.message()));
    if (files.empty()) throw Error(fmt::format("{}: no .png files in the folder", dir));
    std::sort(files.begin(), files.end());
    return files;
}

RawFrameReader::RawFrameReader(std::FILE* stream, int width, int height, std::string name)
    : stream_(stream), width_(width), height_(height), name_(std::move(name)) {
    checkInputDimensions(width, height, fmt::format("{}: raw frame", name_));
}

bool RawFrameReader::read(ImageRgba8& frame) {
    if (frame.width() != width_ || frame.height() != height_) frame = ImageRgba8(width_, height_);
    const std::size_t want = frameBytes();
    std::size_t got = 0;
    auto* bytes = reinterpret_cast<unsigned char*>(frame.data());
    while (got < want) {
        const std::size_t n = std::fread(bytes + got, 1, want - got, stream_);
        if (n == 0) break;
        got += n;
    }
    if (got == 0 && std::feof(stream_)) return false;
    if (got < want) {
        if (std::ferror(stream_))
            throw Error(fmt::format("{}: reading raw frame {} failed: {}", name_, frames_, std::strerror(errno)));
        throw Error(fmt::format("{}: raw frame {} is cut short: {} of {} bytes ({}x{} RGBA8), after {} whole frame(s)",
                                name_, frames_, got, want, width_, height_, frames_));
    }
    ++frames_;
    return true;
}

void RawFrameWriter::write(ImageView<const Rgba8> frame) {
    for (int y = 0; y < frame.height(); ++y)
        out_->write({reinterpret_cast<const std::uint8_t*>(frame.row(y)), std::size_t(frame.width()) * 4});
    out_->flush();
    ++frames_;
}

}  // namespace ssfx::io
