// What -o does to what it names (AtomicFile, png.hpp): regular files replaced atomically
// with their mode kept, symbolic links followed, FIFOs written into, read-only files
// refused, temporary names that fit, temporaries removed on SIGTERM. Every file here is one
// the test makes (never the real /dev).
#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "ssfx/core/error.hpp"
#include "ssfx/io/png.hpp"

using namespace ssfx;
namespace fs = std::filesystem;

namespace {

fs::path freshDir(const std::string& name) {
    const fs::path d = fs::path(SSFX_TEST_OUT_DIR) / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::span<const std::uint8_t> bytesOf(const std::string& s) {
    return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

std::string contents(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int temporaries(const fs::path& dir) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string().rfind(".ssfx-", 0) == 0;
    return n;
}

mode_t modeOf(const fs::path& p) {
    struct stat st {};
    ::stat(p.c_str(), &st);
    return st.st_mode & 07777;
}

}  // namespace

TEST(AtomicFile, AnExistingFileKeepsItsModeAndANewOneGetsTheUmasks) {
    const fs::path d = freshDir("atomic_mode");
    const fs::path f = d / "private.png";
    io::writeFileAtomic(f.string(), bytesOf("old"));
    ::chmod(f.c_str(), 0600);
    io::writeFileAtomic(f.string(), bytesOf("new"));
    EXPECT_EQ(contents(f), "new");
    EXPECT_EQ(modeOf(f), mode_t(0600));
    ::chmod(f.c_str(), 0640);
    io::writeFileAtomic(f.string(), bytesOf("newer"));
    EXPECT_EQ(modeOf(f), mode_t(0640));
    const mode_t mask = ::umask(0);
    ::umask(mask);
    const fs::path g = d / "fresh.png";
    io::writeFileAtomic(g.string(), bytesOf("x"));
    EXPECT_EQ(modeOf(g), mode_t(0666 & ~mask));
    EXPECT_EQ(temporaries(d), 0);
}

TEST(AtomicFile, ASymbolicLinkIsFollowedAndItsTargetReplaced) {
    const fs::path d = freshDir("atomic_link");
    fs::create_directories(d / "real");
    const fs::path target = d / "real" / "out.png", link = d / "link.png";
    io::writeFileAtomic(target.string(), bytesOf("old"));
    fs::create_symlink("real/out.png", link);  // relative to the link's directory
    io::writeFileAtomic(link.string(), bytesOf("new"));
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
    EXPECT_EQ(contents(target), "new");
    // A dangling link creates its target.
    const fs::path dangling = d / "dangling.png";
    fs::create_symlink("real/later.png", dangling);
    io::writeFileAtomic(dangling.string(), bytesOf("made"));
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dangling)));
    EXPECT_EQ(contents(d / "real" / "later.png"), "made");
    EXPECT_EQ(temporaries(d), 0);
    EXPECT_EQ(temporaries(d / "real"), 0);
}

TEST(AtomicFile, AReadOnlyFileIsRefusedAndLeftAlone) {
    const fs::path d = freshDir("atomic_readonly");
    const fs::path f = d / "keep.png";
    io::writeFileAtomic(f.string(), bytesOf("precious"));
    ::chmod(f.c_str(), 0444);  // refused even for root, who may write anything
    try {
        io::writeFileAtomic(f.string(), bytesOf("overwritten"));
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("read-only"), std::string::npos) << e.what();
    }
    EXPECT_EQ(contents(f), "precious");
    EXPECT_EQ(temporaries(d), 0);
}

TEST(AtomicFile, ANameOfTheLongestLengthFits) {
    const fs::path d = freshDir("atomic_long");
    const fs::path f = d / (std::string(251, 'n') + ".png");  // 255 bytes: NAME_MAX
    io::writeFileAtomic(f.string(), bytesOf("long"));
    EXPECT_EQ(contents(f), "long");
}

TEST(AtomicFile, AFifoIsWrittenIntoNotReplaced) {
    const fs::path d = freshDir("atomic_fifo");
    const fs::path fifo = d / "pipe.png";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
    std::string got;
    std::thread reader([&] { got = contents(fifo); });
    io::writeFileAtomic(fifo.string(), bytesOf("through the pipe"));
    reader.join();
    EXPECT_EQ(got, "through the pipe");
    EXPECT_TRUE(fs::is_fifo(fs::status(fifo)));
    EXPECT_EQ(temporaries(d), 0);
}

TEST(AtomicFile, ADirectoryIsAnError) {
    const fs::path d = freshDir("atomic_dir");
    EXPECT_THROW(io::writeFileAtomic(d.string(), bytesOf("x")), Error);
}

TEST(AtomicFile, SigtermDuringAWriteLeavesNoTemporary) {
    // A child process starts an output, writes part of it and is sent SIGTERM before the
    // commit: the temporary goes, the old file stays, and the child dies by the signal.
    const fs::path d = freshDir("atomic_signal");
    const fs::path f = d / "out.png";
    io::writeFileAtomic(f.string(), bytesOf("old"));
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        io::AtomicFile out(f.string());
        out.write(bytesOf("half of it"));
        ::kill(::getpid(), SIGTERM);
        ::_exit(0);  // not reached
    }
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
    EXPECT_EQ(temporaries(d), 0);
    EXPECT_EQ(contents(f), "old");
}

// ---- bounded reads -------------------------------------------------------------------

TEST(BoundedRead, TheSignatureIsCheckedFirstAndTheCapStopsAnEndlessInput) {
    // A FIFO fed without end by a writer thread (what /dev/zero does, without touching
    // /dev): a PNG read refuses it after its first 8 bytes, a JSON read at its 16 MiB cap.
    std::signal(SIGPIPE, SIG_IGN);
    const fs::path d = freshDir("bounded_fifo");
    for (const char* kind : {"png", "json"}) {
        const fs::path fifo = d / (std::string("endless.") + kind);
        ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
        std::thread writer([&] {
            const int fd = ::open(fifo.c_str(), O_WRONLY);
            if (fd < 0) return;
            std::vector<char> zeros(1 << 16, ' ');
            while (::write(fd, zeros.data(), zeros.size()) > 0) {
            }
            ::close(fd);  // the reader closed its end: EPIPE
        });
        try {
            if (std::string(kind) == "png")
                io::readPng(fifo.string());
            else
                io::readFile(fifo.string(), io::kMaxJsonFileBytes, "JSON");
            ADD_FAILURE() << "no error for " << kind;
        } catch (const Error& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find(fifo.string()), std::string::npos) << m;
            EXPECT_NE(m.find(std::string(kind) == "png" ? "wrong signature" : "16777216 bytes"), std::string::npos)
                << m;
        }
        writer.join();
    }
}

TEST(BoundedRead, ADirectoryAndAFileAboveTheCapAreNamedAsSuch) {
    const fs::path d = freshDir("bounded_files");
    try {
        io::readPng(d.string());
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
    }
    const fs::path f = d / "big.json";
    io::writeFileAtomic(f.string(), bytesOf(std::string(1000, ' ')));
    EXPECT_EQ(io::readFile(f.string(), 1000, "JSON").size(), 1000u);
    EXPECT_THROW(io::readFile(f.string(), 999, "JSON"), Error);
}

TEST(PixelLimit, ALowerLimitRefusesFromTheHeaderAndIsRestored) {
    // A 4x4 image under a 15-pixel limit: refused by every decoder, whole-file APNG included.
    const auto png = io::encodePng(ImageRgba8(4, 4).view());
    io::Animation a;
    a.frames.assign(2, io::Frame{ImageRgba8(3, 3), 1, 25});  // 18 pixels in all, 9 per frame
    const auto apng = io::encodeApng(a);
    io::setMaxPixels(15);
    EXPECT_THROW(io::decodePng(png, "four.png"), Error);
    EXPECT_THROW(io::decodeApng(apng, "two.png"), Error);  // all frames together: 18 > 15
    io::ApngReader streamed(apng, "two.png");              // a frame at a time: 9 <= 15
    EXPECT_NE(streamed.next(), nullptr);
    EXPECT_THROW(io::setMaxPixels(0), Error);
    EXPECT_THROW(io::setMaxPixels(kMaxPixels + 1), Error);
    io::setMaxPixels(kMaxPixels);
    EXPECT_EQ(io::decodePng(png, "four.png").width(), 4);
    EXPECT_EQ(io::maxPixels(), kMaxPixels);
}

TEST(OutputSet, FilesOfASetAppearTogetherOrNotAtAll) {
    const fs::path d = freshDir("output_set");
    io::writeFileAtomic((d / "a.txt").string(), bytesOf("old a"));
    try {
        io::OutputSet set;
        io::writeFileAtomic((d / "a.txt").string(), bytesOf("new a"));
        io::writeFileAtomic((d / "b.txt").string(), bytesOf("new b"));
        EXPECT_EQ(contents(d / "a.txt"), "old a");  // nothing moves before the set's commit
        EXPECT_FALSE(fs::exists(d / "b.txt"));
        throw Error("a late failure");
    } catch (const Error&) {
    }
    EXPECT_EQ(contents(d / "a.txt"), "old a");
    EXPECT_FALSE(fs::exists(d / "b.txt"));
    EXPECT_EQ(temporaries(d), 0);
    {
        io::OutputSet set;
        io::writeFileAtomic((d / "a.txt").string(), bytesOf("new a"));
        {
            io::OutputSet inner;  // joins the outer set
            io::writeFileAtomic((d / "b.txt").string(), bytesOf("new b"));
            inner.commit();
        }
        EXPECT_FALSE(fs::exists(d / "b.txt"));
        set.commit();
    }
    EXPECT_EQ(contents(d / "a.txt"), "new a");
    EXPECT_EQ(contents(d / "b.txt"), "new b");
    EXPECT_EQ(temporaries(d), 0);
}

// Issue #35 item 3: a name of one of this process's descriptors (/proc/self/fd/N, /dev/fd/N,
// and so /dev/stdout) is written into through the descriptor, at its offset: a file the
// shell opened with >> keeps its content, a pipe gets the bytes; never renamed over.
TEST(AtomicFile, DescriptorNamesAreWrittenIntoNotReplaced) {
    const fs::path d = freshDir("atomic_fd");
    const fs::path log = d / "log.bin";
    { std::ofstream(log) << "earlier\n"; }
    const int fd = ::open(log.c_str(), O_WRONLY | O_APPEND);
    ASSERT_GE(fd, 0);
    const std::string names[] = {fmt::format("/proc/self/fd/{}", fd), fmt::format("/dev/fd/{}", fd)};
    for (const std::string& name : names) {
        io::AtomicFile f(name);
        EXPECT_TRUE(f.direct()) << name;
        f.write({reinterpret_cast<const std::uint8_t*>("new\n"), 4});
        f.commit();
    }
    ::close(fd);
    EXPECT_EQ(contents(log), "earlier\nnew\nnew\n");
    EXPECT_EQ(temporaries(d), 0);

    int p[2];
    ASSERT_EQ(::pipe(p), 0);
    {
        io::AtomicFile f(fmt::format("/proc/self/fd/{}", p[1]));
        f.write({reinterpret_cast<const std::uint8_t*>("abc"), 3});
        f.commit();
    }
    ::close(p[1]);
    char buf[8] = {};
    EXPECT_EQ(::read(p[0], buf, sizeof buf), 3);
    EXPECT_EQ(std::string(buf), "abc");
    ::close(p[0]);

    // A descriptor that is not open is an error naming it, not a file created in /proc.
    EXPECT_THROW(io::AtomicFile("/dev/fd/987"), Error);
}
