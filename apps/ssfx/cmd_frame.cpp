// ssfx frame: the whole frame on one device (render, adaptive shading with AO, anti-aliasing),
// one image or an animation, with a per-pass profile (docs/frame.md).
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "apps/ssfx/commands.hpp"
#include "apps/ssfx/console.hpp"
#include "ssfx/aa/presets.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/scene/camera_path.hpp"
#include "ssfx/vk/context.hpp"
#ifdef SSFX_HAVE_GPU
#include "ssfx/eval/frame_experiment.hpp"
#include "ssfx/gpu/ao.hpp"
#include "ssfx/gpu/frame.hpp"
#endif

namespace ssfx::cli {

namespace {

struct FrameOptions {
    std::string scene, view, path, size = "1280x720", ao = "sao", aa = "ddaa2", aaPreset, lookup = "model", schedule,
                                   device, out, profile;
    std::vector<std::string> params, aoParams, aaParams;
    int frames = 0, m = 4, stall = 0, fps = 25;
    bool validation = false;
};

#ifdef SSFX_HAVE_GPU
void run(const FrameOptions& o, const CLI::App& cmd) {
    // Every option is checked before the scene is loaded or a device is opened.
    if (o.scene.empty()) throw Error("no scene given (--scene atrium | cornell | FILE.json | MODEL)");
    if (o.out.empty()) throw Error("no output given (-o out.png | out.apng)");
    const std::string ext = std::filesystem::path(o.out).extension().string();
    if (ext != ".png" && ext != ".apng")
        throw Error(fmt::format("-o '{}': use a .png or .apng file name (several frames: an APNG)", o.out));
    if (!o.profile.empty() && std::filesystem::path(o.profile).extension() != ".json")
        throw Error(fmt::format("--profile '{}': use a .json file name", o.profile));
    if (!o.view.empty() && !o.path.empty()) throw Error("--view and --path: give one (neither: the built-in orbit)");
    if (!o.view.empty() && cmd.count("--frames") && o.frames != 1)
        throw Error("--frames goes with --path or the orbit (--view renders one frame)");
    const int frames = o.frames > 0 ? o.frames : o.view.empty() ? 24 : 1;
    const auto [w, h] = parseSize(o.size, "--size", 16384);

    gpu::FrameSettings fs;
    fs.width = w;
    fs.height = h;
    fs.m = o.m;
    fs.ao = o.ao;
    fs.aa = o.aa;
    if (gpu::hasGpuAo(o.ao)) {
        const ao::AoMethodInfo& method = ao::aoMethodById(o.ao);
        fs.aoParams = method.defaults("");
        for (const auto& text : o.aoParams) {
            const auto [name, value] = parseParam(text, method.params, method.id);
            ao::setParam(method, fs.aoParams, name, value);
        }
        method.validate(fs.aoParams);
    } else if (o.ao != "none") {
        throw Error(fmt::format("--ao {}: sao, alchemy, gtao or none", o.ao));
    } else if (!o.aoParams.empty()) {
        throw Error("--ao-param goes with an AO method (--ao none)");
    }
    if (o.aa != "none") {
        const MethodInfo* m = findMethod(o.aa);
        if (!m) throw Error(fmt::format("--aa {}: no such method (ssfx methods lists them; or none)", o.aa));
        if (!o.aaPreset.empty()) {
            fs.aaSettings.preset = aa::parsePreset(o.aaPreset);
            if (!fs.aaSettings.preset)
                throw Error(fmt::format("--aa-preset '{}' (low, medium, high, ultra, extreme)", o.aaPreset));
        }
        for (const auto& p : o.aaParams) fs.aaSettings.params.push_back(parseParam(p, m->params, m->id));
    } else if (!o.aaParams.empty() || !o.aaPreset.empty()) {
        throw Error("--aa-param and --aa-preset go with an AA method (--aa none)");
    }
    fs.shading = adaptiveParams(o.params, o.stall);
    fs.lookup = gpu::parseSampling(o.lookup);
    fs.schedule = o.schedule.empty() ? gpu::Schedule::FromParams : gpu::parseSchedule(o.schedule);

    const scene::Scene scene = scene::loadScene(o.scene);
    std::vector<scene::View> views;
    const scene::View& first = scene.views.at(0).second;
    if (!o.view.empty())
        views.push_back(scene.view(o.view));
    else if (!o.path.empty())
        views = scene::readCameraPath(o.path, first).sample(frames);
    else
        views = scene::orbit(first, frames);

    vkx::ContextOptions co;
    co.device = o.device;
    co.graphics = true;
    co.validation = o.validation;
    auto ctx = vkx::Context::create(co);
    if (fs.lookup == gpu::Sampling::Hardware && fs.shading.shading.maxAnisotropy > 1 && ctx->info.type == "cpu")
        printNote("frame",
                  "lavapipe's anisotropic filtering is very slow (docs/gpu.md, \"Adaptive shading\"); "
                  "-p maxAnisotropy=1 keeps the hardware lookup trilinear");
    gpu::FrameRenderer renderer(ctx, scene, fs);
    // lavapipe compiles each pipeline on its first dispatch: with --profile, one untimed frame first.
    if (!o.profile.empty()) renderer.render(views[0]);
    // Frames are written as they come (an APNG streamed through io::ApngWriter: one frame in
    // memory, however many there are); the image and the profile appear together or not at all.
    io::OutputSet outputs;
    const bool animated = views.size() > 1 || ext == ".apng";
    std::optional<io::ApngWriter> apng;
    if (animated) apng.emplace(o.out, w, h, std::uint32_t(views.size()));
    std::vector<gpu::FrameResult> results;  // the pass times (the images are written, then dropped)
    {
        ProgressLine line("frame");
        for (std::size_t f = 0; f < views.size(); ++f) {
            line.report({"frames", std::int64_t(f), std::int64_t(views.size()), "frames"});
            gpu::FrameResult r = renderer.render(views[f]);
            if (apng)
                apng->add(r.image.view(), 1, std::uint16_t(o.fps));
            else
                io::writePng(o.out, r.image.view());
            r.image = ImageRgba8();
            results.push_back(std::move(r));
        }
    }
    if (apng) apng->commit();

    // The profile: each pass's median over the frames and its share of the frame's median.
    const eval::FrameProfile profile = eval::frameProfile(results);
    const double frameMedian = profile.frameMedian;
    const std::string clock(gpu::frameClockName(renderer.clock()));
    const char* clockText = renderer.clock() == gpu::FrameClock::Timestamps ? "GPU timestamps" : "host clock";
    std::string summary = fmt::format(
        "{} {}x{} m={} ao={} aa={}: {} frame{} on {} ({}), median {:.2f} ms per frame ({}{}) -> {}\n", scene.name, w, h,
        o.m, o.ao, o.aa, views.size(), views.size() == 1 ? "" : "s", ctx->info.name, ctx->info.type, frameMedian,
        clockText, o.profile.empty() ? "; no warm-up: the first frame includes compiling the pipelines" : "", o.out);
    if (!o.profile.empty()) {
        nlohmann::ordered_json j;
        j["device"] = ctx->info.name;
        j["device_type"] = ctx->info.type;
        j["clock"] = clock;
        j["scene"] = scene.name;
        j["size"] = {w, h};
        j["ss"] = o.m;
        j["ao"] = o.ao;
        j["aa"] = o.aa;
        j["schedule"] = o.schedule.empty() ? "params" : o.schedule;
        j["lookup"] = o.lookup;
        j["passes"] = profile.passes;
        auto& perFrame = j["frames"] = nlohmann::ordered_json::array();
        for (std::size_t f = 0; f < results.size(); ++f) {
            nlohmann::ordered_json fr;
            fr["frame"] = f;
            for (std::size_t p = 0; p < profile.passes.size(); ++p) fr["ms"][profile.passes[p]] = profile.ms[p][f];
            fr["total_ms"] = profile.totals[f];
            perFrame.push_back(fr);
        }
        for (std::size_t p = 0; p < profile.passes.size(); ++p) j["median_ms"][profile.passes[p]] = profile.medians[p];
        j["median_ms"]["frame"] = frameMedian;
        writeOutput(o.profile, j.dump(2) + "\n");
        summary += fmt::format("{:<14} {:>10} {:>8}\n", "pass", "median ms", "share");
        for (std::size_t p = 0; p < profile.passes.size(); ++p)
            summary += fmt::format("{:<14} {:>10.3f} {:>7.1f}%\n", profile.passes[p], profile.medians[p],
                                   100 * profile.share(p));
        summary += fmt::format("{:<14} {:>10.3f} {:>7.1f}%\n", "frame", frameMedian, 100.0);
    }
    outputs.commit();
    printResult(summary);
    for (const auto& m : renderer.validationMessages()) printNote("validation", m);
}
#endif

}  // namespace

void addFrameCommand(CLI::App& app) {
    auto o = std::make_shared<FrameOptions>();
    auto* cmd = app.add_subcommand(
        "frame", "The whole frame on one device: render, shade adaptively, ambient occlusion, anti-alias (Vulkan)");
    cmd->add_option("--scene", o->scene, "atrium, cornell, a scene .json or a model file");
    cmd->add_option("--view", o->view, "One frame of this named view (ssfx render SCENE --list-views)");
    cmd->add_option("--path", o->path,
                    "A camera path file: {\"keyframes\": [{\"position\": [x,y,z], \"target\": [x,y,z], \"fov\": "
                    "deg, \"time\": s (optional)}, ...]} (at least two keyframes; interpolated)");
    cmd->add_option("--frames", o->frames,
                    "Frames along --path or the orbit (default 24); without --view and --path: an orbit around the "
                    "scene's first view's target")
        ->check(CLI::Range(1, 100000));
    cmd->add_option("--size", o->size, "Final image size WxH (default 1280x720)");
    cmd->add_option("--ss", o->m, "Supersampling M: an M x M G-buffer, shaded adaptively (1..4, default 4)")
        ->check(CLI::Range(1, 4));
    cmd->add_option("--ao", o->ao, "Ambient occlusion on the ambient term: sao (default), alchemy, gtao or none");
    cmd->add_option("--ao-param", o->aoParams,
                    "NAME=VALUE of the AO method (repeatable; ssfx methods --family ao), e.g. guardBand=32");
    cmd->add_option("--aa", o->aa,
                    "Anti-aliasing of the shaded frame: an ssfx aa method reading the final size (ddaa2 default, "
                    "ddaa1, fxaa3c, fxaa3d, blur, noaa) or none");
    cmd->add_option("--aa-preset", o->aaPreset, "Edge-threshold preset of the AA method (ssfx aa --list-presets)");
    cmd->add_option("--aa-param", o->aaParams, "NAME=VALUE of the AA method (repeatable)");
    cmd->add_option("-p,--param", o->params, "NAME=VALUE of the adaptive shading (repeatable; ssfx deferred --help)");
    cmd->add_option("--stall", o->stall, "Extra dependent operations per shaded sample (a heavy shader)")
        ->check(CLI::Range(0, 10000000));
    cmd->add_option("--lookup", o->lookup,
                    "The shading's texture lookup: model (default: the CPU's sampler model) or hardware "
                    "(textureGrad, anisotropic)")
        ->check(CLI::IsMember({"model", "hardware"}));
    cmd->add_option("--schedule", o->schedule,
                    "The shading's rest pass: pixel, tiled or list (default: -p tiled's); the same image")
        ->check(CLI::IsMember({"pixel", "tiled", "list"}));
    cmd->add_option("--fps", o->fps, "Frames per second of the APNG (default 25)")->check(CLI::Range(1, 1000));
    cmd->add_option("-o,--out", o->out, "out.png (one frame) or out.apng / out.png (several frames: an APNG)");
    cmd->add_option("--profile", o->profile,
                    "Write per-frame, per-pass times (ms) and their medians as JSON, and print the table (after one "
                    "untimed warm-up frame)");
    cmd->add_option("--device", o->device, "Vulkan device index or part of its name (ssfx devices)");
    cmd->add_flag("--validation", o->validation, "Enable the Khronos validation layer and print its messages");
    cmd->footer(
        "Passes per frame: depth draw (with the AO's guard band), G-buffer draw (M x M), AO, adaptive shading (AO on\n"
        "the ambient term), encode to 8 bits, anti-aliasing, read-back; nothing else leaves the device. Times:\n"
        "GPU timestamps (on a queue without them: each pass its own submission, timed on the host).\n"
        "docs/frame.md. Examples:\n"
        "  ssfx frame --scene atrium --view nave --size 1280x720 -o frame.png --profile profile.json\n"
        "  ssfx frame --scene atrium --frames 48 --size 640x360 --ss 2 --ao-param guardBand=32 -o orbit.apng\n"
        "  ssfx frame --scene sponza.json --path path.json --frames 120 --ao gtao --aa fxaa3c -o fly.apng");
    cmd->callback([o, cmd] {
#ifdef SSFX_HAVE_GPU
        run(*o, *cmd);
#else
        (void)cmd;
        throw Error("ssfx frame: this ssfx was built without the GPU backend");
#endif
    });
}

}  // namespace ssfx::cli
