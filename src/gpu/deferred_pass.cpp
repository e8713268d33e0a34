// Adaptive supersampling for deferred shading as Vulkan compute passes (ssfx/gpu/deferred.hpp;
// docs/gpu.md, "Adaptive shading").
#include "ssfx/gpu/deferred.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <optional>

#include "ssfx/core/error.hpp"
#include "ssfx/render/renderer.hpp"
#include "ssfx/vk/compute.hpp"
#include "ssfx/vk/timer.hpp"

namespace ssfx::gpu {

namespace {

const std::uint32_t kFirst[] = {
#include "shaders/deferred_first.comp.inc"
};
const std::uint32_t kEvaluate[] = {
#include "shaders/deferred_evaluate.comp.inc"
};
const std::uint32_t kRest[] = {
#include "shaders/deferred_rest.comp.inc"
};
const std::uint32_t kList[] = {
#include "shaders/deferred_list.comp.inc"
};

using S = vk::PipelineStageFlagBits;
using A = vk::AccessFlagBits;
using L = vk::ImageLayout;
using F = vk::Format;
using Desc = vk::DescriptorType;

// deferred.glsl's Setup block (std430: 4-byte scalars, then 16-byte vectors).
struct DeferredSetup {
    std::int32_t width, height, m, n;
    std::int32_t sampleW, sampleH, lightCount, maxAnisotropy;
    std::int32_t stall, textureSize, levelCount, useAo;
    float cDepth, cNormal, cShading, tMin;
    float tEdge, specular, shininess, p00;
    float p11, c0Hi, c0Lo, c1Hi;
    float c1Lo, c2Hi, c2Lo, pad0;
    glm::vec4 ambient, background;
    std::array<glm::ivec4, 16> order;
    std::array<glm::ivec4, 16> level;
};
static_assert(offsetof(DeferredSetup, ambient) == 112 && offsetof(DeferredSetup, order) == 144 &&
                  sizeof(DeferredSetup) == 144 + 2 * 16 * 16,
              "DeferredSetup: deferred.glsl's std430 layout");
struct LightData {
    glm::vec4 vector, color;
};
struct MaterialData {
    glm::vec4 diffuse;
    glm::ivec4 layer;
};

// The bindings of every pass (deferred.glsl): one layout, each shader reads its own.
const std::vector<vkx::BindingSpec> kBindings = {
    {Desc::eStorageBuffer},        {Desc::eStorageBuffer},        {Desc::eStorageBuffer},
    {Desc::eStorageBuffer},        {Desc::eCombinedImageSampler}, {Desc::eCombinedImageSampler},
    {Desc::eCombinedImageSampler}, {Desc::eCombinedImageSampler}, {Desc::eCombinedImageSampler},
    {Desc::eCombinedImageSampler}, {Desc::eStorageImage},         {Desc::eStorageImage},
    {Desc::eStorageImage},         {Desc::eStorageImage},         {Desc::eStorageBuffer},
    {Desc::eStorageBuffer},        {Desc::eStorageBuffer},        {Desc::eStorageBuffer},
    {Desc::eStorageBuffer},        {Desc::eCombinedImageSampler}};

constexpr F kColorFormat = F::eR32G32B32A32Sfloat;  // S, the metrics, the output
constexpr F kKFormat = F::eR32Uint;
constexpr int kGroup = 8;  // deferred.glsl's local size
// The rest pass's shaders (deferred_rest.comp's kVariant; the list is deferred_list.comp).
enum Variant { kPerPixel = 0, kTiled = 1, kBruteForce = 2, kSampleList = 3 };

int variantOf(Schedule schedule, const deferred::AdaptiveParams& p) {
    switch (schedule) {
        case Schedule::PerPixel: return kPerPixel;
        case Schedule::Tiled: return kTiled;
        case Schedule::SampleList: return kSampleList;
        case Schedule::FromParams: break;
    }
    return p.tiled ? kTiled : kPerPixel;
}

// A double as a float pair hi + lo (exact.glsl's pairs).
std::array<float, 2> pairOf(double v) {
    const float hi = float(v);
    return {hi, float(v - double(hi))};
}

vk::raii::ImageView view2d(const vkx::Context& c, const vkx::Image& img) {
    return vk::raii::ImageView(c.device, vk::ImageViewCreateInfo({}, *img.image, vk::ImageViewType::e2D, img.format, {},
                                                                 vk::ImageSubresourceRange(img.aspect, 0, 1, 0, 1)));
}

bool oneOf(vk::Format f, std::initializer_list<vk::Format> formats) {
    return std::find(formats.begin(), formats.end(), f) != formats.end();
}

// One G-buffer plane as record() takes it.
void checkPlane(const ImageRef& r, const char* name, std::initializer_list<vk::Format> formats, std::uint32_t w,
                std::uint32_t h) {
    if (!r.view) throw Error(fmt::format("gpu::AdaptiveShading: no {} view", name));
    if (!oneOf(r.format, formats)) {
        std::string expected;
        for (vk::Format f : formats) expected += (expected.empty() ? "" : " or ") + vk::to_string(f);
        throw Error(
            fmt::format("gpu::AdaptiveShading: {} format {} (expected {})", name, vk::to_string(r.format), expected));
    }
    if (!(r.usage & vk::ImageUsageFlagBits::eSampled))
        throw Error(fmt::format("gpu::AdaptiveShading: the {} image needs SAMPLED usage", name));
    if (r.layout != L::eShaderReadOnlyOptimal && r.layout != L::eGeneral && r.layout != L::eDepthReadOnlyOptimal &&
        r.layout != L::eDepthStencilReadOnlyOptimal)
        throw Error(fmt::format("gpu::AdaptiveShading: {} layout {} (expected a read-only layout or GENERAL)", name,
                                vk::to_string(r.layout)));
    if (r.width != w || r.height != h)
        throw Error(fmt::format("gpu::AdaptiveShading: {} is {}x{}, expected the sample grid's {}x{}", name, r.width,
                                r.height, w, h));
}

}  // namespace

std::string_view scheduleName(Schedule s) {
    return s == Schedule::PerPixel     ? "pixel"
           : s == Schedule::Tiled      ? "tiled"
           : s == Schedule::SampleList ? "list"
                                       : "params";
}

Schedule parseSchedule(std::string_view name) {
    for (const Schedule s : {Schedule::FromParams, Schedule::PerPixel, Schedule::Tiled, Schedule::SampleList})
        if (name == scheduleName(s)) return s;
    throw Error(fmt::format("schedule '{}': expected pixel, tiled, list or params", name));
}

struct AdaptiveShading::Impl {
    std::shared_ptr<vkx::Context> ctx;
    Sampling lookup;
    std::vector<scene::Light> lights;
    glm::vec3 ambient{0.0f}, background{0.0f};
    std::size_t materialCount = 0, layerCount = 0;
    int textureSize = 1, levelCount = 0;
    std::array<glm::ivec4, 16> levels{};
    vkx::Buffer materials, texels;
    vkx::Image textures;  // the device sampler's (render::uploadTextureArray)
    vk::raii::Sampler nearest{nullptr}, hardware{nullptr};
    int hardwareAnisotropy = -1;  // the hardware sampler's maxAnisotropy
    std::unique_ptr<vkx::ComputePipeline> first;
    std::array<std::unique_ptr<vkx::ComputePipeline>, 5> evaluate;  // per m (made on first use)
    std::array<std::unique_ptr<vkx::ComputePipeline>, 3> rest;
    std::array<std::unique_ptr<vkx::ComputePipeline>, 4> list;  // enqueue, args, shade, resolve
    vkx::Buffer setupBuffer, lightBuffer, counters;
    // The sample list's buffers, for `listPixels` pixels of up to `listSamples` samples each
    // (grown on demand), and its indirect group counts.
    vkx::Buffer listEntries, listColours, listBases, listArgs;
    // Bound for the ambient occlusion when a G-buffer has none (setup.useAo = 0: never read).
    vkx::Image aoStandIn;
    vk::raii::ImageView aoStandInView{nullptr};
    std::size_t listPixels = 0, listSamples = 0;
    std::unique_ptr<vkx::GpuTimer> timer;
    bool profiling = false;
    // Scratch of one image size: S, k, the metrics.
    struct Scratch {
        int w = 0, h = 0;
        vkx::Image first, k, metrics;
    } scratch;

    Impl(std::shared_ptr<vkx::Context> context, const scene::Scene& scene, Sampling s)
        : ctx(std::move(context)), lookup(s) {
        if (!ctx) throw Error("gpu::AdaptiveShading: no Vulkan context");
        vkx::Context& c = *ctx;
        if (!c.pushDescriptors)
            throw Error(
                "gpu::AdaptiveShading: the device has no VK_KHR_push_descriptor (the passes push their "
                "descriptors)");
        if (!c.computeSubgroupOps(vk::SubgroupFeatureFlagBits::eArithmetic | vk::SubgroupFeatureFlagBits::eBallot))
            throw Error(
                "gpu::AdaptiveShading: the device has no subgroup arithmetic and ballot in compute shaders (the rest "
                "pass counts its idle lanes with them; the sample list reserves its ranges with them)");
        scene.validate();
        lights = scene.lights;
        ambient = scene.ambient;
        background = scene.background;
        materialCount = scene.materials.size();
        layerCount = scene.textures.layers.size();
        vkx::guarded("creating the GPU adaptive shading", [&] {
            std::vector<MaterialData> mats;
            for (const auto& m : scene.materials)
                mats.push_back({glm::vec4(m.diffuse, 1.0f), glm::ivec4(m.textureLayer, 0, 0, 0)});
            if (mats.empty()) mats.push_back({});
            materials = c.uploadBuffer(mats.data(), mats.size() * sizeof(MaterialData),
                                       vk::BufferUsageFlagBits::eStorageBuffer);
            uploadTexels(scene.textures);
            textures = render::uploadTextureArray(c, scene.textures);
            nearest = vk::raii::Sampler(
                c.device,
                vk::SamplerCreateInfo({}, vk::Filter::eNearest, vk::Filter::eNearest, vk::SamplerMipmapMode::eNearest,
                                      vk::SamplerAddressMode::eClampToEdge, vk::SamplerAddressMode::eClampToEdge,
                                      vk::SamplerAddressMode::eClampToEdge, 0.0f, false, 1.0f, false,
                                      vk::CompareOp::eNever, 0.0f, VK_LOD_CLAMP_NONE));
            first = make(kFirst, 0);
            for (int v = 0; v < 3; ++v) rest[std::size_t(v)] = make(kRest, v);
            for (int stage = 0; stage < 4; ++stage) list[std::size_t(stage)] = make(kList, stage);
            listArgs = c.createBuffer(
                16, vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eIndirectBuffer, false);
            setupBuffer = c.createBuffer(sizeof(DeferredSetup), vk::BufferUsageFlagBits::eStorageBuffer, true);
            counters = c.createBuffer(
                16, vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferDst, true);
            timer = std::make_unique<vkx::GpuTimer>(c, 7);
            aoStandIn = c.createImage(F::eR32Sfloat, 1, 1,
                                      vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst,
                                      vk::ImageAspectFlagBits::eColor);
            aoStandInView = view2d(c, aoStandIn);
            c.submit([&](const vk::raii::CommandBuffer& cmd) {
                vkx::transition(cmd, aoStandIn, L::eUndefined, L::eTransferDstOptimal, S::eTopOfPipe, {}, S::eTransfer,
                                A::eTransferWrite);
                cmd.clearColorImage(*aoStandIn.image, L::eTransferDstOptimal,
                                    vk::ClearColorValue(1.0f, 1.0f, 1.0f, 1.0f),
                                    vk::ImageSubresourceRange(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1));
                vkx::transition(cmd, aoStandIn, L::eTransferDstOptimal, L::eShaderReadOnlyOptimal, S::eTransfer,
                                A::eTransferWrite, S::eComputeShader, A::eShaderRead);
            });
        });
    }

    // A pass's pipeline: specialization constants 0 (the lookup) and 1 (`variant`: the rest
    // pass's variant, the list's stage, the evaluate pass's m).
    std::unique_ptr<vkx::ComputePipeline> make(std::span<const std::uint32_t> spirv, std::int32_t variant) const {
        const std::array<std::int32_t, 2> values{lookup == Sampling::Hardware ? 1 : 0, variant};
        const std::array<vk::SpecializationMapEntry, 2> entries{vk::SpecializationMapEntry(0, 0, 4),
                                                                vk::SpecializationMapEntry(1, 4, 4)};
        const vk::SpecializationInfo info(2, entries.data(), sizeof(values), values.data());
        return std::make_unique<vkx::ComputePipeline>(*ctx, spirv, kBindings, 0, &info, true);
    }

    // The model's texel buffer: level l of every layer after the previous levels, RGBA8 in one
    // uint per texel (the bytes as stored: r in the low byte).
    void uploadTexels(const scene::TextureArray& t) {
        levelCount = t.levelCount();
        textureSize = std::max(1, t.size);
        if (levelCount > 16) throw Error(fmt::format("gpu::AdaptiveShading: {} mip levels (at most 16)", levelCount));
        std::vector<std::uint32_t> words;
        for (int l = 0; l < levelCount; ++l) {
            const int size = t.layers[0][std::size_t(l)].width();
            levels[std::size_t(l)] = {int(words.size()), size, 0, 0};
            for (const auto& layer : t.layers) {
                const ImageRgba8& img = layer[std::size_t(l)];
                for (const Rgba8& p : img.pixels())
                    words.push_back(std::uint32_t(p.r) | std::uint32_t(p.g) << 8 | std::uint32_t(p.b) << 16 |
                                    std::uint32_t(p.a) << 24);
            }
        }
        if (words.empty()) words.push_back(0);
        texels = ctx->uploadBuffer(words.data(), words.size() * sizeof(std::uint32_t),
                                   vk::BufferUsageFlagBits::eStorageBuffer);
    }

    const vk::raii::Sampler& hardwareSampler(int maxAnisotropy) {
        if (hardwareAnisotropy != maxAnisotropy) {
            const vkx::Context& c = *ctx;
            const bool aniso = c.anisotropy && maxAnisotropy > 1;
            hardware = vk::raii::Sampler(
                c.device, vk::SamplerCreateInfo({}, vk::Filter::eLinear, vk::Filter::eLinear,
                                                vk::SamplerMipmapMode::eLinear, vk::SamplerAddressMode::eRepeat,
                                                vk::SamplerAddressMode::eRepeat, vk::SamplerAddressMode::eRepeat, 0.0f,
                                                aniso, aniso ? std::min(float(maxAnisotropy), c.maxAnisotropy) : 1.0f,
                                                false, vk::CompareOp::eAlways, 0.0f, VK_LOD_CLAMP_NONE));
            hardwareAnisotropy = maxAnisotropy;
        }
        return hardware;
    }

    // The sample list's buffers for a w x h image of n samples per pixel (every sample at worst).
    void ensureList(int w, int h, int n) {
        const std::size_t pixels = std::size_t(w) * std::size_t(h), samples = std::size_t(n);
        if (pixels <= listPixels && samples <= listSamples) return;
        listPixels = std::max(listPixels, pixels), listSamples = std::max(listSamples, samples);
        const vk::DeviceSize most = vk::DeviceSize(listPixels) * listSamples;
        const auto usage = vk::BufferUsageFlagBits::eStorageBuffer;
        listEntries = ctx->createBuffer(most * 4, usage, false);
        listColours = ctx->createBuffer(most * 16, usage, false);
        listBases = ctx->createBuffer(vk::DeviceSize(listPixels) * 4, usage, false);
    }

    void ensureScratch(int w, int h) {
        if (scratch.w == w && scratch.h == h) return;
        vkx::Context& c = *ctx;
        const auto usage = vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eTransferSrc;
        const auto uw = std::uint32_t(w), uh = std::uint32_t(h);
        scratch.first = c.createImage(kColorFormat, uw, uh, usage, vk::ImageAspectFlagBits::eColor);
        scratch.k = c.createImage(kKFormat, uw, uh, usage, vk::ImageAspectFlagBits::eColor);
        scratch.metrics = c.createImage(kColorFormat, uw, uh, usage, vk::ImageAspectFlagBits::eColor);
        scratch.w = w, scratch.h = h;
    }

    // lavapipe ends every loop of an invocation silently once its loops together have run
    // 65535 iterations (vkx::Context::maxShaderLoopIterations): a run whose pixels may need
    // more is refused rather than shaded wrong. Per shaded sample at most: the stall's
    // iterations (16 steps each, deferred.glsl), the lights, the quad's boundary test (6), the
    // model's anisotropic probes and the sample loop's own; per pixel m^2 samples (brute
    // force, or k = m^2), and a margin for the tiled ranking and the loops a compiler keeps.
    void checkLoopBudget(int m, const deferred::ShadingParams& sp, int lightCount) const {
        const std::int64_t budget = ctx->maxShaderLoopIterations;
        if (budget == 0) return;
        const std::int64_t n = std::int64_t(m) * m, margin = 128;
        const std::int64_t perSample = 6 + lightCount + sp.maxAnisotropy + 16 + 1;  // + 15: the stall's rest
        const std::int64_t needed = n * (sp.stall / 16 + perSample) + margin;
        if (needed <= budget) return;
        const std::int64_t most = std::max<std::int64_t>(0, 16 * ((budget - margin) / n - perSample));
        throw Error(fmt::format(
            "stall {}: on {} a shader invocation runs at most {} loop iterations in all (Mesa's loop limiter; past "
            "it the results are wrong), and a pixel of this run may need {} (m = {}, {} lights); at m = {} the "
            "stall can be at most {}",
            sp.stall, ctx->info.name, budget, needed, m, lightCount, m, most));
    }

    // The setup block of one run.
    void writeSetup(const DeviceGBuffer& g, const deferred::ShadingParams& sp, const deferred::AdaptiveParams* ap) {
        const int sw = g.m * g.width, sh = g.m * g.height;
        const Projection proj = projection(g.camera, sw, sh);  // (checks the camera)
        DeferredSetup s{};
        s.width = g.width, s.height = g.height, s.m = g.m, s.n = g.m * g.m;
        s.sampleW = sw, s.sampleH = sh;
        s.maxAnisotropy = sp.maxAnisotropy, s.stall = sp.stall;
        s.textureSize = textureSize, s.levelCount = levelCount;
        s.useAo = g.ambientOcclusion.view ? 1 : 0;
        if (ap) {
            s.cDepth = ap->cDepth, s.cNormal = ap->cNormal, s.cShading = ap->cShading;
            s.tMin = ap->tMin, s.tEdge = ap->tEdge;
        }
        s.specular = sp.specular, s.shininess = sp.shininess;
        s.p00 = proj.p00, s.p11 = proj.p11;
        const auto c0 = pairOf(proj.c0), c1 = pairOf(proj.c1), c2 = pairOf(proj.c2);
        s.c0Hi = c0[0], s.c0Lo = c0[1], s.c1Hi = c1[0], s.c1Lo = c1[1], s.c2Hi = c2[0], s.c2Lo = c2[1];
        s.ambient = glm::vec4(ambient, 0.0f), s.background = glm::vec4(background, 0.0f);
        const auto order = deferred::ditherOrder(g.m);
        for (std::size_t i = 0; i < order.size(); ++i) s.order[i] = {order[i][0], order[i][1], 0, 0};
        s.level = levels;
        std::vector<LightData> data;
        for (const deferred::CameraLight& l : deferred::cameraLights(lights, g.view))
            data.push_back({glm::vec4(l.vector, l.point ? 1.0f : 0.0f), glm::vec4(l.color, 0.0f)});
        s.lightCount = int(data.size());
        checkLoopBudget(g.m, sp, s.lightCount);
        if (data.empty()) data.push_back({});
        const vk::DeviceSize bytes = data.size() * sizeof(LightData);
        if (lightBuffer.size < bytes)
            lightBuffer = ctx->createBuffer(bytes, vk::BufferUsageFlagBits::eStorageBuffer, true);
        std::memcpy(lightBuffer.mapped, data.data(), bytes);
        std::memcpy(setupBuffer.mapped, &s, sizeof(s));
    }

    // The passes: first, evaluate and rest (or brute force), with the barriers between them.
    void recordPasses(const vk::raii::CommandBuffer& cmd, const DeviceGBuffer& g, int variant, int maxAnisotropy,
                      vk::ImageView output) {
        const auto w = std::uint32_t(g.width), h = std::uint32_t(g.height);
        ensureScratch(g.width, g.height);
        for (vkx::Image* img : {&scratch.first, &scratch.k, &scratch.metrics})
            vkx::transition(cmd, *img, L::eUndefined, L::eGeneral, S::eComputeShader, {}, S::eComputeShader,
                            A::eShaderRead | A::eShaderWrite);
        cmd.fillBuffer(*counters.buffer, 0, VK_WHOLE_SIZE, 0u);
        const vk::MemoryBarrier filled(A::eTransferWrite, A::eShaderRead | A::eShaderWrite);
        cmd.pipelineBarrier(S::eTransfer, S::eComputeShader, {}, filled, {}, {});

        const vk::Sampler texSampler = *hardwareSampler(lookup == Sampling::Hardware ? maxAnisotropy : 1);
        const vk::DescriptorBufferInfo bufs[] = {{*setupBuffer.buffer, 0, VK_WHOLE_SIZE},
                                                 {*lightBuffer.buffer, 0, VK_WHOLE_SIZE},
                                                 {*materials.buffer, 0, VK_WHOLE_SIZE},
                                                 {*texels.buffer, 0, VK_WHOLE_SIZE},
                                                 {*counters.buffer, 0, VK_WHOLE_SIZE}};
        const vk::DescriptorImageInfo sampled[] = {
            {texSampler, *textures.view, L::eShaderReadOnlyOptimal},
            {*nearest, g.depth.view, g.depth.layout},
            {*nearest, g.normal.view, g.normal.layout},
            {*nearest, g.uv.view, g.uv.layout},
            {*nearest, g.uvGrad.view, g.uvGrad.layout},
            {*nearest, g.ids.view, g.ids.layout},
            g.ambientOcclusion.view
                ? vk::DescriptorImageInfo(*nearest, g.ambientOcclusion.view, g.ambientOcclusion.layout)
                : vk::DescriptorImageInfo(*nearest, *aoStandInView, L::eShaderReadOnlyOptimal)};
        const vk::DescriptorImageInfo storage[] = {{nullptr, *scratch.first.view, L::eGeneral},
                                                   {nullptr, *scratch.k.view, L::eGeneral},
                                                   {nullptr, *scratch.metrics.view, L::eGeneral},
                                                   {nullptr, output, L::eGeneral}};
        std::vector<vk::WriteDescriptorSet> writes;
        for (std::uint32_t b = 0; b < 4; ++b) writes.push_back({{}, b, 0, Desc::eStorageBuffer, {}, bufs[b]});
        for (std::uint32_t b = 0; b < 6; ++b) writes.push_back({{}, 4 + b, 0, Desc::eCombinedImageSampler, sampled[b]});
        for (std::uint32_t b = 0; b < 4; ++b) writes.push_back({{}, 10 + b, 0, Desc::eStorageImage, storage[b]});
        writes.push_back({{}, 14, 0, Desc::eStorageBuffer, {}, bufs[4]});
        writes.push_back({{}, 19, 0, Desc::eCombinedImageSampler, sampled[6]});
        const bool sampleList = variant == kSampleList;
        vk::DescriptorBufferInfo listBufs[4];
        if (sampleList) {
            ensureList(g.width, g.height, g.m * g.m);
            const vk::Buffer listBuffers[] = {*listEntries.buffer, *listColours.buffer, *listBases.buffer,
                                              *listArgs.buffer};
            for (std::size_t b = 0; b < 4; ++b)
                listBufs[b] = vk::DescriptorBufferInfo(listBuffers[b], 0, VK_WHOLE_SIZE);
            for (std::uint32_t b = 0; b < 4; ++b)
                writes.push_back({{}, 15 + b, 0, Desc::eStorageBuffer, {}, listBufs[b]});
        }

        const std::uint32_t gx = vkx::groupCount(w, kGroup), gy = vkx::groupCount(h, kGroup);
        auto pass = [&](const vkx::ComputePipeline& p, std::uint32_t interval) {
            if (profiling) timer->begin(cmd, interval, S::eComputeShader);
            p.dispatchPushed(cmd, writes, nullptr, gx, gy);
            if (profiling) timer->end(cmd, interval, S::eComputeShader);
            vkx::computeBarrier(cmd, S::eComputeShader, A::eShaderRead | A::eShaderWrite);
        };
        // Timer intervals: first 1, evaluate 2, rest 3; brute force 1.
        if (variant != kBruteForce) {
            pass(*first, 1);
            auto& evaluateM = evaluate[std::size_t(g.m)];
            if (!evaluateM) evaluateM = make(kEvaluate, g.m);
            pass(*evaluateM, 2);
        }
        if (!sampleList) {
            pass(*rest[std::size_t(variant)], variant == kBruteForce ? 1 : 3);
            return;
        }
        // The sample list: enqueue, its group counts, the samples (indirect), the resolve;
        // timer intervals 4, 5 and 6 inside 3: enqueue, shade, resolve.
        auto timed = [&](std::uint32_t interval, auto&& dispatch) {
            if (profiling) timer->begin(cmd, interval, S::eComputeShader);
            dispatch();
            if (profiling) timer->end(cmd, interval, S::eComputeShader);
        };
        if (profiling) timer->begin(cmd, 3, S::eComputeShader);
        timed(4, [&] { list[0]->dispatchPushed(cmd, writes, nullptr, gx, gy); });
        vkx::computeBarrier(cmd, S::eComputeShader, A::eShaderRead | A::eShaderWrite);
        list[1]->dispatchPushed(cmd, writes, nullptr, 1);
        vkx::computeBarrier(cmd, S::eComputeShader | S::eDrawIndirect, A::eShaderRead | A::eIndirectCommandRead);
        timed(5, [&] { list[2]->dispatchPushedIndirect(cmd, writes, nullptr, *listArgs.buffer); });
        vkx::computeBarrier(cmd, S::eComputeShader, A::eShaderRead | A::eShaderWrite);
        timed(6, [&] { list[3]->dispatchPushed(cmd, writes, nullptr, gx, gy); });
        if (profiling) timer->end(cmd, 3, S::eComputeShader);
        vkx::computeBarrier(cmd, S::eComputeShader, A::eShaderRead | A::eShaderWrite);
    }

    // Uploads a host G-buffer, runs, reads back.
    GpuDeferredResult run(const scene::GBuffer& g, const deferred::ShadingParams& sp,
                          const deferred::AdaptiveParams* ap, Schedule schedule) {
        deferred::validateGBuffer(g, materialCount, layerCount);
        if (g.m < 1 || g.m > 4) throw Error(fmt::format("deferred: G-buffer supersampling m = {} is not in 1..4", g.m));
        vkx::Context& c = *ctx;
        const auto sw = std::uint32_t(g.sampleWidth()), sh = std::uint32_t(g.sampleHeight());
        c.requireImageSize(sw, sh, "gpu::AdaptiveShading sample grid");
        const auto w = std::uint32_t(g.width), h = std::uint32_t(g.height);
        const std::size_t n = std::size_t(sw) * sh, pixels = std::size_t(w) * h;
        GpuDeferredResult r;
        vkx::guarded("running the GPU adaptive shading", [&] {
            // The planes, in the formats that hold the host's values exactly.
            struct Plane {
                F format;
                std::size_t bytes;  // per texel
                const void* data;
                std::uint32_t width, height;
            };
            std::vector<std::uint32_t> ids(n);
            std::vector<glm::vec4> normals(n);
            for (std::size_t i = 0; i < n; ++i) {
                ids[i] = std::uint32_t(g.material[i]) | std::uint32_t(std::uint16_t(g.layer[i])) << 16;
                normals[i] = glm::vec4(g.normal[i], 0.0f);
            }
            std::vector<Plane> planes{{F::eR32Sfloat, 4, g.depth.data(), sw, sh},
                                      {F::eR32G32B32A32Sfloat, 16, normals.data(), sw, sh},
                                      {F::eR32G32Sfloat, 8, g.uv.data(), sw, sh},
                                      {F::eR32G32B32A32Sfloat, 16, g.uvGrad.data(), sw, sh},
                                      {F::eR16G16Uint, 4, ids.data(), sw, sh}};
            const bool occlusion = !g.ambientOcclusion.empty();
            if (occlusion) planes.push_back({F::eR32Sfloat, 4, g.ambientOcclusion.data(), w, h});
            // Each plane at a multiple of 16 bytes (a copy's offset is a multiple of its texel size).
            auto aligned = [](vk::DeviceSize v) { return (v + 15) & ~vk::DeviceSize(15); };
            auto planeBytes = [](const Plane& p) { return vk::DeviceSize(p.bytes) * p.width * p.height; };
            vk::DeviceSize total = 0;
            for (const Plane& p : planes) total += aligned(planeBytes(p));
            vkx::Buffer upload = c.createBuffer(total, vk::BufferUsageFlagBits::eTransferSrc, true);
            std::vector<vkx::Image> images;
            std::vector<vk::raii::ImageView> views;
            std::vector<vk::DeviceSize> offsets;
            vk::DeviceSize offset = 0;
            for (const Plane& p : planes) {
                std::memcpy(static_cast<std::uint8_t*>(upload.mapped) + offset, p.data, planeBytes(p));
                offsets.push_back(offset);
                offset += aligned(planeBytes(p));
                images.push_back(c.createImage(p.format, p.width, p.height,
                                               vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst,
                                               vk::ImageAspectFlagBits::eColor));
                views.push_back(view2d(c, images.back()));
            }
            const auto outUsage = vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eTransferSrc;
            vkx::Image out = c.createImage(kColorFormat, w, h, outUsage, vk::ImageAspectFlagBits::eColor);
            const bool adaptive = ap != nullptr;
            // Read back: the output, and for the adaptive method k and the metrics.
            vkx::Buffer down =
                c.createBuffer(pixels * (adaptive ? 36 : 16), vk::BufferUsageFlagBits::eTransferDst, true);

            DeviceGBuffer dg;
            const auto sampled = vk::ImageUsageFlagBits::eSampled;
            auto ref = [&](std::size_t i) {
                return ImageRef{*views[i],       planes[i].format, sampled,
                                planes[i].width, planes[i].height, L::eShaderReadOnlyOptimal};
            };
            dg.depth = ref(0), dg.normal = ref(1), dg.uv = ref(2), dg.uvGrad = ref(3), dg.ids = ref(4);
            if (occlusion) dg.ambientOcclusion = ref(5);
            dg.width = g.width, dg.height = g.height, dg.m = g.m;
            dg.camera = g.camera.camera, dg.view = g.camera.view;
            writeSetup(dg, sp, ap);
            const int variant = !adaptive ? kBruteForce : variantOf(schedule, *ap);

            c.submit([&](const vk::raii::CommandBuffer& cmd) {
                for (std::size_t i = 0; i < images.size(); ++i) {
                    vkx::transition(cmd, images[i], L::eUndefined, L::eTransferDstOptimal, S::eTopOfPipe, {},
                                    S::eTransfer, A::eTransferWrite);
                    cmd.copyBufferToImage(
                        *upload.buffer, *images[i].image, L::eTransferDstOptimal,
                        vk::BufferImageCopy(offsets[i], 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1}, {0, 0, 0},
                                            {planes[i].width, planes[i].height, 1}));
                    vkx::transition(cmd, images[i], L::eTransferDstOptimal, L::eShaderReadOnlyOptimal, S::eTransfer,
                                    A::eTransferWrite, S::eComputeShader, A::eShaderRead);
                }
                vkx::transition(cmd, out, L::eUndefined, L::eGeneral, S::eTopOfPipe, {}, S::eComputeShader,
                                A::eShaderWrite);
                timer->reset(cmd);
                timer->begin(cmd, 0, S::eComputeShader);
                profiling = true;
                struct NotProfiling {
                    Impl& p;
                    ~NotProfiling() { p.profiling = false; }
                } notProfiling{*this};
                recordPasses(cmd, dg, variant, sp.maxAnisotropy, *out.view);
                timer->end(cmd, 0, S::eComputeShader);
                // Read back (the passes' barrier made their writes visible to compute; the
                // copies need their own).
                const vk::MemoryBarrier toCopy(A::eShaderWrite, A::eTransferRead);
                cmd.pipelineBarrier(S::eComputeShader, S::eTransfer, {}, toCopy, {}, {});
                auto copy = [&](const vkx::Image& img, vk::DeviceSize at) {
                    vkx::transition(cmd, img, L::eGeneral, L::eTransferSrcOptimal, S::eComputeShader, A::eShaderWrite,
                                    S::eTransfer, A::eTransferRead);
                    cmd.copyImageToBuffer(*img.image, L::eTransferSrcOptimal, *down.buffer,
                                          vk::BufferImageCopy(at, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1},
                                                              {0, 0, 0}, {w, h, 1}));
                };
                copy(out, 0);
                if (adaptive) {
                    copy(scratch.metrics, pixels * 16);  // (offsets: multiples of the texel sizes)
                    copy(scratch.k, pixels * 32);
                }
                const vk::MemoryBarrier toHost(A::eTransferWrite | A::eShaderWrite, A::eHostRead);
                cmd.pipelineBarrier(S::eTransfer | S::eComputeShader, S::eHost, {}, toHost, {}, {});
            });
            const bool listed = variant == kSampleList;
            const auto ms = timer->milliseconds(listed ? 7 : adaptive ? 4 : 2);
            if (adaptive)
                r.firstMs = ms[1], r.evaluateMs = ms[2], r.restMs = ms[3];
            else
                r.restMs = ms[1];
            if (listed) r.listEnqueueMs = ms[4], r.listShadeMs = ms[5], r.listResolveMs = ms[6];
            const auto* colour = static_cast<const glm::vec4*>(down.mapped);
            r.image = deferred::ImageRgbF(int(w), int(h));
            for (std::size_t i = 0; i < pixels; ++i) r.image.pixels[i] = glm::vec3(colour[i]);
            const int samples = g.m * g.m;
            r.samples = Image<std::uint8_t>(int(w), int(h), std::uint8_t(samples));
            if (adaptive) {
                const auto* k =
                    reinterpret_cast<const std::uint32_t*>(static_cast<const std::uint8_t*>(down.mapped) + pixels * 32);
                const auto* metric =
                    reinterpret_cast<const glm::vec4*>(static_cast<const std::uint8_t*>(down.mapped) + pixels * 16);
                r.kDepth = ImageF(int(w), int(h)), r.kNormal = ImageF(int(w), int(h));
                r.kShading = ImageF(int(w), int(h));
                for (std::size_t i = 0; i < pixels; ++i) {
                    r.samples.data()[i] = std::uint8_t(k[i]);
                    r.kDepth.data()[i] = metric[i].x, r.kNormal.data()[i] = metric[i].y;
                    r.kShading.data()[i] = metric[i].z;
                }
            }
            const auto* count = static_cast<const std::uint32_t*>(counters.mapped);
            r.busyLanes = count[0], r.issuedLanes = count[1], r.subgroupSize = int(count[2]);
            r.possible = std::int64_t(pixels) * samples;
            r.shaded = std::int64_t(count[0]) + (adaptive ? std::int64_t(pixels) : 0);
        });
        return r;
    }
};

AdaptiveShading::AdaptiveShading(std::shared_ptr<vkx::Context> ctx, const scene::Scene& scene, Sampling lookup)
    : impl_(std::make_unique<Impl>(std::move(ctx), scene, lookup)) {}

AdaptiveShading::~AdaptiveShading() = default;

Sampling AdaptiveShading::lookup() const { return impl_->lookup; }

GpuDeferredResult AdaptiveShading::adaptive(const scene::GBuffer& gbuffer, const deferred::AdaptiveParams& params,
                                            Schedule schedule) {
    deferred::validate(params);
    return impl_->run(gbuffer, params.shading, &params, schedule);
}

GpuDeferredResult AdaptiveShading::bruteForce(const scene::GBuffer& gbuffer, const deferred::ShadingParams& params) {
    deferred::validate(params);
    return impl_->run(gbuffer, params, nullptr, Schedule::FromParams);
}

ImageRef imageRef(const render::DeviceImage& d) {
    return ImageRef{d.view, d.format, d.usage, d.width, d.height, d.layout};
}

DeviceGBuffer deviceGBuffer(const render::DeviceGBufferImages& images) {
    DeviceGBuffer g;
    g.depth = imageRef(images.depth), g.normal = imageRef(images.normal), g.uv = imageRef(images.uv);
    g.uvGrad = imageRef(images.uvGrad), g.ids = imageRef(images.ids);
    g.width = images.width, g.height = images.height, g.m = images.m;
    g.camera = images.camera.camera, g.view = images.camera.view;
    return g;
}

void AdaptiveShading::record(const vk::raii::CommandBuffer& cmd, const DeviceGBuffer& g,
                             const deferred::AdaptiveParams& params, const ImageRef& output, Schedule schedule) {
    deferred::validate(params);
    if (g.m < 1 || g.m > 4) throw Error(fmt::format("gpu::AdaptiveShading: m = {} is not in 1..4", g.m));
    checkDimensions(g.width, g.height, "gpu::AdaptiveShading image");
    const auto sw = std::uint32_t(g.m * g.width), sh = std::uint32_t(g.m * g.height);
    impl_->ctx->requireImageSize(sw, sh, "gpu::AdaptiveShading sample grid");
    checkPlane(g.depth, "depth", {F::eD32Sfloat, F::eR32Sfloat}, sw, sh);
    checkPlane(g.normal, "normal", {F::eR16G16B16A16Snorm, F::eR32G32B32A32Sfloat}, sw, sh);
    checkPlane(g.uv, "uv", {F::eR32G32Sfloat}, sw, sh);
    checkPlane(g.uvGrad, "uv gradient", {F::eR32G32B32A32Sfloat}, sw, sh);
    checkPlane(g.ids, "ids", {F::eR16G16Uint}, sw, sh);
    if (g.ambientOcclusion.view)
        checkPlane(g.ambientOcclusion, "ambient occlusion", {F::eR32Sfloat}, std::uint32_t(g.width),
                   std::uint32_t(g.height));
    if (!output.view || output.format != kColorFormat || !(output.usage & vk::ImageUsageFlagBits::eStorage) ||
        output.layout != L::eGeneral)
        throw Error(
            "gpu::AdaptiveShading: the output must be an R32G32B32A32_SFLOAT view with STORAGE usage in "
            "layout GENERAL");
    if (output.width != std::uint32_t(g.width) || output.height != std::uint32_t(g.height))
        throw Error(fmt::format("gpu::AdaptiveShading: output is {}x{}, expected {}x{}", output.width, output.height,
                                g.width, g.height));
    vkx::guarded("recording the GPU adaptive shading", [&] {
        impl_->writeSetup(g, params.shading, &params);
        impl_->recordPasses(cmd, g, variantOf(schedule, params), params.shading.maxAnisotropy, output.view);
    });
}

}  // namespace ssfx::gpu
