// Whole-file reads and atomic writes (temporary file in the same directory + rename).
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#include "ssfx/io/png.hpp"

namespace ssfx::io {

std::vector<std::uint8_t> readFile(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw Error(fmt::format("{}: cannot open for reading ({})", path, std::strerror(errno)));
    std::vector<std::uint8_t> bytes;
    std::uint8_t buf[1 << 16];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.insert(bytes.end(), buf, buf + n);
    const bool failed = std::ferror(f) != 0;
    std::fclose(f);
    if (failed) throw Error(fmt::format("{}: read error", path));
    return bytes;
}

void writeFileAtomic(const std::string& path, std::span<const std::uint8_t> bytes) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    if (fs::is_directory(target)) throw Error(fmt::format("{}: is a directory", path));
    std::random_device rd;
    const fs::path tmp = target.parent_path() /
                         fmt::format(".{}.tmp{}-{:08x}", target.filename().string(), ::getpid(), rd());
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) throw Error(fmt::format("{}: cannot create output file ({})", path, std::strerror(errno)));
    bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    ok = (std::fflush(f) == 0) && ok;
    ok = (::fsync(::fileno(f)) == 0) && ok;
    ok = (std::fclose(f) == 0) && ok;
    if (!ok) {
        std::remove(tmp.c_str());
        throw Error(fmt::format("{}: write failed ({})", path, std::strerror(errno)));
    }
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) {
        std::remove(tmp.c_str());
        throw Error(fmt::format("{}: cannot move output into place ({})", path, ec.message()));
    }
}

}  // namespace ssfx::io
