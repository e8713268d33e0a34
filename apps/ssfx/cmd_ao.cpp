// ssfx ao: ambient obscurance from a depth buffer (EXR + camera JSON) or an analytic scene.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <filesystem>
#include <optional>

#include "apps/ssfx/commands.hpp"
#include "apps/ssfx/console.hpp"
#include "ssfx/ao/registry.hpp"
#include "ssfx/io/camera.hpp"
#include "ssfx/io/exr.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/scene/analytic.hpp"
#ifdef SSFX_HAVE_RENDER
#include "ssfx/render/renderer.hpp"
#include "ssfx/scene/raytrace.hpp"
#endif
#ifdef SSFX_HAVE_GPU
#include <cstring>

#include "ssfx/gpu/ao.hpp"
#include "ssfx/vk/compute.hpp"
#endif

namespace ssfx::cli {

namespace {

struct AoOptions {
    std::string method = "sao", depth, camera, scene, view, size, output, saveDepth, saveCamera, device, preset;
    std::string backend = "cpu", savePasses, normals, bentNormals;
    std::vector<std::string> params;
    double fovDeg = 60;
    int threads = 0, rays = 256;
};

void writeAo(const std::string& path, const ImageF& a) {
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".exr") {
        io::writeExr(path, a.view(), "Y");
    } else if (ext == ".png") {
        ImageRgba8 img(a.width(), a.height());
        for (int y = 0; y < a.height(); ++y)
            for (int x = 0; x < a.width(); ++x) {
                const auto g = std::uint8_t(std::lround(std::clamp(a(x, y), 0.0f, 1.0f) * 255.0f));
                img(x, y) = {g, g, g, 255};
            }
        io::writePng(path, img.view());
    } else {
        throw Error(fmt::format("output '{}': use a .png (8-bit) or .exr (float) file name", path));
    }
}

// --save-passes DIR: every intermediate as a float EXR (channel Y).
void writeStages(const std::string& dir, const ao::AoStages& st) {
    std::filesystem::create_directories(dir);
    auto write = [&](const std::string& name, const ImageF& img) {
        if (img.pixelCount() > 0) io::writeExr((std::filesystem::path(dir) / name).string(), img.view(), "Y");
    };
    write("z.exr", st.z);
    for (std::size_t m = 0; m < st.pyramid.size(); ++m) write(fmt::format("z{}.exr", m + 1), st.pyramid[m]);
    write("raw.exr", st.raw);
    write("quad.exr", st.quad);
    write("zblur.exr", st.zBlur);
    write("horizontal.exr", st.horizontal);
    write("ao.exr", st.result);
}

void writeNormals(const std::string& path, const Image<ao::Vec3>& n) {
    std::vector<ImageF> c(3, ImageF(n.width(), n.height()));
    for (int y = 0; y < n.height(); ++y)
        for (int x = 0; x < n.width(); ++x) c[0](x, y) = n(x, y).x, c[1](x, y) = n(x, y).y, c[2](x, y) = n(x, y).z;
    io::writeExr(path, {{"N.X", c[0].view()}, {"N.Y", c[1].view()}, {"N.Z", c[2].view()}});
}

void writeStages(const std::string& dir, const ao::GtaoStages& st) {
    std::filesystem::create_directories(dir);
    auto write = [&](const std::string& name, const ImageF& img) {
        io::writeExr((std::filesystem::path(dir) / name).string(), img.view(), "Y");
    };
    for (std::size_t m = 0; m < st.chain.size(); ++m) write(fmt::format("t{}.exr", m), st.chain[m]);
    write("edges.exr", st.edges);
    writeNormals((std::filesystem::path(dir) / "normals.exr").string(), st.normals);
    write("raw.exr", st.raw);
    write("ao.exr", st.result);
}

// A camera-space normal buffer: channels N.X, N.Y, N.Z (a G-buffer's, `ssfx render --gbuffer 1`).
Image<ao::Vec3> readNormals(const std::string& path) {
    ImageF c[3];
    const char* names[3] = {"N.X", "N.Y", "N.Z"};
    for (int i = 0; i < 3; ++i) c[i] = io::readExr(path, names[i]);
    Image<ao::Vec3> n(c[0].width(), c[0].height());
    for (int y = 0; y < n.height(); ++y)
        for (int x = 0; x < n.width(); ++x) n(x, y) = {c[0](x, y), c[1](x, y), c[2](x, y)};
    return n;
}

#ifdef SSFX_HAVE_GPU
std::shared_ptr<vkx::Context> gpuContext(const AoOptions& o, bool graphics) {
    vkx::ContextOptions co;
    co.device = o.device;
    co.graphics = graphics;
    try {
        return vkx::Context::create(co);
    } catch (const Error& e) {
        throw Error(fmt::format("--backend vulkan looked for a Vulkan 1.3 device with a compute queue{}{}: {}",
                                graphics ? " and graphics" : "",
                                o.device.empty() ? "" : fmt::format(" matching '{}'", o.device), e.what()));
    }
}
#endif

void run(const AoOptions& o, const CLI::App& cmd) {
    if (o.output.empty() && o.saveDepth.empty() && o.savePasses.empty())
        throw Error("no output file given (use -o FILE)");
    const bool vulkan = o.backend == "vulkan";
    // Options that do not apply to the input chosen are refused, not ignored.
    const bool analyticScene = o.scene == "corner" || o.scene == "room";
    if (!o.depth.empty())
        for (const char* opt : {"--size", "--fov", "--view"})
            if (cmd.count(opt))
                throw Error(fmt::format("{} does not apply to --depth (the depth file has its size and camera)", opt));
    if (analyticScene && cmd.count("--view"))
        throw Error(fmt::format("--view does not apply to the analytic scene '{}'", o.scene));
    if (cmd.count("--device") && !vulkan && (analyticScene || !o.depth.empty()))
        throw Error("--device goes with --backend vulkan or a rendered scene");
    if (!o.scene.empty() && !analyticScene && cmd.count("--fov"))
        throw Error("--fov does not apply to a rendered scene (its views have their own)");
    const ao::AoMethodInfo& method = ao::aoMethodById(o.method);
    if (cmd.count("--rays") && !method.needsGeometry) throw Error("--rays applies to -m raytraced only");
#ifdef SSFX_HAVE_GPU
    if (vulkan && !gpu::hasGpuAo(method.id))
        throw Error(fmt::format("{} has no GPU pass (--backend vulkan runs sao, alchemy and gtao)", method.id));
    if (vulkan && (!o.normals.empty() || !o.bentNormals.empty()))
        throw Error(fmt::format("{} is CPU-only (gtao's GPU pass reconstructs the normals from depth)",
                                o.normals.empty() ? "--bent-normals" : "--normals"));
#else
    if (vulkan) throw Error("--backend vulkan: this ssfx was built without the GPU backend");
#endif
    if (!o.savePasses.empty() && method.needsGeometry)
        throw Error("--save-passes: the ray-traced truth has no passes (it reads the geometry)");
    if ((!o.normals.empty() || !o.bentNormals.empty()) && method.id != "gtao")
        throw Error(fmt::format("{} applies to -m gtao only", o.normals.empty() ? "--bent-normals" : "--normals"));
    if (!o.bentNormals.empty() && std::filesystem::path(o.bentNormals).extension() != ".exr")
        throw Error(fmt::format("--bent-normals '{}': use an .exr file name", o.bentNormals));
    if (!o.output.empty()) {  // the output format, before any work
        const std::string ext = std::filesystem::path(o.output).extension().string();
        if (ext != ".png" && ext != ".exr")
            throw Error(fmt::format("output '{}': use a .png (8-bit) or .exr (float) file name", o.output));
    }
    if (o.scene.empty() == o.depth.empty()) throw Error("give either --depth FILE (with --camera) or --scene NAME");
    const Exec exec{o.threads};
    if (!o.preset.empty() && method.presets.empty()) throw Error(fmt::format("--preset: {} has no presets", o.method));
    // The preset first, then the -p overrides, every one checked before any work.
    ao::AoParams params = method.defaults(o.preset);
    if (method.needsGeometry) std::get<ao::RaytracedParams>(params).raysPerPixel = o.rays;
    for (const auto& text : o.params) {
        const auto [name, value] = parseParam(text, method.params, o.method);
        ao::setParam(method, params, name, value);
    }
    method.validate(params);
    const int guard = ao::guardBandOf(params);
    Camera cam;
    ImageF depth;
    std::optional<scene::AnalyticScene> scene;
    std::unique_ptr<ao::RayScene> meshScene;  // a rendered scene's triangles (Embree)
    const bool analytic = o.scene == "corner" || o.scene == "room";
    if (!o.scene.empty() && !analytic) {
#ifdef SSFX_HAVE_RENDER
        // A renderer scene: D32F depth from Vulkan, geometry for the ground truth from Embree.
        const auto [w, h] = parseSize(o.size);
        const scene::Scene rs = scene::loadScene(o.scene);
        const scene::View view = o.view.empty() ? rs.views.at(0).second : rs.view(o.view);
#ifdef SSFX_HAVE_GPU
        if (vulkan && o.savePasses.empty() && o.saveDepth.empty()) {
            // The renderer and the AO on one device: the AO passes read the depth image where
            // the draw left it, recorded into the draw's command buffer; only A comes back.
            if (o.output.empty()) return;
            auto ctx = gpuContext(o, true);
            render::Renderer renderer(ctx);
            gpu::AoPass pass(ctx, method.id, params);
            const std::uint32_t ow = std::uint32_t(w), oh = std::uint32_t(h);
            const auto outUsage = vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eTransferSrc;
            const vkx::Image out =
                ctx->createImage(vk::Format::eR32Sfloat, ow, oh, outUsage, vk::ImageAspectFlagBits::eColor);
            const vk::raii::ImageView outView(
                ctx->device, vk::ImageViewCreateInfo({}, *out.image, vk::ImageViewType::e2D, vk::Format::eR32Sfloat, {},
                                                     {vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1}));
            const vkx::Buffer download =
                ctx->createBuffer(vk::DeviceSize(ow) * oh * 4, vk::BufferUsageFlagBits::eTransferDst, true);
            using S = vk::PipelineStageFlagBits;
            using A = vk::AccessFlagBits;
            using L = vk::ImageLayout;
            const scene::CameraSetup setup = scene::cameraSetup(view, w, h, guard);
            renderer.renderDepthOnDevice(
                rs, view, w, h, DepthFormat::D32F, guard,
                [&](const vk::raii::CommandBuffer& c, const render::DeviceDepth& d) {
                    vkx::transition(c, out, L::eUndefined, L::eGeneral, S::eTopOfPipe, {}, S::eComputeShader,
                                    A::eShaderWrite);
                    pass.record(c, gpu::ImageRef{d.view, d.format, d.usage, d.width, d.height, d.layout}, setup.camera,
                                gpu::ImageRef{*outView, out.format, outUsage, ow, oh, L::eGeneral});
                    vkx::transition(c, out, L::eGeneral, L::eTransferSrcOptimal, S::eComputeShader, A::eShaderWrite,
                                    S::eTransfer, A::eTransferRead);
                    c.copyImageToBuffer(*out.image, L::eTransferSrcOptimal, *download.buffer,
                                        vk::BufferImageCopy(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1},
                                                            {0, 0, 0}, {ow, oh, 1}));
                });
            ImageF a(w, h);
            std::memcpy(a.data(), download.mapped, std::size_t(ow) * oh * 4);
            if (!o.saveCamera.empty()) io::writeCameraJson(o.saveCamera, setup.camera);
            writeAo(o.output, a);
            return;
        }
#endif
        render::Renderer renderer({o.device, false});
        auto r = renderer.renderDepth(rs, view, w, h, DepthFormat::D32F, guard);
        depth = std::move(r.depth);
        cam = r.camera.camera;
        if (method.needsGeometry) meshScene = scene::cameraSpaceRayScene(rs, r.camera);
#else
        throw Error(fmt::format("scene '{}': this ssfx was built without the renderer (analytic scenes: corner, room)",
                                o.scene));
#endif
    } else if (!o.depth.empty()) {
        if (method.needsGeometry) throw Error(fmt::format("{} needs the geometry: use --scene", o.method));
        if (o.camera.empty()) throw Error("--depth needs --camera FILE (JSON: fov_y_deg, z_near, z_far)");
        io::CameraBuffer stated;
        cam = io::readCameraJson(o.camera, &stated);
        depth = io::readExr(o.depth);
        if (stated.stated) {  // the camera describes a buffer: it must be this one
            if (depth.width() != stated.width + 2 * stated.guard || depth.height() != stated.height + 2 * stated.guard)
                throw Error(fmt::format("{} is {}x{}, but {} describes {}x{} with a guard band of {} ({}x{} in all)",
                                        o.depth, depth.width(), depth.height(), o.camera, stated.width, stated.height,
                                        stated.guard, stated.width + 2 * stated.guard,
                                        stated.height + 2 * stated.guard));
            if (guard != stated.guard)
                throw Error(fmt::format("-p guardBand={} but {} has a guard band of {} (give -p guardBand={})", guard,
                                        o.camera, stated.guard, stated.guard));
        }
        try {  // the depth's values, checked here so that a bad one is named with its file
            ao::depthToZ(depth.view(), cam, exec);
        } catch (const Error& e) {
            throw Error(fmt::format("{}: {}", o.depth, e.what()));
        }
    } else {
        scene = scene::analyticSceneByName(o.scene);
        const auto [w, h] = parseSize(o.size);
        cam.fovY = o.fovDeg * M_PI / 180.0;
        depth = scene::castGeometry(*scene, cam, w + 2 * guard, h + 2 * guard, exec).depth;
    }
    if (!o.saveDepth.empty()) io::writeExr(o.saveDepth, depth.view(), "Z");
    if (!o.saveCamera.empty()) io::writeCameraJson(o.saveCamera, cam);
    if (o.output.empty() && o.savePasses.empty()) return;
    Image<ao::Vec3> normals, bent;
    if (!o.normals.empty()) {
        normals = readNormals(o.normals);
        if (normals.width() != depth.width() || normals.height() != depth.height())
            throw Error(fmt::format("--normals {} is {}x{}, the depth buffer {}x{} (guard band included)", o.normals,
                                    normals.width(), normals.height(), depth.width(), depth.height()));
    }
    ImageF a;
    ao::AoStages stages;
    ao::AoStages* st = o.savePasses.empty() ? nullptr : &stages;
    if (const auto* gp = std::get_if<ao::GtaoParams>(&params); gp && !vulkan) {
        const ao::GtaoBuffers buffers{normals.view(), o.bentNormals.empty() ? nullptr : &bent};
        if (st) {
            ao::GtaoStages gs;
            a = ao::gtao(depth.view(), cam, *gp, exec, buffers, &gs);
            writeStages(o.savePasses, gs);
        } else {
            a = ao::gtao(depth.view(), cam, *gp, exec, buffers);
        }
        if (!o.bentNormals.empty()) writeNormals(o.bentNormals, bent);
        if (!o.output.empty()) writeAo(o.output, a);
        return;
    }
    if (vulkan) {
#ifdef SSFX_HAVE_GPU
        gpu::AoPass pass(gpuContext(o, false), method.id, params);
        if (st)
            stages = pass.runStages(depth.view(), cam), a = stages.result;
        else
            a = pass.run(depth.view(), cam);
#endif
    } else if (st) {
        if (const auto* p = std::get_if<ao::SaoParams>(&params))
            a = ao::sao(depth.view(), cam, *p, exec, st);
        else
            a = ao::alchemy(depth.view(), cam, std::get<ao::AlchemyParams>(params), exec, st);
    } else {
        ProgressLine line("ao");
        ao::AoInput input{depth.view(), cam, nullptr, line.fn(), {}};
        if (method.needsGeometry)
            input.geometry = meshScene ? meshScene.get() : static_cast<const ao::RayScene*>(&*scene);
        a = method.run(input, params, exec);
    }
    if (st) writeStages(o.savePasses, stages);
    if (!o.output.empty()) writeAo(o.output, a);
}

}  // namespace

void addAoCommand(CLI::App& app) {
    auto o = std::make_shared<AoOptions>();
    auto* cmd =
        app.add_subcommand("ao", "Ambient obscurance: SAO, the AlchemyAO baseline, GTAO, or ray-traced ground truth");
    std::string ids;
    for (const ao::AoMethodInfo& m : ao::aoMethods()) ids += fmt::format("{}{}", ids.empty() ? "" : ", ", m.id);
    cmd->add_option("-m,--method", o->method, ids + " (default sao)");
    cmd->add_option("--depth", o->depth, "Depth buffer (EXR; channel Z, Y, R or the only one; values in [0, 1])");
    cmd->add_option("--camera", o->camera, "Camera JSON of the depth buffer: {\"fov_y_deg\", \"z_near\", \"z_far\"}");
    cmd->add_option("--scene", o->scene,
                    "Scene instead of a depth file: analytic corner or room; or rendered with Vulkan: atrium, "
                    "cornell, a scene .json or a model file");
    cmd->add_option("--view", o->view, "With a rendered scene: its named viewpoint (default: the first)");
    cmd->add_option("--backend", o->backend,
                    "cpu (default) or vulkan: sao, alchemy and gtao as Vulkan compute passes (docs/gpu.md); with a "
                    "rendered scene the render and the AO run on one device and only A is read back")
        ->check(CLI::IsMember({"cpu", "vulkan"}));
    cmd->add_option("--device", o->device,
                    "With a rendered scene or --backend vulkan: Vulkan device index or name part ('ssfx devices')");
    cmd->add_option("--size", o->size, "With --scene: output size WxH (the buffer adds the guard band)")
        ->default_val("960x540");
    cmd->add_option("--fov", o->fovDeg, "With an analytic scene: vertical field of view in degrees (default 60)")
        ->check(CLI::Range(1.0, 179.0));
    cmd->add_option("-o,--output", o->output, "AO output: .png (8-bit) or .exr (float)");
    cmd->add_option("--preset", o->preset,
                    "sao: paper (the defaults: the paper's text) or released (the authors' released shaders, "
                    "June 2012: 11 taps, 6.28 per turn, spin summed in float, linear intensity, r 0.7 m, bias "
                    "0.012 m, intensity 0.7, 9-tap stride-2 blur, RGB8 storage; docs/methods/sao.md). gtao: "
                    "low, medium, high (the defaults), ultra (XeGTAO's 1x2, 2x2, 3x3, 9x3 slices x steps), ideal "
                    "(the definition's estimator: no auto-tuned multiplier, power or lift), paper (the course's "
                    "pipeline: 1 slice, 6 steps, horizons from -1, thickness heuristic; docs/methods/gtao.md). -p "
                    "overrides it");
    cmd->add_option("--normals", o->normals,
                    "gtao: camera-space normals (EXR channels N.X, N.Y, N.Z, e.g. a G-buffer from 'ssfx render "
                    "--gbuffer 1'; the depth's size, guard band included) instead of normals from depth");
    cmd->add_option("--bent-normals", o->bentNormals,
                    "gtao: also write the bent normals of the output (EXR, N.X N.Y N.Z, camera space)");
    std::string names;  // from the registry's tables
    for (const ao::AoMethodInfo& m : ao::aoMethods()) {
        names += fmt::format("{}{}:", names.empty() ? "" : "; ", m.id);
        for (const ParamInfo& p : m.params) {
            names += ' ';
            names += p.name;
        }
    }
    cmd->add_option("-p,--param", o->params,
                    "NAME=VALUE (repeatable; ranges and defaults: ssfx methods --family ao): " + names);
    cmd->add_option("--rays", o->rays, "raytraced: rays per pixel (default 256)")->check(CLI::Range(1, 65536));
    cmd->add_option("--save-depth", o->saveDepth, "Also write the depth buffer used (EXR, channel Z)");
    cmd->add_option("--save-camera", o->saveCamera, "Also write its camera (JSON)");
    cmd->add_option("--save-passes", o->savePasses,
                    "sao, alchemy: also write every intermediate into this directory as float EXRs: z.exr, the "
                    "pyramid's z1.exr.., raw.exr (sample pass), quad.exr (2x2 pass), zblur.exr (packed key), "
                    "horizontal.exr, ao.exr (with --backend vulkan and a rendered scene, from the read-back depth); "
                    "gtao: t0.exr..t4.exr (the depth chain), edges.exr, normals.exr, raw.exr (main pass), ao.exr");
    cmd->add_option("--threads", o->threads, "Worker threads (0 = all)")->check(CLI::Range(0, 1024));
    cmd->footer(
        "Depth d in [0, 1] (0 = near plane); d = 1 exactly is nothing drawn (sky, A = 1) for any far plane;\n"
        "camera space looks down -z (docs/methods/sao.md).\n"
        "Examples:\n"
        "  ssfx ao --scene room --size 960x540 -p guardBand=64 -o ao.png --save-depth d.exr --save-camera c.json\n"
        "  ssfx ao --scene atrium --view colonnade --size 960x540 -p guardBand=64 -o ao.png\n"
        "  ssfx ao --preset released --depth d.exr --camera c.json -p guardBand=64 -o released.png\n"
        "  ssfx ao -m raytraced --scene scenes/sponza.json --size 480x270 --rays 256 -o truth.exr\n"
        "  ssfx ao -m alchemy --depth d.exr --camera c.json -p guardBand=64 -o alchemy.exr\n"
        "  ssfx ao -m gtao --preset ultra --depth d.exr --camera c.json -p guardBand=64 -p radius=1 -o gtao.exr\n"
        "  ssfx ao --backend vulkan --scene atrium --size 1920x1080 -p guardBand=192 -o ao.png\n"
        "  ssfx ao --backend vulkan --depth d.exr --camera c.json -p guardBand=64 --save-passes passes -o ao.exr");
    cmd->callback([o, cmd] {
        io::OutputSet outputs;  // -o, --save-depth and --save-camera: all or none
        run(*o, *cmd);
        outputs.commit();
    });
}

}  // namespace ssfx::cli
