// The whole frame on one device: render, shade adaptively with AO, encode, anti-alias, read
// back (ssfx/gpu/frame.hpp; docs/frame.md).
#include "ssfx/gpu/frame.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstring>
#include <functional>
#include <optional>

#include "ssfx/core/error.hpp"
#include "ssfx/gpu/ao.hpp"
#include "ssfx/render/renderer.hpp"
#include "ssfx/vk/compute.hpp"
#include "ssfx/vk/timer.hpp"

namespace ssfx::gpu {

namespace {

const std::uint32_t kEncode[] = {
#include "shaders/encode_rgba8.comp.inc"
};

using S = vk::PipelineStageFlagBits;
using A = vk::AccessFlagBits;
using L = vk::ImageLayout;
using F = vk::Format;
using U = vk::ImageUsageFlagBits;

// An image of the frame with a 2-D view (a sampled image's own view is an array).
struct FrameImage {
    vkx::Image image;
    vk::raii::ImageView view{nullptr};
    vk::ImageUsageFlags usage;

    ImageRef ref() const { return ImageRef{*view, image.format, usage, image.width, image.height, L::eGeneral}; }
};

FrameImage makeImage(vkx::Context& ctx, F format, std::uint32_t w, std::uint32_t h, vk::ImageUsageFlags usage) {
    FrameImage f;
    f.usage = usage;
    f.image = ctx.createImage(format, w, h, usage, vk::ImageAspectFlagBits::eColor);
    f.view =
        vk::raii::ImageView(ctx.device, vk::ImageViewCreateInfo({}, *f.image.image, vk::ImageViewType::e2D, format, {},
                                                                {vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1}));
    return f;
}

// UNDEFINED -> GENERAL for a compute pass's output (its old contents are not needed).
void toGeneral(const vk::raii::CommandBuffer& cmd, const FrameImage& f) {
    vkx::transition(cmd, f.image, L::eUndefined, L::eGeneral, S::eTopOfPipe, {}, S::eComputeShader,
                    A::eShaderWrite | A::eShaderRead);
}

}  // namespace

double FrameResult::totalMs() const {
    double sum = 0;
    for (const auto& p : passes) sum += p.milliseconds;
    return sum;
}

std::string_view frameClockName(FrameClock c) { return c == FrameClock::Timestamps ? "timestamps" : "host"; }

struct FrameRenderer::Impl {
    std::shared_ptr<vkx::Context> ctx;
    scene::Scene scene;
    FrameSettings settings;
    int guard = 0;
    FrameClock clock = FrameClock::Timestamps;
    render::Renderer renderer;
    std::optional<AoPass> ao;
    AdaptiveShading shading;
    std::optional<AaPass> aa;
    vkx::ComputePipeline encode;
    FrameImage occlusion, shaded, encoded, antialiased;
    vkx::Buffer readback;

    Impl(std::shared_ptr<vkx::Context> c, const scene::Scene& s, const FrameSettings& fs)
        : ctx(checked(std::move(c), fs)),
          scene(s),
          settings(fs),
          guard(fs.ao == "none" ? 0 : ao::guardBandOf(fs.aoParams)),
          renderer(ctx),
          shading(ctx, scene, fs.lookup),
          encode(*ctx, kEncode, {{vk::DescriptorType::eStorageImage}, {vk::DescriptorType::eStorageImage}}, 0, nullptr,
                 true) {
        // The compute passes are a submission of their own, after the draws': there lavapipe's
        // timestamps are right too (they miss compute work recorded after a draw in one command
        // buffer; docs/gpu.md). A queue without timestamps gets the host's clock, pass by pass.
        clock = ctx->timestampPeriodNs > 0 ? FrameClock::Timestamps : FrameClock::Host;
        const auto w = std::uint32_t(fs.width), h = std::uint32_t(fs.height);
        ctx->requireImageSize(std::uint32_t(fs.m) * w, std::uint32_t(fs.m) * h,
                              fmt::format("the G-buffer (--ss {})", fs.m));
        ctx->requireImageSize(w + 2 * std::uint32_t(guard), h + 2 * std::uint32_t(guard),
                              fmt::format("the depth draw with its guard band of {}", guard));
        if (fs.ao != "none") ao.emplace(ctx, fs.ao, fs.aoParams);
        if (fs.aa != "none") aa.emplace(ctx, fs.aa, fs.aaSettings, Sampling::Model);
        deferred::validate(fs.shading);
        vkx::guarded("creating the frame's images", [&] {
            occlusion = makeImage(*ctx, F::eR32Sfloat, w, h, U::eStorage | U::eSampled);
            shaded = makeImage(*ctx, F::eR32G32B32A32Sfloat, w, h, U::eStorage);
            encoded = makeImage(*ctx, F::eR8G8B8A8Unorm, w, h, U::eStorage | U::eSampled | U::eTransferSrc);
            if (aa) antialiased = makeImage(*ctx, F::eR8G8B8A8Unorm, w, h, U::eStorage | U::eTransferSrc);
            readback = ctx->createBuffer(vk::DeviceSize(w) * h * 4, vk::BufferUsageFlagBits::eTransferDst, true);
        });
    }

    // The settings' checks that come before any Vulkan object is made.
    static std::shared_ptr<vkx::Context> checked(std::shared_ptr<vkx::Context> c, const FrameSettings& fs) {
        if (!c) throw Error("gpu::FrameRenderer: no Vulkan context");
        if (!c->graphics)
            throw Error("gpu::FrameRenderer: the context has no graphics queue (ContextOptions::graphics)");
        if (fs.m < 1 || fs.m > 4) throw Error(fmt::format("--ss {}: the supersampling is 1..4", fs.m));
        checkDimensions(fs.width, fs.height, "the frame");
        if (fs.ao != "none" && !hasGpuAo(fs.ao))
            throw Error(fmt::format("--ao {}: not an AO method with a GPU pass (sao, alchemy, gtao, none)", fs.ao));
        if (fs.aa != "none") {
            const MethodInfo* m = findMethod(fs.aa);
            if (!m) throw Error(fmt::format("--aa {}: no such anti-aliasing method (ssfx methods lists them)", fs.aa));
            if (m->inputScale != 1)
                throw Error(fmt::format(
                    "--aa {}: it reads a {}x larger image than it writes; the frame's shading is at the final size "
                    "(use --ss for supersampling)",
                    fs.aa, m->inputScale));
        }
        return c;
    }

    FrameResult render(const scene::View& view) {
        const FrameSettings& fs = settings;
        FrameResult r;
        // The draws: one submission each, their attachments kept on the device.
        std::shared_ptr<const void> keepDepth, keepGBuffer;
        std::optional<render::DeviceDepth> depth;
        Camera depthCamera;
        if (ao) {
            const auto d = renderer.renderDepthOnDevice(
                scene, view, fs.width, fs.height, DepthFormat::D32F, guard,
                [&](const vk::raii::CommandBuffer&, const render::DeviceDepth& dd) { depth = dd; }, &keepDepth);
            depthCamera = d.camera.camera;
            r.passes.push_back({"depth draw", d.gpuMs});
        }
        std::optional<render::DeviceGBufferImages> gimages;
        const scene::GBuffer g = renderer.renderGBufferOnDevice(
            scene, view, fs.width, fs.height, fs.m,
            [&](const vk::raii::CommandBuffer&, const render::DeviceGBufferImages& images) { gimages = images; },
            &keepGBuffer);
        r.passes.push_back({"gbuffer draw", g.gpuMs});

        DeviceGBuffer dg = deviceGBuffer(*gimages);
        if (ao) dg.ambientOcclusion = occlusion.ref();
        const FrameImage& final = aa ? antialiased : encoded;
        const auto w = std::uint32_t(fs.width), h = std::uint32_t(fs.height);

        // The compute passes and the read-back, in order.
        using Record = std::function<void(const vk::raii::CommandBuffer&)>;
        std::vector<std::pair<std::string, Record>> passes;
        if (ao)
            passes.emplace_back("ao", [&](const vk::raii::CommandBuffer& cmd) {
                toGeneral(cmd, occlusion);
                ao->record(cmd, imageRef(*depth), depthCamera, occlusion.ref());
                vkx::computeBarrier(cmd, S::eComputeShader, A::eShaderRead);
            });
        passes.emplace_back("shading", [&](const vk::raii::CommandBuffer& cmd) {
            toGeneral(cmd, shaded);
            shading.record(cmd, dg, fs.shading, shaded.ref(), fs.schedule);
            vkx::computeBarrier(cmd, S::eComputeShader, A::eShaderRead);
        });
        passes.emplace_back("encode", [&](const vk::raii::CommandBuffer& cmd) {
            toGeneral(cmd, encoded);
            const vk::DescriptorImageInfo in(nullptr, *shaded.view, L::eGeneral),
                out(nullptr, *encoded.view, L::eGeneral);
            const std::array<vk::WriteDescriptorSet, 2> writes = {
                vk::WriteDescriptorSet({}, 0, 0, vk::DescriptorType::eStorageImage, in),
                vk::WriteDescriptorSet({}, 1, 0, vk::DescriptorType::eStorageImage, out)};
            encode.dispatchPushed(cmd, writes, nullptr, vkx::groupCount(w, 8), vkx::groupCount(h, 8));
            vkx::computeBarrier(cmd, S::eComputeShader | S::eTransfer, A::eShaderRead | A::eTransferRead);
        });
        if (aa)
            passes.emplace_back("aa", [&](const vk::raii::CommandBuffer& cmd) {
                toGeneral(cmd, antialiased);
                aa->record(cmd, encoded.ref(), antialiased.ref());
                vkx::computeBarrier(cmd, S::eTransfer, A::eTransferRead);
            });
        passes.emplace_back("readback", [&](const vk::raii::CommandBuffer& cmd) {
            vkx::transition(cmd, final.image, L::eGeneral, L::eTransferSrcOptimal, S::eComputeShader, A::eShaderWrite,
                            S::eTransfer, A::eTransferRead);
            cmd.copyImageToBuffer(
                *final.image.image, L::eTransferSrcOptimal, *readback.buffer,
                vk::BufferImageCopy(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1}, {0, 0, 0}, {w, h, 1}));
            const vk::MemoryBarrier toHost(A::eTransferWrite, A::eHostRead);
            cmd.pipelineBarrier(S::eTransfer, S::eHost, {}, toHost, {}, {});
        });

        vkx::guarded("rendering the frame's passes", [&] {
            if (clock == FrameClock::Timestamps) {
                const vkx::GpuTimer timer(*ctx, std::uint32_t(passes.size()));
                ctx->submit([&](const vk::raii::CommandBuffer& cmd) {
                    timer.reset(cmd);
                    for (std::uint32_t i = 0; i < passes.size(); ++i) {
                        timer.begin(cmd, i);
                        passes[i].second(cmd);
                        timer.end(cmd, i);
                    }
                });
                const std::vector<double> ms = timer.milliseconds();
                for (std::size_t i = 0; i < passes.size(); ++i) r.passes.push_back({passes[i].first, ms[i]});
            } else {
                for (const auto& [name, record] : passes) {
                    const auto t0 = std::chrono::steady_clock::now();
                    ctx->submit(record);
                    const std::chrono::duration<double, std::milli> dt = std::chrono::steady_clock::now() - t0;
                    r.passes.push_back({name, dt.count()});
                }
            }
        });
        r.image = ImageRgba8(fs.width, fs.height);
        std::memcpy(r.image.data(), readback.mapped, std::size_t(w) * h * 4);
        return r;
    }
};

FrameRenderer::FrameRenderer(std::shared_ptr<vkx::Context> ctx, const scene::Scene& scene,
                             const FrameSettings& settings)
    : impl_(std::make_unique<Impl>(std::move(ctx), scene, settings)) {}
FrameRenderer::~FrameRenderer() = default;

FrameResult FrameRenderer::render(const scene::View& view) { return impl_->render(view); }
FrameClock FrameRenderer::clock() const { return impl_->clock; }
const FrameSettings& FrameRenderer::settings() const { return impl_->settings; }
std::vector<std::string> FrameRenderer::validationMessages() const { return impl_->ctx->validationMessages(); }

}  // namespace ssfx::gpu
