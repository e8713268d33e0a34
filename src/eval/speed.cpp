// The speed protocol (see speed.hpp).
#include "ssfx/eval/speed.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "ssfx/aa/registry.hpp"
#include "ssfx/eval/quality.hpp"
#include "ssfx/io/png.hpp"

namespace ssfx::eval {

std::vector<TimingResult> timeMethodsOn(std::vector<std::string>& ids,
                                        const std::function<ImageRgba8(int scale)>& input, int repetitions, int warmup,
                                        const Exec& exec, const std::function<void(int, int)>& rounds) {
    if (std::find(ids.begin(), ids.end(), "blur") == ids.end()) ids.push_back("blur");  // the baseline
    std::vector<MethodVariant> variants;
    for (const auto& id : ids) variants.push_back({id, id, {}});
    return timeVariantsOn(variants, input, repetitions, warmup, exec, "blur", rounds);
}

std::vector<TimingResult> timeVariantsOn(const std::vector<MethodVariant>& variants,
                                         const std::function<ImageRgba8(int scale)>& input, int repetitions, int warmup,
                                         const Exec& exec, const std::string& baseline,
                                         const std::function<void(int, int)>& rounds) {
    ImageRgba8 inputs[3];  // x1, x2, x4
    inputs[0] = input(1);
    std::vector<TimedMethod> timed;
    // One output buffer per variant, allocated once (the steady state of a frame loop).
    std::vector<ImageRgba8> outputs;
    outputs.reserve(variants.size());
    for (const auto& v : variants) {
        const MethodInfo* m = &methodById(v.id);
        const int slot = m->inputScale == 4 ? 2 : m->inputScale == 2 ? 1 : 0;
        if (inputs[slot].empty()) inputs[slot] = input(m->inputScale);
        const ImageRgba8& in = inputs[slot];
        ImageRgba8& out = outputs.emplace_back(inputs[0].width(), inputs[0].height());
        const MethodSettings* settings = &v.settings;
        timed.push_back(
            {v.name, [m, &in, &out, settings, exec] { m->runInto(in.view(), out.view(), *settings, exec); }, {}});
    }
    return timeInterleaved(timed, repetitions, warmup, baseline, rounds);
}

SpeedTable measureSpeed(const std::string& dir, const SpeedOptions& o) {
    SpeedTable t;
    t.images = o.images.empty() ? findRenderSets(dir) : o.images;
    if (t.images.empty()) throw Error(fmt::format("no renders in '{}' (need NAME.png and NAMEx8.png)", dir));
    t.methods = o.methods.empty() ? paperMethodOrder() : o.methods;
    if (std::find(t.methods.begin(), t.methods.end(), "blur") == t.methods.end()) t.methods.push_back("blur");
    t.repetitions = o.repetitions;
    t.machine = machineInfo(resolvedThreads(o.exec));
    for (const auto& name : t.images) {
        auto file = [&](int scale) { return io::readPng(renderSetPath(dir, name, scale)); };
        auto rounds = [&](int r, int n) {
            if (o.progress) o.progress({fmt::format("speed: {}", name), r, n, "rounds"});
        };
        t.results.push_back(timeMethodsOn(t.methods, file, o.repetitions, o.warmup, o.exec, rounds));
    }
    return t;
}

std::string speedMarkdown(const SpeedTable& t) {
    std::string s = fmt::format(
        "Machine: {}, {} of {} threads, SIMD target {}; {} repetitions per method and image, interleaved, "
        "fastest and slowest quarter dropped.\n\n",
        t.machine.cpu, t.machine.threads, t.machine.hardwareThreads, t.machine.simdTarget, t.repetitions);
    for (int table = 0; table < 2; ++table) {
        s += table == 0 ? "Relative to blur = 100 (trimmed means)\n\n" : "\nMedian time (ms)\n\n";
        s += "| image |";
        for (const auto& m : t.methods) s += " " + m + " |";
        s += "\n|---|";
        for (std::size_t m = 0; m < t.methods.size(); ++m) s += "---:|";
        s += "\n";
        std::vector<double> mean(t.methods.size(), 0.0);
        for (std::size_t i = 0; i < t.images.size(); ++i) {
            s += "| " + t.images[i] + " |";
            for (std::size_t m = 0; m < t.methods.size(); ++m) {
                const double v = table == 0 ? t.results[i][m].relative : t.results[i][m].medianMs;
                mean[m] += v / double(t.images.size());
                s += table == 0 ? fmt::format(" {:.0f} |", v) : fmt::format(" {:.3f} |", v);
            }
            s += "\n";
        }
        s += "| mean |";
        for (double v : mean) s += table == 0 ? fmt::format(" {:.0f} |", v) : fmt::format(" {:.3f} |", v);
        s += "\n";
    }
    return s;
}

std::string speedJson(const SpeedTable& t) {
    nlohmann::ordered_json j;
    j["machine"] = {{"cpu", t.machine.cpu},
                    {"hardware_threads", t.machine.hardwareThreads},
                    {"threads", t.machine.threads},
                    {"simd_target", t.machine.simdTarget}};
    j["protocol"] = {{"repetitions", t.repetitions},
                     {"baseline", "blur"},
                     {"relative", "trimmed mean (middle half) / blur's trimmed mean * 100"}};
    for (std::size_t i = 0; i < t.images.size(); ++i)
        for (std::size_t m = 0; m < t.methods.size(); ++m) {
            const auto& r = t.results[i][m];
            j["images"][t.images[i]][t.methods[m]] = {
                {"median_ms", r.medianMs}, {"trimmed_mean_ms", r.trimmedMeanMs}, {"relative", r.relative}};
        }
    return j.dump(2) + "\n";
}

}  // namespace ssfx::eval
