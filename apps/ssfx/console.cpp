#include "apps/ssfx/console.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "ssfx/core/error.hpp"
#include "ssfx/io/png.hpp"

namespace ssfx::cli {

namespace {
std::atomic<bool> gQuiet{false}, gForceProgress{false};
std::atomic<ProgressLine*> gActive{nullptr};  // the innermost line alive

void endActive() {
    if (ProgressLine* line = gActive.load()) line->end();
}

std::string clock(double seconds) {
    const auto s = std::int64_t(seconds + 0.5);
    return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
                     : fmt::format("{}:{:02}", s / 60, s % 60);
}
}  // namespace

namespace {
bool gStdoutClosed = false;
}  // namespace

int reportError(std::string_view message) {
    endActive();
    fmt::print(stderr, "ssfx: error: {}\n", message);
    return 2;
}

void guardStdout() {
    if (::fcntl(STDOUT_FILENO, F_GETFD) != -1 || errno != EBADF) return;
    // /dev/full takes descriptor 1 and fails every write (ENOSPC), which finishStdout() reports.
    // Not close-on-exec: open() returns 1 itself when 0 is open, and descriptor 1 is inherited.
    const int fd = ::open("/dev/full", O_WRONLY);
    if (fd >= 0 && fd != STDOUT_FILENO) ::dup2(fd, STDOUT_FILENO), ::close(fd);
    gStdoutClosed = true;
}

bool finishStdout() {
    errno = 0;
    if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return true;
    const int e = errno;
    reportError(fmt::format("cannot write to standard output ({})", gStdoutClosed ? "it is closed"
                                                                    : e           ? std::strerror(e)
                                                                                  : "write error"));
    return false;
}

void setQuiet(bool q) { gQuiet = q; }
bool quiet() { return gQuiet; }
void setForceProgress(bool force) { gForceProgress = force; }

void printResult(std::string_view text) {
    if (quiet()) return;
    endActive();
    std::fwrite(text.data(), 1, text.size(), stdout);
}

void printNote(std::string_view prefix, std::string_view text) {
    if (quiet()) return;
    endActive();
    fmt::print(stderr, "{}: {}\n", prefix, text);
}

void reportProgress(const Progress& p) {
    if (ProgressLine* line = gActive.load()) line->report(p);
}

void writeOutput(const std::string& path, const std::string& text) {
    if (path != "-") return io::writeTextAtomic(path, text);
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
        throw Error(
            fmt::format("cannot write to standard output ({})", gStdoutClosed ? "it is closed" : std::strerror(errno)));
}

bool anyStdout(std::initializer_list<std::string_view> paths) {
    int n = 0;
    for (auto p : paths) n += p == "-";
    if (n > 1) throw Error("only one output can go to stdout ('-')");
    std::vector<std::pair<std::string_view, std::filesystem::path>> files;
    for (auto p : paths) {
        if (p.empty() || p == "-") continue;
        std::error_code ec;
        const auto full =
            std::filesystem::weakly_canonical(std::filesystem::absolute(std::filesystem::path(p), ec), ec);
        for (const auto& [other, otherFull] : files)
            if (full == otherFull)
                throw Error(fmt::format("'{}' and '{}' name one file: give each output its own", other, p));
        files.emplace_back(p, full);
    }
    return n == 1;
}

ProgressLine::ProgressLine(std::string prefix, bool logSteps)
    : outer_(gActive.exchange(this)),
      prefix_(std::move(prefix)),
      start_(Clock::now()),
      live_(gForceProgress || ::isatty(STDERR_FILENO) == 1),
      logSteps_(logSteps) {}

ProgressLine::~ProgressLine() {
    end();
    gActive = outer_;
}

void ProgressLine::end() {
    const std::lock_guard lock(mutex_);
    if (drawn_) draw(true);
}

ProgressFn ProgressLine::fn() {
    return [this](const Progress& p) { report(p); };
}

void ProgressLine::report(const Progress& p) {
    if (quiet()) return;
    const std::lock_guard lock(mutex_);
    const auto now = Clock::now();
    if (p.what != what_ || !started_) {
        if (drawn_) draw(true);
        // The first step began when the line was made (before its first unit was done).
        if (started_) start_ = now;
        started_ = true;
        what_ = p.what;
        unit_ = p.unit;
        lastDraw_ = {};
        done_ = total_ = 0;
        // Off a terminal a step is one line, once, not a line per count.
        if (!live_ && logSteps_) fmt::print(stderr, "{}: {}\n", prefix_, what_);
    }
    if (p.done < done_) return;  // reports from several threads may arrive out of order
    const bool wasLast = total_ > 0 && done_ >= total_;
    done_ = p.done;
    total_ = p.total;
    if (!live_ || wasLast) return;
    const bool last = total_ > 0 && done_ >= total_;
    if (last || now - lastDraw_ >= std::chrono::milliseconds(100)) {
        lastDraw_ = now;
        draw(last);  // the last count ends the line
    }
}

void ProgressLine::draw(bool final) {
    if (!live_) return;
    std::string line = fmt::format("{}: {}", prefix_, what_);
    if (done_ > 0 || total_ > 0) {
        const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
        line += total_ > 0 ? fmt::format("  {}/{} {}", done_, total_, unit_) : fmt::format("  {} {}", done_, unit_);
        if (seconds > 0 && done_ > 0) {
            const double rate = double(done_) / seconds;
            line += fmt::format("  {:.{}f} {}/s", rate, rate >= 100 ? 0 : rate >= 10 ? 1 : 2, unit_);
            if (final)
                line += fmt::format("  {}", clock(seconds));
            else if (total_ > 0)
                line += fmt::format("  ETA {}", clock(double(total_ - done_) / rate));
        }
    }
    // \r and "erase to the end of the line" (ECMA-48 EL): the line is redrawn in place.
    fmt::print(stderr, "\r{}\x1b[K{}", line, final ? "\n" : "");
    std::fflush(stderr);
    drawn_ = !final;
}

}  // namespace ssfx::cli
