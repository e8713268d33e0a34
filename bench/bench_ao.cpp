// Google Benchmark for ambient obscurance at 1920x1080 with the paper's 192 px guard band
// on the analytic "room" (the speed targets): the full SAO pipeline; the AO sample
// pass alone at r = 0.25 m and 4 m (flat in the radius?) for SAO and AlchemyAO; and both at
// r = 1.5 m (SAO vs the baseline), all in the same binary and run. Unit: visible Mpix/s.
// With the GPU backend built and a Vulkan device present, the same on the GPU (gpu/...): the
// full SAO pipeline and the sample pass alone, timed by GPU timestamps (manual time), at
// 1920x1080 + 192 and, for SAO against AlchemyAO at 1.5 m, at 2560x1600 + 256 (paper Fig. 5).
// GTAO against SAO (issue 37's target): both full pipelines at 1920x1080 + 64 px on the room,
// GTAO per preset and at R = 0.25 m and 4 m (flat in the radius?).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>
#include <string>

#include "ssfx/ao/alchemy.hpp"
#include "ssfx/ao/gtao.hpp"
#include "ssfx/ao/sao.hpp"
#include "ssfx/core/memory.hpp"
#include "ssfx/scene/analytic.hpp"
#ifdef SSFX_HAVE_GPU
#include <cstdio>
#include <memory>

#include "ssfx/core/error.hpp"
#include "ssfx/gpu/ao.hpp"
#endif

namespace {

constexpr int kW = 1920, kH = 1080, kGuard = 192;

const ssfx::scene::GeometryBuffer& room() {
    static const auto g =
        ssfx::scene::castGeometry(ssfx::scene::roomScene(), ssfx::Camera{}, kW + 2 * kGuard, kH + 2 * kGuard);
    return g;
}

const ssfx::scene::GeometryBuffer& room64() {
    static const auto g = ssfx::scene::castGeometry(ssfx::scene::roomScene(), ssfx::Camera{}, kW + 128, kH + 128);
    return g;
}

// The full pipelines at 1920x1080 + 64: SAO's paper defaults, GTAO's `preset` with radius R.
void fullAt64(benchmark::State& state, const std::string& preset, float radius) {
    ssfx::ao::SaoParams sp;
    sp.guardBand = 64;
    ssfx::ao::GtaoParams gp = preset.empty() ? ssfx::ao::GtaoParams{} : ssfx::ao::gtaoPreset(preset);
    gp.guardBand = 64, gp.radius = radius;
    ssfx::ao::GtaoTimings sum{};  // GTAO's stages (ms), the profile beside the total
    for (auto _ : state) {
        ssfx::ao::GtaoTimings t{};
        auto a = preset.empty() ? ssfx::ao::sao(room64().depth.view(), ssfx::Camera{}, sp)
                                : ssfx::ao::gtao(room64().depth.view(), ssfx::Camera{}, gp, {}, &t);
        benchmark::DoNotOptimize(a.data());
        sum.z += t.z, sum.chain += t.chain, sum.main += t.main, sum.denoise += t.denoise;
    }
    state.SetItemsProcessed(state.iterations() * kW * kH);
    if (!preset.empty()) {  // per iteration: z, the chain, edges + normals + main pass, denoiser
        const double n = double(state.iterations());
        state.counters["z_ms"] = sum.z / n, state.counters["chain_ms"] = sum.chain / n;
        state.counters["main_ms"] = sum.main / n, state.counters["denoise_ms"] = sum.denoise / n;
    }
}

void saoFull(benchmark::State& state) {
    ssfx::ao::SaoParams p;
    p.guardBand = kGuard;
    for (auto _ : state) {
        auto a = ssfx::ao::sao(room().depth.view(), ssfx::Camera{}, p);
        benchmark::DoNotOptimize(a.data());
    }
    state.SetItemsProcessed(state.iterations() * kW * kH);
}

// The sample pass over the visible region, on a prepared z pyramid (AlchemyAO reads its level 0).
void samplePass(benchmark::State& state, bool sao, float radius) {
    const ssfx::Camera cam;
    const auto proj = ssfx::projection(cam, kW + 2 * kGuard, kH + 2 * kGuard);
    const auto z = ssfx::ao::depthToZ(room().depth.view(), cam);
    // Built once, in the one-buffer layout the passes read: the timing is the pass alone.
    ssfx::ao::ZPyramid pyr;
    ssfx::ao::zPyramid(z.view(), 5, ssfx::ao::PyramidFilter::RotatedGrid, pyr);
    const ssfx::ao::Region region{kGuard, kGuard, kW, kH};
    ssfx::ao::SaoParams sp;
    sp.radius = radius;
    ssfx::ao::AlchemyParams ap;
    ap.radius = radius;
    for (auto _ : state) {
        auto a =
            sao ? ssfx::ao::saoSamplePass(pyr, proj, region, sp) : ssfx::ao::alchemySamplePass(pyr, proj, region, ap);
        benchmark::DoNotOptimize(a.data());
    }
    state.SetItemsProcessed(state.iterations() * kW * kH);
}

#ifdef SSFX_HAVE_GPU
std::shared_ptr<ssfx::vkx::Context> gpuContext() {
    static const std::shared_ptr<ssfx::vkx::Context> ctx = []() -> std::shared_ptr<ssfx::vkx::Context> {
        try {
            return ssfx::vkx::Context::create();
        } catch (const ssfx::Error& e) {
            std::fprintf(stderr, "bench_ao: no Vulkan device, the gpu/ benchmarks skip: %s\n", e.what());
            return nullptr;
        }
    }();
    return ctx;
}

const ssfx::scene::GeometryBuffer& room2560() {
    static const auto g = ssfx::scene::castGeometry(ssfx::scene::roomScene(), ssfx::Camera{}, 2560 + 512, 1600 + 512);
    return g;
}

// One GPU pipeline run per iteration; the time is the GPU's (the stage's timestamps, or the
// whole pipeline's when `stage` is null).
// The buffers: 1920x1080 + 192 (the paper's), 2560x1600 + 256, 1920x1080 + 64 (GTAO vs SAO).
enum class Buffer { Paper, Large, Guard64 };

// One GPU pipeline run per iteration; the time is the GPU's (the stage's timestamps, or the
// whole pipeline's when `stage` is null); every stage's mean time as a counter (<stage>_ms).
void gpuRun(benchmark::State& state, const ssfx::ao::AoParams& params, const char* method, const char* stage,
            Buffer buffer) {
    if (!gpuContext()) {
        state.SkipWithError("no Vulkan device");
        return;
    }
    ssfx::gpu::AoPass pass(gpuContext(), method, params);
    const auto& g = buffer == Buffer::Large ? room2560() : buffer == Buffer::Guard64 ? room64() : room();
    pass.run(g.depth.view(), ssfx::Camera{});  // warm-up: pipelines, scratch images
    std::map<std::string, double> stages;
    for (auto _ : state) {
        pass.run(g.depth.view(), ssfx::Camera{});
        double ms = pass.lastMilliseconds();
        for (const auto& d : pass.lastDispatches()) {
            stages[d.stage] += d.milliseconds;
            if (stage && d.stage == stage) ms = d.milliseconds;
        }
        state.SetIterationTime(ms / 1000.0);
    }
    for (const auto& [name, total] : stages) {
        std::string key = name + "_ms";
        std::replace(key.begin(), key.end(), ' ', '_');
        state.counters[key] = total / double(state.iterations());
    }
    state.SetItemsProcessed(state.iterations() * (buffer == Buffer::Large ? 2560 * 1600 : kW * kH));
}

void registerGpu() {
    ssfx::ao::SaoParams full;
    full.guardBand = kGuard;
    benchmark::RegisterBenchmark("gpu/sao/full/1080p+192",
                                 [full](benchmark::State& s) { gpuRun(s, full, "sao", nullptr, Buffer::Paper); })
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime();
    for (const float r : {0.25f, 1.5f, 4.0f}) {
        ssfx::ao::SaoParams sp = full;
        sp.radius = r;
        ssfx::ao::AlchemyParams ap;
        ap.guardBand = kGuard, ap.radius = r;
        const std::string rs = std::to_string(r).substr(0, 4);
        benchmark::RegisterBenchmark(("gpu/sao/full/r=" + rs).c_str(),
                                     [sp](benchmark::State& s) { gpuRun(s, sp, "sao", nullptr, Buffer::Paper); })
            ->Unit(benchmark::kMillisecond)
            ->UseManualTime();
        benchmark::RegisterBenchmark(("gpu/sao/samples/r=" + rs).c_str(),
                                     [sp](benchmark::State& s) { gpuRun(s, sp, "sao", "sample", Buffer::Paper); })
            ->Unit(benchmark::kMillisecond)
            ->UseManualTime();
        benchmark::RegisterBenchmark(("gpu/alchemy/samples/r=" + rs).c_str(),
                                     [ap](benchmark::State& s) { gpuRun(s, ap, "alchemy", "sample", Buffer::Paper); })
            ->Unit(benchmark::kMillisecond)
            ->UseManualTime();
    }
    ssfx::ao::SaoParams sp;
    sp.guardBand = 256, sp.radius = 1.5f;
    ssfx::ao::AlchemyParams ap;
    ap.guardBand = 256, ap.radius = 1.5f;
    benchmark::RegisterBenchmark("gpu/sao/full/2560x1600+256/r=1.5",
                                 [sp](benchmark::State& s) { gpuRun(s, sp, "sao", nullptr, Buffer::Large); })
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime();
    benchmark::RegisterBenchmark("gpu/alchemy/full/2560x1600+256/r=1.5",
                                 [ap](benchmark::State& s) { gpuRun(s, ap, "alchemy", nullptr, Buffer::Large); })
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime();
    // GTAO against SAO on the GPU, as on the CPU: 1920x1080 + 64, SAO's paper defaults.
    ssfx::ao::SaoParams s64;
    s64.guardBand = 64;
    benchmark::RegisterBenchmark("gpu/sao/full/1080p+64",
                                 [s64](benchmark::State& s) { gpuRun(s, s64, "sao", nullptr, Buffer::Guard64); })
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime();
    for (const char* preset : {"low", "high", "ultra"}) {
        ssfx::ao::GtaoParams gp = ssfx::ao::gtaoPreset(preset);
        gp.guardBand = 64;
        benchmark::RegisterBenchmark((std::string("gpu/gtao/full/1080p+64/") + preset + "/r=0.50").c_str(),
                                     [gp](benchmark::State& s) { gpuRun(s, gp, "gtao", nullptr, Buffer::Guard64); })
            ->Unit(benchmark::kMillisecond)
            ->UseManualTime();
    }
}
#endif

const bool registered = [] {
    benchmark::RegisterBenchmark("sao/full/1080p+192", saoFull)->Unit(benchmark::kMillisecond)->UseRealTime();
    benchmark::RegisterBenchmark("sao/full/1080p+64", [](benchmark::State& s) { fullAt64(s, "", 1.0f); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    for (const char* preset : {"low", "medium", "high", "ultra"})
        benchmark::RegisterBenchmark((std::string("gtao/full/1080p+64/") + preset + "/r=0.50").c_str(),
                                     [preset](benchmark::State& s) { fullAt64(s, preset, 0.5f); })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    for (float r : {0.25f, 4.0f})
        benchmark::RegisterBenchmark(("gtao/full/1080p+64/high/r=" + std::to_string(r).substr(0, 4)).c_str(),
                                     [r](benchmark::State& s) { fullAt64(s, "high", r); })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    for (float r : {0.25f, 1.5f, 4.0f})
        for (bool sao : {true, false})
            benchmark::RegisterBenchmark(
                (std::string(sao ? "sao" : "alchemy") + "/samples/r=" + std::to_string(r).substr(0, 4)).c_str(),
                [sao, r](benchmark::State& s) { samplePass(s, sao, r); })
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
#ifdef SSFX_HAVE_GPU
    registerGpu();
#endif
    return true;
}();

}  // namespace

int main(int argc, char** argv) {
    ssfx::tuneAllocatorForImages();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
