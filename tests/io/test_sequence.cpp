// Frame sequences (io/sequence.hpp): numbered file patterns, frame ranges, folders, raw
// streams cut short, and the ordered pipeline (core/parallel.hpp) that runs them.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include <sys/stat.h>

#include "ssfx/core/error.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/io/sequence.hpp"
#include "tests/support/test_support.hpp"

namespace ssfx {
namespace {

namespace fs = std::filesystem;

TEST(FramePattern, FormatsTheFrameNumber) {
    EXPECT_EQ(io::FramePattern("in/frame.%04d.png").path(7), "in/frame.0007.png");
    EXPECT_EQ(io::FramePattern("in/frame.%04d.png").path(12345), "in/frame.12345.png");
    EXPECT_EQ(io::FramePattern("%d.png").path(42), "42.png");
    EXPECT_EQ(io::FramePattern("100%%_%02d.png").path(3), "100%_03.png");
    EXPECT_TRUE(io::FramePattern::isPattern("a%03d.png"));
    EXPECT_FALSE(io::FramePattern::isPattern("100%%.png"));
    EXPECT_FALSE(io::FramePattern::isPattern("plain.png"));
}

TEST(FramePattern, RefusesWhatIsNotOneFrameNumber) {
    for (const char* bad : {"plain.png", "%s.png", "%4d.png", "%-4d.png", "%00d.png", "%d_%d.png", "%010d.png",
                            "f%d/x.png", "trailing%"}) {
        const std::string message = test::errorOf([&] { io::FramePattern p(bad); });
        EXPECT_NE(message.find("frame pattern"), std::string::npos) << bad << ": " << message;
    }
}

TEST(FramePattern, FindsTheExistingFramesItNames) {
    const fs::path dir = fs::path(test::outDir()) / "pattern";
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const char* name :
         {"f.0003.png", "f.0001.png", "f.0010.png", "f.3.png", "f.00002.png", "g.0004.png", "f.0005.png.bak"})
        std::ofstream(dir / name) << "x";
    const io::FramePattern p((dir / "f.%04d.png").string());
    EXPECT_EQ(p.existing(), (std::vector<int>{1, 3, 10}));  // not f.3 or f.00002: other widths
    EXPECT_TRUE(io::FramePattern((dir / "none.%04d.png").string()).existing().empty());
}

TEST(FramePattern, NamesTheFrameOfAFileName) {
    const io::FramePattern p("in/f.%04d.png");
    EXPECT_EQ(p.frameOf("f.0007.png"), 7);
    EXPECT_EQ(p.frameOf("f.12345.png"), 12345);
    for (const char* other : {"f.7.png", "f.+007.png", "f.00007.png", "g.0007.png", "f.0007.png.bak", "f..png"})
        EXPECT_EQ(p.frameOf(other), -1) << other;
    EXPECT_EQ(io::FramePattern("%d").frameOf("42"), 42);
    EXPECT_EQ(io::FramePattern("%d").frameOf("042"), -1);
    for (int n : {0, 9, 10, 999999999}) EXPECT_EQ(p.frameOf(fs::path(p.path(n)).filename().string()), n);
}

// Issue #35 items 6 and 7: the frames of a range are checked against the folder's listing
// (no list of a billion numbers), and a frame that is not a regular file is refused by name
// before anything opens it (a FIFO would block the run).
TEST(FramePattern, SelectsFramesLazilyAndRefusesWhatIsNotAFile) {
    const fs::path dir = fs::path(test::outDir()) / "select";
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const char* name : {"f.0001.png", "f.0002.png", "f.0003.png", "f.0005.png"}) std::ofstream(dir / name) << "x";
    const io::FramePattern p((dir / "f.%04d.png").string());
    EXPECT_EQ(p.select(nullptr), (std::vector<int>{1, 2, 3, 5}));
    const io::FrameRange two = io::FrameRange::parse("2-3"), all = io::FrameRange::parse("0-999999999"),
                         gap = io::FrameRange::parse("1-5");
    EXPECT_EQ(p.select(&two), (std::vector<int>{2, 3}));
    const std::string m = test::errorOf([&] { p.select(&all); });
    EXPECT_NE(m.find("999999996 of 1000000000 frames are missing, the first: " + p.path(0)), std::string::npos) << m;
    const std::string g = test::errorOf([&] { p.select(&gap); });
    EXPECT_NE(g.find("1 of 5 frames are missing, the first: " + p.path(4)), std::string::npos) << g;
    const io::FramePattern none((dir / "none.%d.png").string());
    EXPECT_NE(test::errorOf([&] { none.select(nullptr); }).find("no files match"), std::string::npos);

    ASSERT_EQ(::mkfifo((dir / "f.0004.png").c_str(), 0600), 0);
    fs::create_directories(dir / "f.0006.png");
    const std::string fifo = test::errorOf([&] { p.select(&gap); });
    EXPECT_NE(fifo.find(p.path(4) + ": a FIFO, not a regular file"), std::string::npos) << fifo;
    const std::string folder = test::errorOf([&] { p.select(nullptr); });  // the FIFO first
    EXPECT_NE(folder.find("a FIFO"), std::string::npos) << folder;
    fs::remove(dir / "f.0004.png");
    EXPECT_NE(test::errorOf([&] { p.select(nullptr); }).find(p.path(6) + ": a folder"), std::string::npos);
}

TEST(FrameRange, ParsesRangesAndRefusesTheRest) {
    const io::FrameRange r = io::FrameRange::parse("1-4"), one = io::FrameRange::parse("7");
    EXPECT_EQ(r.first, 1);
    EXPECT_EQ(r.last, 4);
    EXPECT_EQ(r.count(), 4);
    EXPECT_EQ(one.first, 7);
    EXPECT_EQ(one.last, 7);
    EXPECT_EQ(io::FrameRange::parse("0-999999999").count(), 1000000000);
    for (const char* bad : {"", "5-2", "a-b", "-3", "1-", "1-2-3", "1 - 2", "9999999999"}) {
        const std::string message = test::errorOf([&] { io::FrameRange::parse(bad); });
        EXPECT_NE(message.find("--frames"), std::string::npos) << bad << ": " << message;
    }
}

TEST(PngFilesIn, ListsAFoldersPngsByName) {
    const fs::path dir = fs::path(test::outDir()) / "folder";
    fs::remove_all(dir);
    fs::create_directories(dir / "sub.png");
    for (const char* name : {"b.png", "a.PNG", "c.txt"}) std::ofstream(dir / name) << "x";
    EXPECT_EQ(io::pngFilesIn(dir.string()), (std::vector<std::string>{"a.PNG", "b.png"}));
    EXPECT_NE(test::errorOf([&] { io::pngFilesIn((dir / "b.png").string()); }).find("not a folder"), std::string::npos);
    fs::remove_all(dir / "sub.png");
    fs::create_directories(dir / "empty");
    EXPECT_NE(test::errorOf([&] { io::pngFilesIn((dir / "empty").string()); }).find("no .png"), std::string::npos);
}

// A stream of `bytes` bytes 0, 1, 2, ... (mod 251) in a temporary file.
std::FILE* streamOf(std::size_t bytes) {
    std::FILE* f = std::tmpfile();
    for (std::size_t i = 0; i < bytes; ++i) std::fputc(int(i % 251), f);
    std::rewind(f);
    return f;
}

TEST(RawFrames, ReadsWholeFramesAndNamesTheOneCutShort) {
    const int w = 5, h = 3;
    const std::size_t frame = std::size_t(w) * h * 4;
    std::FILE* f = streamOf(2 * frame + 7);
    io::RawFrameReader reader(f, w, h, "test stream");
    ImageRgba8 img;
    ASSERT_TRUE(reader.read(img));
    EXPECT_EQ(img.width(), w);
    EXPECT_EQ(img(1, 0).r, 4);  // byte 4: the second pixel's red
    ASSERT_TRUE(reader.read(img));
    EXPECT_EQ(img(0, 0).r, std::uint8_t(frame % 251));
    const std::string message = test::errorOf([&] { reader.read(img); });
    EXPECT_NE(message.find("test stream: raw frame 2 is cut short: 7 of 60 bytes"), std::string::npos) << message;
    EXPECT_EQ(reader.framesRead(), 2);
    std::fclose(f);

    std::FILE* empty = streamOf(0);
    io::RawFrameReader none(empty, w, h, "empty");
    EXPECT_FALSE(none.read(img));
    std::fclose(empty);
    EXPECT_THROW(io::RawFrameReader(stdin, 0, 3, "bad size"), Error);
}

TEST(RawFrames, WriterWritesEveryFrameWhole) {
    const std::string path = test::outDir() + "/frames.rgba";
    ImageRgba8 a(4, 2, Rgba8{1, 2, 3, 4}), b(4, 2, Rgba8{5, 6, 7, 8});
    {
        io::AtomicFile out(path);
        io::RawFrameWriter writer(out);
        writer.write(a.view());
        writer.write(b.view());
        EXPECT_EQ(writer.framesWritten(), 2);
        out.commit();
    }
    EXPECT_EQ(fs::file_size(path), 2u * 4 * 2 * 4);
    std::FILE* f = std::fopen(path.c_str(), "rb");
    io::RawFrameReader reader(f, 4, 2, path);
    ImageRgba8 img;
    ASSERT_TRUE(reader.read(img));
    EXPECT_EQ(img, a);
    ASSERT_TRUE(reader.read(img));
    EXPECT_EQ(img, b);
    EXPECT_FALSE(reader.read(img));
    std::fclose(f);
}

TEST(OrderedPipeline, ConsumesInOrderWithBoundedItemsInFlight) {
    for (int threads : {1, 2, 8}) {
        const int n = 200, inFlight = 4;
        std::vector<int> slots(inFlight, -1), consumed;
        std::atomic<int> live{0}, most{0};
        orderedPipeline(
            inFlight, Exec{threads},
            [&](int i) {
                if (i >= n) return false;
                const int now = ++live;
                for (int seen = most.load(); now > seen && !most.compare_exchange_weak(seen, now);) {
                }
                slots[std::size_t(i % inFlight)] = i;
                return true;
            },
            [&](int i) {
                if (i % 7 == 0) std::this_thread::yield();  // uneven work: out-of-order finishes
                slots[std::size_t(i % inFlight)] *= 3;
            },
            [&](int i) {
                consumed.push_back(slots[std::size_t(i % inFlight)]);
                --live;
            });
        ASSERT_EQ(consumed.size(), std::size_t(n)) << threads;
        for (int i = 0; i < n; ++i) EXPECT_EQ(consumed[std::size_t(i)], 3 * i) << threads;
        EXPECT_LE(most.load(), inFlight) << threads;
    }
}

TEST(OrderedPipeline, AnErrorInWorkStopsItAndIsRethrown) {
    int consumed = 0;
    EXPECT_THROW(orderedPipeline(
                     3, Exec{2}, [&](int i) { return i < 100; },
                     [&](int i) {
                         if (i == 10) throw Error("frame 10 is bad");
                     },
                     [&](int) { ++consumed; }),
                 Error);
    EXPECT_EQ(consumed, 10);
}

// Issue #35 item 5: a bad item k leaves exactly items 0..k-1 consumed, however the threads
// are timed. Here the bad item fails at once while the ones before it are slow, the case
// where a pipeline that stops at the first exception loses finished work; many rounds, more
// threads than cores, and a busy thread beside them for uneven scheduling.
TEST(OrderedPipeline, ABadItemLeavesExactlyTheItemsBeforeItConsumed) {
    std::atomic<bool> stop{false};
    std::thread load([&] {
        for (volatile unsigned x = 0; !stop.load(std::memory_order_relaxed);) x = x + 1;
    });
    for (int round = 0; round < 60; ++round) {
        const int threads = 2 << (round % 3), bad = 1 + round % 7, inFlight = 2 * threads;
        std::vector<int> consumed;
        std::string message;
        try {
            orderedPipeline(
                inFlight, Exec{threads}, [&](int i) { return i < 40; },
                [&](int i) {
                    if (i == bad) throw Error(fmt::format("item {} is bad", i));
                    if (i < bad) std::this_thread::sleep_for(std::chrono::microseconds(200 * (bad - i)));
                },
                [&](int i) { consumed.push_back(i); });
        } catch (const Error& e) {
            message = e.what();
        }
        EXPECT_EQ(message, fmt::format("item {} is bad", bad)) << "round " << round;
        std::vector<int> want(static_cast<std::size_t>(bad));
        for (int i = 0; i < bad; ++i) want[std::size_t(i)] = i;
        EXPECT_EQ(consumed, want) << "round " << round << ", threads " << threads;
    }
    stop = true;
    load.join();
}

}  // namespace
}  // namespace ssfx
