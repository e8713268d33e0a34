// Table 1 of the adaptive supersampling paper on our scenes (see deferred_experiment.hpp).
#include "ssfx/eval/deferred_experiment.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "ssfx/aa/fxaa.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/eval/metrics.hpp"
#include "ssfx/eval/plot.hpp"
#include "ssfx/eval/timing.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/render/renderer.hpp"
#ifdef SSFX_HAVE_GPU
#include "ssfx/gpu/deferred.hpp"
#endif

namespace ssfx::eval {

namespace fs = std::filesystem;

namespace {

std::string cell(double v, int digits) { return std::isfinite(v) ? fmt::format("{:.{}f}", v, digits) : "-"; }

ImageF toFloat(const Image<std::uint8_t>& k) {
    ImageF f(k.width(), k.height());
    for (std::size_t i = 0; i < k.pixels().size(); ++i) f.data()[i] = float(k.pixels()[i]);
    return f;
}

double maxAbsoluteError(const deferred::ImageRgbF& a, const deferred::ImageRgbF& b) {
    const ImageF e = deferred::absoluteError(a, b);
    return double(*std::max_element(e.pixels().begin(), e.pixels().end()));
}

std::size_t countDifferent(const Image<std::uint8_t>& a, const Image<std::uint8_t>& b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i) n += a.pixels()[i] != b.pixels()[i];
    return n;
}

nlohmann::ordered_json number(double v) {
    return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
}

}  // namespace

Section runDeferredExperiment(const DeferredExperimentOptions& o) {
    auto say = [&](const std::string& s) {
        if (o.progress) o.progress({s});
    };
    deferred::validate(o.params);
    const fs::path out(o.outDir);
    io::makeDirectories((out / "images").string());
    io::makeDirectories((out / "data").string());
    const int w = o.quick ? 256 : o.width, h = o.quick ? 192 : o.height,
              reps = o.quick ? 1 : std::max(1, o.repetitions);
    const scene::Scene scene = scene::loadScene(o.scene);
    const scene::View& view = scene.view(o.view);
    render::Renderer renderer({o.device, false});
    deferred::ShadingParams stalled = o.params.shading;
    stalled.stall = o.stall;
    deferred::AdaptiveParams stalledParams = o.params;
    stalledParams.shading = stalled;
    deferred::AdaptiveParams tiledParams = o.params, tiledStalledParams = stalledParams;
    tiledParams.tiled = tiledStalledParams.tiled = true;

    if (o.backend != "cpu" && o.backend != "vulkan")
        throw Error(fmt::format("eval deferred: backend '{}' (expected cpu or vulkan)", o.backend));
#ifdef SSFX_HAVE_GPU
    // The GPU passes on a compute context of their own: lavapipe's compute timestamps do not
    // cover the dispatches once the renderer has drawn on the same context (docs/gpu.md).
    std::unique_ptr<gpu::AdaptiveShading> gpuShading;
    std::string gpuDevice;
    if (o.backend == "vulkan") {
        vkx::ContextOptions co;
        co.device = o.device;
        auto ctx = vkx::Context::create(co);
        gpuDevice = ctx->info.name;
        gpuShading = std::make_unique<gpu::AdaptiveShading>(ctx, scene, gpu::parseSampling(o.lookup));
    }
#else
    if (o.backend == "vulkan")
        throw Error("eval deferred --backend vulkan: this ssfx was built without the GPU backend");
#endif

    struct Row {
        std::string ss, method;
        double gbufferMs, shadeMs, stalledMs, mse, psnr, samples;
        double idleLanes = NAN, vsCpu = NAN;  // the GPU rows: rest pass's idle lanes, max |GPU - CPU|
    };
    std::vector<Row> rows;
#ifdef SSFX_HAVE_GPU
    std::vector<Row> gpuRows;
    std::vector<std::string> gpuNotes;  // k against the CPU's, per m
    double gpuSpeedupPlain = NAN, gpuSpeedupStalled = NAN, listSpeedupPlain = NAN, listSpeedupStalled = NAN;
    int gpuSubgroup = 0;
#endif
    nlohmann::ordered_json j;
    j["scene"] = o.scene;
    j["view"] = o.view;
    j["size"] = {w, h};
    j["stall"] = o.stall;
    j["repetitions"] = reps;
    j["device"] = renderer.device().name;
    j["params"] = {{"cDepth", o.params.cDepth},
                   {"cNormal", o.params.cNormal},
                   {"cShading", o.params.cShading},
                   {"tMin", o.params.tMin},
                   {"tEdge", o.params.tEdge}};
    double speedupPlain = NAN, speedupStalled = NAN;
    for (int m = 1; m <= 4; ++m) {
        say(fmt::format("deferred: {} {}x{} m = {} on {}", o.scene, w, h, m, renderer.device().name));
        std::vector<double> gpu;
        scene::GBuffer g;
        for (int r = 0; r < reps; ++r) {
            g = renderer.renderGBuffer(scene, view, w, h, m);
            gpu.push_back(g.gpuMs);
        }
        const double gbufferMs = median(gpu);
        // Reference and ours, plain and stalled, interleaved so that both see the same machine state.
        std::vector<double> refMs, refStallMs, oursMs, oursStallMs, tiledMs, tiledStallMs, fxaaMs;
        deferred::DeferredResult ref, ours;
        for (int r = 0; r < reps; ++r) {
            ref = deferred::bruteForceSupersampling(scene, g, o.params.shading, o.exec);
            refMs.push_back(ref.totalMs());
            refStallMs.push_back(deferred::bruteForceSupersampling(scene, g, stalled, o.exec).totalMs());
            if (m == 1) {
                const ImageRgba8 img = deferred::toRgba8(ref.image);
                const auto t0 = std::chrono::steady_clock::now();
                const ImageRgba8 aa = aa::fxaa3d(img.view(), {}, o.exec);
                fxaaMs.push_back(
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
                if (r == 0) io::writePng((out / "images" / "deferred_m1_fxaa3d.png").string(), aa.view());
                continue;
            }
            ours = deferred::adaptiveSupersampling(scene, g, o.params, o.exec);
            oursMs.push_back(ours.totalMs());
            oursStallMs.push_back(deferred::adaptiveSupersampling(scene, g, stalledParams, o.exec).totalMs());
            const auto tiled = deferred::adaptiveSupersampling(scene, g, tiledParams, o.exec);
            SSFX_ASSERT(tiled.image == ours.image && tiled.shaded == ours.shaded);  // only the order differs
            tiledMs.push_back(tiled.totalMs());
            tiledStallMs.push_back(deferred::adaptiveSupersampling(scene, g, tiledStalledParams, o.exec).totalMs());
        }
        const std::string ss = fmt::format("{0}x{0}", m);
#ifdef SSFX_HAVE_GPU
        if (gpuShading) {
            // The same rows on the GPU passes, on the same G-buffer, times from GPU timestamps.
            std::vector<double> bMs, bStallMs, aMs, aStallMs, tMs, tStallMs, lMs, lStallMs;
            gpu::GpuDeferredResult gb, ga, gt, gl;
            // Run -1 warms up, untimed: lavapipe compiles a shader's variant on its first dispatch.
            for (int r = -1; r < reps; ++r) {
                const auto keep = [r](std::vector<double>& v, double ms) {
                    if (r >= 0) v.push_back(ms);
                };
                gb = gpuShading->bruteForce(g, o.params.shading);
                keep(bMs, gb.totalMs());
                keep(bStallMs, gpuShading->bruteForce(g, stalled).totalMs());
                if (m == 1) continue;
                using gpu::Schedule;
                ga = gpuShading->adaptive(g, o.params, Schedule::PerPixel);
                keep(aMs, ga.totalMs());
                keep(aStallMs, gpuShading->adaptive(g, stalledParams, Schedule::PerPixel).totalMs());
                gt = gpuShading->adaptive(g, o.params, Schedule::Tiled);
                keep(tMs, gt.totalMs());
                keep(tStallMs, gpuShading->adaptive(g, stalledParams, Schedule::Tiled).totalMs());
                gl = gpuShading->adaptive(g, o.params, Schedule::SampleList);
                keep(lMs, gl.totalMs());
                keep(lStallMs, gpuShading->adaptive(g, stalledParams, Schedule::SampleList).totalMs());
                // Only the lanes' order differs.
                SSFX_ASSERT(gt.image == ga.image && gt.shaded == ga.shaded);
                SSFX_ASSERT(gl.image == ga.image && gl.shaded == ga.shaded);
            }
            gpuSubgroup = gb.subgroupSize;
            const double vsCpuRef = maxAbsoluteError(gb.image, ref.image);
            if (m == 1) {
                gpuRows.push_back({ss, "default", gbufferMs, median(bMs), median(bStallMs), NAN, NAN, NAN,
                                   gb.idleLaneShare(), vsCpuRef});
            } else {
                const double gmse = deferred::mse(ga.image, gb.image);
                gpuRows.push_back({ss, "brute force", gbufferMs, median(bMs), median(bStallMs), NAN, NAN, 100.0,
                                   gb.idleLaneShare(), vsCpuRef});
                const double vsCpuOurs = maxAbsoluteError(ga.image, ours.image);
                gpuRows.push_back({ss, "ours", gbufferMs, median(aMs), median(aStallMs), gmse, psnrFromMse(gmse),
                                   ga.shadedPercent(), ga.idleLaneShare(), vsCpuOurs});
                gpuRows.push_back({ss, "ours, tiles by k", gbufferMs, median(tMs), median(tStallMs), gmse,
                                   psnrFromMse(gmse), gt.shadedPercent(), gt.idleLaneShare(), vsCpuOurs});
                gpuRows.push_back({ss, "ours, sample list", gbufferMs, median(lMs), median(lStallMs), gmse,
                                   psnrFromMse(gmse), gl.shadedPercent(), gl.idleLaneShare(), vsCpuOurs});
                gpuNotes.push_back(fmt::format("{}: k differs from the CPU's at {} of {} pixels", ss,
                                               countDifferent(ga.samples, ours.samples), ga.samples.pixels().size()));
                if (m == 4) {
                    gpuSpeedupPlain = median(bMs) / median(aMs);
                    gpuSpeedupStalled = median(bStallMs) / median(aStallMs);
                    listSpeedupPlain = median(bMs) / median(lMs);
                    listSpeedupStalled = median(bStallMs) / median(lStallMs);
                }
            }
        }
#endif
        io::writePng((out / "images" / fmt::format("deferred_m{}_brute_force.png", m)).string(),
                     deferred::toRgba8(ref.image).view());
        if (m == 1) {
            rows.push_back({ss, "default", gbufferMs, median(refMs), median(refStallMs), NAN, NAN, NAN});
            const double f = median(fxaaMs);
            rows.push_back({ss, "+ fxaa3d", gbufferMs, median(refMs) + f, median(refStallMs) + f, NAN, NAN, NAN});
            continue;
        }
        const double mse = deferred::mse(ours.image, ref.image);
        const double psnr = psnrFromMse(mse);
        rows.push_back({ss, "brute force", gbufferMs, median(refMs), median(refStallMs), NAN, NAN, 100.0});
        rows.push_back({ss, "ours", gbufferMs, median(oursMs), median(oursStallMs), mse, psnr, ours.shadedPercent()});
        rows.push_back({ss, "ours, 8x8 tiles by k", gbufferMs, median(tiledMs), median(tiledStallMs), mse, psnr,
                        ours.shadedPercent()});
        if (m == 4) {
            speedupPlain = median(refMs) / median(oursMs);
            speedupStalled = median(refStallMs) / median(oursStallMs);
        }
        const float n = float(m * m);
        const auto stem = [&](const char* what) {
            return (out / "images" / fmt::format("deferred_m{}_{}.png", m, what)).string();
        };
        io::writePng(stem("ours"), deferred::toRgba8(ours.image).view());
        io::writePng(stem("samples"), heatMap(toFloat(ours.samples).view(), 1.0f, n).view());
        io::writePng(stem("error"), heatMap(deferred::absoluteError(ours.image, ref.image).view(), 0.0f, 0.05f).view());
        io::writePng(stem("k_depth"), heatMap(ours.kDepth.view(), 0.0f, n).view());
        io::writePng(stem("k_normal"), heatMap(ours.kNormal.view(), 0.0f, n).view());
        io::writePng(stem("k_shading"), heatMap(ours.kShading.view(), 0.0f, n).view());
    }

    Section section;
    section.title = "Adaptive supersampling for deferred shading (the paper's Table 1)";
    // The note is laid out in the report, whose root its links are relative to.
    section.note =
        "The method ([doc](methods/adaptive.html)) against brute-force supersampling on the atrium's G-buffer "
        "from the Vulkan renderer. Images at 4x4: brute force, ours, the per-pixel sample count (blue 1 .. "
        "red 16), the absolute error (0 .. 0.05) and each metric's k (paper Figure 8). Data: "
        "[deferred/data/deferred.json](deferred/data/deferred.json).";
    Block b;
    b.heading = fmt::format("Adaptive supersampling (paper Table 1) on {} / {}, {}x{}", o.scene, o.view, w, h);
    b.text = fmt::format(
        "Device for the G-buffer: {} (GPU time of the draw). Shading on the CPU ({} threads), median of {} run(s); "
        "stalled: {} extra dependent operations per shaded sample. MSE and PSNR of ours against brute force at the "
        "same m (RGB in [0, 1]). \"8x8 tiles by k\": the same method shading each 8x8 tile's pixels grouped by "
        "sample count (the paper's future work; identical output). Constants: cDepth {}, cNormal {}, cShading {}, "
        "thresholds {} / {}.",
        renderer.device().name, o.exec.threads == 0 ? std::string("all") : std::to_string(o.exec.threads), reps,
        o.stall, o.params.cDepth, o.params.cNormal, o.params.cShading, o.params.tMin, o.params.tEdge);
    b.table.header = {"supersampling",      "method",      "G-buffer ms", "shading ms", "total ms",
                      "stalled shading ms", "MSE (x1e-5)", "PSNR dB",     "samples %"};
    for (const auto& r : rows) {
        b.table.addRow({r.ss, r.method, cell(r.gbufferMs, 1), cell(r.shadeMs, 1), cell(r.gbufferMs + r.shadeMs, 1),
                        cell(r.stalledMs, 1), cell(r.mse * 1e5, 2), cell(r.psnr, 2), cell(r.samples, 2)});
        j["rows"].push_back({{"supersampling", r.ss},
                             {"method", r.method},
                             {"gbuffer_ms", r.gbufferMs},
                             {"shading_ms", r.shadeMs},
                             {"stalled_ms", r.stalledMs},
                             {"mse", number(r.mse)},
                             {"psnr", number(r.psnr)},
                             {"samples_percent", number(r.samples)}});
    }
    b.after =
        fmt::format("At 4x4: ours is {:.2f}x faster than brute force in shading, {:.2f}x with the stall (same run).",
                    speedupPlain, speedupStalled);
    for (const char* name : {"brute_force", "ours", "samples", "error", "k_depth", "k_normal", "k_shading"})
        b.figures.push_back(
            {fmt::format("images/deferred_m4_{}.png", name), fmt::format("4x4: {}", name), Figure::Kind::Image, 0, 0});
    section.blocks.push_back(std::move(b));
    j["speedup_4x4"] = {{"plain", speedupPlain}, {"stalled", speedupStalled}};
#ifdef SSFX_HAVE_GPU
    if (gpuShading) {
        Block gb;
        gb.heading = fmt::format("The same on the GPU passes ({}, lookup {})", gpuDevice, o.lookup);
        gb.text = fmt::format(
            "gpu::AdaptiveShading (docs/gpu.md, \"Adaptive shading\") on the same G-buffers (uploaded), shading "
            "times from GPU timestamps around the passes, median of {} run(s); MSE and PSNR of ours against the GPU's "
            "brute force at the same m. \"Lanes idle\": the share of the rest pass's (brute force's) lane-iterations "
            "that wait for a busier lane of their subgroup (subgroup {}), counted in the shader. \"Max |GPU - CPU|\": "
            "the largest channel difference from the CPU's image of the same row (RGB in [0, 1]). \"Ours\": one "
            "invocation per pixel; \"tiles by k\": each 8x8 tile's pixels ranked by k before the rest pass; \"sample "
            "list\": the samples enqueued and shaded one per invocation (gpu::Schedule; the same image).",
            reps, gpuSubgroup);
        gb.table.header = {"supersampling", "method",  "shading ms", "total ms",     "stalled shading ms",
                           "MSE (x1e-5)",   "PSNR dB", "samples %",  "lanes idle %", "max |GPU - CPU|"};
        for (const auto& r : gpuRows) {
            gb.table.addRow({r.ss, r.method, cell(r.shadeMs, 2), cell(r.gbufferMs + r.shadeMs, 1), cell(r.stalledMs, 1),
                             cell(r.mse * 1e5, 2), cell(r.psnr, 2), cell(r.samples, 2), cell(100.0 * r.idleLanes, 1),
                             fmt::format("{:.2g}", r.vsCpu)});
            j["gpu"]["rows"].push_back({{"supersampling", r.ss},
                                        {"method", r.method},
                                        {"shading_ms", r.shadeMs},
                                        {"stalled_ms", r.stalledMs},
                                        {"mse", number(r.mse)},
                                        {"psnr", number(r.psnr)},
                                        {"samples_percent", number(r.samples)},
                                        {"idle_lanes", r.idleLanes},
                                        {"max_abs_vs_cpu", r.vsCpu}});
        }
        std::string notes;
        for (const auto& n : gpuNotes) notes += (notes.empty() ? "" : "; ") + n;
        gb.after = fmt::format(
            "At 4x4 on the GPU: ours is {:.2f}x faster than brute force in shading, {:.2f}x with the stall; with the "
            "sample list {:.2f}x and {:.2f}x (the CPU: {:.2f}x, {:.2f}x). {}.",
            gpuSpeedupPlain, gpuSpeedupStalled, listSpeedupPlain, listSpeedupStalled, speedupPlain, speedupStalled,
            notes);
        j["gpu"]["device"] = gpuDevice;
        j["gpu"]["lookup"] = o.lookup;
        j["gpu"]["speedup_4x4"] = {{"plain", gpuSpeedupPlain}, {"stalled", gpuSpeedupStalled}};
        j["gpu"]["sample_list_speedup_4x4"] = {{"plain", listSpeedupPlain}, {"stalled", listSpeedupStalled}};
        section.blocks.push_back(std::move(gb));
    }
#endif
    const std::string text = j.dump(2) + "\n";
    io::writeTextAtomic((out / "data" / "deferred.json").string(), text);
    io::writeTextAtomic((out / "data" / "deferred.md").string(), markdown(section));
    return section;
}

}  // namespace ssfx::eval
