// Vulkan rasterisation of scenes into depth buffers, G-buffers and forward-shaded colour
// (see renderer.hpp). One draw of the whole scene per request with dynamic rendering;
// attachments are copied to host-visible buffers and converted on the CPU.
#include "ssfx/render/renderer.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstring>
#include <map>

#include "ssfx/core/error.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/vk/compute.hpp"
#include "ssfx/vk/context.hpp"
#include "ssfx/vk/timer.hpp"

namespace ssfx::render {

namespace {

// SPIR-V compiled from src/render/shaders/ by ssfx_add_shaders (CMake) at build time.
const std::uint32_t kSceneVert[] = {
#include "shaders/scene.vert.inc"
};
const std::uint32_t kGBufferFrag[] = {
#include "shaders/gbuffer.frag.inc"
};
const std::uint32_t kForwardFrag[] = {
#include "shaders/forward.frag.inc"
};

enum class Pass { Depth, GBuffer, Forward };

// Layouts of the shaders' buffers (common.glsl): std140 / std430 with vec4 members only.
struct FrameData {
    glm::mat4 view;
    glm::vec4 ambient;
    glm::vec4 params;  // derivative scale, light count
    glm::vec4 eye;     // camera position, world space
};
struct MaterialData {
    glm::vec4 diffuse;
    glm::ivec4 layer;
};
struct LightData {
    glm::vec4 vector, color;
};
static_assert(sizeof(FrameData) == 112 && sizeof(MaterialData) == 32 && sizeof(LightData) == 32);

// The G-buffer's attachments (documented in renderer.hpp and docs/render.md).
constexpr std::array<vk::Format, 4> kGBufferFormats = {vk::Format::eR16G16B16A16Snorm, vk::Format::eR32G32Sfloat,
                                                       vk::Format::eR32G32B32A32Sfloat, vk::Format::eR16G16Uint};
constexpr std::array<std::size_t, 4> kGBufferBytes = {8, 8, 16, 4};

vk::Format vkDepthFormat(DepthFormat f) {
    switch (f) {
        case DepthFormat::D16: return vk::Format::eD16Unorm;
        case DepthFormat::D24: return vk::Format::eX8D24UnormPack32;
        case DepthFormat::D32F: return vk::Format::eD32Sfloat;
    }
    return vk::Format::eD32Sfloat;
}

std::size_t depthBytes(vk::Format f) { return f == vk::Format::eD16Unorm ? 2 : 4; }

// Converts the copied depth aspect to [0, 1]: unorm values exactly as v / (2^n - 1) rounded
// once to float (for D24 that rounding is below half a D24 step); D32F as stored.
ImageF depthFromBytes(const void* bytes, vk::Format f, int w, int h) {
    ImageF d(w, h);
    const std::size_t n = std::size_t(w) * std::size_t(h);
    if (f == vk::Format::eD16Unorm) {
        const auto* p = static_cast<const std::uint16_t*>(bytes);
        for (std::size_t i = 0; i < n; ++i) d.data()[i] = float(double(p[i]) / 65535.0);
    } else if (f == vk::Format::eX8D24UnormPack32) {
        const auto* p = static_cast<const std::uint32_t*>(bytes);
        for (std::size_t i = 0; i < n; ++i) d.data()[i] = float(double(p[i] & 0xFFFFFFu) / 16777215.0);
    } else {
        std::memcpy(d.data(), bytes, n * sizeof(float));
    }
    return d;
}

struct ColorTarget {
    vk::Format format;
    vk::ClearColorValue clear;
    std::size_t bytesPerTexel;
};

// The scene shaders' descriptor set (common.glsl): frame, materials, lights, textures.
const std::array<vkx::BindingSpec, 4> kBindings = {
    vkx::BindingSpec{vk::DescriptorType::eUniformBuffer,
                     vk::ShaderStageFlagBits::eVertex | vk::ShaderStageFlagBits::eFragment},
    vkx::BindingSpec{vk::DescriptorType::eStorageBuffer, vk::ShaderStageFlagBits::eFragment},
    vkx::BindingSpec{vk::DescriptorType::eStorageBuffer, vk::ShaderStageFlagBits::eFragment},
    vkx::BindingSpec{vk::DescriptorType::eCombinedImageSampler, vk::ShaderStageFlagBits::eFragment}};

std::shared_ptr<vkx::Context> graphicsContext(std::shared_ptr<vkx::Context> context) {
    if (!context) throw Error("renderer: no Vulkan context given");
    if (!context->graphics)
        throw Error(
            "renderer: the shared Vulkan context has no graphics queue (create it with ContextOptions::graphics)");
    return context;
}

}  // namespace

struct Renderer::Impl {
    explicit Impl(std::shared_ptr<vkx::Context> context) : shared(graphicsContext(std::move(context))), ctx(*shared) {
        setLayout = vkx::makeSetLayout(ctx, kBindings);
        const vk::PushConstantRange push(vk::ShaderStageFlagBits::eVertex, 0, sizeof(glm::mat4));
        const vk::DescriptorSetLayout layouts[] = {*setLayout};
        pipelineLayout = vk::raii::PipelineLayout(ctx.device, vk::PipelineLayoutCreateInfo({}, layouts, push));
        vert = vkx::makeShaderModule(ctx, kSceneVert);
        gbufferFrag = vkx::makeShaderModule(ctx, kGBufferFrag);
        forwardFrag = vkx::makeShaderModule(ctx, kForwardFrag);
        sampler = vk::raii::Sampler(
            ctx.device, vk::SamplerCreateInfo({}, vk::Filter::eLinear, vk::Filter::eLinear,
                                              vk::SamplerMipmapMode::eLinear, vk::SamplerAddressMode::eRepeat,
                                              vk::SamplerAddressMode::eRepeat, vk::SamplerAddressMode::eRepeat, 0.0f,
                                              ctx.anisotropy, std::min(16.0f, ctx.maxAnisotropy), VK_FALSE,
                                              vk::CompareOp::eAlways, 0.0f, VK_LOD_CLAMP_NONE));
    }

    const vk::raii::Pipeline& pipeline(Pass pass, vk::Format depthFormat) {
        const auto key = std::make_pair(int(pass), int(depthFormat));
        auto it = pipelines.find(key);
        if (it != pipelines.end()) return it->second;
        std::vector<vk::PipelineShaderStageCreateInfo> stages = {
            vk::PipelineShaderStageCreateInfo({}, vk::ShaderStageFlagBits::eVertex, *vert, "main")};
        std::vector<vk::Format> colorFormats;
        if (pass == Pass::GBuffer) {
            stages.emplace_back(vk::PipelineShaderStageCreateFlags(), vk::ShaderStageFlagBits::eFragment, *gbufferFrag,
                                "main");
            colorFormats.assign(kGBufferFormats.begin(), kGBufferFormats.end());
        } else if (pass == Pass::Forward) {
            stages.emplace_back(vk::PipelineShaderStageCreateFlags(), vk::ShaderStageFlagBits::eFragment, *forwardFrag,
                                "main");
            colorFormats = {vk::Format::eR8G8B8A8Unorm};
        }
        const vk::VertexInputBindingDescription binding(0, sizeof(scene::Vertex), vk::VertexInputRate::eVertex);
        const std::array<vk::VertexInputAttributeDescription, 4> attributes = {
            vk::VertexInputAttributeDescription(0, 0, vk::Format::eR32G32B32Sfloat, offsetof(scene::Vertex, position)),
            vk::VertexInputAttributeDescription(1, 0, vk::Format::eR32G32B32Sfloat, offsetof(scene::Vertex, normal)),
            vk::VertexInputAttributeDescription(2, 0, vk::Format::eR32G32Sfloat, offsetof(scene::Vertex, uv)),
            vk::VertexInputAttributeDescription(3, 0, vk::Format::eR32Uint, offsetof(scene::Vertex, material))};
        const vk::PipelineVertexInputStateCreateInfo vertexInput({}, binding, attributes);
        const vk::PipelineInputAssemblyStateCreateInfo assembly({}, vk::PrimitiveTopology::eTriangleList);
        const vk::PipelineViewportStateCreateInfo viewport({}, 1, nullptr, 1, nullptr);
        // Two-sided surfaces (imported models are not reliably closed or consistently wound).
        const vk::PipelineRasterizationStateCreateInfo raster(
            {}, VK_FALSE, VK_FALSE, vk::PolygonMode::eFill, vk::CullModeFlagBits::eNone,
            vk::FrontFace::eCounterClockwise, VK_FALSE, 0, 0, 0, 1.0f);
        const vk::PipelineMultisampleStateCreateInfo multisample({}, vk::SampleCountFlagBits::e1);
        const vk::PipelineDepthStencilStateCreateInfo depth({}, VK_TRUE, VK_TRUE, vk::CompareOp::eLess);
        const std::vector<vk::PipelineColorBlendAttachmentState> blend(
            colorFormats.size(),
            vk::PipelineColorBlendAttachmentState(VK_FALSE, {}, {}, {}, {}, {}, {},
                                                  vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
                                                      vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA));
        const vk::PipelineColorBlendStateCreateInfo blending({}, VK_FALSE, vk::LogicOp::eCopy, blend);
        const std::array<vk::DynamicState, 2> dynamicStates = {vk::DynamicState::eViewport, vk::DynamicState::eScissor};
        const vk::PipelineDynamicStateCreateInfo dynamic({}, dynamicStates);
        const vk::PipelineRenderingCreateInfo rendering(0, colorFormats, depthFormat);
        vk::GraphicsPipelineCreateInfo info({}, stages, &vertexInput, &assembly, nullptr, &viewport, &raster,
                                            &multisample, &depth, &blending, &dynamic, *pipelineLayout);
        info.pNext = &rendering;
        return pipelines.emplace(key, vk::raii::Pipeline(ctx.device, nullptr, info)).first->second;
    }

    struct Result {
        std::vector<vkx::Buffer> colors;
        vkx::Buffer depth;
        double gpuMs = 0;
    };

    // Work recorded after a draw, on its attachments left on the device.
    using Recorder = std::function<void(const vk::raii::CommandBuffer&, const DeviceDepth& depth,
                                        const std::vector<DeviceImage>& colors)>;

    // One draw of `scene` from `cam` into width x height attachments; returns their contents.
    // `after`: the attachments stay on the device for work recorded after the draw (not read
    // back): the depth in DEPTH_READ_ONLY_OPTIMAL, the colours in SHADER_READ_ONLY_OPTIMAL.
    Result draw(const scene::Scene& scene, const scene::CameraSetup& cam, Pass pass, vk::Format depthFormat,
                const std::vector<ColorTarget>& targets, float derivativeScale, const Recorder& after = {},
                std::shared_ptr<const void>* keep = nullptr) {
        scene.validate();
        const auto w = std::uint32_t(cam.bufferWidth()), h = std::uint32_t(cam.bufferHeight());
        ctx.requireImageSize(w, h, "render size");
        ctx.requireAttachmentFormat(depthFormat, true, "depth");
        for (const auto& t : targets) ctx.requireAttachmentFormat(t.format, false, "a colour attachment");

        // Scene data.
        vkx::Buffer vertices = ctx.uploadBuffer(scene.vertices.data(), scene.vertices.size() * sizeof(scene::Vertex),
                                                vk::BufferUsageFlagBits::eVertexBuffer);
        vkx::Buffer indices = ctx.uploadBuffer(scene.indices.data(), scene.indices.size() * sizeof(std::uint32_t),
                                               vk::BufferUsageFlagBits::eIndexBuffer);
        std::vector<MaterialData> materials;
        for (const auto& m : scene.materials)
            materials.push_back({glm::vec4(m.diffuse, 1.0f), glm::ivec4(m.textureLayer, 0, 0, 0)});
        std::vector<LightData> lights;
        for (const auto& l : scene.lights)
            lights.push_back(
                {glm::vec4(l.vector, l.type == scene::Light::Type::Point ? 1.0f : 0.0f), glm::vec4(l.color, 0.0f)});
        const auto lightCount = float(lights.size());
        if (lights.empty()) lights.push_back({});
        vkx::Buffer materialBuffer = ctx.uploadBuffer(materials.data(), materials.size() * sizeof(MaterialData),
                                                      vk::BufferUsageFlagBits::eStorageBuffer);
        vkx::Buffer lightBuffer =
            ctx.uploadBuffer(lights.data(), lights.size() * sizeof(LightData), vk::BufferUsageFlagBits::eStorageBuffer);
        const glm::dvec3 eye = glm::dvec3(glm::inverse(cam.view)[3]);
        const FrameData frame{glm::mat4(cam.view), glm::vec4(scene.ambient, 0.0f),
                              glm::vec4(derivativeScale, lightCount, 0, 0), glm::vec4(glm::vec3(eye), 1.0f)};
        vkx::Buffer frameBuffer = ctx.uploadBuffer(&frame, sizeof(frame), vk::BufferUsageFlagBits::eUniformBuffer);
        vkx::Image textures = uploadTextureArray(ctx, scene.textures);

        vkx::DescriptorSets sets(ctx, setLayout, kBindings);
        sets.bind(0, 0, frameBuffer);
        sets.bind(0, 1, materialBuffer);
        sets.bind(0, 2, lightBuffer);
        sets.bind(0, 3, *textures.view, vk::ImageLayout::eShaderReadOnlyOptimal, *sampler);

        // Attachments and their read-back buffers (none with `after`).
        const auto usage = vk::ImageUsageFlagBits::eTransferSrc;
        const vk::ImageUsageFlags onDevice = after ? vk::ImageUsageFlagBits::eSampled : vk::ImageUsageFlags{};
        std::vector<vkx::Image> colorImages;
        Result result;
        for (const auto& t : targets) {
            colorImages.push_back(ctx.createImage(t.format, w, h,
                                                  vk::ImageUsageFlagBits::eColorAttachment | usage | onDevice,
                                                  vk::ImageAspectFlagBits::eColor));
            if (!after)
                result.colors.push_back(ctx.createBuffer(vk::DeviceSize(w) * h * t.bytesPerTexel,
                                                         vk::BufferUsageFlagBits::eTransferDst, true));
        }
        const vk::ImageUsageFlags depthUsage = vk::ImageUsageFlagBits::eDepthStencilAttachment | usage | onDevice;
        vkx::Image depthImage = ctx.createImage(depthFormat, w, h, depthUsage, vk::ImageAspectFlagBits::eDepth);
        // For `after`: 2-D views (a sampled image's own view is an array).
        const auto view2d = [&](const vkx::Image& img, vk::Format format, vk::ImageAspectFlags aspect) {
            return vk::raii::ImageView(ctx.device, vk::ImageViewCreateInfo({}, *img.image, vk::ImageViewType::e2D,
                                                                           format, {}, {aspect, 0, 1, 0, 1}));
        };
        vk::raii::ImageView depth2d{nullptr};
        std::vector<vk::raii::ImageView> colors2d;
        if (after) {
            depth2d = view2d(depthImage, depthFormat, vk::ImageAspectFlagBits::eDepth);
            for (std::size_t i = 0; i < targets.size(); ++i)
                colors2d.push_back(view2d(colorImages[i], targets[i].format, vk::ImageAspectFlagBits::eColor));
        }
        const bool readDepth = pass != Pass::Forward && !after;
        if (readDepth)
            result.depth = ctx.createBuffer(vk::DeviceSize(w) * h * depthBytes(depthFormat),
                                            vk::BufferUsageFlagBits::eTransferDst, true);
        const vkx::GpuTimer timer(ctx);

        const vk::raii::Pipeline& pipe = pipeline(pass, depthFormat);
        const glm::mat4 viewProjection = cam.viewProjectionF();
        ctx.submit([&](const vk::raii::CommandBuffer& cmd) {
            using S = vk::PipelineStageFlagBits;
            using A = vk::AccessFlagBits;
            for (const auto& img : colorImages)
                vkx::transition(cmd, img, vk::ImageLayout::eUndefined, vk::ImageLayout::eColorAttachmentOptimal,
                                S::eTopOfPipe, {}, S::eColorAttachmentOutput, A::eColorAttachmentWrite);
            vkx::transition(cmd, depthImage, vk::ImageLayout::eUndefined, vk::ImageLayout::eDepthAttachmentOptimal,
                            S::eTopOfPipe, {}, S::eEarlyFragmentTests | S::eLateFragmentTests,
                            A::eDepthStencilAttachmentRead | A::eDepthStencilAttachmentWrite);
            timer.reset(cmd);
            timer.begin(cmd);
            std::vector<vk::RenderingAttachmentInfo> colorInfos;
            for (std::size_t i = 0; i < targets.size(); ++i)
                colorInfos.emplace_back(*colorImages[i].view, vk::ImageLayout::eColorAttachmentOptimal,
                                        vk::ResolveModeFlagBits::eNone, nullptr, vk::ImageLayout::eUndefined,
                                        vk::AttachmentLoadOp::eClear, vk::AttachmentStoreOp::eStore,
                                        vk::ClearValue(targets[i].clear));
            const vk::RenderingAttachmentInfo depthInfo(
                *depthImage.view, vk::ImageLayout::eDepthAttachmentOptimal, vk::ResolveModeFlagBits::eNone, nullptr,
                vk::ImageLayout::eUndefined, vk::AttachmentLoadOp::eClear, vk::AttachmentStoreOp::eStore,
                vk::ClearValue(vk::ClearDepthStencilValue(1.0f, 0)));
            cmd.beginRendering(vk::RenderingInfo({}, vk::Rect2D({0, 0}, {w, h}), 1, 0, colorInfos, &depthInfo));
            cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipe);
            cmd.setViewport(0, vk::Viewport(0.0f, 0.0f, float(w), float(h), 0.0f, 1.0f));
            cmd.setScissor(0, vk::Rect2D({0, 0}, {w, h}));
            cmd.bindVertexBuffers(0, {*vertices.buffer}, {vk::DeviceSize(0)});
            cmd.bindIndexBuffer(*indices.buffer, 0, vk::IndexType::eUint32);
            cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelineLayout, 0, sets[0], {});
            cmd.pushConstants<glm::mat4>(*pipelineLayout, vk::ShaderStageFlagBits::eVertex, 0, viewProjection);
            cmd.drawIndexed(std::uint32_t(scene.indices.size()), 1, 0, 0, 0);
            cmd.endRendering();
            timer.end(cmd);
            for (std::size_t i = 0; i < targets.size() && !after; ++i) {
                vkx::transition(cmd, colorImages[i], vk::ImageLayout::eColorAttachmentOptimal,
                                vk::ImageLayout::eTransferSrcOptimal, S::eColorAttachmentOutput,
                                A::eColorAttachmentWrite, S::eTransfer, A::eTransferRead);
                cmd.copyImageToBuffer(
                    *colorImages[i].image, vk::ImageLayout::eTransferSrcOptimal, *result.colors[i].buffer,
                    vk::BufferImageCopy(0, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1),
                                        {0, 0, 0}, {w, h, 1}));
            }
            if (after) {
                vkx::transition(cmd, depthImage, vk::ImageLayout::eDepthAttachmentOptimal,
                                vk::ImageLayout::eDepthReadOnlyOptimal, S::eEarlyFragmentTests | S::eLateFragmentTests,
                                A::eDepthStencilAttachmentWrite, S::eComputeShader, A::eShaderRead);
                std::vector<DeviceImage> colors;
                for (std::size_t i = 0; i < targets.size(); ++i) {
                    vkx::transition(cmd, colorImages[i], vk::ImageLayout::eColorAttachmentOptimal,
                                    vk::ImageLayout::eShaderReadOnlyOptimal, S::eColorAttachmentOutput,
                                    A::eColorAttachmentWrite, S::eComputeShader, A::eShaderRead);
                    colors.push_back(DeviceImage{*colors2d[i], targets[i].format,
                                                 vk::ImageUsageFlagBits::eColorAttachment | usage | onDevice, w, h,
                                                 vk::ImageLayout::eShaderReadOnlyOptimal});
                }
                after(cmd, DeviceDepth{*depth2d, depthFormat, depthUsage, w, h, vk::ImageLayout::eDepthReadOnlyOptimal},
                      colors);
            }
            if (readDepth) {
                vkx::transition(cmd, depthImage, vk::ImageLayout::eDepthAttachmentOptimal,
                                vk::ImageLayout::eTransferSrcOptimal, S::eLateFragmentTests,
                                A::eDepthStencilAttachmentWrite, S::eTransfer, A::eTransferRead);
                cmd.copyImageToBuffer(
                    *depthImage.image, vk::ImageLayout::eTransferSrcOptimal, *result.depth.buffer,
                    vk::BufferImageCopy(0, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eDepth, 0, 0, 1),
                                        {0, 0, 0}, {w, h, 1}));
            }
            const vk::MemoryBarrier toHost(A::eTransferWrite, A::eHostRead);
            cmd.pipelineBarrier(S::eTransfer, S::eHost, {}, toHost, {}, {});
        });
        result.gpuMs = timer.milliseconds()[0];
        if (keep) {  // the attachments and their 2-D views outlive the call
            struct Kept {
                std::vector<vkx::Image> colors;
                vkx::Image depth;
                vk::raii::ImageView depth2d;
                std::vector<vk::raii::ImageView> colors2d;
            };
            *keep = std::make_shared<const Kept>(
                Kept{std::move(colorImages), std::move(depthImage), std::move(depth2d), std::move(colors2d)});
        }
        return result;
    }

    std::shared_ptr<vkx::Context> shared;
    vkx::Context& ctx;
    vk::raii::DescriptorSetLayout setLayout{nullptr};
    vk::raii::PipelineLayout pipelineLayout{nullptr};
    vk::raii::ShaderModule vert{nullptr}, gbufferFrag{nullptr}, forwardFrag{nullptr};
    vk::raii::Sampler sampler{nullptr};
    std::map<std::pair<int, int>, vk::raii::Pipeline> pipelines;
};

using vkx::guarded;

// A scene's texture array as one sampled image (renderer.hpp).
vkx::Image uploadTextureArray(vkx::Context& ctx, const scene::TextureArray& t) {
    return guarded("uploading the texture array", [&] {
        scene::TextureArray white;
        white.size = 1;
        white.layers.push_back({ImageRgba8(1, 1, Rgba8{255, 255, 255, 255})});
        const scene::TextureArray& tex = t.layers.empty() ? white : t;
        const auto layers = std::uint32_t(tex.layers.size()), levels = std::uint32_t(tex.levelCount());
        vk::DeviceSize total = 0;
        for (std::uint32_t l = 0; l < levels; ++l) total += vk::DeviceSize(tex.layers[0][l].pixelCount()) * 4 * layers;
        vkx::Buffer staging = ctx.createBuffer(total, vk::BufferUsageFlagBits::eTransferSrc, true);
        std::vector<vk::BufferImageCopy> regions;
        vk::DeviceSize offset = 0;
        for (std::uint32_t l = 0; l < levels; ++l) {
            const auto& first = tex.layers[0][l];
            regions.emplace_back(
                offset, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, l, 0, layers),
                vk::Offset3D(0, 0, 0), vk::Extent3D(std::uint32_t(first.width()), std::uint32_t(first.height()), 1));
            for (std::uint32_t k = 0; k < layers; ++k) {
                const auto& img = tex.layers[k][l];
                std::memcpy(static_cast<std::uint8_t*>(staging.mapped) + offset, img.data(),
                            std::size_t(img.pixelCount()) * 4);
                offset += vk::DeviceSize(img.pixelCount()) * 4;
            }
        }
        const auto size = std::uint32_t(tex.layers[0][0].width());
        vkx::Image image = ctx.createImage(vk::Format::eR8G8B8A8Unorm, size, size,
                                           vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst,
                                           vk::ImageAspectFlagBits::eColor, layers, levels);
        // Read by the renderer's fragment shaders and the GPU shading's compute passes (a
        // compute-only queue has no fragment stage).
        const vk::PipelineStageFlags readers =
            ctx.graphics ? vk::PipelineStageFlagBits::eFragmentShader | vk::PipelineStageFlagBits::eComputeShader
                         : vk::PipelineStageFlags(vk::PipelineStageFlagBits::eComputeShader);
        ctx.submit([&](const vk::raii::CommandBuffer& cmd) {
            vkx::transition(cmd, image, vk::ImageLayout::eUndefined, vk::ImageLayout::eTransferDstOptimal,
                            vk::PipelineStageFlagBits::eTopOfPipe, {}, vk::PipelineStageFlagBits::eTransfer,
                            vk::AccessFlagBits::eTransferWrite);
            cmd.copyBufferToImage(*staging.buffer, *image.image, vk::ImageLayout::eTransferDstOptimal, regions);
            vkx::transition(cmd, image, vk::ImageLayout::eTransferDstOptimal, vk::ImageLayout::eShaderReadOnlyOptimal,
                            vk::PipelineStageFlagBits::eTransfer, vk::AccessFlagBits::eTransferWrite, readers,
                            vk::AccessFlagBits::eShaderRead);
        });
        return image;
    });
}

Renderer::Renderer(const RendererOptions& options)
    : Renderer(vkx::Context::create(vkx::ContextOptions{options.device, options.validation, true})) {}

Renderer::Renderer(std::shared_ptr<vkx::Context> context)
    : impl_(guarded("creating the renderer", [&] { return std::make_unique<Impl>(std::move(context)); })) {}

Renderer::~Renderer() = default;

const vkx::DeviceInfo& Renderer::device() const { return impl_->ctx.info; }

const std::shared_ptr<vkx::Context>& Renderer::context() const { return impl_->shared; }

std::vector<std::string> Renderer::validationMessages() const { return impl_->ctx.validationMessages(); }

DepthRender Renderer::renderDepth(const scene::Scene& scene, const scene::View& view, int width, int height,
                                  DepthFormat format, int guard) {
    return guarded("rendering depth", [&] {
        DepthRender out;
        out.camera = scene::cameraSetup(view, width, height, guard);
        const vk::Format f = vkDepthFormat(format);
        auto r = impl_->draw(scene, out.camera, Pass::Depth, f, {}, 1.0f);
        out.depth = depthFromBytes(r.depth.mapped, f, out.camera.bufferWidth(), out.camera.bufferHeight());
        out.gpuMs = r.gpuMs;
        return out;
    });
}

DepthRender Renderer::renderDepthOnDevice(const scene::Scene& scene, const scene::View& view, int width, int height,
                                          DepthFormat format, int guard, const DepthRecorder& after,
                                          std::shared_ptr<const void>* keep) {
    if (!after) throw Error("renderDepthOnDevice: no work to record after the draw");
    return guarded("rendering depth", [&] {
        DepthRender out;
        out.camera = scene::cameraSetup(view, width, height, guard);
        const auto r = impl_->draw(
            scene, out.camera, Pass::Depth, vkDepthFormat(format), {}, 1.0f,
            [&](const vk::raii::CommandBuffer& cmd, const DeviceDepth& depth, const std::vector<DeviceImage>&) {
                after(cmd, depth);
            },
            keep);
        out.gpuMs = r.gpuMs;
        return out;
    });
}

namespace {

// A G-buffer's size, m and camera (no planes), after checking them.
scene::GBuffer gbufferFrame(const scene::View& view, int width, int height, int m) {
    if (m < 1 || m > 4) throw Error(fmt::format("G-buffer supersampling m = {} is not in 1..4", m));
    checkDimensions(width, height, "G-buffer size");
    scene::GBuffer g;
    g.width = width;
    g.height = height;
    g.m = m;
    g.camera = scene::cameraSetup(view, m * width, m * height, 0);
    return g;
}

// The G-buffer's attachments: normal, uv, uv gradient, ids (background: 0xFFFF, none).
std::vector<ColorTarget> gbufferTargets() {
    const std::array<vk::ClearColorValue, 4> clears = {
        vk::ClearColorValue(0.0f, 0.0f, 0.0f, 0.0f), vk::ClearColorValue(0.0f, 0.0f, 0.0f, 0.0f),
        vk::ClearColorValue(0.0f, 0.0f, 0.0f, 0.0f),
        vk::ClearColorValue(std::array<std::uint32_t, 4>{0xFFFFu, 0xFFFFu, 0, 0})};
    std::vector<ColorTarget> targets;
    for (std::size_t i = 0; i < 4; ++i) targets.push_back({kGBufferFormats[i], clears[i], kGBufferBytes[i]});
    return targets;
}

}  // namespace

scene::GBuffer Renderer::renderGBufferOnDevice(const scene::Scene& scene, const scene::View& view, int width,
                                               int height, int m, const GBufferRecorder& after,
                                               std::shared_ptr<const void>* keep) {
    if (!after) throw Error("renderGBufferOnDevice: no work to record after the draw");
    scene::GBuffer g = gbufferFrame(view, width, height, m);
    return guarded("rendering the G-buffer", [&] {
        const auto r = impl_->draw(
            scene, g.camera, Pass::GBuffer, vk::Format::eD32Sfloat, gbufferTargets(), float(m),
            [&](const vk::raii::CommandBuffer& cmd, const DeviceDepth& depth, const std::vector<DeviceImage>& colors) {
                after(cmd, DeviceGBufferImages{depth, colors[0], colors[1], colors[2], colors[3], g.width, g.height,
                                               g.m, g.camera});
            },
            keep);
        g.gpuMs = r.gpuMs;
        return g;
    });
}

scene::GBuffer Renderer::renderGBuffer(const scene::Scene& scene, const scene::View& view, int width, int height,
                                       int m) {
    scene::GBuffer g = gbufferFrame(view, width, height, m);
    return guarded("rendering the G-buffer", [&] {
        auto r = impl_->draw(scene, g.camera, Pass::GBuffer, vk::Format::eD32Sfloat, gbufferTargets(), float(m));
        const int sw = g.sampleWidth(), sh = g.sampleHeight();
        const std::size_t n = std::size_t(sw) * std::size_t(sh);
        g.depth = depthFromBytes(r.depth.mapped, vk::Format::eD32Sfloat, sw, sh);
        g.normal.resize(n);
        g.uv.resize(n);
        g.uvGrad.resize(n);
        g.material.resize(n);
        g.layer.resize(n);
        const auto* normals = static_cast<const std::int16_t*>(r.colors[0].mapped);
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c)
                g.normal[i][c] = std::max(float(normals[4 * i + std::size_t(c)]) / 32767.0f, -1.0f);
        std::memcpy(g.uv.data(), r.colors[1].mapped, n * sizeof(glm::vec2));
        std::memcpy(g.uvGrad.data(), r.colors[2].mapped, n * sizeof(glm::vec4));
        const auto* ids = static_cast<const std::uint16_t*>(r.colors[3].mapped);
        for (std::size_t i = 0; i < n; ++i) {
            g.material[i] = ids[2 * i];
            g.layer[i] = ids[2 * i + 1] == 0xFFFFu ? std::int16_t(-1) : std::int16_t(ids[2 * i + 1]);
        }
        g.gpuMs = r.gpuMs;
        return g;
    });
}

ColorRender Renderer::renderColor(const scene::Scene& scene, const scene::View& view, int width, int height,
                                  int scale) {
    if (scale < 1 || scale > 16) throw Error(fmt::format("colour scale {} is not in 1..16", scale));
    return guarded("rendering colour", [&] {
        checkDimensions(width, height, "colour size");
        const scene::CameraSetup cam = scene::cameraSetup(view, scale * width, scale * height, 0);
        const glm::vec3 bg = glm::clamp(scene.background, 0.0f, 1.0f);
        auto r = impl_->draw(scene, cam, Pass::Forward, vk::Format::eD32Sfloat,
                             {{vk::Format::eR8G8B8A8Unorm, vk::ClearColorValue(bg.r, bg.g, bg.b, 1.0f), 4}}, 1.0f);
        ColorRender out;
        out.color = ImageRgba8(cam.bufferWidth(), cam.bufferHeight());
        std::memcpy(out.color.data(), r.colors[0].mapped, std::size_t(out.color.pixelCount()) * 4);
        out.gpuMs = r.gpuMs;
        return out;
    });
}

void writeAaRenderSet(Renderer& renderer, const scene::Scene& scene, const scene::View& view, int width, int height,
                      const std::string& dir, const std::string& name, const ProgressFn& progress) {
    std::vector<ImageRgba8> images;  // all rendered before any is written
    const char* suffix[] = {"", "x2", "x4", "x8"};
    // Eight steps: four renders, four PNGs (the x8 PNG alone takes longer than the renders).
    auto step = [&](int done) {
        if (progress) progress({"the 1x, x2, x4 and x8 images", done, 8, "steps"});
    };
    step(0);
    for (int scale : {1, 2, 4, 8}) {
        images.push_back(renderer.renderColor(scene, view, width, height, scale).color);
        step(int(images.size()));
    }
    for (std::size_t i = 0; i < images.size(); ++i) {
        io::writePng(dir + "/" + name + suffix[i] + ".png", images[i].view());
        step(int(i) + 5);
    }
}

}  // namespace ssfx::render
