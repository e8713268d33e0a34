// ssfx aa: apply an anti-aliasing method to a PNG (or every frame of an APNG).
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>

#include "apps/ssfx/backend.hpp"
#include "apps/ssfx/commands.hpp"
#include "apps/ssfx/console.hpp"
#include "ssfx/aa/presets.hpp"
#include "ssfx/aa/registry.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/io/sequence.hpp"

namespace ssfx::cli {

std::pair<int, int> parseSize(const std::string& text, const std::string& option, int maxSide) {
    // WIDTHxHEIGHT, each a whole number in 1..maxSide: no sign, no overflow (4294967360x36
    // is refused, not read as 64x36).
    const auto bad = [&] {
        return Error(fmt::format("{} '{}' is not WIDTHxHEIGHT (1..{} each)", option, text, maxSide));
    };
    const auto x = text.find('x');
    if (x == std::string::npos) throw bad();
    auto side = [&](std::string_view s) {
        std::int64_t v = 0;
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (s.empty() || s[0] == '-' || ec != std::errc() || end != s.data() + s.size() || v < 1 || v > maxSide)
            throw bad();
        return int(v);
    };
    const std::string_view t(text);
    return {side(t.substr(0, x)), side(t.substr(x + 1))};
}

std::int64_t parseMaxPixels(const std::string& text) {
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || v < 1 || v > kMaxPixels)
        throw Error(fmt::format("--max-pixels '{}' is not a whole number in [1, {}]", text, kMaxPixels));
    return v;
}

std::pair<std::string, double> parseParam(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw Error(fmt::format("parameter '{}' is not of the form NAME=VALUE", text));
    const std::string name = text.substr(0, eq), value = text.substr(eq + 1);
    if (value == "true") return {name, 1.0};
    if (value == "false") return {name, 0.0};
    double v = 0;
    // An explicit plus sign is a number too (from_chars takes only '-').
    const std::size_t skip = value.size() > 1 && value[0] == '+' && value[1] != '-' && value[1] != '+' ? 1 : 0;
    const auto [end, ec] = std::from_chars(value.data() + skip, value.data() + value.size(), v);
    if (ec != std::errc() || end != value.data() + value.size())
        throw Error(fmt::format("parameter {}: '{}' is not a number", name, value));
    return {name, v};
}

std::pair<std::string, double> parseParam(const std::string& text, std::span<const ParamInfo> table,
                                          std::string_view id) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw Error(fmt::format("parameter '{}' is not of the form NAME=VALUE", text));
    const std::string name = text.substr(0, eq);
    return {name, parseParamValue(findParam(table, id, name), std::string_view(text).substr(eq + 1), id)};
}

namespace {

struct AaOptions {
    std::string method, input, output, preset, filtering = "gpu", raw, frames;
    std::vector<std::string> params;
    int threads = 0;
    bool listPresets = false;
    BackendOptions backend;
};

void printPresets() {
    fmt::print(
        "Edge-threshold presets of fxaa3c, fxaa3d, ddaa1, ddaa2, ddaa2p: a pixel is left unchanged\n"
        "when its luma contrast < max(edgeThresholdMin, lumaMax * edgeThreshold).\n\n");
    fmt::print("{:<8} {:>16} {:>14}  {}\n", "preset", "edgeThresholdMin", "edgeThreshold", "");
    for (const auto& p : aa::kPresets)
        fmt::print("{:<8} {:>16} {:>14}  {}\n", p.name, p.thresholds.edgeThresholdMin, p.thresholds.edgeThreshold,
                   p.doc);
}

// ---- frame sequences: numbered files, folders, raw streams ------------------------------
// Where a sequence's frames come from: numbered files, a folder's PNGs or a raw stream.
struct CloseFile {
    void operator()(std::FILE* f) const {
        if (f && f != stdin) std::fclose(f);
    }
};

struct Frames {
    std::vector<std::string> files;  // numbered files or a folder's PNGs, in order
    std::vector<int> numbers;        // the numbered files' frame numbers
    std::unique_ptr<std::FILE, CloseFile> rawFile;
    std::unique_ptr<io::RawFrameReader> raw;
    std::string rawName;
};

bool isFolder(const std::string& path) {
    std::error_code ec;
    return std::filesystem::is_directory(path, ec);
}

Frames openFrames(const AaOptions& o, std::pair<int, int> rawSize, bool outPattern) {
    Frames f;
    if (io::FramePattern::isPattern(o.input)) {
        const io::FramePattern pattern(o.input);
        std::optional<io::FrameRange> range;
        if (!o.frames.empty()) range = io::FrameRange::parse(o.frames);
        f.numbers = pattern.select(range ? &*range : nullptr);
        for (int n : f.numbers) f.files.push_back(pattern.path(n));
        return f;
    }
    if (!o.frames.empty()) throw Error("--frames goes with a numbered input (frame.%04d.png)");
    const std::string input = io::FramePattern::plain(o.input);
    if (input != "-" && isFolder(input)) {
        for (const auto& name : io::pngFilesIn(input))
            f.files.push_back((std::filesystem::path(input) / name).string());
        return f;
    }
    if (rawSize.first == 0) {
        if (input == "-") throw Error("standard input ('-') holds raw frames: give their size with --raw WxH");
        std::error_code ec;
        if (!std::filesystem::exists(input, ec)) throw Error(fmt::format("{}: no such file or folder", input));
        if (outPattern)
            throw Error(fmt::format(
                "{} is one image, but the output '{}' is numbered: a numbered output takes numbered input files "
                "(in/frame.%04d.png) or a folder (write a '%' in a plain file name as %%)",
                input, o.output));
        throw Error(fmt::format("{}: raw frames need their size (--raw WxH)", input));
    }
    f.rawName = input == "-" ? "stdin" : input;
    f.rawFile.reset(input == "-" ? stdin : std::fopen(input.c_str(), "rb"));
    if (!f.rawFile) throw Error(fmt::format("{}: cannot open ({})", input, std::strerror(errno)));
    f.raw = std::make_unique<io::RawFrameReader>(f.rawFile.get(), rawSize.first, rawSize.second, f.rawName);
    return f;
}

void runFrames(const AaOptions& o, const Applier& method, const Exec& exec) {
    const auto rawSize = o.raw.empty() ? std::pair<int, int>{0, 0} : parseSize(o.raw, "--raw", 16384);
    // The output: numbered files, a folder (the input's file names), or a raw stream. A
    // numbered output's pattern is checked before the input is opened.
    const bool outPattern = io::FramePattern::isPattern(o.output);
    std::optional<io::FramePattern> pattern;
    if (outPattern) pattern.emplace(o.output);
    Frames in = openFrames(o, rawSize, outPattern);
    const std::string output = outPattern ? o.output : io::FramePattern::plain(o.output);
    // Without --raw a plain output path is a folder; with it, a raw file unless it is a folder.
    const bool outFolder = !outPattern && output != "-" && (isFolder(output) || output.back() == '/' || o.raw.empty());
    const bool outRaw = !outPattern && !outFolder;
    // Folders made here are removed again if the run fails before writing into them.
    std::optional<io::OutputFolder> made;
    if (outPattern) {
        const auto parent = std::filesystem::path(pattern->path(0)).parent_path();
        if (!parent.empty()) made.emplace(parent.string());
    }
    if (outFolder) {
        if (in.raw)
            throw Error("raw frames go to a numbered output (out/frame.%04d.png) or a raw stream, not a folder");
        made.emplace(output);
    }
    std::unique_ptr<io::AtomicFile> rawFile;
    std::unique_ptr<io::RawFrameWriter> rawOut;
    if (outRaw) {
        rawFile = std::make_unique<io::AtomicFile>(output);
        rawOut = std::make_unique<io::RawFrameWriter>(*rawFile);
    }
    const int count = in.raw ? -1 : int(in.files.size());
    auto name = [&](int i) { return in.raw ? fmt::format("{} frame {}", in.rawName, i) : in.files[std::size_t(i)]; };
    // PNG inputs: every frame has --raw's size when it is given, and one size (the first
    // frame's) when they go into one raw stream, which a reader splits by that size.
    std::pair<int, int> frameSize = rawSize;
    auto checkSize = [&](int i, const ImageRgba8& frame) {
        if (in.raw || (rawSize.first == 0 && !outRaw)) return;
        if (frameSize.first == 0) frameSize = {frame.width(), frame.height()};
        if (frame.width() == frameSize.first && frame.height() == frameSize.second) return;
        throw Error(fmt::format("{}: {}x{}, but {} {}x{}: {}", name(i), frame.width(), frame.height(),
                                rawSize.first ? "--raw says" : fmt::format("the first frame ({}) is", name(0)),
                                frameSize.first, frameSize.second,
                                rawSize.first ? "every frame must have the size --raw gives"
                                              : "every frame of one raw stream must have one size"));
    };
    // Frames in flight: a few per thread, each an input, an output and its PNG slot. Files are
    // decoded and encoded in the parallel stage; only the raw stream is read in order. A bad
    // frame k stops the run after frames 0..k-1 are written, whatever the threads' timing.
    const int slots = 2 * resolvedThreads(exec);
    const auto slotCount = std::size_t(slots);
    std::vector<ImageRgba8> inputs(slotCount), outputs(slotCount);
    std::vector<std::vector<std::uint8_t>> encoded(slotCount);
    std::optional<Error> stopped;  // a raw stream cut short: reported after the frames before it
    int written = 0;
    ProgressLine progress("aa");
    const std::string what = in.raw ? in.rawName : o.input;
    orderedPipeline(
        slots, exec,
        [&](int i) {
            if (!in.raw) return i < count;
            try {
                return in.raw->read(inputs[std::size_t(i % slots)]);
            } catch (const Error& e) {
                stopped.emplace(e.what());
                return false;
            }
        },
        [&](int i) {
            const auto slot = std::size_t(i % slots);
            if (!in.raw) {
                const std::string& file = in.files[std::size_t(i)];
                const std::vector<std::uint8_t> bytes = io::readPngFile(file);
                if (io::isApng(bytes))
                    throw Error(fmt::format(
                        "{}: an animated PNG in a frame sequence, whose frames are still images; run it on its own "
                        "(ssfx aa -m {} {} -o out.png: every frame, an APNG out)",
                        file, o.method, file));
                inputs[slot] = io::decodePng(bytes, file);
            }
            try {
                outputs[slot] = method.apply(inputs[slot].view());
            } catch (const Error& e) {  // e.g. a resolve's size rule: say which frame
                throw Error(fmt::format("{}: {}", name(i), e.what()));
            }
            if (!rawOut) encoded[slot] = io::encodePng(outputs[slot].view());
        },
        [&](int i) {
            const auto slot = std::size_t(i % slots);
            checkSize(i, inputs[slot]);
            if (rawOut) {
                rawOut->write(outputs[slot].view());
            } else if (pattern) {
                io::writeFileAtomic(pattern->path(in.numbers.empty() ? i : in.numbers[std::size_t(i)]), encoded[slot]);
            } else {
                io::writeFileAtomic(
                    (std::filesystem::path(output) / std::filesystem::path(in.files[std::size_t(i)]).filename())
                        .string(),
                    encoded[slot]);
            }
            ++written;
            progress.report({what, i + 1, std::max(count, 0), "frames"});
        });
    if (stopped) {
        // What became of the whole frames before the cut, said as the help says it.
        const bool held = rawFile && !rawFile->direct();
        throw Error(fmt::format("{}; {}", stopped->what(),
                                held ? fmt::format("{} is not written (a raw output file appears only whole)", output)
                                : written ? fmt::format("the {} frame(s) before it were written", written)
                                          : "nothing was written"));
    }
    if (in.raw && written == 0)
        throw Error(fmt::format("{}: no frames (the raw stream is empty); nothing was written", in.rawName));
    if (rawFile) rawFile->commit();
    if (made) made->keep();
}

bool isSequence(const AaOptions& o) {
    // (A single PNG to "-" is a PNG on standard output, not a raw stream.)
    return !o.raw.empty() || o.input == "-" || io::FramePattern::isPattern(o.input) ||
           io::FramePattern::isPattern(o.output) || isFolder(io::FramePattern::plain(o.input)) || !o.frames.empty();
}

void run(AaOptions o) {
    if (o.listPresets) {
        printPresets();
        return;
    }
    if (o.method.empty()) throw Error("no method given (use -m METHOD; 'ssfx methods' lists them)");
    if (o.input.empty()) throw Error("no input file given");
    if (o.output.empty()) throw Error("no output file given (use -o FILE)");
    const MethodInfo& m = methodById(o.method);
    MethodSettings settings;
    if (!o.preset.empty()) {
        settings.preset = aa::parsePreset(o.preset);
        if (!settings.preset)
            throw Error(fmt::format("unknown preset '{}' (presets: low, medium, high, ultra, extreme)", o.preset));
    }
    takeSamplingParam(o.params, o.backend);
    for (const auto& p : o.params) settings.params.push_back(parseParam(p, methodById(o.method).params, o.method));
    if (o.filtering == "exact") settings.filtering = Filtering::Exact;
    const Exec exec{o.threads};
    const Applier method = makeApplier(o.backend, m, settings, exec);
    if (isSequence(o)) {
        runFrames(o, method, exec);
        return;
    }

    // One file: a '%' in its name is written %% (as in the numbered patterns).
    o.input = io::FramePattern::plain(o.input);
    o.output = io::FramePattern::plain(o.output);
    const std::vector<std::uint8_t> bytes = io::readPngFile(o.input);
    if (io::isApng(bytes)) {
        io::Animation anim = io::decodeApng(bytes, o.input);
        ProgressLine progress("aa");
        const auto n = std::int64_t(anim.frames.size());
        for (std::size_t i = 0; i < anim.frames.size(); ++i) {
            try {
                anim.frames[i].image = method.apply(anim.frames[i].image.view());
            } catch (const Error& e) {  // e.g. a resolve's size rule: say which file and frame
                throw Error(fmt::format("{} (frame {}): {}", o.input, i, e.what()));
            }
            progress.report({o.input, std::int64_t(i) + 1, n, "frames"});
        }
        io::writeApng(o.output, anim);
    } else {
        const ImageRgba8 in = io::decodePng(bytes, o.input);
        ImageRgba8 out;
        try {
            out = method.apply(in.view());
        } catch (const Error& e) {
            throw Error(fmt::format("{}: {}", o.input, e.what()));
        }
        io::writePng(o.output, out.view());
    }
}

}  // namespace

void addAaCommand(CLI::App& app) {
    auto opts = std::make_shared<AaOptions>();
    auto* cmd = app.add_subcommand(
        "aa", "Apply an anti-aliasing method to a PNG, every frame of an APNG, a frame sequence or a raw stream");
    std::string methodList;
    for (const MethodInfo& mi : methods()) methodList += fmt::format("\n  {:<7} {}", mi.id, mi.summary);
    cmd->add_option("-m,--method", opts->method, "Method id:" + methodList);
    cmd->add_option("input", opts->input,
                    "Input PNG/APNG, numbered PNGs (in/frame.%04d.png), a folder of PNGs, or raw frames ('-' = "
                    "stdin, with --raw) (ssaax2/ddaa2p take the 2x render, ssaax4 the 4x)");
    cmd->add_option("-o,--output", opts->output,
                    "Output PNG/APNG, numbered PNGs (out/frame.%04d.png), a folder (the input's file names), or raw "
                    "frames ('-' = stdout, or a file with --raw); every file written atomically");
    cmd->add_option("--raw", opts->raw,
                    "Raw RGBA8 frames of this size (WxH) on the input '-' or FILE; the output is raw too unless it "
                    "is numbered or a folder (ffmpeg -f rawvideo -pix_fmt rgba)");
    cmd->add_option("--frames", opts->frames,
                    "Frames A-B (or A) of a numbered input (default: every file that exists)");
    cmd->add_option("--preset", opts->preset, "Edge-threshold preset: low, medium (default), high, ultra, extreme");
    cmd->add_option("-p,--param", opts->params, "Parameter override NAME=VALUE (repeatable; see 'ssfx methods')")
        ->allow_extra_args(false);
    cmd->add_option("--filtering", opts->filtering, "Bilinear model: gpu (default, matches GPUs) or exact (float)")
        ->check(CLI::IsMember({"gpu", "exact"}));
    cmd->add_option("--threads", opts->threads, "Worker threads (0 = all; the output bytes do not depend on it)")
        ->check(CLI::Range(0, 1024));
    cmd->add_flag("--list-presets", opts->listPresets, "Print the presets with their thresholds and exit");
    addBackendOptions(cmd, opts->backend);
    cmd->footer(
        "Sequences: frames run in parallel, a few per thread in memory at a time, and are written in order;\n"
        "a numbered output keeps the input's frame numbers (raw or folder input: 0, 1, ...).\n"
        "  ssfx aa -m ddaa2 'in/frame.%04d.png' -o 'out/frame.%04d.png' --frames 1-240\n"
        "  ssfx aa -m ddaa2 in/ -o out/\n"
        "  ffmpeg -i in.mkv -f rawvideo -pix_fmt rgba - | ssfx aa --raw 1920x1080 -m ddaa2 - -o - |\n"
        "    ffmpeg -f rawvideo -pix_fmt rgba -s 1920x1080 -i - -c:v ffv1 out.mkv\n"
        "A bad frame (unreadable, an APNG among stills, cut short, or of another size in a raw stream) stops the\n"
        "run with an error naming it. The frames before it are written, each whole: numbered files, a folder,\n"
        "a pipe or stdout; a raw output FILE appears only whole, so it is then not written at all. The frames\n"
        "of one raw stream have one size: --raw's, else the first frame's. An empty raw stream is an error.\n"
        "A '%' in a plain (not numbered) file name is written %%: ssfx aa -m ddaa2 100%%.png -o out%%.png\n"
        "GPU: --backend vulkan runs the method as a Vulkan compute pass (docs/gpu.md); with the default\n"
        "-p sampling=model the output bytes are the CPU's, -p sampling=hardware uses the device's filtering\n"
        "and arithmetic (the fast path, exact to the device's precision). -p edges=list|one-pass|segments\n"
        "chooses how blur and the edge-test methods run (default auto: on a CPU device the segments for\n"
        "blur, fxaa3c and ddaa1, and for fxaa3d and ddaa2 with sampling=hardware, else the list; one pass\n"
        "on a GPU).\n"
        "  ssfx aa -m ddaa2 --backend vulkan in.png -o out.png");
    cmd->callback([opts] { run(*opts); });
}

}  // namespace ssfx::cli
