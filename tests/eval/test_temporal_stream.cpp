// Temporal evaluation that streams its frames: the same figures as the in-memory
// computation, --source given on outputs the test writes, and an animation larger than
// the whole-file reader's all-frames limit scored by the CLI in about one x8 frame of memory.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "ssfx/core/error.hpp"
#include "ssfx/eval/temporal.hpp"
#include "ssfx/io/png.hpp"

using namespace ssfx;
namespace fs = std::filesystem;

extern char** environ;

namespace {

// A slanted dark bar moving right by 1/4 px per frame on white, drawn point-sampled at
// `scale` times the 1x size (aliased at every scale, as a renderer without AA draws it).
ImageRgba8 barFrame(int w, int h, int t, int scale) {
    ImageRgba8 img(w * scale, h * scale, Rgba8{255, 255, 255, 255});
    for (int y = 0; y < img.height(); ++y) {
        Rgba8* row = img.view().row(y);
        const double yy = (y + 0.5) / scale;
        for (int x = 0; x < img.width(); ++x) {
            const double u = (x + 0.5) / scale - 0.3 * w - 0.25 * t - 0.35 * yy;
            if (u >= 0 && u < 0.15 * w) row[x] = {20, 40, 200, 255};
        }
    }
    return img;
}

fs::path dirFor(const std::string& name) {
    const fs::path d = fs::path(SSFX_TEST_OUT_DIR) / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

// DIR/NAME.png, NAMEx2.png, NAMEx4.png, NAMEx8.png of `frames` frames (only `scales`).
void writeAnimation(const fs::path& dir, const std::string& name, int w, int h, int frames,
                    std::initializer_list<int> scales) {
    for (int s : scales) {
        const std::string file = (dir / (s == 1 ? name + ".png" : name + "x" + std::to_string(s) + ".png")).string();
        io::ApngWriter out(file, w * s, h * s, std::uint32_t(frames));
        for (int t = 0; t < frames; ++t) out.add(barFrame(w, h, t, s).view(), 1, 25);
        out.commit();
    }
}

#ifdef SSFX_CLI
// Runs the ssfx tool with `args` (stdout and stderr to files in `dir`); returns the exit
// status and the child's peak resident memory in MiB.
std::pair<int, double> runCli(const std::vector<std::string>& args, const fs::path& dir) {
    std::vector<std::string> all{SSFX_CLI};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, (dir / "cli.out").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 2, (dir / "cli.err").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid;
    const int spawned = posix_spawn(&pid, SSFX_CLI, &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    if (spawned != 0) return {-1, 0};
    int status = 0;
    struct rusage ru {};
    if (wait4(pid, &status, 0, &ru) != pid || !WIFEXITED(status)) return {-1, 0};
    return {WEXITSTATUS(status), double(ru.ru_maxrss) / 1024.0};  // ru_maxrss: kilobytes on Linux
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
#endif

}  // namespace

TEST(TemporalStream, ApngFramesGiveTheFiguresOfTheDrawnFramesAndOfANaiveComputation) {
    const int w = 40, h = 24, frames = 6;
    const fs::path dir = dirFor("temporal_small");
    writeAnimation(dir, "bar", w, h, frames, {1, 2, 4, 8});
    eval::TemporalOptions o;
    o.methods = {"noaa", "ddaa2", "ssaax2", "ssaax4"};
    const auto drawn = eval::evaluateTemporal(
        frames, [&](int t, int s) { return barFrame(w, h, t, s); }, o);
    const auto files = eval::apngFrames(dir.string(), "bar");
    const auto streamed = eval::evaluateTemporal(*files, o);
    ASSERT_EQ(streamed.results.size(), 4u);
    for (std::size_t m = 0; m < 4; ++m) {
        EXPECT_EQ(streamed.results[m].flickerLevels, drawn.results[m].flickerLevels) << o.methods[m];
        EXPECT_EQ(streamed.results[m].psnr, drawn.results[m].psnr) << o.methods[m];
        EXPECT_EQ(streamed.outputs[m], drawn.outputs[m]);
        // The definition written out (temporal.hpp), on the kept frames.
        double sum = 0;
        for (int t = 0; t < frames; ++t) {
            const int u = (t + 1) % frames;
            const auto &o0 = drawn.outputs[m][std::size_t(t)], &o1 = drawn.outputs[m][std::size_t(u)];
            const auto &r0 = drawn.truth[std::size_t(t)], &r1 = drawn.truth[std::size_t(u)];
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    for (int c = 0; c < 3; ++c) {
                        auto ch = [&](const ImageRgba8& i) { return double((&i(x, y).r)[c]) / 255.0; };
                        const double d = (ch(o1) - ch(o0)) - (ch(r1) - ch(r0));
                        sum += d * d;
                    }
        }
        EXPECT_NEAR(streamed.results[m].flickerLevels, 255.0 * std::sqrt(sum / (double(w) * h * 3 * frames)), 1e-9);
    }
    EXPECT_GT(streamed.results[0].flickerLevels, streamed.results[3].flickerLevels);  // ssaax4 steadier than noaa
    // Without keepOutputs nothing is kept, and onFrame sees every frame in order.
    o.keepOutputs = false;
    int seen = 0;
    o.onFrame = [&](int t, const std::vector<ImageRgba8>& outs, const ImageRgba8& ref) {
        EXPECT_EQ(t, seen++);
        EXPECT_EQ(outs.size(), 4u);
        EXPECT_EQ(ref, drawn.truth[std::size_t(t)]);
    };
    const auto again = eval::evaluateTemporal(*eval::apngFrames(dir.string(), "bar"), o);
    EXPECT_EQ(seen, frames);
    EXPECT_TRUE(again.outputs.empty() && again.truth.empty());
    EXPECT_EQ(again.results[1].flickerLevels, drawn.results[1].flickerLevels);
}

TEST(TemporalStream, GivenOutputsAreScoredAsTheComputedOnes) {
    const int w = 32, h = 20, frames = 5;
    const fs::path dir = dirFor("temporal_given");
    writeAnimation(dir, "bar", w, h, frames, {1, 8});
    eval::TemporalOptions o;
    o.methods = {"noaa", "fxaa3d", "ddaa2"};
    const auto computed = eval::evaluateTemporal(*eval::apngFrames(dir.string(), "bar"), o);
    // Write the outputs as another tool would, NAME_METHOD.png, and score them as given.
    std::vector<std::pair<std::string, std::string>> given;
    for (std::size_t m = 0; m < o.methods.size(); ++m) {
        io::Animation a;
        for (const auto& f : computed.outputs[m]) a.frames.push_back({f, 1, 25});
        const std::string file = (dir / ("bar_" + o.methods[m] + ".png")).string();
        io::writeApng(file, a);
        given.emplace_back(o.methods[m], file);
    }
    const auto scored = eval::evaluateTemporalGiven(*eval::apngFrames(dir.string(), "bar"), given, o);
    for (std::size_t m = 0; m < o.methods.size(); ++m) {
        EXPECT_EQ(scored.results[m].method, o.methods[m]);
        EXPECT_EQ(scored.results[m].flickerLevels, computed.results[m].flickerLevels);
        EXPECT_EQ(scored.results[m].temporalPsnr, computed.results[m].temporalPsnr);
        EXPECT_EQ(scored.results[m].psnr, computed.results[m].psnr);
    }
    // A given animation with another frame count, or a missing one: clear errors.
    io::Animation shortAnim;
    for (int t = 0; t < frames - 1; ++t) shortAnim.frames.push_back({computed.outputs[0][std::size_t(t)], 1, 25});
    io::writeApng((dir / "bar_blur.png").string(), shortAnim);
    try {
        eval::evaluateTemporalGiven(*eval::apngFrames(dir.string(), "bar"), {{"blur", (dir / "bar_blur.png").string()}},
                                    o);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("4 frames, the animation has 5"), std::string::npos) << e.what();
    }
    EXPECT_THROW(
        eval::evaluateTemporalGiven(*eval::apngFrames(dir.string(), "bar"), {{"x", (dir / "nope.png").string()}}, o),
        Error);
    EXPECT_THROW(eval::apngFrames((dir / "nothing").string(), "bar"), Error);  // no x8 file
#ifdef SSFX_CLI
    // The CLI: --source given finds bar_METHOD.png for the methods asked for and prints the
    // same figures; user mistakes exit 2 with a message.
    fs::remove(dir / "bar_blur.png");
    const std::string json = (dir / "given.json").string();
    EXPECT_EQ(
        runCli({"eval", "temporal", "--dir", dir.string(), "--image", "bar", "--source", "given", "--json", json}, dir)
            .first,
        0)
        << slurp(dir / "cli.err");
    std::ifstream in(json);
    const auto j = nlohmann::json::parse(in);
    ASSERT_EQ(j.size(), 3u);  // noaa, fxaa3d, ddaa2: the files present
    for (std::size_t m = 0; m < o.methods.size(); ++m)
        EXPECT_NEAR(j[o.methods[m]]["flicker_levels"].get<double>(), computed.results[m].flickerLevels, 1e-12);
    EXPECT_EQ(runCli({"eval", "temporal", "--source", "given"}, dir).first, 2);
    EXPECT_NE(slurp(dir / "cli.err").find("--dir"), std::string::npos);
    EXPECT_EQ(runCli({"eval", "temporal", "--dir", dir.string(), "--image", "nope"}, dir).first, 2);
    EXPECT_NE(slurp(dir / "cli.err").find("nopex8.png"), std::string::npos);
    EXPECT_EQ(
        runCli({"eval", "temporal", "--dir", dir.string(), "--image", "bar", "--source", "given", "--methods", "blur"},
               dir)
            .first,
        2);
    EXPECT_NE(slurp(dir / "cli.err").find("bar_blur.png"), std::string::npos);
#endif
}

TEST(TemporalStream, AnAnimationBeyondTheAllFramesLimitIsScoredInAboutOneX8Frame) {
#ifndef SSFX_CLI
    GTEST_SKIP() << "built without the ssfx tool (SSFX_BUILD_APPS=OFF): the memory of a CLI run cannot be measured";
#else
    // 17 frames of 4096x4096 at x8: 285 M pixels, beyond the whole-file reader's limit of
    // 2^28 (268 M). One x8 frame is 64 MiB; holding them all would take 1.1 GiB.
    const int w = 512, h = 512, frames = 17;
    const fs::path dir = dirFor("temporal_big");
    writeAnimation(dir, "big", w, h, frames, {1, 8});
    EXPECT_THROW(io::readApng((dir / "bigx8.png").string()), Error);  // the whole-file reader refuses it
    const std::string json = (dir / "big.json").string();
    const std::string out = (dir / "out").string();
    const auto [status, peakMiB] = runCli({"eval", "temporal", "--dir", dir.string(), "--image", "big", "--methods",
                                           "noaa,ddaa2", "--json", json, "--out", out, "--threads", "2"},
                                          dir);
    ASSERT_EQ(status, 0) << slurp(dir / "cli.err");
    RecordProperty("peak_rss_mib", std::to_string(peakMiB));
    std::printf("eval temporal on 17 frames of 4096x4096 (x8): peak RSS %.0f MiB\n", peakMiB);
    // One x8 frame (64 MiB) plus the program, the 1x frames and the writers' buffers (142
    // MiB measured in the release build); the frames all together would be 17 x 64 = 1088
    // MiB. Under AddressSanitizer (shadow memory, freed blocks held in quarantine: 420 MiB
    // measured) only the second bound holds.
#if defined(__SANITIZE_ADDRESS__)
    EXPECT_LT(peakMiB, 17 * 64.0);
#else
    EXPECT_LT(peakMiB, 3 * 64.0 + 64.0);
#endif
    std::ifstream in(json);
    const auto j = nlohmann::json::parse(in);
    EXPECT_GT(j["noaa"]["flicker_levels"].get<double>(), j["ddaa2"]["flicker_levels"].get<double>());
    // --out wrote whole animations, frame by frame.
    io::ApngReader r((fs::path(out) / "big_ddaa2.png").string());
    EXPECT_EQ(r.frameCount(), std::uint32_t(frames));
    int n = 0;
    while (r.next()) ++n;
    EXPECT_EQ(n, frames);
#endif
}
