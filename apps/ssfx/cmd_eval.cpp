// ssfx eval: the evaluation harness (ssfx/eval/*.hpp). Subcommands:
//   quality   the paper's PSNR protocol (Table 2) plus SSIM, on a directory of renders
// Long runs print progress on stderr.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <map>

#include "apps/ssfx/commands.hpp"
#include "apps/ssfx/console.hpp"
#include "ssfx/eval/ao_experiments.hpp"
#include "ssfx/eval/kernels.hpp"
#include "ssfx/eval/quality.hpp"
#include "ssfx/eval/report.hpp"
#include "ssfx/eval/speed.hpp"
#include "ssfx/eval/temporal.hpp"
#include "ssfx/eval/test_images.hpp"
#include "ssfx/io/png.hpp"
#ifdef SSFX_HAVE_RENDER
#include "ssfx/eval/deferred_experiment.hpp"
#include "ssfx/render/renderer.hpp"
#include "ssfx/scene/raytrace.hpp"
#endif
#ifdef SSFX_HAVE_GPU
#include "ssfx/eval/frame_experiment.hpp"
#endif

namespace ssfx::cli {

namespace {

// Steps of the evaluation go to the command's progress line (a log line each off a terminal).
void progressLine(const Progress& p) { reportProgress(p); }

void addQuality(CLI::App& eval) {
    struct Options {
        std::string dir, json, markdown, source = "compute", outputs, protocol = "both";
        std::vector<std::string> methods, images, params;
        int threads = 0;
    };
    auto o = std::make_shared<Options>();
    auto* cmd = eval.add_subcommand(
        "quality", "PSNR, SSIM and per-pixel errors of every method: the paper's protocol and the truth's");
    cmd->add_option("dir", o->dir, "Directory with NAME.png, NAMEx2/x4/x8.png (e.g. from 'ssfx testimages')")
        ->required();
    cmd->add_option("--json", o->json, "Also write the tables as JSON ('-': to stdout, instead of the table)");
    cmd->add_option("--md", o->markdown, "Also write the tables as Markdown ('-': to stdout)");
    cmd->add_option("--source", o->source,
                    "compute: run each method on the renders; given: score the NAME_METHOD.png files in DIR")
        ->check(CLI::IsMember({"compute", "given"}));
    cmd->add_option("--protocol", o->protocol,
                    "paper: the x8 upscale against the x8 render (Table 2); truth: the 1x output against the x8 "
                    "render resolved to 1x; both (default)")
        ->check(CLI::IsMember({"paper", "truth", "both"}));
    cmd->add_option("--outputs", o->outputs, "With --source compute: also write NAME_METHOD.png to this directory");
    cmd->add_option("--methods", o->methods,
                    "Method columns (default: ssaax4,ssaax2,blur,fxaa3c,fxaa3d,ddaa1,ddaa2,"
                    "ddaa2p,noaa)")
        ->delimiter(',');
    cmd->add_option("--images", o->images, "Image rows (default: every NAME with NAMEx8.png in DIR)")->delimiter(',');
    cmd->add_option("-p,--param", o->params,
                    "NAME=VALUE for the methods that have parameter NAME (repeatable), e.g. -p chromaWeight=1");
    cmd->add_option("--threads", o->threads, "Worker threads (0 = all)")->check(CLI::Range(0, 1024));
    cmd->footer(
        "Each method's 1x output (x2 render for ssaax2/ddaa2p, x4 for ssaax4) is scored\n"
        "  paper: upscaled x8 with the Mitchell filter, against NAMEx8.png (the paper's Table 2);\n"
        "  truth: against the truth, NAMEx8.png resolved to 1x with the Mitchell filter.\n"
        "PSNR = 10 log10(1 / MSE) over RGB in [0,1]; SSIM on non-overlapping 8x8 windows; the largest\n"
        "and 99th-percentile per-pixel error max(|dR|,|dG|,|dB|) in levels; each over the whole image\n"
        "and over the edge pixels only (where the truth differs from NAME.png). The terminal shows\n"
        "PSNR and SSIM; --json and --md have every figure (docs/evaluation.md).");
    cmd->callback([o] {
        ProgressLine line("eval", true);
        const bool toStdout = anyStdout({o->json, o->markdown});  // checked before the work
        eval::QualityOptions q;
        q.methods = o->methods;
        q.images = o->images;
        for (const auto& text : o->params) q.settings.params.push_back(parseParam(text));
        q.source = o->source == "given" ? eval::OutputSource::Given : eval::OutputSource::Compute;
        q.protocols = eval::parseProtocols(o->protocol);
        q.outputsDir = o->outputs;
        if (!q.outputsDir.empty() && q.source == eval::OutputSource::Given)
            throw Error("--outputs goes with --source compute (with --source given the outputs are the inputs)");
        if (!q.outputsDir.empty()) io::makeDirectories(q.outputsDir);
        q.exec = Exec{o->threads};
        q.progress = progressLine;
        const eval::QualityTable t = eval::evaluateQuality(o->dir, q);
        if (!toStdout) printResult(eval::qualityText(t));
        if (!o->json.empty()) writeOutput(o->json, eval::qualityJson(t));
        if (!o->markdown.empty()) writeOutput(o->markdown, eval::qualityMarkdown(t));
    });
}

void addTemporal(CLI::App& eval) {
    struct Options {
        std::string dir, name = "animated", out, json, markdown, source = "compute";
        std::vector<std::string> methods;
        int threads = 0;
    };
    auto o = std::make_shared<Options>();
    auto* cmd = eval.add_subcommand("temporal", "Flicker of every method on an animation, against its x8 render");
    cmd->add_option("--dir", o->dir,
                    "Read NAME.png, NAMEx2/x4/x8.png (APNG) from here (default: draw ssfx's 'animated' directly)");
    cmd->add_option("--image", o->name, "Animation name (default: animated)");
    cmd->add_option("--source", o->source,
                    "compute: run each method on the frames; given: score the NAME_METHOD.png animations in --dir "
                    "(outputs made elsewhere, e.g. the DDAA author's) against the same x8 truth")
        ->check(CLI::IsMember({"compute", "given"}));
    cmd->add_option("--out", o->out, "Write NAME_METHOD.png and NAME_truth.png (APNG) to this directory");
    cmd->add_option("--json", o->json, "Also write the results as JSON ('-': to stdout, instead of the table)");
    cmd->add_option("--md", o->markdown, "Also write the results as Markdown ('-': to stdout)");
    cmd->add_option("--methods", o->methods,
                    "Methods (default: the quality table's; with --source given: those whose NAME_METHOD.png exists)")
        ->delimiter(',');
    cmd->add_option("--threads", o->threads, "Worker threads (0 = all)")->check(CLI::Range(0, 1024));
    cmd->footer(
        "flicker = RMS over frames, pixels and RGB of (dO_t - dR_t), in 8-bit levels, where dO_t is the\n"
        "method's frame-to-frame difference and dR_t that of the x8 render resolved to 1x (around the\n"
        "loop); tPSNR is the same as a PSNR; PSNR compares each output frame with the resolved frame.\n"
        "Frames are streamed: one frame of each scale is in memory at a time (a 4800x4800 x8 frame is\n"
        "92 MB), plus two 1x frames per method (and each 1x frame with --out: APNGs are written as they\n"
        "come), whatever the number of frames (docs/evaluation.md).");
    cmd->callback([o] {
        ProgressLine line("eval", true);
        const bool toStdout = anyStdout({o->json, o->markdown});  // checked before the work
        if (o->source == "given" && o->dir.empty())
            throw Error("--source given needs --dir (where NAME_METHOD.png are)");
        std::unique_ptr<eval::FrameSource> source;
        int fps = 25;
        if (o->dir.empty()) {
            const auto& info = eval::testImageByName(o->name);
            fps = info.fps;
            source = eval::drawnFrames(
                info.frames, [name = o->name](int t, int scale) { return eval::drawTestImage(name, scale, t); });
        } else {
            const std::string x8 = eval::renderSetPath(o->dir, o->name, 8);
            if (!std::filesystem::exists(x8))
                throw Error(fmt::format("{}: no such file (the x8 animation of '{}')", x8, o->name));
            source = eval::apngFrames(o->dir, o->name);
            io::ApngReader first(x8);
            const io::Frame* f = first.next();
            if (f && f->delaySeconds() > 0) fps = int(std::lround(1.0 / f->delaySeconds()));
        }
        eval::TemporalOptions t;
        t.methods = o->methods;
        t.exec = Exec{o->threads};
        t.progress = progressLine;
        t.keepOutputs = false;
        std::vector<std::pair<std::string, std::string>> given;
        if (o->source == "given") {
            const std::vector<std::string> ids = o->methods.empty() ? eval::paperMethodOrder() : o->methods;
            for (const auto& id : ids) {
                const std::string file =
                    (std::filesystem::path(o->dir) / fmt::format("{}_{}.png", o->name, id)).string();
                if (std::filesystem::exists(file))
                    given.emplace_back(id, file);
                else if (!o->methods.empty())
                    throw Error(fmt::format("{}: no such file (given outputs of {})", file, id));
            }
            if (given.empty())
                throw Error(fmt::format("--source given: no {}_METHOD.png animation in {}", o->name, o->dir));
        }
        const std::vector<std::string> names = [&] {
            std::vector<std::string> n;
            if (!given.empty())
                for (const auto& g : given) n.push_back(g.first);
            else
                n = o->methods.empty() ? eval::paperMethodOrder() : o->methods;
            return n;
        }();
        // --out: every animation written frame by frame, committed together at the end.
        std::vector<std::unique_ptr<io::ApngWriter>> writers;
        if (!o->out.empty()) {
            io::makeDirectories(o->out);
            t.onFrame = [&](int frame, const std::vector<ImageRgba8>& outputs, const ImageRgba8& ref) {
                if (frame == 0) {
                    auto open = [&](const std::string& suffix) {
                        writers.push_back(std::make_unique<io::ApngWriter>(
                            (std::filesystem::path(o->out) / (o->name + "_" + suffix + ".png")).string(), ref.width(),
                            ref.height(), std::uint32_t(source->frames())));
                    };
                    open("truth");
                    for (const auto& n : names) open(n);
                }
                writers[0]->add(ref.view(), 1, std::uint16_t(fps));
                for (std::size_t m = 0; m < outputs.size(); ++m)
                    writers[m + 1]->add(outputs[m].view(), 1, std::uint16_t(fps));
            };
        }
        const eval::TemporalRun run =
            given.empty() ? eval::evaluateTemporal(*source, t) : eval::evaluateTemporalGiven(*source, given, t);
        for (auto& w : writers) w->commit();
        if (!toStdout) printResult(eval::temporalMarkdown(run.results));
        if (!o->json.empty()) writeOutput(o->json, eval::temporalJson(run.results));
        if (!o->markdown.empty()) writeOutput(o->markdown, eval::temporalMarkdown(run.results));
    });
}

void addKernels(CLI::App& eval) {
    struct Options {
        std::string json, markdown;
        eval::KernelExperimentOptions k;
    };
    auto o = std::make_shared<Options>();
    auto* cmd = eval.add_subcommand("kernels", "Angle error of derivative kernels on aliased lines (paper's Figure 3)");
    cmd->add_option("--step", o->k.stepDegrees, "Angle step in degrees (default 0.5)")->check(CLI::Range(0.01, 45.0));
    cmd->add_option("--widths", o->k.widths, "Line widths in pixels (default 1,2,4)")->delimiter(',');
    cmd->add_option("--size", o->k.size, "Image side in pixels (default 64)")->check(CLI::Range(32, 1024));
    cmd->add_option("--supersample", o->k.supersample, "1 = aliased lines (default); n = n x n coverage")
        ->check(CLI::Range(1, 16));
    cmd->add_flag_function(
        "--edge", [o](std::int64_t) { o->k.shape = eval::KernelExperimentOptions::Shape::Edge; },
        "Half-plane edges instead of lines");
    cmd->add_option("--json", o->json, "Also write the results (with the error per angle) as JSON ('-': to stdout)");
    cmd->add_option("--md", o->markdown, "Also write the table as Markdown ('-': to stdout)");
    cmd->callback([o] {
        const bool toStdout = anyStdout({o->json, o->markdown});
        const auto e = eval::runKernelExperiment(o->k);
        if (!toStdout) printResult(eval::kernelMarkdown(e));
        if (!o->json.empty()) writeOutput(o->json, eval::kernelJson(e));
        if (!o->markdown.empty()) writeOutput(o->markdown, eval::kernelMarkdown(e));
    });
}

void addSpeed(CLI::App& eval) {
    struct Options {
        std::string dir, json, markdown;
        eval::SpeedOptions s;
        int threads = 0;
    };
    auto o = std::make_shared<Options>();
    auto* cmd =
        eval.add_subcommand("speed", "Time every method on each image relative to blur = 100 (paper's Table 3)");
    cmd->add_option("dir", o->dir, "Directory with NAME.png, NAMEx2/x4/x8.png (e.g. from 'ssfx testimages')")
        ->required();
    cmd->add_option("--methods", o->s.methods, "Methods (default: the quality table's; blur is always timed)")
        ->delimiter(',');
    cmd->add_option("--images", o->s.images, "Images (default: every NAME with NAMEx8.png in DIR)")->delimiter(',');
    cmd->add_option("--reps", o->s.repetitions, "Timed repetitions (default 40)")->check(CLI::Range(4, 100000));
    cmd->add_option("--warmup", o->s.warmup, "Untimed rounds first (default 3)")->check(CLI::Range(0, 1000));
    cmd->add_option("--threads", o->threads, "Worker threads (0 = all)")->check(CLI::Range(0, 1024));
    cmd->add_option("--json", o->json, "Also write the results as JSON ('-': to stdout, instead of the table)");
    cmd->add_option("--md", o->markdown, "Also write the tables as Markdown ('-': to stdout)");
    cmd->callback([o] {
        ProgressLine line("eval", true);
        const bool toStdout = anyStdout({o->json, o->markdown});  // checked before the work
        o->s.exec = Exec{o->threads};
        o->s.progress = progressLine;
        const auto t = eval::measureSpeed(o->dir, o->s);
        if (!toStdout) printResult(eval::speedMarkdown(t));
        if (!o->json.empty()) writeOutput(o->json, eval::speedJson(t));
        if (!o->markdown.empty()) writeOutput(o->markdown, eval::speedMarkdown(t));
    });
}

// Scenes rendered with Vulkan (D32F depth) for the AO accuracy table, each "SCENE[:VIEW]";
// a scene file that is absent here (the shared models) is skipped with a message.
const std::vector<std::string> kDefaultAoScenes = {"atrium:colonnade", "cornell:corner", "scenes/sponza.json:arcade",
                                                   "scenes/bunny.json:front"};

eval::AoSceneSource renderedAoScenes(const std::vector<std::string>& specs) {
#ifdef SSFX_HAVE_RENDER
    return [specs](int width, int height, int guard) {
        std::vector<eval::AoRenderedScene> out;
        std::unique_ptr<render::Renderer> renderer;
        for (const auto& spec : specs) {
            const auto colon = spec.rfind(':');
            const std::string scenePath = colon == std::string::npos ? spec : spec.substr(0, colon);
            const std::string viewName = colon == std::string::npos ? "" : spec.substr(colon + 1);
            scene::Scene scene;
            try {
                scene = scene::loadScene(scenePath);
            } catch (const Error& e) {
                if (scenePath.find('/') == std::string::npos) throw;  // a built-in name: a real error
                progressLine({fmt::format("ao: skipping {} ({})", scenePath, e.what())});
                continue;
            }
            if (!renderer) renderer = std::make_unique<render::Renderer>();
            progressLine({fmt::format("ao: rendering {} on {}", spec, renderer->device().name)});
            const scene::View& view = viewName.empty() ? scene.views.at(0).second : scene.view(viewName);
            auto r = renderer->renderDepth(scene, view, width, height, DepthFormat::D32F, guard);
            out.push_back({scene.name, std::move(r.depth), r.camera.camera,
                           std::shared_ptr<const ao::RayScene>(scene::cameraSpaceRayScene(scene, r.camera))});
        }
        return out;
    };
#else
    if (!specs.empty()) progressLine({"ao: built without the renderer; rendered scenes left out"});
    return {};
#endif
}

void addReport(CLI::App& eval) {
    auto o = std::make_shared<eval::ReportOptions>();
    auto threads = std::make_shared<int>(0);
    auto* cmd = eval.add_subcommand("report", "Run the whole evaluation and write the HTML report");
    cmd->add_option("--out", o->outDir, "Output directory (created if missing); open DIR/index.html")->required();
    cmd->add_option("--author-data", o->authorDataDir,
                    "The DDAA author's data (e.g. ../shared/reference/ppaa): adds the paper's rows reproduced");
    cmd->add_option("--methods", o->methods, "Methods (default: all, in the paper's order)")->delimiter(',');
    cmd->add_option("--reps", o->speedRepetitions, "Timed repetitions per method and image (default 20)")
        ->check(CLI::Range(4, 100000));
    cmd->add_flag("--quick", o->quick, "Fewer repetitions and every 4th animation frame (tests)");
    cmd->add_flag("!--no-ao", o->ambientObscurance, "Leave out the ambient obscurance experiments");
    cmd->add_option("--ao-backend", o->aoBackend,
                    "cpu (default) or vulkan: the AO experiments also run the GPU passes (accuracy, radius sweep "
                    "and per-pass times from GPU timestamps) beside the CPU columns")
        ->check(CLI::IsMember({"cpu", "vulkan"}));
    cmd->add_option("--ao-device", o->aoDevice, "With --ao-backend vulkan: a device index or part of its name");
    auto deferredBackend = std::make_shared<std::string>("cpu");
    cmd->add_option("--deferred-backend", *deferredBackend,
                    "cpu (default) or vulkan: adaptive supersampling's Table 1 also on the GPU passes (GPU "
                    "timestamps, idle lanes, distance to the CPU's image) in a table beside the CPU's")
        ->check(CLI::IsMember({"cpu", "vulkan"}));
    auto scenes = std::make_shared<std::vector<std::string>>(kDefaultAoScenes);
    cmd->add_option("--ao-scene", *scenes,
                    "Rendered scenes for the AO accuracy table, SCENE[:VIEW] (repeatable; "
                    "default atrium:colonnade cornell:corner scenes/sponza.json:arcade "
                    "scenes/bunny.json:front; 'none' for none)");
    cmd->add_option("--threads", *threads, "Worker threads (0 = all)")->check(CLI::Range(0, 1024));
    auto noRender = std::make_shared<bool>(false);
    cmd->add_flag("--no-render", *noRender,
                  "Leave out what needs the Vulkan renderer: the atrium in the quality table, adaptive supersampling, "
                  "the whole frame on one device");
    cmd->callback([o, threads, scenes, noRender, deferredBackend] {
        if (*deferredBackend == "vulkan" && *noRender)
            throw Error("--deferred-backend with --no-render: the experiment needs the renderer");
        if (!o->aoDevice.empty() && o->aoBackend != "vulkan") throw Error("--ao-device goes with --ao-backend vulkan");
        if (o->aoBackend == "vulkan" && !o->ambientObscurance) throw Error("--ao-backend with --no-ao: nothing to run");
        ProgressLine line("eval", true);
        // --author-data must name the data, and is not silently dropped by --quick.
        if (!o->authorDataDir.empty() && !std::filesystem::is_directory(o->authorDataDir))
            throw Error(
                fmt::format("--author-data {}: no such directory (the DDAA author's data, e.g. "
                            "../shared/reference/ppaa)",
                            o->authorDataDir));
        if (!o->authorDataDir.empty() && o->quick)
            throw Error("--author-data with --quick: the quick report leaves the paper's rows out; drop one of them");
        if (!(scenes->size() == 1 && scenes->front() == "none")) o->renderedScenes = renderedAoScenes(*scenes);
#ifdef SSFX_HAVE_RENDER
        // The atrium's nave, forward-shaded at 1x..8x, joins the quality table (like the paper's sponza).
        if (!*noRender)
            o->addRenderSets = [quick = o->quick](const std::string& dir) {
                render::Renderer renderer;
                const scene::Scene scene = scene::atrium();
                progressLine({fmt::format("report: rendering the atrium at 1x..8x on {}", renderer.device().name)});
                const int w = quick ? 160 : 640, h = quick ? 90 : 360;
                render::writeAaRenderSet(renderer, scene, scene.view("nave"), w, h, dir, "atrium");
                return std::vector<std::pair<std::string, std::string>>{
                    {"atrium", fmt::format("The procedural atrium (view nave), {}x{}, rasterised with Vulkan and "
                                           "forward-shaded without anti-aliasing: checker floor, brick walls, thin "
                                           "bars, curtain folds (ssfx render atrium --view nave --aa-set).",
                                           w, h)}};
            };
#endif
#ifdef SSFX_HAVE_RENDER
        // Adaptive supersampling's Table 1 at 512x384 (the paper's 1024x768: ssfx eval deferred).
        if (!*noRender)
            o->deferredExperiment = [quick = o->quick, threads = *threads,
                                     backend = *deferredBackend](const std::string& dir) {
                eval::DeferredExperimentOptions d;
                d.outDir = dir;
                d.backend = backend;
                d.quick = quick;
                d.width = 512;
                d.height = 384;
                d.repetitions = 3;
                d.exec = Exec{threads};
                d.progress = progressLine;
                return eval::runDeferredExperiment(d);
            };
#endif
#ifdef SSFX_HAVE_GPU
        // The whole frame on one device: an orbit of the atrium, its per-pass profile (docs/frame.md).
        if (!*noRender)
            o->frameExperiment = [quick = o->quick](const std::string& dir) {
                eval::FrameExperimentOptions f;
                f.outDir = dir;
                f.quick = quick;
                f.progress = progressLine;
                return eval::runFrameExperiment(f);
            };
#endif
        o->exec = Exec{*threads};
        o->progress = progressLine;
        eval::writeReport(*o);
        printNote("eval", fmt::format("wrote {}/index.html", o->outDir));
    });
}

#ifdef SSFX_HAVE_RENDER
void addDeferred(CLI::App& eval) {
    auto o = std::make_shared<eval::DeferredExperimentOptions>();
    auto threads = std::make_shared<int>(0);
    auto size = std::make_shared<std::string>("1024x768");
    auto* cmd = eval.add_subcommand("deferred",
                                    "The adaptive supersampling paper's Table 1: time, stalled time, "
                                    "MSE/PSNR vs brute force and samples shaded for m = 1..4");
    cmd->add_option("--out", o->outDir, "Output directory: images/, data/deferred.json, data/deferred.md")->required();
    cmd->add_option("--scene", o->scene, "Scene (default atrium)");
    cmd->add_option("--view", o->view, "View (default nave)");
    cmd->add_option("--size", *size, "Final image size (default 1024x768, the paper's)");
    cmd->add_option("--stall", o->stall, "Extra operations per sample in the stalled columns (default 400)")
        ->check(CLI::Range(0, 10000000));
    cmd->add_option("--reps", o->repetitions, "Timed runs per row, median (default 3)")->check(CLI::Range(1, 1000));
    cmd->add_flag("--quick", o->quick, "256x192, one run (tests)");
    cmd->add_option("--device", o->device, "Vulkan device for the G-buffer (and the GPU passes)");
    cmd->add_option("--backend", o->backend,
                    "cpu (default) or vulkan: also the GPU passes on the same G-buffers, in a table of their own "
                    "(GPU timestamps, idle lanes, distance to the CPU's image)")
        ->check(CLI::IsMember({"cpu", "vulkan"}));
    auto lookup = cmd->add_option("--lookup", o->lookup,
                                  "With --backend vulkan: model (default, the CPU's sampler model) or hardware (the "
                                  "device's anisotropic sampler)")
                      ->check(CLI::IsMember({"model", "hardware"}));
    cmd->add_option("--threads", *threads, "Worker threads (0 = all)")->check(CLI::Range(0, 1024));
    cmd->callback([o, threads, size, lookup] {
        if (lookup->count() && o->backend != "vulkan") throw Error("--lookup goes with --backend vulkan");
        std::tie(o->width, o->height) = parseSize(*size, "--size", 8192);
        o->exec = Exec{*threads};
        ProgressLine line("eval", true);
        o->progress = progressLine;
        printResult(eval::markdown(eval::runDeferredExperiment(*o)));
    });
}
#endif

void addAo(CLI::App& eval) {
    auto o = std::make_shared<eval::AoExperimentOptions>();
    auto threads = std::make_shared<int>(0);
    auto* cmd = eval.add_subcommand("ao",
                                    "The SAO paper's experiments on analytic scenes (z and normal precision, "
                                    "pyramid filters, radius scaling, pass times, accuracy)");
    cmd->add_option("--out", o->outDir, "Output directory: images/, plots/, data/ao.json, data/ao.md")->required();
    cmd->add_flag("--quick", o->quick, "Small sizes and few repetitions (tests)");
    auto scenes = std::make_shared<std::vector<std::string>>(kDefaultAoScenes);
    cmd->add_option("--ao-scene", *scenes,
                    "Rendered scenes for the accuracy table, SCENE[:VIEW] (repeatable; "
                    "'none' for none)");
    cmd->add_option("--threads", *threads, "Worker threads (0 = all)")->check(CLI::Range(0, 1024));
    cmd->add_option("--backend", o->backend,
                    "cpu (default) or vulkan: also the GPU passes, their accuracy beside the CPU's and their GPU "
                    "timestamps (radius sweep, per-pass table)")
        ->check(CLI::IsMember({"cpu", "vulkan"}));
    cmd->add_option("--device", o->device, "With --backend vulkan: a device index or part of its name");
    cmd->add_flag("--speed-only", o->speedOnly,
                  "Only the speed experiments: Figure 5 (radius sweep) and Table 3 (per-pass times), with "
                  "--backend vulkan also from GPU timestamps");
    cmd->footer(
        "Scenes: 'corner' (floor meeting a wall) and 'room' (walls, boxes from 5 cm to 2 m, a stair, a\n"
        "column, spheres), ray cast exactly; for the accuracy table also the atrium, the Cornell box,\n"
        "Sponza and the bunny rasterised with Vulkan (the last two when ../shared/assets is present),\n"
        "their triangles ray traced with Embree. The ground truth is ray-traced obscurance with SAO's\n"
        "falloff (docs/evaluation.md).");
    cmd->callback([o, threads, scenes] {
        if (!o->device.empty() && o->backend != "vulkan") throw Error("--device goes with --backend vulkan");
        ProgressLine line("eval", true);
        if (!(scenes->size() == 1 && scenes->front() == "none")) o->renderedScenes = renderedAoScenes(*scenes);
        o->exec = Exec{*threads};
        o->progress = progressLine;
        printResult(eval::markdown(eval::runAoExperiments(*o)));
    });
}

}  // namespace

void addEvalCommand(CLI::App& app) {
    auto* eval = app.add_subcommand("eval", "Evaluation harness: quality, temporal stability, speed, kernels, report");
    eval->require_subcommand(1);
    addQuality(*eval);
    addTemporal(*eval);
    addKernels(*eval);
    addSpeed(*eval);
    addReport(*eval);
    addAo(*eval);
#ifdef SSFX_HAVE_RENDER
    addDeferred(*eval);
#endif
}

}  // namespace ssfx::cli
