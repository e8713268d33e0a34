// Whole-file reads and atomic writes (temporary file in the target's directory + rename;
// see AtomicFile in png.hpp for what is replaced, what is written into and what is refused).
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
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

void checkPath(const std::string& path) {
    // The C library stops a path at its first NUL: 'victim\0.png' would name 'victim'.
    if (path.find('\0') == std::string::npos) return;
    std::string shown;
    for (char c : path) shown += c == '\0' ? std::string("\\0") : std::string(1, c);
    throw Error(fmt::format("path '{}' contains a NUL byte (\\0), which no file name can hold", shown));
}

std::uint64_t pngFileLimit() {
    // 5 bytes a pixel (kMaxImageFileBytes' rule) at the process's pixel limit, plus room for
    // ancillary chunks (profiles, text, EXIF), so that --max-pixels bounds the read too.
    return std::min<std::uint64_t>(kMaxImageFileBytes, 5 * std::uint64_t(maxPixels()) + (std::uint64_t(16) << 20));
}

void checkInputDimensions(std::int64_t width, std::int64_t height, const std::string& what) {
    checkDimensions(width, height, what);
    if (width * height > maxPixels())
        throw Error(fmt::format("{}: size {}x{} exceeds the pixel limit of {} (--max-pixels)", what, width, height,
                                maxPixels()));
}

InputFile::InputFile(const std::string& path, const char* kind) : path_(path) {
    checkPath(path);
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw Error(fmt::format("{}: is a directory, not {} data", path, kind));
    file_ = std::fopen(path.c_str(), "rb");
    if (!file_) throw Error(fmt::format("{}: cannot open for reading ({})", path, std::strerror(errno)));
}

InputFile::~InputFile() {
    if (file_) std::fclose(file_);
}

std::vector<std::uint8_t> InputFile::signature(std::span<const std::uint8_t> magic, const char* kind) {
    std::vector<std::uint8_t> bytes;
    if (append(bytes, magic.size()) < magic.size() || std::memcmp(bytes.data(), magic.data(), magic.size()) != 0)
        throw Error(fmt::format("{}: not in {} format (wrong signature)", path_, kind));
    return bytes;
}

std::uint64_t InputFile::append(std::vector<std::uint8_t>& bytes, std::uint64_t n) {
    // In steps of at most 1 MiB: a length claimed by a header costs only what arrives.
    std::uint64_t done = 0;
    while (done < n) {
        const std::size_t step = std::size_t(std::min<std::uint64_t>(n - done, std::uint64_t(1) << 20));
        const std::size_t from = bytes.size();
        bytes.resize(from + step);
        const std::size_t got = std::fread(bytes.data() + from, 1, step, file_);
        bytes.resize(from + got);
        done += got;
        if (got < step) break;
    }
    return done;
}

void InputFile::checkError() const {
    if (std::ferror(file_)) throw Error(fmt::format("{}: read error", path_));
}

std::vector<std::uint8_t> readFile(const std::string& path, std::uint64_t maxBytes, const char* kind,
                                   std::span<const std::uint8_t> signature) {
    InputFile f(path, kind);
    // The signature first: a wrong file is refused after its first few bytes.
    std::vector<std::uint8_t> bytes = signature.empty() ? std::vector<std::uint8_t>() : f.signature(signature, kind);
    while (f.append(bytes, 1 << 16) > 0)
        if (bytes.size() > maxBytes)
            throw Error(fmt::format("{}: more than {} bytes, the limit for a {} file", path, maxBytes, kind));
    f.checkError();
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

// The descriptor of this process that `path` names by its form: /dev/stdout (1),
// /dev/stderr (2), /dev/stdin (0), /dev/fd/N, /proc/self/fd/N, /proc/thread-self/fd/N and
// /proc/PID/fd/N with our own PID; -1 for any other path. Such a name is a view of an open
// descriptor (a file opened by the shell with >>, a pipe, a terminal), not a file to replace.
int descriptorNamed(const fs::path& path) {
    const std::string s = path.lexically_normal().string();
    if (s == "/dev/stdin") return 0;
    if (s == "/dev/stdout") return 1;
    if (s == "/dev/stderr") return 2;
    for (const std::string& dir : {std::string("/dev/fd/"), std::string("/proc/self/fd/"),
                                   std::string("/proc/thread-self/fd/"), fmt::format("/proc/{}/fd/", ::getpid())}) {
        if (s.size() <= dir.size() || s.compare(0, dir.size(), dir) != 0) continue;
        int fd = 0;
        const char* first = s.data() + dir.size();
        const auto [end, ec] = std::from_chars(first, s.data() + s.size(), fd);
        if (ec == std::errc() && end == s.data() + s.size() && fd >= 0) return fd;
    }
    return -1;
}

// `path` with every symbolic link along it followed (a dangling link gives its target: the
// file to create), so that the target is what gets replaced, in the target's directory. The
// walk stops at a name of one of our descriptors (descriptorNamed; its links, such as
// /proc/self/fd/1 -> pipe:[123], do not name files).
fs::path followLinks(const fs::path& path) {
    fs::path p = path;
    for (int depth = 0; depth < 40; ++depth) {
        std::error_code ec;
        if (descriptorNamed(p) >= 0 || !fs::is_symlink(fs::symlink_status(p, ec))) return p;
        const fs::path to = fs::read_symlink(p, ec);
        if (ec) throw Error(fmt::format("{}: cannot read the symbolic link ({})", path.string(), ec.message()));
        p = to.is_absolute() ? to : p.parent_path() / to;
    }
    throw Error(fmt::format("{}: too many levels of symbolic links", path.string()));
}

// Our standard output or error when `info` is the same file (the shell's `-o log >> log`).
int standardStreamOf(const struct stat& info) {
    for (int fd : {1, 2}) {
        struct stat s {};
        if (::fstat(fd, &s) == 0 && s.st_dev == info.st_dev && s.st_ino == info.st_ino) return fd;
    }
    return -1;
}

}  // namespace

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
    if (path == "-") {  // standard output, written as it comes
        file_ = stdout;
        direct_ = true;
        return;
    }
    checkPath(path);
    const fs::path target = followLinks(fs::path(path));
    if (const int fd = descriptorNamed(target); fd >= 0) {
        openDescriptor(fd);
        return;
    }
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
    struct stat info {};
    if (fs::exists(st)) {
        if (::stat(target.c_str(), &info) != 0)
            throw Error(fmt::format("{}: cannot stat ({})", path, std::strerror(errno)));
        if (const int fd = standardStreamOf(info); fd >= 0) {  // written where the shell points it
            openDescriptor(fd);
            return;
        }
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
    if (keepMode_) {
        // The replacement is ours (owner and group of this process), as with cp and install:
        // a set-user-ID or set-group-ID bit stays only where its owner (group) is unchanged,
        // so running as root over another user's setuid file never makes a root-owned one.
        struct stat now {};
        if (::fstat(fd, &now) == 0) {
            if (now.st_uid != info.st_uid) mode &= ~mode_t(S_ISUID | S_ISGID);
            if (now.st_gid != info.st_gid) mode &= ~mode_t(S_ISGID);
        } else {
            mode &= ~mode_t(S_ISUID | S_ISGID);
        }
    }
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

void AtomicFile::openDescriptor(int fd) {
    direct_ = true;
    if (fd == 1 || fd == 2) {  // through the stream, in order with what else goes there
        file_ = fd == 1 ? stdout : stderr;
        return;
    }
    // A copy of the descriptor: it writes at the descriptor's offset (appends where the
    // shell opened it with >>) and closing it leaves the original open.
    const int copy = ::fcntl(fd, F_DUPFD_CLOEXEC, 3);
    if (copy < 0 || !(file_ = ::fdopen(copy, "wb"))) {
        const int e = errno;
        if (copy >= 0) ::close(copy);
        throw Error(fmt::format("{}: descriptor {} cannot be written ({})", path_, fd, std::strerror(e)));
    }
}

AtomicFile::~AtomicFile() {
    if (!file_) return;
    if (direct_) {
        if (file_ != stdout && file_ != stderr) std::fclose(file_);
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
        const bool ok = std::fflush(file_) == 0 && (file_ == stdout || file_ == stderr || std::fclose(file_) == 0);
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
    checkPath(dir);
    std::error_code ec;
    const fs::path p(dir);
    if (fs::exists(p, ec) && !fs::is_directory(p, ec))
        throw Error(fmt::format("{}: exists and is not a directory (an output directory was expected)", dir));
    fs::create_directories(p, ec);
    if (ec) throw Error(fmt::format("{}: cannot create the output directory ({})", dir, ec.message()));
}

OutputFolder::OutputFolder(const std::string& dir) {
    checkPath(dir);
    std::error_code ec;
    for (fs::path p = fs::path(dir).lexically_normal(); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
        created_.insert(created_.begin(), p.string());
        if (p == p.parent_path()) break;
    }
    makeDirectories(dir);
}

OutputFolder::~OutputFolder() {
    for (auto it = created_.rbegin(); it != created_.rend(); ++it) {
        std::error_code ec;
        if (!fs::is_directory(*it, ec) || !fs::is_empty(*it, ec) || ec) break;  // holds something: kept
        fs::remove(*it, ec);
    }
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
