// ssfx deferred: adaptive supersampling of a rendered G-buffer, beside brute-force supersampling.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <optional>

#include "apps/ssfx/commands.hpp"
#include "apps/ssfx/console.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/deferred/registry.hpp"
#include "ssfx/eval/metrics.hpp"
#include "ssfx/eval/plot.hpp"
#include "ssfx/io/exr.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/render/renderer.hpp"
#include "ssfx/vk/context.hpp"
#ifdef SSFX_HAVE_GPU
#include "ssfx/gpu/deferred.hpp"
#endif

namespace ssfx::cli {

namespace {

struct DeferredOptions {
    std::string scene, view, size = "1024x768", out, device, backend = "cpu", lookup, schedule, aoImage;
    std::vector<std::string> params;
    int m = 4, stall = 0, threads = 0;
    bool bruteForce = false;
};

#ifdef SSFX_HAVE_GPU
// The method (and brute force) on the GPU, on a compute context of its own: lavapipe's
// compute timestamps do not cover the dispatches once the renderer has drawn on the same
// context (docs/gpu.md, "Adaptive shading").
struct GpuRun {
    deferred::DeferredResult adaptive;
    std::optional<deferred::DeferredResult> brute;
    std::string device, summary;
};
GpuRun runOnGpu(const DeferredOptions& o, const scene::Scene& scene, const scene::GBuffer& g,
                const deferred::AdaptiveParams& p) {
    vkx::ContextOptions co;
    co.device = o.device;
    auto ctx = vkx::Context::create(co);
    gpu::AdaptiveShading shading(ctx, scene, gpu::parseSampling(o.lookup.empty() ? "model" : o.lookup));
    if (shading.lookup() == gpu::Sampling::Hardware && p.shading.maxAnisotropy > 1 && ctx->info.type == "cpu")
        printNote("deferred",
                  "lavapipe's anisotropic filtering is very slow (docs/gpu.md, \"Adaptive shading\"); "
                  "-p maxAnisotropy=1 keeps the hardware lookup trilinear");
    GpuRun r;
    r.device = ctx->info.name;
    // Untimed warm-up of each pipeline (without the stall): lavapipe compiles a shader's
    // variant on its first dispatch, inside the timestamps.
    constexpr std::array<gpu::Schedule, 3> kSchedules{gpu::Schedule::PerPixel, gpu::Schedule::Tiled,
                                                      gpu::Schedule::SampleList};
    deferred::AdaptiveParams warm = p;
    warm.shading.stall = 0;
    for (const gpu::Schedule s : kSchedules) shading.adaptive(g, warm, s);
    if (o.bruteForce) shading.bruteForce(g, warm.shading);
    // Every schedule (the same image); the one asked for (or -p tiled's) is the result.
    const gpu::Schedule chosen = !o.schedule.empty() ? gpu::parseSchedule(o.schedule)
                                 : p.tiled           ? gpu::Schedule::Tiled
                                                     : gpu::Schedule::PerPixel;
    r.summary = "; rest pass:";
    const char* names[] = {"per pixel", "tiled", "sample list"};
    for (std::size_t i = 0; i < kSchedules.size(); ++i) {
        gpu::GpuDeferredResult one = shading.adaptive(g, p, kSchedules[i]);
        r.summary += fmt::format("{} {} {:.2f} ms, {:.1f} % of lanes idle", i ? ";" : "", names[i], one.restMs,
                                 100.0 * one.idleLaneShare());
        if (kSchedules[i] == gpu::Schedule::SampleList)
            r.summary += fmt::format(" (enqueue {:.2f}, shade {:.2f}, resolve {:.2f} ms)", one.listEnqueueMs,
                                     one.listShadeMs, one.listResolveMs);
        if (i + 1 == kSchedules.size()) r.summary += fmt::format(" (subgroup {})", one.subgroupSize);
        if (kSchedules[i] == chosen) r.adaptive = std::move(one);
    }
    if (o.bruteForce) {
        const gpu::GpuDeferredResult b = shading.bruteForce(g, p.shading);
        r.summary += fmt::format("; brute force {:.1f} % of lanes idle", 100.0 * b.idleLaneShare());
        r.brute = b;
    }
    return r;
}
#endif

}  // namespace

deferred::AdaptiveParams adaptiveParams(const std::vector<std::string>& params, int stall) {
    const deferred::DeferredMethodInfo& method = deferred::deferredMethodById("adaptive");
    deferred::DeferredParams all = method.defaults();
    std::get<deferred::AdaptiveParams>(all).shading.stall = stall;
    for (const auto& text : params) {
        const auto [name, value] = parseParam(text, method.params, method.id);
        deferred::setParam(method, all, name, value);
    }
    method.validate(all);
    return std::get<deferred::AdaptiveParams>(all);
}

namespace {

void run(const DeferredOptions& o) {
    if (o.scene.empty()) throw Error("no scene given (--scene atrium | cornell | FILE.json | MODEL)");
    if (o.out.empty()) throw Error("no output folder given (--out DIR)");
    const bool vulkan = o.backend == "vulkan";
    if (!o.lookup.empty() && !vulkan) throw Error("--lookup goes with --backend vulkan (the CPU runs the model)");
    if (!o.schedule.empty() && !vulkan)
        throw Error("--schedule goes with --backend vulkan (on the CPU: -p tiled=true|false)");
#ifndef SSFX_HAVE_GPU
    if (vulkan) throw Error("--backend vulkan: this ssfx was built without the GPU backend");
#endif
    const auto [w, h] = parseSize(o.size, "--size", 8192);
    const deferred::AdaptiveParams p = adaptiveParams(o.params, o.stall);
    const scene::Scene scene = scene::loadScene(o.scene);
    const scene::View& view = o.view.empty() ? scene.views.at(0).second : scene.view(o.view);
    render::Renderer renderer({o.device, false});
    // The ambient occlusion is read (and checked) before the draw: a bad file costs nothing.
    ImageF ambientOcclusion;
    if (!o.aoImage.empty()) ambientOcclusion = io::readExr(o.aoImage);
    if (!ambientOcclusion.empty() && (ambientOcclusion.width() != w || ambientOcclusion.height() != h))
        throw Error(fmt::format("--ao-image {}: {}x{}, the image is {}x{}", o.aoImage, ambientOcclusion.width(),
                                ambientOcclusion.height(), w, h));
    scene::GBuffer g = renderer.renderGBuffer(scene, view, w, h, o.m);
    g.ambientOcclusion = std::move(ambientOcclusion);
    const Exec exec{o.threads};
    deferred::DeferredResult a;
    std::optional<deferred::DeferredResult> ref;  // brute force
    std::string where = renderer.device().name, gpuSummary;
    if (vulkan) {
#ifdef SSFX_HAVE_GPU
        GpuRun r = runOnGpu(o, scene, g, p);
        a = std::move(r.adaptive);
        ref = std::move(r.brute);
        where = fmt::format("{} (vulkan, lookup={}; GPU ms)", r.device, o.lookup.empty() ? "model" : o.lookup);
        gpuSummary = r.summary;
#endif
    } else {
        a = deferred::adaptiveSupersampling(scene, g, p, exec);
        if (o.bruteForce) ref = deferred::bruteForceSupersampling(scene, g, p.shading, exec);
        where += "; cpu";
    }

    namespace fs = std::filesystem;
    io::makeDirectories(o.out);
    const fs::path dir(o.out);
    const float n = float(o.m * o.m);
    ImageF samples(w, h);
    for (int yy = 0; yy < h; ++yy)
        for (int xx = 0; xx < w; ++xx) samples(xx, yy) = float(a.samples(xx, yy));
    io::writePng((dir / "image.png").string(), deferred::toRgba8(a.image).view());
    io::writePng((dir / "samples.png").string(), eval::heatMap(samples.view(), 1.0f, n).view());
    io::writePng((dir / "k_depth.png").string(), eval::heatMap(a.kDepth.view(), 0.0f, n).view());
    io::writePng((dir / "k_normal.png").string(), eval::heatMap(a.kNormal.view(), 0.0f, n).view());
    io::writePng((dir / "k_shading.png").string(), eval::heatMap(a.kShading.view(), 0.0f, n).view());
    std::string summary = fmt::format(
        "{} {}x{} m={} on {}: G-buffer {:.1f} ms (GPU); adaptive {:.2f} ms (first {:.2f}, evaluate {:.2f}, rest "
        "{:.2f}), {:.2f} % of the samples",
        scene.name, w, h, o.m, where, g.gpuMs, a.totalMs(), a.firstMs, a.evaluateMs, a.restMs, a.shadedPercent());
    if (ref) {
        io::writePng((dir / "brute_force.png").string(), deferred::toRgba8(ref->image).view());
        io::writePng((dir / "error.png").string(),
                     eval::heatMap(deferred::absoluteError(a.image, ref->image).view(), 0.0f, 0.05f).view());
        const double mse = deferred::mse(a.image, ref->image);
        summary += fmt::format("; brute force {:.2f} ms; MSE {:.3g} (x1e-5: {:.2f}), PSNR {:.2f} dB", ref->restMs, mse,
                               mse * 1e5, eval::psnrFromMse(mse));
    }
    printResult(summary + gpuSummary + fmt::format(" -> {}\n", o.out));
}

}  // namespace

void addDeferredCommand(CLI::App& app) {
    auto o = std::make_shared<DeferredOptions>();
    auto* cmd = app.add_subcommand("deferred",
                                   "Adaptive supersampling for deferred shading (beside brute-force supersampling)");
    cmd->add_option("--scene", o->scene, "atrium, cornell, a scene .json or a model file");
    cmd->add_option("--view", o->view, "Named viewpoint (default: the scene's first)");
    cmd->add_option("--size", o->size, "Final image size WxH (default 1024x768)");
    cmd->add_option("--ss", o->m, "Supersampling M: the G-buffer has M x M samples per pixel (1..4, default 4)")
        ->check(CLI::Range(1, 4));
    cmd->add_option("--stall", o->stall, "Extra dependent operations per shaded sample (emulates a heavy shader)")
        ->check(CLI::Range(0, 10000000));
    cmd->add_flag("--brute-force", o->bruteForce,
                  "Also shade every sample (brute-force supersampling); write brute_force.png and error.png, print "
                  "MSE/PSNR against it");
    std::string names;  // from the registry's table
    for (const ParamInfo& p : deferred::deferredMethodById("adaptive").params)
        names += fmt::format(" {} ({})", p.name, p.valueText(p.defaultValue()));
    cmd->add_option("-p,--param", o->params,
                    "NAME=VALUE (repeatable; ranges: ssfx methods --family deferred):" + names);
    cmd->add_option("--out", o->out,
                    "Output folder: image.png, samples.png (k heat map), k_depth/k_normal/k_shading.png "
                    "(each metric's k), with --brute-force brute_force.png, error.png (|error| 0..0.05)");
    cmd->add_option("--backend", o->backend,
                    "cpu (default) or vulkan: shade on the GPU (the G-buffer read back and uploaded; times from GPU "
                    "timestamps after an untimed warm-up; runs the rest pass's three schedules and prints each one's "
                    "time and idle-lane share)")
        ->check(CLI::IsMember({"cpu", "vulkan"}));
    cmd->add_option("--lookup", o->lookup,
                    "With --backend vulkan: model (default: the CPU's sampler model in the shader) or hardware (the "
                    "device's textureGrad with anisotropic filtering)")
        ->check(CLI::IsMember({"model", "hardware"}));
    cmd->add_option("--schedule", o->schedule,
                    "With --backend vulkan: the rest pass's schedule whose result is written: pixel (one invocation "
                    "per pixel), tiled (8x8 tiles ranked by k) or list (one sample per invocation); default: -p "
                    "tiled's. All three run and are printed; their images are the same")
        ->check(CLI::IsMember({"pixel", "tiled", "list"}));
    cmd->add_option("--ao-image", o->aoImage,
                    "Ambient occlusion of the final pixels (an EXR of --size, values in [0, 1], e.g. from ssfx ao -o "
                    "ao.exr with the same scene, view and size): multiplies the ambient term of every sample");
    cmd->add_option("--device", o->device, "Vulkan device index or part of its name");
    cmd->add_option("--threads", o->threads, "Worker threads (0 = all)")->check(CLI::Range(0, 1024));
    cmd->footer(
        "docs/methods/adaptive.md. Example:\n"
        "  ssfx deferred --scene atrium --view nave --size 1024x768 --ss 4 --brute-force --out out/deferred\n"
        "  ssfx deferred --backend vulkan --lookup hardware --scene atrium --ss 4 --brute-force --out out/gpu");
    cmd->callback([o] {
        io::OutputSet outputs;  // the images, the heat maps and the numbers: all or none
        run(*o);
        outputs.commit();
    });
}

}  // namespace ssfx::cli
