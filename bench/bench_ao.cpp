// Google Benchmark for ambient obscurance at 1920x1080 with the paper's 192 px guard band
// on the analytic "room" (the speed targets): the full SAO pipeline; the AO sample
// pass alone at r = 0.25 m and 4 m (flat in the radius?) for SAO and AlchemyAO; and both at
// r = 1.5 m (SAO vs the baseline), all in the same binary and run. Unit: visible Mpix/s.
#include <benchmark/benchmark.h>

#include "ssfx/ao/alchemy.hpp"
#include "ssfx/ao/sao.hpp"
#include "ssfx/core/memory.hpp"
#include "ssfx/scene/analytic.hpp"

namespace {

constexpr int kW = 1920, kH = 1080, kGuard = 192;

const ssfx::scene::GeometryBuffer& room() {
    static const auto g =
        ssfx::scene::castGeometry(ssfx::scene::roomScene(), ssfx::Camera{}, kW + 2 * kGuard, kH + 2 * kGuard);
    return g;
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

const bool registered = [] {
    benchmark::RegisterBenchmark("sao/full/1080p+192", saoFull)->Unit(benchmark::kMillisecond)->UseRealTime();
    for (float r : {0.25f, 1.5f, 4.0f})
        for (bool sao : {true, false})
            benchmark::RegisterBenchmark(
                (std::string(sao ? "sao" : "alchemy") + "/samples/r=" + std::to_string(r).substr(0, 4)).c_str(),
                [sao, r](benchmark::State& s) { samplePass(s, sao, r); })
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
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
