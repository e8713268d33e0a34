// The whole frame on one device as a report section (ssfx/eval/frame_experiment.hpp).
#include "ssfx/eval/frame_experiment.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "ssfx/ao/sao.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/eval/plot.hpp"
#include "ssfx/eval/timing.hpp"
#include "ssfx/gpu/frame.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/scene/camera_path.hpp"

namespace ssfx::eval {

FrameProfile frameProfile(const std::vector<gpu::FrameResult>& frames) {
    if (frames.empty()) throw Error("frame profile: no frames");
    FrameProfile p;
    for (const auto& pass : frames[0].passes) p.passes.push_back(pass.pass);
    p.ms.assign(p.passes.size(), {});
    for (std::size_t f = 0; f < frames.size(); ++f) {
        if (frames[f].passes.size() != p.passes.size())
            throw Error(fmt::format("frame profile: frame {} has {} passes, frame 0 {}", f, frames[f].passes.size(),
                                    p.passes.size()));
        for (std::size_t i = 0; i < p.passes.size(); ++i) {
            if (frames[f].passes[i].pass != p.passes[i])
                throw Error(fmt::format("frame profile: frame {}'s pass {} is {}, frame 0's {}", f, i,
                                        frames[f].passes[i].pass, p.passes[i]));
            p.ms[i].push_back(frames[f].passes[i].milliseconds);
        }
        p.totals.push_back(frames[f].totalMs());
    }
    for (const auto& m : p.ms) p.medians.push_back(median(m));
    p.frameMedian = median(p.totals);
    return p;
}

Section runFrameExperiment(const FrameExperimentOptions& o) {
    namespace fs = std::filesystem;
    const fs::path out(o.outDir);
    const int w = o.quick ? 160 : o.width, h = o.quick ? 90 : o.height, frames = o.quick ? 4 : o.frames;
    const scene::Scene scene = scene::loadScene(o.scene);
    gpu::FrameSettings settings;
    settings.width = w;
    settings.height = h;
    settings.m = o.m;
    settings.ao = o.ao;
    settings.aa = o.aa;
    if (o.ao != "none") {
        const ao::AoMethodInfo& method = ao::aoMethodById(o.ao);
        settings.aoParams = method.defaults("");
        ao::setParam(method, settings.aoParams, "guardBand", o.aoGuardBand);
    }
    vkx::ContextOptions co;
    co.device = o.device;
    co.graphics = true;
    auto ctx = vkx::Context::create(co);
    gpu::FrameRenderer renderer(ctx, scene, settings);
    std::vector<scene::View> views;
    if (o.tour.empty()) {
        views = scene::orbit(scene.views.at(0).second, frames);
    } else {
        std::vector<scene::Keyframe> keys;
        for (const auto& name : o.tour) {
            const scene::View& v = scene.view(name);
            keys.push_back({v.eye, v.target, v.fovYDeg, double(keys.size())});
        }
        views = scene::CameraPath(keys, scene.view(o.tour.front())).sample(frames);
    }
    if (o.progress) o.progress({"frame: warm-up", 0, 1, ""});
    renderer.render(views[0]);  // lavapipe compiles each pipeline on its first dispatch

    io::Animation animation;
    std::vector<gpu::FrameResult> results;
    for (std::size_t f = 0; f < views.size(); ++f) {
        if (o.progress) o.progress({"frame: the path", std::int64_t(f), std::int64_t(views.size()), "frames"});
        gpu::FrameResult r = renderer.render(views[f]);
        animation.frames.push_back({std::move(r.image), 1, 12});
        results.push_back(std::move(r));
    }
    // The profile: each pass's median, its share of the median frame; a bar per frame.
    const FrameProfile profile = frameProfile(results);
    Table table;
    table.header = {"pass", "median (ms)", "share of the frame"};
    std::vector<Series> series;
    std::vector<std::string> categories;
    for (std::size_t f = 0; f < results.size(); ++f) categories.push_back(std::to_string(f));
    nlohmann::ordered_json j;
    j["scene"] = scene.name;
    j["device"] = ctx->info.name;
    j["clock"] = std::string(gpu::frameClockName(renderer.clock()));
    j["size"] = {w, h};
    j["ss"] = o.m;
    j["ao"] = o.ao;
    j["aa"] = o.aa;
    j["passes"] = profile.passes;
    for (std::size_t p = 0; p < profile.passes.size(); ++p) {
        table.addRow({profile.passes[p], fmt::format("{:.3f}", profile.medians[p]),
                      fmt::format("{:.1f} %", 100.0 * profile.share(p))});
        j["median_ms"][profile.passes[p]] = profile.medians[p];
        j["per_frame_ms"][profile.passes[p]] = profile.ms[p];
        series.push_back({profile.passes[p], profile.ms[p]});
    }
    const double frameMedian = profile.frameMedian;
    table.addRow({"frame (sum of the passes)", fmt::format("{:.3f}", frameMedian), "100 %"});
    j["median_ms"]["frame"] = frameMedian;

    fs::create_directories(out / "anim");
    fs::create_directories(out / "plots");
    fs::create_directories(out / "data");
    io::writeApng((out / "anim" / "frame.png").string(), animation);
    ChartStyle style;
    style.title =
        fmt::format("Frame profile: {} {}x{}, m = {}, {}, {} on {}", scene.name, w, h, o.m, o.ao, o.aa, ctx->info.name);
    style.xLabel = "frame of the orbit";
    style.yLabel = "time (ms)";
    io::writePng((out / "plots" / "frame_profile.png").string(), stackedBarChart(categories, series, style).view());
    io::writeTextAtomic((out / "data" / "frame.json").string(), j.dump(1) + "\n");

    Section s;
    s.title = "The whole frame on one device";
    s.note = fmt::format(
        "The three papers as the stages of one frame, on {} ({}): a depth draw with a guard band of {} px and {} from "
        "it; the {}x{} G-buffer draw, shaded adaptively with the AO on the ambient term; 8-bit encode; {}; the "
        "read-back, the only transfer. `ssfx frame --scene {} --path PATH.json --frames {} --size {}x{} --ss {} --ao "
        "{} "
        "--ao-param guardBand={} --aa {} --profile profile.json -o frames.apng` (docs/frame.md; the path's keyframes: "
        "the views below). Times: {} ({}), medians over {} frames after one untimed warm-up frame.",
        ctx->info.name, ctx->info.type, o.aoGuardBand, o.ao, o.m, o.m, o.aa, scene.name, frames, w, h, o.m, o.ao,
        o.aoGuardBand, o.aa,
        renderer.clock() == gpu::FrameClock::Timestamps ? "GPU timestamps around each pass" : "the host's clock",
        gpu::frameClockName(renderer.clock()), frames);
    Block profileBlock;
    profileBlock.heading = "Frame profile";
    profileBlock.table = std::move(table);
    profileBlock.figures.push_back({"plots/frame_profile.png", "per-pass time of every frame (stacked)",
                                    Figure::Kind::Plot, style.width, style.height});
    s.blocks.push_back(std::move(profileBlock));
    Block anim;
    std::string through;
    for (const auto& name : o.tour) through += (through.empty() ? "" : ", ") + name;
    anim.heading = "The animation";
    anim.figures.push_back(
        {"anim/frame.png",
         fmt::format("{} frames, {}x{}, {}", frames, w, h,
                     o.tour.empty() ? std::string("the built-in orbit around the first view's target")
                                    : "a camera path through the views " + through),
         Figure::Kind::Animation, w, h});
    s.blocks.push_back(std::move(anim));
    io::writeTextAtomic((out / "data" / "frame.md").string(), markdown(s));
    return s;
}

}  // namespace ssfx::eval
