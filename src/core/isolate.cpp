// See isolate.hpp. The child writes its result to an anonymous in-memory file (memfd) that
// the parent reads after the child has exited: no pipe to drain while waiting, no temporary
// file on disk. Record: one tag byte ('S' success, 'E' error) then the payload.
#include "ssfx/core/isolate.hpp"

#include <fmt/format.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <new>

#include "ssfx/core/error.hpp"

// Sanitizer runtimes (ASan, libFuzzer) run a death callback when they report an error; in a
// child that is the parent's callback (libFuzzer would save the parent's input as a crash of
// its own). Weak: absent without sanitizers.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace ssfx {

namespace {

bool writeAll(int fd, const void* data, std::size_t size) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    while (size > 0) {
        const ssize_t n = ::write(fd, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        size -= std::size_t(n);
    }
    return true;
}

[[noreturn]] void child(int fd, const std::function<std::vector<std::uint8_t>()>& work) {
    if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
    std::signal(SIGINT, SIG_DFL);  // the parent's handlers (io::AtomicFile's clean-up) are not ours
    std::signal(SIGTERM, SIG_DFL);
    char tag = 'S';
    std::vector<std::uint8_t> out;
    std::string message;
    try {
        out = work();
    } catch (const std::bad_alloc&) {
        tag = 'E';
        message = "out of memory";
    } catch (const std::exception& e) {
        tag = 'E';
        message = e.what();
    } catch (...) {
        tag = 'E';
        message = "an unknown exception";
    }
    const bool ok = writeAll(fd, &tag, 1) &&
                    (tag == 'S' ? writeAll(fd, out.data(), out.size()) : writeAll(fd, message.data(), message.size()));
    ::_exit(ok ? 0 : 3);  // no destructors, no atexit (the parent's), no leak check of a forked copy
}

}  // namespace

std::vector<std::uint8_t> runIsolated(const std::function<std::vector<std::uint8_t>()>& work, const std::string& what,
                                      const std::string& parser) {
    const int fd = ::memfd_create("ssfx-isolated", MFD_CLOEXEC);
    if (fd < 0)
        throw Error(fmt::format("{}: cannot create a memory file for the {} ({})", what, parser, std::strerror(errno)));
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    const pid_t pid = ::fork();
    if (pid < 0) throw Error(fmt::format("{}: cannot start the {} ({})", what, parser, std::strerror(errno)));
    if (pid == 0) child(fd, work);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw Error(fmt::format("{}: lost the {} ({})", what, parser, std::strerror(errno)));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        const std::string how = WIFSIGNALED(status)
                                    ? fmt::format("signal {}, {}", WTERMSIG(status), strsignal(WTERMSIG(status)))
                                    : fmt::format("exit status {}", WEXITSTATUS(status));
        throw Error(fmt::format("{}: the {} stopped abnormally ({}); the file is malformed or not what its name says",
                                what, parser, how));
    }
    struct stat st {};
    char tag = 0;
    if (::fstat(fd, &st) != 0 || st.st_size < 1 || ::pread(fd, &tag, 1, 0) != 1)
        throw Error(fmt::format("{}: the {} returned nothing", what, parser));
    std::vector<std::uint8_t> bytes(std::size_t(st.st_size) - 1);
    for (std::size_t at = 0; at < bytes.size();) {
        const ssize_t n = ::pread(fd, bytes.data() + at, bytes.size() - at, off_t(at + 1));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw Error(fmt::format("{}: cannot read the {}'s result", what, parser));
        at += std::size_t(n);
    }
    if (tag == 'E') throw Error(std::string(bytes.begin(), bytes.end()));
    if (tag != 'S') throw Error(fmt::format("{}: the {} returned a malformed result", what, parser));
    return bytes;
}

}  // namespace ssfx
