// ssfx render: depth buffers, G-buffers and forward-shaded colour of a scene (Vulkan).
#include <fmt/format.h>

#include <cmath>
#include <tuple>

#include <filesystem>
#include <optional>

#include "apps/ssfx/commands.hpp"
#include "apps/ssfx/console.hpp"
#include "ssfx/ao/depth.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/io/exr.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/render/renderer.hpp"

namespace ssfx::cli {

namespace {

struct RenderOptions {
    std::string scene, view, size = "960x540", depthFormat = "d32f", out, device, far;
    int scale = 1, gbuffer = 0, guard = 0;
    double near = 0;
    bool listViews = false, validation = false, aaSet = false;
};

DepthFormat parseDepthFormat(const std::string& f) {
    if (f == "d16") return DepthFormat::D16;
    if (f == "d24") return DepthFormat::D24;
    if (f == "d32f") return DepthFormat::D32F;
    throw Error(fmt::format("--depth-format '{}' (d16, d24, d32f)", f));
}

void run(const RenderOptions& o) {
    if (o.scene.empty())
        throw Error("no scene given (a built-in name: atrium, cornell; a scene .json; or a model file)");
    scene::Scene scene = scene::loadScene(o.scene);
    if (o.listViews) {
        for (const auto& [name, v] : scene.views)
            fmt::print("{}: eye ({:.3g}, {:.3g}, {:.3g}) target ({:.3g}, {:.3g}, {:.3g}) fov {:.3g} deg\n", name,
                       v.eye.x, v.eye.y, v.eye.z, v.target.x, v.target.y, v.target.z, v.fovYDeg);
        return;
    }
    if (o.out.empty()) throw Error("no output folder given (--out DIR)");
    scene::View view = o.view.empty() ? scene.views.at(0).second : scene.view(o.view);
    if (!(std::isfinite(o.near) && o.near >= 0))
        throw Error(fmt::format("--near {}: a finite distance > 0 (m)", o.near));
    if (o.near > 0) view.zNear = o.near;
    if (!o.far.empty()) {
        if (o.far == "inf") {
            view.zFar = INFINITY;
        } else {
            char* end = nullptr;
            view.zFar = std::strtod(o.far.c_str(), &end);
            if (!end || *end || !(view.zFar > view.zNear))
                throw Error(fmt::format("--far '{}': a distance > near, or inf", o.far));
        }
    }
    const auto [w, h] = parseSize(o.size);
    const DepthFormat format = parseDepthFormat(o.depthFormat);
    // Everything is rendered before anything is written, and every size is checked before
    // anything is rendered (the pixel limit, the device's largest attachment).
    render::Renderer renderer({o.device, o.validation});
    {
        std::vector<std::tuple<std::int64_t, std::int64_t, std::string>> sizes;
        if (o.aaSet) {
            sizes.emplace_back(std::int64_t(w) * 8, std::int64_t(h) * 8, "the x8 colour image of --aa-set");
        } else {
            sizes.emplace_back(std::int64_t(w) + 2 * o.guard, std::int64_t(h) + 2 * o.guard,
                               "the depth buffer (with --guard)");
            sizes.emplace_back(std::int64_t(w) * o.scale, std::int64_t(h) * o.scale, "the colour image (with --scale)");
            if (o.gbuffer > 0)
                sizes.emplace_back(std::int64_t(w) * o.gbuffer, std::int64_t(h) * o.gbuffer,
                                   "the G-buffer (with --gbuffer)");
        }
        for (const auto& [bw, bh, what] : sizes) {
            checkDimensions(bw, bh, what);
            if (bw > renderer.device().maxImageDimension2D || bh > renderer.device().maxImageDimension2D)
                throw Error(fmt::format("{} would be {}x{}, above the device's limit of {} pixels per side", what, bw,
                                        bh, renderer.device().maxImageDimension2D));
        }
    }
    io::OutputSet outputs;  // depth.exr, z.exr, camera.json, color.png, gbuffer.exr: all or none
    if (o.aaSet) {
        io::makeDirectories(o.out);
        {
            ProgressLine line("render");
            render::writeAaRenderSet(renderer, scene, view, w, h, o.out, scene.name, line.fn());
        }
        outputs.commit();
        printResult(fmt::format("{}: {}.png, {}x2.png, {}x4.png, {}x8.png -> {}\n", scene.name, scene.name, scene.name,
                                scene.name, scene.name, o.out));
        return;
    }
    const auto depth = renderer.renderDepth(scene, view, w, h, format, o.guard);
    const auto color = renderer.renderColor(scene, view, w, h, o.scale);
    std::optional<scene::GBuffer> gbuffer;
    if (o.gbuffer > 0) gbuffer = renderer.renderGBuffer(scene, view, w, h, o.gbuffer);
    const ImageF z = ao::depthToZ(depth.depth.view(), depth.camera.camera);

    io::makeDirectories(o.out);
    const std::filesystem::path dir(o.out);
    io::writeExr((dir / "depth.exr").string(), depth.depth.view(), "Z");
    io::writeExr((dir / "z.exr").string(), z.view(), "Z");
    io::writeTextAtomic((dir / "camera.json").string(), scene::cameraSetupJson(depth.camera));
    io::writePng((dir / "color.png").string(), color.color.view());
    if (gbuffer) scene::writeGBufferExr((dir / "gbuffer.exr").string(), *gbuffer);
    outputs.commit();
    std::string summary =
        fmt::format("{} / {}: {} triangles, {}x{} + guard {} on {}: depth ({}) {:.2f} ms, colour x{} {:.2f} ms",
                    scene.name, o.view.empty() ? scene.views.at(0).first : o.view, scene.triangleCount(), w, h, o.guard,
                    renderer.device().name, o.depthFormat, depth.gpuMs, o.scale, color.gpuMs);
    if (gbuffer) summary += fmt::format(", G-buffer {}x{} {:.2f} ms", o.gbuffer, o.gbuffer, gbuffer->gpuMs);
    printResult(summary + fmt::format(" (GPU time) -> {}\n", o.out));
    for (const auto& m : renderer.validationMessages()) printNote("validation", m);
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto o = std::make_shared<RenderOptions>();
    auto* cmd =
        app.add_subcommand("render", "Render a scene with Vulkan: depth buffer, G-buffer, forward-shaded colour");
    cmd->add_option("scene", o->scene,
                    "Built-in scene (atrium, cornell), a scene file (.json) or a model (OBJ, glTF, Collada)");
    cmd->add_option("--view", o->view, "Named viewpoint (default: the scene's first; see --list-views)");
    cmd->add_option("--size", o->size, "Image size WxH without guard band (default 960x540)");
    cmd->add_option("--scale", o->scale, "Colour image rendered at scale x size (1..16; for the AA evaluation)")
        ->check(CLI::Range(1, 16));
    cmd->add_option("--depth-format", o->depthFormat, "d16, d24 (X8_D24) or d32f (default)");
    cmd->add_option("--gbuffer", o->gbuffer, "Also write an m x m supersampled G-buffer (m = 1..4) as gbuffer.exr")
        ->check(CLI::Range(0, 4));
    cmd->add_option("--guard", o->guard, "Guard band in pixels on every side of the depth buffer (default 0)")
        ->check(CLI::Range(0, 4096));
    cmd->add_option("--near", o->near, "Override the view's near plane distance (m)")->check(CLI::PositiveNumber);
    cmd->add_option("--far", o->far, "Override the far plane: a distance in m, or inf");
    cmd->add_option("--out", o->out, "Output folder: depth.exr, z.exr, camera.json, color.png [, gbuffer.exr]");
    cmd->add_option("--device", o->device,
                    "Vulkan device index or part of its name (default: a GPU, else lavapipe; ssfx devices lists them)");
    cmd->add_flag("--validation", o->validation, "Enable the Khronos validation layer and print its messages");
    cmd->add_flag("--aa-set", o->aaSet,
                  "Instead: the colour images at 1x, 2x, 4x, 8x as NAME.png, NAMEx2.png, ... for ssfx eval quality");
    cmd->add_flag("--list-views", o->listViews, "List the scene's viewpoints and exit");
    cmd->footer(
        "Depth is hardware depth in [0, 1] (0 = near); camera.json holds fov_y_deg, z_near, z_far (read by\n"
        "ssfx ao), the size, guard band and the projection and view matrices (docs/render.md).\n"
        "Examples:\n"
        "  ssfx render atrium --view nave --size 1280x720 --guard 128 --out out/atrium\n"
        "  ssfx render scenes/sponza.json --list-views\n"
        "  ssfx render cornell --size 256x256 --gbuffer 4 --depth-format d24 --out out/cornell\n"
        "  ssfx render atrium --view nave --size 640x360 --aa-set --out imgs && ssfx eval quality imgs");
    cmd->callback([o] { run(*o); });
}

}  // namespace ssfx::cli
