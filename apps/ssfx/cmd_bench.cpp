// ssfx bench: the DDAA paper's Table 3 layout on this CPU (every method relative to
// blur = 100, measured in one run with the methods interleaved; see ssfx/eval/timing.hpp).
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <algorithm>

#include "apps/ssfx/backend.hpp"
#include "apps/ssfx/commands.hpp"
#include "apps/ssfx/console.hpp"
#include "ssfx/aa/registry.hpp"
#include "ssfx/aa/resolve.hpp"
#include "ssfx/eval/machine.hpp"
#include "ssfx/eval/speed.hpp"
#include "ssfx/eval/synthetic.hpp"
#include "ssfx/eval/timing.hpp"
#include "ssfx/io/png.hpp"

namespace ssfx::cli {

namespace {

struct BenchOptions {
    std::string image, json;
    std::vector<std::string> methods;
    int reps = 40, warmup = 3, threads = 0, width = 1920;  // synthetic image: width x (width * 9 / 16)
    std::vector<std::string> params;                       // -p sampling=... (vulkan), texture=...
    std::string texture = "unorm";                         // unorm, srgb or both
    BackendOptions backend;
};

// -p texture=unorm|srgb|both: the methods' texture parameter for every method that has one
// (all but noaa); both times each such method twice in the same rounds, the sRGB row named
// ID:srgb (so that the ratio of the two is from one run).
void takeTextureParam(std::vector<std::string>& params, std::string& texture) {
    std::vector<std::string> rest;
    for (const auto& p : params)
        if (p.rfind("texture=", 0) == 0) {
            texture = p.substr(8);
            if (texture != "unorm" && texture != "srgb" && texture != "both")
                throw Error(fmt::format("bench: texture '{}': expected unorm, srgb or both", texture));
        } else {
            rest.push_back(p);
        }
    params = std::move(rest);
}

// The timed rows in order (blur first unless listed), and the baseline row's name.
std::vector<eval::MethodVariant> variantsOf(std::vector<std::string> ids, const std::string& texture,
                                            std::string* baseline) {
    if (std::find(ids.begin(), ids.end(), "blur") == ids.end()) ids.insert(ids.begin(), "blur");
    std::vector<eval::MethodVariant> v;
    MethodSettings srgb;
    srgb.params = {{"texture", 1}};
    for (const auto& id : ids) {
        if (texture != "srgb" || id == "noaa") v.push_back({id, id, {}});
        if (texture != "unorm" && id != "noaa") v.push_back({id, id + ":srgb", srgb});
    }
    *baseline = texture == "srgb" ? "blur:srgb" : "blur";
    return v;
}

// A method's GPU profile over the timed rounds: each dispatch's median time, in dispatch
// order, and the median share of pixels its classify dispatch listed (-1: no list).
struct MethodProfile {
    std::vector<std::pair<std::string, double>> stages;
    double edgeShare = -1;
};

MethodProfile profileOf(const std::vector<DispatchProfile>& rounds) {
    MethodProfile m;
    if (rounds.empty()) return m;
    for (std::size_t k = 0; k < rounds.front().dispatches.size(); ++k) {
        std::vector<double> ms;
        for (const auto& r : rounds)
            if (k < r.dispatches.size()) ms.push_back(r.dispatches[k].second);
        m.stages.emplace_back(rounds.front().dispatches[k].first, eval::median(ms));
    }
    std::vector<double> shares;
    for (const auto& r : rounds) shares.push_back(r.edgeShare);
    m.edgeShare = eval::median(shares);
    return m;
}

// The GPU protocol: the same interleaved rounds, each repetition one submit of one method,
// its time from the GPU timestamps around the pass's dispatches; each repetition's
// per-dispatch times and listed share go to `profiles` (one per method, in ids' order).
std::vector<eval::TimingResult> timeOnBackend(const std::vector<eval::MethodVariant>& variants,
                                              const std::string& baseline, const std::function<ImageRgba8(int)>& input,
                                              const BenchOptions& o, const Exec& exec, std::string* device,
                                              bool* deviceDecode, const std::function<void(int, int)>& rounds,
                                              std::vector<MethodProfile>* profiles) {
    // The rows: the variants as asked; where the baseline (blur) does not run in the model
    // mode one pixel an invocation (the hardware mode, or its segments: a CPU device's
    // default), also blur in that form, the yardstick of issue #34's comparison with the DDAA
    // author's shaders (docs/gpu.md), as BASELINE:reference in the same rounds.
    std::vector<std::pair<eval::MethodVariant, BackendOptions>> rows;
    rows.reserve(variants.size() + 1);  // (no reallocation while a row is read)
    for (const auto& v : variants) rows.emplace_back(v, o.backend);
    std::vector<ImageRgba8> inputs(5);
    std::vector<eval::TimedMethod> timed;
    std::vector<Applier> appliers;
    appliers.reserve(rows.size() + 1);
    std::vector<std::vector<DispatchProfile>> perRound(rows.size() + 1);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const auto& [v, backend] = rows[i];
        const MethodInfo& m = methodById(v.id);
        if (inputs[std::size_t(m.inputScale)].width() == 0) inputs[std::size_t(m.inputScale)] = input(m.inputScale);
        appliers.push_back(makeApplier(backend, m, v.settings, exec));
        const bool model = backend.sampling.empty() || backend.sampling == "model";
        if (v.name == baseline && (appliers.back().edgePath != "one-pass" || !model)) {
            BackendOptions reference = backend;
            reference.sampling = "model";
            reference.edges = "one-pass";
            rows.emplace_back(eval::MethodVariant{v.id, v.name + ":reference", v.settings}, reference);
        }
        *device = appliers.back().device;
        *deviceDecode = *deviceDecode || appliers.back().deviceDecode;
        const Applier* a = &appliers.back();
        const ImageRgba8* in = &inputs[std::size_t(m.inputScale)];
        auto* mine = &perRound[appliers.size() - 1];
        timed.push_back({rows[i].first.name, [a, in] { (void)a->apply(in->view()); },
                         [a, mine] {
                             mine->push_back(a->lastProfile());  // (called for the timed rounds only)
                             return a->lastGpuMs();
                         }});
    }
    perRound.resize(appliers.size());
    auto results = eval::timeInterleaved(timed, o.reps, o.warmup, baseline, rounds);
    for (const auto& r : perRound) profiles->push_back(profileOf(r));
    return results;
}

// The per-dispatch table: a column per stage (in the passes' order), "-" where a method has
// no such dispatch; the share of pixels listed as edge pixels last.
std::string profileTable(const std::vector<eval::TimingResult>& results, const std::vector<MethodProfile>& profiles) {
    static constexpr const char* kOrder[] = {"luma", "classify", "edges", "segments", "method", "one pass", "resolve"};
    std::vector<std::string> columns;
    for (const char* stage : kOrder)
        for (const auto& p : profiles)
            if (std::any_of(p.stages.begin(), p.stages.end(), [&](const auto& s) { return s.first == stage; })) {
                columns.emplace_back(stage);
                break;
            }
    std::string t = "\nper dispatch (median ms of the timed rounds; edge share: pixels the classify dispatch listed)\n";
    const std::size_t nameWidth =
        std::max_element(results.begin(), results.end(),
                         [](const auto& a, const auto& b) { return a.id.size() < b.id.size(); })
            ->id.size() +
        1;
    t += fmt::format("{:<{}}", "method", std::max<std::size_t>(nameWidth, 8));
    for (const auto& c : columns) t += fmt::format(" {:>9}", c);
    t += fmt::format(" {:>11}\n", "edge share");
    for (std::size_t i = 0; i < results.size() && i < profiles.size(); ++i) {
        t += fmt::format("{:<{}}", results[i].id, std::max<std::size_t>(nameWidth, 8));
        for (const auto& c : columns) {
            const auto& st = profiles[i].stages;
            const auto it = std::find_if(st.begin(), st.end(), [&](const auto& s) { return s.first == c; });
            t += it == st.end() ? fmt::format(" {:>9}", "-") : fmt::format(" {:>9.3f}", it->second);
        }
        t += profiles[i].edgeShare < 0 ? fmt::format(" {:>11}\n", "-")
                                       : fmt::format(" {:>10.1f}%\n", 100.0 * profiles[i].edgeShare);
    }
    return t;
}

void run(BenchOptions o) {
    const Exec exec{o.threads};
    checkBackendOptions(o.backend);
    takeSamplingParam(o.params, o.backend);
    takeTextureParam(o.params, o.texture);
    if (!o.params.empty())
        throw Error(
            fmt::format("bench: -p takes texture=unorm|srgb|both, and with --backend vulkan "
                        "sampling=model|hardware and edges=auto|list|one-pass|segments, only ('{}')",
                        o.params[0]));
    const bool gpu = o.backend.backend == "vulkan";
    // Inputs at scale 1, 2 and 4 (the resolves take the supersampled render).
    const std::string source = o.image.empty() ? "synthetic" : o.image;
    ImageRgba8 base;
    if (!o.image.empty()) base = io::readPng(o.image);
    auto input = [&](int scale) {
        if (o.image.empty()) return eval::syntheticScene(o.width, o.width * 9 / 16, scale);
        return scale == 1 ? base : aa::upscaleMitchell(base.view(), scale, {}, exec);
    };
    std::vector<std::string> ids = o.methods;
    if (ids.empty())
        for (const MethodInfo& m : methods()) ids.emplace_back(m.id);
    for (const auto& id : ids) methodById(id);  // every id checked before any work
    const ImageRgba8 first = input(1);
    ProgressLine line("bench");
    const auto scaled = [&](int scale) { return scale == 1 ? first : input(scale); };
    const auto rounds = [&](int r, int n) { line.report({"interleaved rounds", r, n, "rounds"}); };
    std::string device;
    bool deviceDecode = false;
    std::vector<MethodProfile> profiles;
    std::string baseline;
    const std::vector<eval::MethodVariant> variants = variantsOf(ids, o.texture, &baseline);
    const auto results =
        gpu ? timeOnBackend(variants, baseline, scaled, o, exec, &device, &deviceDecode, rounds, &profiles)
            : eval::timeVariantsOn(variants, scaled, o.reps, o.warmup, exec, baseline, rounds);
    line.end();
    const eval::MachineInfo mi = eval::machineInfo(resolvedThreads(exec));
    std::string table = fmt::format(
        "image: {} ({}x{}); {} repetitions, methods interleaved, fastest and slowest quarter dropped; "
        "texture={}\n",
        source, first.width(), first.height(), o.reps, o.texture);
    if (gpu)
        table += fmt::format(
            "backend: vulkan on {}, sampling={}{}, edges={}; times from GPU timestamps around each pass\n\n", device,
            o.backend.sampling.empty() ? "model" : o.backend.sampling,
            deviceDecode ? " (the device's unorm decode, probed exact)" : "",
            o.backend.edges.empty() ? "auto" : o.backend.edges);
    else
        table += fmt::format("machine: {}, {} threads used of {}, SIMD target {}\n\n", mi.cpu, mi.threads,
                             mi.hardwareThreads, mi.simdTarget);
    std::size_t nameWidth = 8;
    for (const auto& r : results) nameWidth = std::max(nameWidth, r.id.size());
    table += fmt::format("{:<{}} {:>10} {:>12} {:>16}\n", "method", nameWidth, "median ms", "trimmed ms",
                         fmt::format("% of {}", baseline));
    for (const auto& r : results)
        table += fmt::format("{:<{}} {:>10.3f} {:>12.3f} {:>16.0f}\n", r.id, nameWidth, r.medianMs, r.trimmedMeanMs,
                             r.relative);
    if (gpu) table += profileTable(results, profiles);
    if (o.json != "-") printResult(table);

    if (!o.json.empty()) {
        nlohmann::json j;
        j["machine"] = {{"cpu", mi.cpu},
                        {"hardware_threads", mi.hardwareThreads},
                        {"threads", mi.threads},
                        {"simd_target", mi.simdTarget}};
        j["backend"] = o.backend.backend;
        j["device"] = gpu ? device : mi.cpu;
        if (gpu) {
            j["sampling"] = o.backend.sampling.empty() ? "model" : o.backend.sampling;
            j["edges"] = o.backend.edges.empty() ? "auto" : o.backend.edges;
            j["device_decode"] = deviceDecode;
        }
        j["image"] = {{"path", source}, {"width", first.width()}, {"height", first.height()}};
        j["texture"] = o.texture;
        j["protocol"] = {{"repetitions", o.reps},
                         {"warmup", o.warmup},
                         {"baseline", baseline},
                         {"relative", "trimmed mean (middle half) / the baseline's trimmed mean * 100"}};
        for (std::size_t i = 0; i < results.size(); ++i) {
            const auto& r = results[i];
            j["methods"][r.id] = {
                {"median_ms", r.medianMs}, {"trimmed_mean_ms", r.trimmedMeanMs}, {"relative", r.relative}};
            if (gpu && i < profiles.size()) {
                auto& d = j["methods"][r.id]["dispatches"] = nlohmann::json::array();
                for (const auto& [stage, ms] : profiles[i].stages) d.push_back({{"stage", stage}, {"median_ms", ms}});
                j["methods"][r.id]["edge_share"] =
                    profiles[i].edgeShare < 0 ? nlohmann::json() : nlohmann::json(profiles[i].edgeShare);
            }
        }
        const std::string text = j.dump(2) + "\n";
        writeOutput(o.json, text);
    }
}

}  // namespace

void addBenchCommand(CLI::App& app) {
    auto opts = std::make_shared<BenchOptions>();
    auto* cmd = app.add_subcommand("bench", "Time every method relative to blur (= 100), as the DDAA paper's Table 3");
    cmd->add_option("--image", opts->image,
                    "PNG to benchmark on (default: a synthetic 1920x1080 drawing); ssaa methods get it upscaled");
    cmd->add_option("--json", opts->json,
                    "Also write the results as JSON to this file ('-': to stdout, instead of the table)");
    cmd->add_option("--methods", opts->methods, "Methods to time (default: all; blur is always included)")
        ->delimiter(',');
    cmd->add_option("--reps", opts->reps, "Timed repetitions per method (default 40)")->check(CLI::Range(4, 100000));
    cmd->add_option("--warmup", opts->warmup, "Untimed rounds first (default 3)")->check(CLI::Range(0, 1000));
    cmd->add_option("--threads", opts->threads, "Worker threads (0 = all)")->check(CLI::Range(0, 1024));
    cmd->add_option("--size", opts->width, "Width of the synthetic image (height = width * 9 / 16; default 1920)")
        ->check(CLI::Range(16, 16384));
    cmd->add_option(
        "-p,--param", opts->params,
        "texture=unorm (default), srgb or both (each method also as ID:srgb, in the same rounds); with --backend "
        "vulkan: sampling=model (default) or sampling=hardware; edges=auto (default), list, one-pass or segments");
    addBackendOptions(cmd, opts->backend);
    cmd->footer(
        "CPU: wall-clock time of each method call. --backend vulkan: GPU timestamps around each pass's\n"
        "dispatches, one submit per method per round (upload and download are not timed), and a second\n"
        "table (and JSON 'dispatches', 'edge_share') with each dispatch's median time: luma, classify and\n"
        "edges for the edge-test methods' list, segments or one pass for their other paths, resolve for\n"
        "ddaa2p's second step, method for a single dispatch; edge share is the share of pixels the classify\n"
        "dispatch listed. Where blur runs in the hardware mode or on its segments (a CPU device's default),\n"
        "a row blur:reference times it in the model mode one pixel an invocation in the same rounds: the\n"
        "yardstick of the comparison with the DDAA author's shaders (docs/gpu.md). scripts/bench_gpu.sh\n"
        "runs it on a drawing, a photograph and a rendered scene.");
    cmd->callback([opts] { run(*opts); });
}

}  // namespace ssfx::cli
