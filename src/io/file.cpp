// Whole-file reads and atomic writes (temporary file in the target's directory + rename;
// see AtomicFile in png.hpp for what is replaced, what is written into and what is refused).
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <random>

#include "ssfx/io/png.hpp"

namespace ssfx::io {

namespace {
std::atomic<std::int64_t> gMaxPixels{kMaxPixels};
}  // namespace

void setMaxPixels(std::int64_t n) {
    if (n < 1 || n > kMaxPixels) throw Error(fmt::format("--max-pixels {} is not in [1, {}]", n, kMaxPixels));
    gMaxPixels.store(n);
}

std::int64_t maxPixels() { return gMaxPixels.load(); }

void checkInputDimensions(std::int64_t width, std::int64_t height, const std::string& what) {
    checkDimensions(width, height, what);
    if (width * height > maxPixels())
        throw Error(fmt::format("{}: size {}x{} exceeds the pixel limit of {} (--max-pixels)", what, width, height,
                                maxPixels()));
}

std::vector<std::uint8_t> readFile(const std::string& path, std::uint64_t maxBytes, const char* kind,
                                   std::span<const std::uint8_t> signature) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw Error(fmt::format("{}: is a directory, not a {} file", path, kind));
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw Error(fmt::format("{}: cannot open for reading ({})", path, std::strerror(errno)));
    std::vector<std::uint8_t> bytes;
    std::uint8_t buf[1 << 16];
    std::size_t n;
    auto fail = [&](const std::string& message) {
        std::fclose(f);
        throw Error(message);
    };
    // The signature first: a wrong file is refused after its first few bytes.
    if (!signature.empty()) {
        n = std::fread(buf, 1, signature.size(), f);
        if (n < signature.size() || std::memcmp(buf, signature.data(), signature.size()) != 0)
            fail(fmt::format("{}: not a {} file (wrong signature)", path, kind));
        bytes.assign(buf, buf + n);
    }
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) {
        if (bytes.size() + n > maxBytes)
            fail(fmt::format("{}: more than {} bytes, the limit for a {} file", path, maxBytes, kind));
        bytes.insert(bytes.end(), buf, buf + n);
    }
    const bool failed = std::ferror(f) != 0;
    std::fclose(f);
    if (failed) throw Error(fmt::format("{}: read error", path));
    return bytes;
}

namespace {

namespace fs = std::filesystem;

// The temporaries alive in this process, so that SIGINT and SIGTERM can remove them: a fixed
// table of paths, filled and cleared under a mutex, read by the handler with unlink() alone
// (async-signal-safe). A slot is used while its flag is set.
constexpr int kSlots = 64;
constexpr std::size_t kSlotBytes = 4096;
char gTempPath[kSlots][kSlotBytes];
std::atomic<bool> gTempUsed[kSlots];
std::mutex gTempMutex;
struct sigaction gPrevious[2];
const int kSignals[2] = {SIGINT, SIGTERM};

extern "C" void removeTemporariesAndDie(int sig) {
    for (int i = 0; i < kSlots; ++i)
        if (gTempUsed[i].load()) ::unlink(gTempPath[i]);
    for (int k = 0; k < 2; ++k)
        if (kSignals[k] == sig) ::sigaction(sig, &gPrevious[k], nullptr);
    ::raise(sig);  // the previous disposition (by default: terminate with this signal)
}

void installHandlersOnce() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (int k = 0; k < 2; ++k) {
            struct sigaction now {};
            ::sigaction(kSignals[k], nullptr, &now);
            if (now.sa_handler != SIG_DFL) continue;  // the program has its own: leave it
            struct sigaction sa {};
            sa.sa_handler = removeTemporariesAndDie;
            sigemptyset(&sa.sa_mask);
            ::sigaction(kSignals[k], &sa, &gPrevious[k]);
        }
    });
}

int registerTemp(const std::string& path) {
    if (path.size() >= kSlotBytes) return -1;
    std::lock_guard<std::mutex> lock(gTempMutex);
    for (int i = 0; i < kSlots; ++i)
        if (!gTempUsed[i].load()) {
            std::memcpy(gTempPath[i], path.c_str(), path.size() + 1);
            gTempUsed[i].store(true);
            return i;
        }
    return -1;  // more than 64 at once: still removed on errors, not on signals
}

void unregisterTemp(int slot) {
    if (slot < 0) return;
    std::lock_guard<std::mutex> lock(gTempMutex);
    gTempUsed[slot].store(false);
}

// `path` with every symbolic link along it followed (a dangling link gives its target: the
// file to create), so that the target is what gets replaced, in the target's directory.
fs::path followLinks(const fs::path& path) {
    fs::path p = path;
    for (int depth = 0; depth < 40; ++depth) {
        std::error_code ec;
        if (!fs::is_symlink(fs::symlink_status(p, ec))) return p;
        const fs::path to = fs::read_symlink(p, ec);
        if (ec) throw Error(fmt::format("{}: cannot read the symbolic link ({})", path.string(), ec.message()));
        p = to.is_absolute() ? to : p.parent_path() / to;
    }
    throw Error(fmt::format("{}: too many levels of symbolic links", path.string()));
}

}  // namespace

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
    if (path == "-") {  // standard output, written as it comes
        file_ = stdout;
        direct_ = true;
        return;
    }
    const fs::path target = followLinks(fs::path(path));
    std::error_code ec;
    const fs::file_status st = fs::status(target, ec);
    if (fs::is_directory(st)) throw Error(fmt::format("{}: is a directory", path));
    if (fs::exists(st) && !fs::is_regular_file(st)) {
        // A device, a FIFO, a socket: written into, never replaced.
        file_ = std::fopen(target.c_str(), "wb");
        if (!file_) throw Error(fmt::format("{}: cannot open for writing ({})", path, std::strerror(errno)));
        direct_ = true;
        return;
    }
    target_ = target.string();
    mode_t mode = 0666;  // a new file: 0666 less the umask, as open(2) gives it
    if (fs::exists(st)) {
        struct stat info {};
        if (::stat(target.c_str(), &info) != 0)
            throw Error(fmt::format("{}: cannot stat ({})", path, std::strerror(errno)));
        // Read-only: no write permission bit at all, or none for us (root passes access()).
        if ((info.st_mode & 0222) == 0 || ::access(target.c_str(), W_OK) != 0)
            throw Error(fmt::format("{}: is read-only; not overwritten", path));
        mode = info.st_mode & 07777;
        keepMode_ = true;
    }
    // A short temporary name beside the target (any target name that fits fits it too).
    std::random_device rd;
    int fd = -1;
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
        tmp_ = (target.parent_path() / fmt::format(".ssfx-{:08x}.tmp", rd())).string();
        fd = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, keepMode_ ? 0600 : mode);
        if (fd < 0 && errno != EEXIST) break;
    }
    if (fd < 0) throw Error(fmt::format("{}: cannot create output file ({})", path, std::strerror(errno)));
    if (keepMode_ && ::fchmod(fd, mode) != 0) {
        const int e = errno;
        ::close(fd), ::unlink(tmp_.c_str());
        throw Error(fmt::format("{}: cannot set the file mode ({})", path, std::strerror(e)));
    }
    installHandlersOnce();
    slot_ = registerTemp(tmp_);
    file_ = ::fdopen(fd, "wb");
    if (!file_) {
        ::close(fd), ::unlink(tmp_.c_str()), unregisterTemp(slot_);
        throw Error(fmt::format("{}: cannot create output file ({})", path, std::strerror(errno)));
    }
}

AtomicFile::~AtomicFile() {
    if (!file_) return;
    if (direct_) {
        if (file_ != stdout) std::fclose(file_);
        return;
    }
    std::fclose(file_);
    std::remove(tmp_.c_str());
    unregisterTemp(slot_);
}

void AtomicFile::write(std::span<const std::uint8_t> bytes) {
    if (!file_) throw Error(fmt::format("{}: write after commit", path_));
    if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
        throw Error(fmt::format("{}: write failed ({})", path_, std::strerror(errno)));
}

void AtomicFile::flush() {
    if (file_ && std::fflush(file_) != 0)
        throw Error(fmt::format("{}: write failed ({})", path_, std::strerror(errno)));
}

namespace {
thread_local OutputSet* gOpenSet = nullptr;
}  // namespace

OutputSet::OutputSet() : outer_(gOpenSet) {
    if (!outer_) gOpenSet = this;
}

OutputSet::~OutputSet() {
    if (outer_) return;
    gOpenSet = nullptr;
    for (const Pending& p : pending_) {  // not committed: none of them appears
        std::remove(p.tmp.c_str());
        unregisterTemp(p.slot);
    }
}

void OutputSet::commit() {
    if (outer_) return;  // the outer set commits
    gOpenSet = nullptr;
    std::vector<Pending> todo;
    todo.swap(pending_);
    for (std::size_t i = 0; i < todo.size(); ++i) {
        std::error_code ec;
        fs::rename(todo[i].tmp, todo[i].target, ec);
        unregisterTemp(todo[i].slot);
        if (ec) {
            for (std::size_t k = i; k < todo.size(); ++k)
                std::remove(todo[k].tmp.c_str()), unregisterTemp(todo[k].slot);
            throw Error(fmt::format("{}: cannot move output into place ({})", todo[i].path, ec.message()));
        }
    }
}

void AtomicFile::commit() {
    if (!file_) throw Error(fmt::format("{}: committed twice", path_));
    if (direct_) {
        const bool ok = std::fflush(file_) == 0 && (file_ == stdout || std::fclose(file_) == 0);
        file_ = nullptr;
        if (!ok) throw Error(fmt::format("{}: write failed ({})", path_, std::strerror(errno)));
        return;
    }
    bool ok = std::fflush(file_) == 0;
    ok = (::fsync(::fileno(file_)) == 0) && ok;
    ok = (std::fclose(file_) == 0) && ok;
    file_ = nullptr;
    if (!ok) {
        std::remove(tmp_.c_str());
        unregisterTemp(slot_);
        throw Error(fmt::format("{}: write failed ({})", path_, std::strerror(errno)));
    }
    if (gOpenSet) {  // part of a set: moved into place with the others
        gOpenSet->pending_.push_back({tmp_, target_, path_, slot_});
        return;
    }
    std::error_code ec;
    fs::rename(tmp_, target_, ec);
    unregisterTemp(slot_);
    if (ec) {
        std::remove(tmp_.c_str());
        throw Error(fmt::format("{}: cannot move output into place ({})", path_, ec.message()));
    }
}

void makeDirectories(const std::string& dir) {
    std::error_code ec;
    const fs::path p(dir);
    if (fs::exists(p, ec) && !fs::is_directory(p, ec))
        throw Error(fmt::format("{}: exists and is not a directory (an output directory was expected)", dir));
    fs::create_directories(p, ec);
    if (ec) throw Error(fmt::format("{}: cannot create the output directory ({})", dir, ec.message()));
}

void writeFileAtomic(const std::string& path, std::span<const std::uint8_t> bytes) {
    AtomicFile f(path);
    f.write(bytes);
    f.commit();
}

void writeTextAtomic(const std::string& path, std::string_view text) {
    writeFileAtomic(path, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

}  // namespace ssfx::io
