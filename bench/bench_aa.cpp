// Google Benchmark: every registered method x {1 thread, all threads} on the synthetic
// 1920x1080 drawing (resolves get the same drawing at 2x/4x), with `copy` (noaa) and
// `blur` as baselines in the same binary. Unit: Mpix/s of output.
#include <benchmark/benchmark.h>

#include "ssfx/aa/registry.hpp"
#include "ssfx/core/memory.hpp"
#include "ssfx/eval/synthetic.hpp"

namespace {

const ssfx::ImageRgba8& input(int scale) {
    static const ssfx::ImageRgba8 in[3] = {ssfx::eval::syntheticScene(1920, 1080, 1),
                                           ssfx::eval::syntheticScene(1920, 1080, 2),
                                           ssfx::eval::syntheticScene(1920, 1080, 4)};
    return in[scale == 4 ? 2 : scale == 2 ? 1 : 0];
}

// The output buffer is allocated once, as a renderer would (runInto).
void runMethod(benchmark::State& state, const ssfx::MethodInfo* m, int threads) {
    const auto& in = input(m->inputScale);
    ssfx::ImageRgba8 out(1920, 1080);
    for (auto _ : state) {
        m->runInto(in.view(), out.view(), {}, ssfx::Exec{threads});
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * 1920 * 1080);
}

const bool registered = [] {
    for (const auto& m : ssfx::methods())
        for (int threads : {1, 0})
            benchmark::RegisterBenchmark((std::string(m.id) + (threads == 1 ? "/threads:1" : "/threads:all")).c_str(),
                                         [mp = &m, threads](benchmark::State& s) { runMethod(s, mp, threads); })
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
    return true;
}();

}  // namespace

int main(int argc, char** argv) {
    ssfx::tuneAllocatorForImages();  // steady state of a renderer: buffers are reused
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
