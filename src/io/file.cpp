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

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    if (fs::is_directory(target)) throw Error(fmt::format("{}: is a directory", path));
    std::random_device rd;
    tmp_ = (target.parent_path() / fmt::format(".{}.tmp{}-{:08x}", target.filename().string(), ::getpid(), rd()))
               .string();
    file_ = std::fopen(tmp_.c_str(), "wb");
    if (!file_) throw Error(fmt::format("{}: cannot create output file ({})", path, std::strerror(errno)));
}

AtomicFile::~AtomicFile() {
    if (file_) {
        std::fclose(file_);
        std::remove(tmp_.c_str());
    }
}

void AtomicFile::write(std::span<const std::uint8_t> bytes) {
    if (!file_) throw Error(fmt::format("{}: write after commit", path_));
    if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
        throw Error(fmt::format("{}: write failed ({})", path_, std::strerror(errno)));
}

void AtomicFile::commit() {
    if (!file_) throw Error(fmt::format("{}: committed twice", path_));
    bool ok = std::fflush(file_) == 0;
    ok = (::fsync(::fileno(file_)) == 0) && ok;
    ok = (std::fclose(file_) == 0) && ok;
    file_ = nullptr;
    if (!ok) {
        std::remove(tmp_.c_str());
        throw Error(fmt::format("{}: write failed ({})", path_, std::strerror(errno)));
    }
    std::error_code ec;
    std::filesystem::rename(tmp_, path_, ec);
    if (ec) {
        std::remove(tmp_.c_str());
        throw Error(fmt::format("{}: cannot move output into place ({})", path_, ec.message()));
    }
}

void writeFileAtomic(const std::string& path, std::span<const std::uint8_t> bytes) {
    AtomicFile f(path);
    f.write(bytes);
    f.commit();
}

}  // namespace ssfx::io
