// ssfx bench: the DDAA paper's Table 3 layout on this CPU (every method relative to
// blur = 100, measured in one run with the methods interleaved; see ssfx/eval/timing.hpp).
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "ssfx/aa/resolve.hpp"
#include "ssfx/eval/machine.hpp"
#include "ssfx/eval/synthetic.hpp"
#include "ssfx/eval/timing.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/registry.hpp"

namespace ssfx::cli {

namespace {

struct BenchOptions {
    std::string image, json;
    std::vector<std::string> methods;
    int reps = 40, warmup = 3, threads = 0, width = 1920;  // synthetic image: width x (width * 9 / 16)
};

void run(const BenchOptions& o) {
    const Exec exec{o.threads};
    // Inputs at scale 1, 2 and 4 (the resolves take the supersampled render).
    ImageRgba8 inputs[3];
    std::string source;
    if (o.image.empty()) {
        for (int i = 0; i < 3; ++i) inputs[i] = eval::syntheticScene(o.width, o.width * 9 / 16, 1 << i);
        source = "synthetic";
    } else {
        inputs[0] = io::readPng(o.image);
        inputs[1] = aa::upscaleMitchell(inputs[0].view(), 2, {}, exec);
        inputs[2] = aa::upscaleMitchell(inputs[0].view(), 4, {}, exec);
        source = o.image;
    }
    std::vector<const MethodInfo*> chosen;
    if (o.methods.empty()) {
        for (const MethodInfo& m : methods()) chosen.push_back(&m);
    } else {
        for (const auto& id : o.methods) chosen.push_back(&methodById(id));
        if (std::none_of(chosen.begin(), chosen.end(), [](auto* m) { return m->id == "blur"; }))
            chosen.push_back(&methodById("blur"));  // the baseline is always measured
    }
    std::vector<eval::TimedMethod> timed;
    const MethodSettings settings;
    // One output buffer per method, allocated once (the steady state of a frame loop).
    std::vector<ImageRgba8> outputs;
    outputs.reserve(chosen.size());
    for (const MethodInfo* m : chosen) {
        const ImageRgba8& in = inputs[m->inputScale == 4 ? 2 : m->inputScale == 2 ? 1 : 0];
        ImageRgba8& out = outputs.emplace_back(inputs[0].width(), inputs[0].height());
        timed.push_back({std::string(m->id), [m, &in, &out, &settings, exec] {
                             m->runInto(in.view(), out.view(), settings, exec);
                         }});
    }
    const auto results = eval::timeInterleaved(timed, o.reps, o.warmup, "blur", [](int r, int n) {
        std::fprintf(stderr, "\rbench: round %d/%d", r, n);
        if (r == n) std::fprintf(stderr, "\n");
    });
    const eval::MachineInfo mi = eval::machineInfo(resolvedThreads(exec));
    fmt::print("image: {} ({}x{}); {} repetitions, methods interleaved, fastest and slowest quarter dropped\n",
               source, inputs[0].width(), inputs[0].height(), o.reps);
    fmt::print("machine: {}, {} threads used of {}, SIMD target {}\n\n", mi.cpu, mi.threads, mi.hardwareThreads,
               mi.simdTarget);
    fmt::print("{:<8} {:>10} {:>12} {:>14}\n", "method", "median ms", "trimmed ms", "% of blur");
    for (const auto& r : results)
        fmt::print("{:<8} {:>10.3f} {:>12.3f} {:>14.0f}\n", r.id, r.medianMs, r.trimmedMeanMs, r.relative);

    if (!o.json.empty()) {
        nlohmann::json j;
        j["machine"] = {{"cpu", mi.cpu},
                        {"hardware_threads", mi.hardwareThreads},
                        {"threads", mi.threads},
                        {"simd_target", mi.simdTarget}};
        j["image"] = {{"path", source}, {"width", inputs[0].width()}, {"height", inputs[0].height()}};
        j["protocol"] = {{"repetitions", o.reps}, {"warmup", o.warmup}, {"baseline", "blur"},
                         {"relative", "trimmed mean (middle half) / blur's trimmed mean * 100"}};
        for (const auto& r : results)
            j["methods"][r.id] = {{"median_ms", r.medianMs}, {"trimmed_mean_ms", r.trimmedMeanMs},
                                  {"relative", r.relative}};
        const std::string text = j.dump(2) + "\n";
        io::writeFileAtomic(o.json, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
    }
}

}  // namespace

void addBenchCommand(CLI::App& app) {
    auto opts = std::make_shared<BenchOptions>();
    auto* cmd = app.add_subcommand("bench", "Time every method relative to blur (= 100), as the DDAA paper's Table 3");
    cmd->add_option("--image", opts->image,
                    "PNG to benchmark on (default: a synthetic 1920x1080 drawing); ssaa methods get it upscaled");
    cmd->add_option("--json", opts->json, "Also write the results as JSON to this file");
    cmd->add_option("--methods", opts->methods, "Methods to time (default: all; blur is always included)")
        ->delimiter(',');
    cmd->add_option("--reps", opts->reps, "Timed repetitions per method (default 40)")->check(CLI::Range(4, 100000));
    cmd->add_option("--warmup", opts->warmup, "Untimed rounds first (default 3)")->check(CLI::Range(0, 1000));
    cmd->add_option("--threads", opts->threads, "Worker threads (0 = all)")->check(CLI::Range(0, 1024));
    cmd->add_option("--size", opts->width, "Width of the synthetic image (height = width * 9 / 16; default 1920)")
        ->check(CLI::Range(16, 16384));
    cmd->callback([opts] { run(*opts); });
}

}  // namespace ssfx::cli
