// Google Benchmark for the Vulkan scene renderer: the atrium and (when ../shared/assets is
// present) the Sponza atrium geometry at 1920x1080: depth (D32F), forward colour, the
// G-buffer at 1x1 and at 4x4 supersampling (7680x4320 samples). The reported time is the
// draw on the device from timestamp queries (manual time); "wall_ms" adds the upload of
// the scene, the attachments and the read-back.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <memory>

#include "ssfx/render/renderer.hpp"

namespace {

using namespace ssfx;

render::Renderer& renderer() {
    static render::Renderer r;
    return r;
}

enum class What { Depth, Color, GBuffer1, GBuffer4 };

void renderBench(benchmark::State& state, const scene::Scene* scene, const std::string& view, What what) {
    double wallMs = 0;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        double gpu = 0;
        switch (what) {
            case What::Depth: gpu = renderer().renderDepth(*scene, scene->view(view), 1920, 1080).gpuMs; break;
            case What::Color: gpu = renderer().renderColor(*scene, scene->view(view), 1920, 1080).gpuMs; break;
            case What::GBuffer1: gpu = renderer().renderGBuffer(*scene, scene->view(view), 1920, 1080, 1).gpuMs; break;
            case What::GBuffer4: gpu = renderer().renderGBuffer(*scene, scene->view(view), 1920, 1080, 4).gpuMs; break;
        }
        wallMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        state.SetIterationTime(gpu * 1e-3);
    }
    state.counters["wall_ms"] = benchmark::Counter(wallMs / double(state.iterations()));
    state.counters["triangles"] = double(scene->triangleCount());
    state.SetLabel(renderer().device().name);
}

}  // namespace

int main(int argc, char** argv) {
    static const scene::Scene atrium = scene::atrium();
    static std::unique_ptr<scene::Scene> sponza;
    const std::filesystem::path sponzaFile = std::filesystem::path(SSFX_SOURCE_DIR) / "scenes" / "sponza.json";
    try {
        sponza = std::make_unique<scene::Scene>(scene::loadScene(sponzaFile.string()));
    } catch (const std::exception& e) {
        fmt::print(stderr, "bench_render: Sponza left out ({})\n", e.what());
    }
    std::vector<std::pair<const scene::Scene*, std::string>> scenes{{&atrium, "nave"}};
    if (sponza) scenes.emplace_back(sponza.get(), "atrium");
    const std::pair<What, const char*> kinds[] = {{What::Depth, "depth_1080p"},
                                                  {What::Color, "colour_1080p"},
                                                  {What::GBuffer1, "gbuffer_1x1_1080p"},
                                                  {What::GBuffer4, "gbuffer_4x4_1080p"}};
    for (const auto& [scene, view] : scenes)
        for (const auto& [what, name] : kinds)
            benchmark::RegisterBenchmark(fmt::format("{}/{}", scene->name, name).c_str(), renderBench, scene, view,
                                         what)
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond)
                ->Iterations(what == What::GBuffer4 ? 2 : 5);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
