// SAO and AlchemyAO as Vulkan compute passes (ssfx/gpu/ao.hpp; docs/gpu.md).
#include "ssfx/gpu/ao.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <iterator>
#include <optional>

#include "src/gpu/shaders/ao/ao_constants.h"
#include "src/gpu/shaders/ao/gtao_constants.h"
#include "ssfx/core/error.hpp"
#include "ssfx/vk/compute.hpp"
#include "ssfx/vk/timer.hpp"

namespace ssfx::gpu {

namespace detail {

// The shared header's promise: member i at byte 4 i, in C++ as in GLSL's std430.
#define SSFX_AO_OFFSET(type, name) offsetof(AoConstants, name),
#define SSFX_AO_SIZE(type, name) sizeof(type),
constexpr std::size_t kAoOffsets[] = {SSFX_AO_CONSTANTS(SSFX_AO_OFFSET)};
constexpr std::size_t kAoSizes[] = {SSFX_AO_CONSTANTS(SSFX_AO_SIZE)};
#undef SSFX_AO_OFFSET
#define SSFX_AO_OFFSET(type, name) offsetof(AoTables, name),
constexpr std::size_t kTableOffsets[] = {SSFX_AO_PARAMS(SSFX_AO_OFFSET)};
#undef SSFX_AO_OFFSET
constexpr bool aoMembersInOrder() {
    for (std::size_t i = 0; i < std::size(kAoOffsets); ++i)
        if (kAoOffsets[i] != 4 * i || kAoSizes[i] != 4) return false;
    for (std::size_t i = 0; i < std::size(kTableOffsets); ++i)
        if (kTableOffsets[i] != 4 * i) return false;
    return true;
}
static_assert(aoMembersInOrder(), "AoConstants, AoTables: 4-byte scalars in order (std430)");
static_assert(sizeof(AoConstants) == 4 * std::size(kAoOffsets), "AoConstants: no padding");
static_assert(sizeof(AoConstants) <= 128, "AoConstants: within the guaranteed push-constant size");
static_assert(offsetof(AoTables, alpha) == 4 * std::size(kTableOffsets) &&
                  sizeof(AoTables) == 4 * (std::size(kTableOffsets) + 4 * SSFX_AO_MAX_TAPS + 2 * SSFX_AO_MAX_BLUR_TAPS),
              "AoTables: float arrays after the scalars, no padding (std430)");

#define SSFX_GTAO_OFFSET(type, name) offsetof(GtaoTables, name),
constexpr std::size_t kGtaoOffsets[] = {SSFX_GTAO_PARAMS(SSFX_GTAO_OFFSET)};
#undef SSFX_GTAO_OFFSET
constexpr bool gtaoMembersInOrder() {
    for (std::size_t i = 0; i < std::size(kGtaoOffsets); ++i)
        if (kGtaoOffsets[i] != 4 * i) return false;
    return true;
}
static_assert(gtaoMembersInOrder() && offsetof(GtaoTables, noise) == 4 * std::size(kGtaoOffsets) &&
                  sizeof(GtaoTables) == 4 * (std::size(kGtaoOffsets) + SSFX_GTAO_NOISE),
              "GtaoTables: 4-byte scalars in order, then the noise (std430)");

#define SSFX_AO_SPEC_ENTRY(id, name, value) vk::SpecializationMapEntry(id, offsetof(AoSpecialization, name), 4),
const vk::SpecializationMapEntry kAoSpecEntries[] = {SSFX_AO_SPECIALIZATION(SSFX_AO_SPEC_ENTRY)};
#undef SSFX_AO_SPEC_ENTRY
static_assert(sizeof(AoSpecialization) == 4 * std::size(kAoSpecEntries), "AoSpecialization: no padding");

}  // namespace detail

namespace {

using detail::AoConstants;
using detail::AoSpecialization;
using detail::AoTables;
using detail::GtaoTables;

const std::uint32_t kDepthToZ[] = {
#include "shaders/depth_to_z.comp.inc"
};
const std::uint32_t kZPyramid[] = {
#include "shaders/z_pyramid.comp.inc"
};
const std::uint32_t kAoSample[] = {
#include "shaders/ao_sample.comp.inc"
};
const std::uint32_t kQuadBilateral[] = {
#include "shaders/quad_bilateral.comp.inc"
};
const std::uint32_t kBilateral[] = {
#include "shaders/bilateral.comp.inc"
};
const std::uint32_t kGtaoChain[] = {
#include "shaders/gtao_chain.comp.inc"
};
const std::uint32_t kGtaoEdges[] = {
#include "shaders/gtao_edges.comp.inc"
};
const std::uint32_t kGtaoMain[] = {
#include "shaders/gtao_main.comp.inc"
};
const std::uint32_t kGtaoDenoise[] = {
#include "shaders/gtao_denoise.comp.inc"
};

using S = vk::PipelineStageFlagBits;
using A = vk::AccessFlagBits;
using L = vk::ImageLayout;
using Desc = vk::DescriptorType;

constexpr vk::Format kZFormat = vk::Format::eR32Sfloat;
constexpr vk::Format kOutputFormat = vk::Format::eR32Sfloat;
constexpr vk::Format kNormalFormat = vk::Format::eR32G32B32A32Sfloat;  // GTAO's normals

bool depthFormatOk(vk::Format f) {
    return f == vk::Format::eD16Unorm || f == vk::Format::eX8D24UnormPack32 || f == vk::Format::eD24UnormS8Uint ||
           f == vk::Format::eD32Sfloat || f == vk::Format::eD32SfloatS8Uint;
}
bool depthLayoutOk(vk::ImageLayout l) {
    return l == L::eDepthStencilReadOnlyOptimal || l == L::eDepthReadOnlyOptimal || l == L::eShaderReadOnlyOptimal ||
           l == L::eGeneral;
}

std::uint32_t groups(int n) { return vkx::groupCount(std::uint32_t(n), SSFX_AO_GROUP); }

// What either method needs from its params: the pipeline's shape, the tables and the
// specializations.
struct AoConfig {
    const char* name;
    bool sao = true;  // false: AlchemyAO (no pyramid, no quad pass, its own estimator)
    int guardBand = 0;
    int levels = 0;  // pyramid levels above 0
    ao::PyramidFilter filter = ao::PyramidFilter::RotatedGrid;
    float radius = 1;
    int packing = 0;  // 0 none, 1 packBlurInput, 2 releasedPacking
    bool spinInFloat = false, zeroOutside = false;
    AoTables tables{};
    // GTAO (spec gtao.md): its own passes, params and tables (the projection's part is
    // filled per recording: gtaoConstants depends on the buffer's width).
    bool gtao = false;
    ao::GtaoParams gtaoParams{};
};

void fillTables(AoTables& t, const ao::SampleConstants& k, const ao::BilateralParams& blur) {
    t.r2 = k.r2, t.bias = k.bias, t.epsilon = k.epsilon, t.scale = k.scale, t.scale2 = k.scale2;
    t.exponent = k.exponent;
    t.numSamples = int(k.alpha.size());
    if (t.numSamples > SSFX_AO_MAX_TAPS) throw Error(fmt::format("ao: at most {} samples", SSFX_AO_MAX_TAPS));
    for (std::size_t i = 0; i < k.alpha.size(); ++i) {
        t.alpha[i] = k.alpha[i], t.dirX[i] = k.dirX[i], t.dirY[i] = k.dirY[i];
        t.tapAngle[i] = k.tapAngle.empty() ? 0.0f : k.tapAngle[i];
    }
    const ao::BilateralTaps taps = ao::bilateralTaps(blur);
    t.taps = int(taps.offset.size());
    static_assert(SSFX_AO_MAX_BLUR_TAPS == 2 * 8 + 1, "blurRadius <= 8 (kSaoParams)");
    for (std::size_t i = 0; i < taps.offset.size(); ++i)
        t.blurOffset[i] = float(taps.offset[i]), t.blurWeight[i] = taps.weight[i];
    t.edgeSharpness = blur.edgeSharpness, t.blurEpsilon = blur.blurEpsilon, t.blurStride = blur.blurStride;
}

AoConfig configOf(const ao::SaoParams& p) {
    AoConfig c{"sao"};
    c.guardBand = p.guardBand;
    c.levels = p.usePyramid ? p.maxMip : 0;
    c.filter = p.pyramidFilter;
    c.radius = p.radius;
    c.packing = p.packBlurInput ? (p.releasedPacking ? 2 : 1) : 0;
    c.spinInFloat = p.spinInFloat;
    c.zeroOutside = p.blur.blurZeroOutside;
    fillTables(c.tables, ao::sampleConstants(p), p.blur);  // (validates p)
    c.tables.logQ = p.logQ;
    c.tables.quadThreshold = p.quadThreshold;
    c.tables.packZMin = p.packZMin;
    return c;
}

AoConfig configOf(const ao::AlchemyParams& p) {
    AoConfig c{"alchemy"};
    c.sao = false;
    c.guardBand = p.guardBand;
    c.radius = p.radius;
    c.zeroOutside = p.blur.blurZeroOutside;
    fillTables(c.tables, ao::sampleConstants(p), p.blur);
    return c;
}

AoConfig configOf(const ao::GtaoParams& p) {
    ao::validate(p);
    AoConfig c{"gtao"};
    c.sao = false;
    c.gtao = true;
    c.guardBand = p.guardBand;
    c.levels = 4;  // the chain's levels 1..4 (spec section 4)
    c.radius = p.radius;
    c.gtaoParams = p;
    return c;
}

// The GTAO tables (the CPU's GtaoSetup: the same floats; rNum, which depends on the
// buffer's width, is a push constant).
void fillGtaoTables(GtaoTables& t, const ao::GtaoParams& p) {
    const ao::GtaoConstants k = ao::gtaoConstants(p, Projection{});
    t.re = k.re, t.rp = k.rp, t.fRp = k.fRp, t.fRe = k.fRe;
    t.spacingPower = p.sampleDistributionPower, t.finalPower = p.finalValuePower;
    t.mipOffset = p.depthMipSamplingOffset, t.toc1 = 1.0f + p.thinOccluderCompensation, t.thickness = p.thickness;
    t.betaMiddle = 1.2f / 5.0f, t.betaLast = 1.2f;  // XeGTAO's DenoiseBlurBeta and its fifth
    t.slices = p.sliceCount, t.steps = p.stepsPerSlice, t.guard = p.guardBand;
    t.lift = p.projectedNormalLift, t.nearFade = p.nearFade, t.fastAcos = p.fastAcos;
    t.offscreenDiscard = p.offscreen == ao::Offscreen::Discard,
    t.minusOne = p.horizonStart == ao::HorizonStart::MinusOne;
    t.xegtaoStorage = p.xegtaoStorage;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const auto n = ao::gtaoNoise(x, y);
            t.noise[2 * (64 * y + x)] = n[0], t.noise[2 * (64 * y + x) + 1] = n[1];
        }
}

// A 2-D view of one level (or all levels) of an image.
vk::raii::ImageView view2d(const vkx::Context& c, const vkx::Image& img, std::uint32_t level, std::uint32_t count) {
    return vk::raii::ImageView(
        c.device,
        vk::ImageViewCreateInfo({}, *img.image, vk::ImageViewType::e2D, img.format, {},
                                vk::ImageSubresourceRange(vk::ImageAspectFlagBits::eColor, level, count, 0, 1)));
}

}  // namespace

// The pipeline shared by Sao and Alchemy.
class AoPipeline {
public:
    AoPipeline(std::shared_ptr<vkx::Context> ctx, AoConfig config) : ctx_(std::move(ctx)), cfg_(std::move(config)) {
        if (!ctx_) throw Error(fmt::format("gpu::{}: no Vulkan context", cfg_.name));
        vkx::Context& c = *ctx_;
        if (!c.pushDescriptors)
            throw Error(
                fmt::format("gpu::{}: the device has no VK_KHR_push_descriptor (the GPU passes push their "
                            "descriptors)",
                            cfg_.name));
        vkx::guarded("creating the GPU AO passes", [&] {
            sampler_ = vk::raii::Sampler(
                c.device,
                vk::SamplerCreateInfo({}, vk::Filter::eNearest, vk::Filter::eNearest, vk::SamplerMipmapMode::eNearest,
                                      vk::SamplerAddressMode::eClampToEdge, vk::SamplerAddressMode::eClampToEdge,
                                      vk::SamplerAddressMode::eClampToEdge, 0.0f, false, 1.0f, false,
                                      vk::CompareOp::eNever, 0.0f, VK_LOD_CLAMP_NONE));
            tables_ = c.uploadBuffer(&cfg_.tables, sizeof(AoTables), vk::BufferUsageFlagBits::eStorageBuffer);
            const std::uint32_t push = sizeof(AoConstants);
            auto make = [&](std::span<const std::uint32_t> spirv, std::vector<vkx::BindingSpec> bindings,
                            const AoSpecialization& spec) {
                const vk::SpecializationInfo info(std::uint32_t(std::size(detail::kAoSpecEntries)),
                                                  detail::kAoSpecEntries, sizeof(spec), &spec);
                return std::make_unique<vkx::ComputePipeline>(c, spirv, std::move(bindings), push, &info, true);
            };
            AoSpecialization spec{};
            depthToZ_ = make(kDepthToZ, {{Desc::eCombinedImageSampler}, {Desc::eStorageImage}}, spec);
            if (cfg_.gtao) {
                const vkx::BindingSpec img{Desc::eStorageImage}, buf{Desc::eStorageBuffer};
                chain_ = make(kGtaoChain, {img, img, buf}, spec);
                edges_ = make(kGtaoEdges, {img, img, img, buf}, spec);
                main_ = make(kGtaoMain, {{Desc::eCombinedImageSampler}, img, img, buf}, spec);
                denoise_ = make(kGtaoDenoise, {img, img, img, img, buf}, spec);
                auto tables = std::make_unique<GtaoTables>();
                fillGtaoTables(*tables, cfg_.gtaoParams);
                gtaoTables_ = c.uploadBuffer(tables.get(), sizeof(GtaoTables), vk::BufferUsageFlagBits::eStorageBuffer);
                timer_ = std::make_unique<vkx::GpuTimer>(c, 1 + kStages);
                return;
            }
            spec.filter = int(cfg_.filter);
            if (cfg_.levels > 0) pyramid_ = make(kZPyramid, {{Desc::eStorageImage}, {Desc::eStorageImage}}, spec);
            spec.estimator = cfg_.sao ? 0 : 1;
            spec.spinInFloat = cfg_.spinInFloat ? 1 : 0;
            sample_ =
                make(kAoSample, {{Desc::eCombinedImageSampler}, {Desc::eStorageImage}, {Desc::eStorageBuffer}}, spec);
            spec.packing = cfg_.packing;
            if (cfg_.sao)
                quad_ = make(kQuadBilateral,
                             {{Desc::eStorageImage},
                              {Desc::eStorageImage},
                              {Desc::eStorageImage},
                              {Desc::eStorageImage},
                              {Desc::eStorageBuffer}},
                             spec);
            const std::vector<vkx::BindingSpec> blurBindings{
                {Desc::eStorageImage}, {Desc::eStorageImage}, {Desc::eStorageImage}, {Desc::eStorageBuffer}};
            spec.zeroOutside = cfg_.zeroOutside ? 1 : 0;
            spec.horizontal = 1;
            spec.packOutput = cfg_.packing == 2 ? 1 : 0;  // the released horizontal pass stores 8 bits
            blurH_ = make(kBilateral, blurBindings, spec);
            spec.horizontal = 0;
            spec.packOutput = 0;
            blurV_ = make(kBilateral, blurBindings, spec);
            timer_ = std::make_unique<vkx::GpuTimer>(c, 1 + kStages);
        });
    }

    void record(const vk::raii::CommandBuffer& cmd, const ImageRef& depth, const Camera& camera,
                const ImageRef& output) {
        const char* id = cfg_.name;
        if (!depth.view || !output.view)
            throw Error(fmt::format("gpu::{}: record() without a depth or output view", id));
        if (!depthFormatOk(depth.format))
            throw Error(
                fmt::format("gpu::{}: depth format {} (expected D16_UNORM, X8_D24_UNORM_PACK32, "
                            "D24_UNORM_S8_UINT, D32_SFLOAT or D32_SFLOAT_S8_UINT)",
                            id, vk::to_string(depth.format)));
        if (!(depth.usage & vk::ImageUsageFlagBits::eSampled))
            throw Error(fmt::format("gpu::{}: the depth image needs SAMPLED usage", id));
        if (!depthLayoutOk(depth.layout))
            throw Error(
                fmt::format("gpu::{}: depth layout {} (expected DEPTH_STENCIL_READ_ONLY_OPTIMAL, "
                            "DEPTH_READ_ONLY_OPTIMAL, SHADER_READ_ONLY_OPTIMAL or GENERAL)",
                            id, vk::to_string(depth.layout)));
        if (output.format != kOutputFormat)
            throw Error(
                fmt::format("gpu::{}: output format {} (expected R32_SFLOAT)", id, vk::to_string(output.format)));
        if (!(output.usage & vk::ImageUsageFlagBits::eStorage))
            throw Error(fmt::format("gpu::{}: the output image needs STORAGE usage", id));
        if (output.layout != L::eGeneral)
            throw Error(fmt::format("gpu::{}: output layout {} (expected GENERAL)", id, vk::to_string(output.layout)));
        const int w = int(depth.width), h = int(depth.height), g = cfg_.guardBand;
        if (w <= 2 * g || h <= 2 * g)
            throw Error(
                fmt::format("gpu::{}: a {}x{} depth buffer has no pixels inside a guard band of {}", id, w, h, g));
        if (output.width != std::uint32_t(w - 2 * g) || output.height != std::uint32_t(h - 2 * g))
            throw Error(fmt::format("gpu::{}: output is {}x{}, expected {}x{} (the depth's size minus the guard band)",
                                    id, output.width, output.height, w - 2 * g, h - 2 * g));
        ctx_->requireImageSize(depth.width, depth.height, fmt::format("gpu::{} depth", id));
        const Projection proj = projection(camera, w, h);  // (checks the camera)
        vkx::guarded("recording the GPU AO passes", [&] { recordPasses(cmd, depth, proj, camera, output.view); });
    }

    ImageF run(ImageView<const float> depth, const Camera& camera, DepthFormat format, AoStages* stages) {
        vkx::Context& c = *ctx_;
        const char* id = cfg_.name;
        checkDimensions(depth.width(), depth.height(), fmt::format("{} depth", id));
        // The CPU's checks, with its messages: the depth values, then the sizes.
        for (int y = 0; y < depth.height(); ++y)
            for (int x = 0; x < depth.width(); ++x)
                if (const float v = depth(x, y); !(v >= 0.0f && v <= 1.0f))
                    throw Error(fmt::format("depth at pixel ({}, {}) is {}, not in [0, 1]", x, y, v));
        const int g = cfg_.guardBand;
        if (depth.width() <= 2 * g || depth.height() <= 2 * g)
            throw Error(fmt::format("{}: a {}x{} depth buffer has no pixels inside a guard band of {}", id,
                                    depth.width(), depth.height(), g));
        projection(camera, depth.width(), depth.height());
        const std::uint32_t w = std::uint32_t(depth.width()), h = std::uint32_t(depth.height());
        c.requireImageSize(w, h, fmt::format("{} depth", id));
        const std::uint32_t ow = w - 2 * std::uint32_t(g), oh = h - 2 * std::uint32_t(g);
        ImageF out{int(ow), int(oh)};
        vkx::guarded("running the GPU AO passes", [&] {
            RunImages& r = runImages(format, w, h, ow, oh);
            upload(r, depth, format);
            c.submit([&](const vk::raii::CommandBuffer& cmd) {
                vkx::transition(cmd, r.depth, L::eUndefined, L::eTransferDstOptimal, S::eAllCommands, {}, S::eTransfer,
                                A::eTransferWrite);
                const vk::BufferImageCopy copy(0, 0, 0, {vk::ImageAspectFlagBits::eDepth, 0, 0, 1}, {0, 0, 0},
                                               {w, h, 1});
                cmd.copyBufferToImage(*r.upload.buffer, *r.depth.image, L::eTransferDstOptimal, copy);
                vkx::transition(cmd, r.depth, L::eTransferDstOptimal, L::eShaderReadOnlyOptimal, S::eTransfer,
                                A::eTransferWrite, S::eComputeShader, A::eShaderRead);
                vkx::transition(cmd, r.out, L::eUndefined, L::eGeneral, S::eAllCommands, {}, S::eComputeShader,
                                A::eShaderWrite);
                timer_->reset(cmd);
                timer_->begin(cmd, 0, S::eComputeShader);
                profiling_ = true;
                stageNames_.clear();
                struct NotProfiling {
                    AoPipeline& p;
                    ~NotProfiling() { p.profiling_ = false; }
                } notProfiling{*this};
                record(cmd,
                       ImageRef{*r.depthView, r.depth.format, RunImages::kDepthUsage, w, h, L::eShaderReadOnlyOptimal},
                       camera, ImageRef{*r.outView, kOutputFormat, RunImages::kOutUsage, ow, oh, L::eGeneral});
                timer_->end(cmd, 0, S::eComputeShader);
                vkx::transition(cmd, r.out, L::eGeneral, L::eTransferSrcOptimal, S::eComputeShader, A::eShaderWrite,
                                S::eTransfer, A::eTransferRead);
                cmd.copyImageToBuffer(
                    *r.out.image, L::eTransferSrcOptimal, *r.download.buffer,
                    vk::BufferImageCopy(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1}, {0, 0, 0}, {ow, oh, 1}));
                if (stages) recordStageCopies(cmd);
                const vk::MemoryBarrier toHost(A::eTransferWrite, A::eHostRead);
                cmd.pipelineBarrier(S::eTransfer, S::eHost, {}, toHost, {}, {});
            });
            const auto ms = timer_->milliseconds(1 + std::uint32_t(stageNames_.size()));
            lastMs_ = ms.empty() ? 0.0 : ms[0];
            lastDispatches_.clear();
            for (std::size_t k = 0; k < stageNames_.size(); ++k)
                lastDispatches_.push_back({stageNames_[k], k + 1 < ms.size() ? ms[k + 1] : 0.0});
            std::memcpy(out.data(), r.download.mapped, std::size_t(ow) * oh * sizeof(float));
            if (stages) readStages(*stages, out);
        });
        return out;
    }

    double lastMilliseconds() const { return lastMs_; }
    const std::vector<AoDispatchTime>& lastDispatches() const { return lastDispatches_; }

private:
    static constexpr std::uint32_t kStages = 6;  // z, pyramid, sample, quad, blur h, blur v

    // The pipeline's scratch images for one buffer size: z with its pyramid levels (one
    // image, a mip level each: Vulkan's mip sizes are the pyramid's, max(1, w >> m)), the
    // packed key, and the raw, quad and horizontally blurred A over the work region.
    struct Scratch {
        int w = 0, h = 0;
        ao::Region work, out;
        vkx::Image z, key, raw, quad, horiz;
        vkx::Image edges, normals;                // GTAO: over the work region
        std::vector<vk::raii::ImageView> zLevel;  // storage views, one per level
        //! The images this method has (AlchemyAO: no quad, no key; only GTAO has edges, normals).
        std::vector<const vkx::Image*> images() const {
            std::vector<const vkx::Image*> v;
            for (const vkx::Image* img : {&z, &raw, &quad, &key, &horiz, &edges, &normals})
                if (*img->image) v.push_back(img);
            return v;
        }
        vk::raii::ImageView zAll{nullptr}, keyView{nullptr}, rawView{nullptr}, quadView{nullptr}, horizView{nullptr};
        vk::raii::ImageView edgesView{nullptr}, normalsView{nullptr};
    };

    Scratch& scratch(int w, int h) {
        if (scratch_ && scratch_->w == w && scratch_->h == h) return *scratch_;
        scratch_.reset();
        vkx::Context& c = *ctx_;
        auto s = std::make_unique<Scratch>();
        s->w = w, s->h = h;
        const int g = cfg_.guardBand;
        s->out = {g, g, w - 2 * g, h - 2 * g};
        // SAO's sample and quad passes cover whole 2x2 quads of the buffer grid (ao::sao());
        // GTAO's main pass the output grown by a pixel per denoiser pass, within the buffer.
        s->work = cfg_.sao    ? ao::quadAligned(s->out, w, h)
                  : cfg_.gtao ? ao::gtaoGrown(s->out, w, h, gtaoPasses())
                              : s->out;
        const auto storage = vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eTransferSrc;
        const auto aspect = vk::ImageAspectFlagBits::eColor;
        const std::uint32_t levels = std::uint32_t(cfg_.levels) + 1;
        s->z = c.createImage(kZFormat, std::uint32_t(w), std::uint32_t(h), storage | vk::ImageUsageFlagBits::eSampled,
                             aspect, 1, levels);
        for (std::uint32_t m = 0; m < levels; ++m) s->zLevel.push_back(view2d(c, s->z, m, 1));
        s->zAll = view2d(c, s->z, 0, levels);
        const std::uint32_t ww = std::uint32_t(s->work.width), wh = std::uint32_t(s->work.height);
        s->raw = c.createImage(kZFormat, ww, wh, storage, aspect);
        s->horiz = c.createImage(kZFormat, ww, wh, storage, aspect);
        s->rawView = view2d(c, s->raw, 0, 1);
        s->horizView = view2d(c, s->horiz, 0, 1);
        if (cfg_.gtao) {  // (quad: the denoiser's second ping-pong image)
            s->quad = c.createImage(kZFormat, ww, wh, storage, aspect);
            s->quadView = view2d(c, s->quad, 0, 1);
            s->edges = c.createImage(kZFormat, ww, wh, storage, aspect);
            s->edgesView = view2d(c, s->edges, 0, 1);
            s->normals = c.createImage(kNormalFormat, ww, wh, storage, aspect);
            s->normalsView = view2d(c, s->normals, 0, 1);
        }
        if (cfg_.sao) {  // the 2x2 pass's output, and the packed key (which its shader declares either way)
            s->quad = c.createImage(kZFormat, ww, wh, storage, aspect);
            s->quadView = view2d(c, s->quad, 0, 1);
            // (The key is written over the work region only; the blur reads nothing else of it.)
            s->key = c.createImage(kZFormat, std::uint32_t(w), std::uint32_t(h), storage, aspect);
            s->keyView = view2d(c, s->key, 0, 1);
        }
        scratch_ = std::move(s);
        return *scratch_;
    }

    // One dispatch group's timestamps (run() only).
    void beginStage(const vk::raii::CommandBuffer& cmd, const char* name) {
        if (!profiling_ || stageNames_.size() >= kStages) return;
        stageNames_.emplace_back(name);
        timer_->begin(cmd, std::uint32_t(stageNames_.size()), S::eComputeShader);
    }
    void endStage(const vk::raii::CommandBuffer& cmd) {
        if (profiling_ && !stageNames_.empty()) timer_->end(cmd, std::uint32_t(stageNames_.size()), S::eComputeShader);
    }

    static void written(const vk::raii::CommandBuffer& cmd) {
        const vk::MemoryBarrier b(A::eShaderWrite, A::eShaderRead | A::eShaderWrite);
        cmd.pipelineBarrier(S::eComputeShader, S::eComputeShader, {}, b, {}, {});
    }

    void recordPasses(const vk::raii::CommandBuffer& cmd, const ImageRef& depth, const Projection& proj,
                      const Camera& camera, vk::ImageView output) {
        Scratch& s = scratch(proj.width, proj.height);
        // The scratch images to GENERAL, their old contents dropped, after an earlier
        // recording's reads and writes.
        std::vector<vk::ImageMemoryBarrier> discard;
        for (const vkx::Image* img : s.images())
            discard.emplace_back(A::eShaderRead | A::eShaderWrite | A::eTransferRead, A::eShaderWrite | A::eShaderRead,
                                 L::eUndefined, L::eGeneral, VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED,
                                 *img->image,
                                 vk::ImageSubresourceRange(vk::ImageAspectFlagBits::eColor, 0, img->levels, 0, 1));
        cmd.pipelineBarrier(S::eComputeShader | S::eTransfer, S::eComputeShader, {}, {}, {}, discard);

        AoConstants pc{};
        pc.width = proj.width, pc.height = proj.height;
        // The camera's doubles as float pairs hi + lo (depth_to_z.comp); zNear zFar rounded as the CPU's c0.
        auto pair = [](double v, float& hi, float& lo) {
            hi = float(v);
            lo = std::isinf(v) ? 0.0f : float(v - double(hi));
        };
        pair(camera.zNear, pc.zNear, pc.zNearLo);
        pair(camera.zFar, pc.zFar, pc.zFarLo);
        pair(std::isinf(camera.zFar) ? 0.0 : camera.zNear * camera.zFar, pc.zNearFar, pc.zNearFarLo);
        const ao::PositionFactors f = ao::positionFactors(proj);
        pc.ax = f.ax, pc.bx = f.bx, pc.ay = f.ay, pc.by = f.by;
        pc.radiusS = -cfg_.radius * proj.pixelsPerMeter;  // as the CPU: (-radius * S) / z
        auto region = [&](AoConstants& c, ao::Region r) {
            c.regionX = r.x0, c.regionY = r.y0, c.regionW = r.width, c.regionH = r.height;
        };
        auto image = [](std::uint32_t binding, const vk::DescriptorImageInfo& info) {
            return vk::WriteDescriptorSet({}, binding, 0, Desc::eStorageImage, info);
        };
        auto storage = [](vk::ImageView v) { return vk::DescriptorImageInfo(nullptr, v, L::eGeneral); };
        const vk::DescriptorBufferInfo tableInfo(*tables_.buffer, 0, VK_WHOLE_SIZE);

        // 1. depth -> z, the whole buffer.
        beginStage(cmd, "z");
        {
            AoConstants c = pc;
            region(c, {0, 0, proj.width, proj.height});
            const vk::DescriptorImageInfo in(*sampler_, depth.view, depth.layout), out = storage(*s.zLevel[0]);
            const vk::WriteDescriptorSet writes[] = {{{}, 0, 0, Desc::eCombinedImageSampler, in}, image(1, out)};
            depthToZ_->dispatchPushed(cmd, writes, &c, groups(proj.width), groups(proj.height));
        }
        endStage(cmd);
        written(cmd);
        if (cfg_.gtao) {
            pc.radiusS = ao::gtaoConstants(cfg_.gtaoParams, proj).rNum;  // the main pass's rNum
            recordGtao(cmd, s, pc, output);
            return;
        }
        // 2. the pyramid, level by level.
        if (cfg_.levels > 0) {
            beginStage(cmd, "pyramid");
            recordLevels(cmd, s, pc, *pyramid_, nullptr);
            endStage(cmd);
        }
        // 3. the sample pass over the work region.
        beginStage(cmd, "sample");
        {
            AoConstants c = pc;
            region(c, s.work);
            c.levels = cfg_.levels;
            const vk::DescriptorImageInfo in(*sampler_, *s.zAll, L::eGeneral), out = storage(*s.rawView);
            const vk::WriteDescriptorSet writes[] = {{{}, 0, 0, Desc::eCombinedImageSampler, in},
                                                     image(1, out),
                                                     {{}, 2, 0, Desc::eStorageBuffer, {}, tableInfo}};
            sample_->dispatchPushed(cmd, writes, &c, groups(s.work.width), groups(s.work.height));
        }
        endStage(cmd);
        written(cmd);
        // 4. SAO: the 2x2 quad bilateral (and the packing), one invocation per quad.
        vk::ImageView blurIn = *s.rawView, blurZ = *s.zLevel[0];
        if (cfg_.sao) {
            beginStage(cmd, "quad");
            AoConstants c = pc;
            region(c, s.work);
            const vk::DescriptorImageInfo raw = storage(*s.rawView), quad = storage(*s.quadView),
                                          z = storage(*s.zLevel[0]), key = storage(*s.keyView);
            const vk::WriteDescriptorSet writes[] = {image(0, raw),
                                                     image(1, quad),
                                                     image(2, z),
                                                     image(3, key),
                                                     {{}, 4, 0, Desc::eStorageBuffer, {}, tableInfo}};
            quad_->dispatchPushed(cmd, writes, &c, groups((s.work.width + 1) / 2), groups((s.work.height + 1) / 2));
            endStage(cmd);
            written(cmd);
            blurIn = *s.quadView;
            if (cfg_.packing != 0) blurZ = *s.keyView;
        }
        // 5-6. the separable bilateral: horizontal over the work region, vertical into the output.
        for (const bool horizontal : {true, false}) {
            beginStage(cmd, horizontal ? "blur h" : "blur v");
            AoConstants c = pc;
            region(c, horizontal ? s.work : s.out);
            c.srcX = s.work.x0, c.srcY = s.work.y0, c.srcW = s.work.width, c.srcH = s.work.height;
            const vk::DescriptorImageInfo in = storage(horizontal ? blurIn : *s.horizView),
                                          out = storage(horizontal ? *s.horizView : output), z = storage(blurZ);
            const vk::WriteDescriptorSet writes[] = {
                image(0, in), image(1, out), image(2, z), {{}, 3, 0, Desc::eStorageBuffer, {}, tableInfo}};
            (horizontal ? blurH_ : blurV_)->dispatchPushed(cmd, writes, &c, groups(c.regionW), groups(c.regionH));
            endStage(cmd);
            if (horizontal) written(cmd);
        }
    }

    // One dispatch per level m = 1..levels, level m (max(1, w / 2) x max(1, h / 2)) from
    // level m - 1: SAO's pyramid, GTAO's chain (which reads `tables` at binding 2).
    void recordLevels(const vk::raii::CommandBuffer& cmd, Scratch& s, const AoConstants& pc,
                      vkx::ComputePipeline& pipeline, const vk::DescriptorBufferInfo* tables) {
        int fw = pc.width, fh = pc.height;
        for (int m = 1; m <= cfg_.levels; ++m) {
            const int cw = std::max(1, fw / 2), ch = std::max(1, fh / 2);
            AoConstants c = pc;
            c.regionX = 0, c.regionY = 0, c.regionW = cw, c.regionH = ch;
            c.srcW = fw, c.srcH = fh;
            const vk::DescriptorImageInfo in(nullptr, *s.zLevel[std::size_t(m) - 1], L::eGeneral),
                out(nullptr, *s.zLevel[std::size_t(m)], L::eGeneral);
            std::vector<vk::WriteDescriptorSet> writes{{{}, 0, 0, Desc::eStorageImage, in},
                                                       {{}, 1, 0, Desc::eStorageImage, out}};
            if (tables) writes.emplace_back(vk::WriteDescriptorSet({}, 2, 0, Desc::eStorageBuffer, {}, *tables));
            pipeline.dispatchPushed(cmd, writes, &c, groups(cw), groups(ch));
            written(cmd);
            fw = cw, fh = ch;
        }
    }

    int gtaoPasses() const { return cfg_.gtaoParams.denoisePasses; }
    // GTAO after depth -> z (spec gtao.md): the chain's levels 1-4, the edges and normals and
    // the main pass over the work region, then the denoiser's passes (the last into the output).
    void recordGtao(const vk::raii::CommandBuffer& cmd, Scratch& s, const AoConstants& pc, vk::ImageView output) {
        auto region = [&](AoConstants& c, ao::Region r) {
            c.regionX = r.x0, c.regionY = r.y0, c.regionW = r.width, c.regionH = r.height;
        };
        const vk::DescriptorBufferInfo tables(*gtaoTables_.buffer, 0, VK_WHOLE_SIZE);
        auto storage = [](vk::ImageView v) { return vk::DescriptorImageInfo(nullptr, v, L::eGeneral); };
        auto write = [](std::uint32_t binding, const vk::DescriptorImageInfo& info) {
            return vk::WriteDescriptorSet({}, binding, 0, Desc::eStorageImage, info);
        };
        // 2. the chain, level by level.
        beginStage(cmd, "chain");
        recordLevels(cmd, s, pc, *chain_, &tables);
        endStage(cmd);
        // 3. edges and normals of the work region.
        beginStage(cmd, "edges");
        {
            AoConstants c = pc;
            region(c, s.work);
            const vk::DescriptorImageInfo z = storage(*s.zLevel[0]), e = storage(*s.edgesView),
                                          n = storage(*s.normalsView);
            const vk::WriteDescriptorSet writes[] = {
                write(0, z), write(1, e), write(2, n), {{}, 3, 0, Desc::eStorageBuffer, {}, tables}};
            edges_->dispatchPushed(cmd, writes, &c, groups(s.work.width), groups(s.work.height));
        }
        endStage(cmd);
        written(cmd);
        // 4. the main pass over the work region.
        beginStage(cmd, "main");
        {
            AoConstants c = pc;
            region(c, s.work);
            const vk::DescriptorImageInfo chain(*sampler_, *s.zAll, L::eGeneral), n = storage(*s.normalsView),
                                                                                  out = storage(*s.rawView);
            const vk::WriteDescriptorSet writes[] = {{{}, 0, 0, Desc::eCombinedImageSampler, chain},
                                                     write(1, n),
                                                     write(2, out),
                                                     {{}, 3, 0, Desc::eStorageBuffer, {}, tables}};
            main_->dispatchPushed(cmd, writes, &c, groups(s.work.width), groups(s.work.height));
        }
        endStage(cmd);
        written(cmd);
        // 5. the denoiser: max(1, passes) ping-ponged passes (0: A clamped), the last into the output.
        beginStage(cmd, "denoise");
        const int passes = gtaoPasses();
        // raw is kept (a stage); the middle passes alternate between horiz and quad.
        vk::ImageView cur = *s.rawView, other = *s.horizView, spare = *s.quadView;
        for (int pass = 0; pass < std::max(1, passes); ++pass) {
            const bool last = pass == std::max(1, passes) - 1;
            AoConstants c = pc;
            region(c, last ? s.out : ao::gtaoGrown(s.out, pc.width, pc.height, passes - 1 - pass));
            c.srcX = s.work.x0, c.srcY = s.work.y0, c.srcW = s.work.width, c.srcH = s.work.height;
            c.levels = passes == 0 ? 0 : last ? 2 : 1;  // the mode
            const vk::DescriptorImageInfo in = storage(cur), out = storage(last ? output : other),
                                          z = storage(*s.zLevel[0]), e = storage(*s.edgesView);
            const vk::WriteDescriptorSet writes[] = {
                write(0, in), write(1, out), write(2, z), write(3, e), {{}, 4, 0, Desc::eStorageBuffer, {}, tables}};
            denoise_->dispatchPushed(cmd, writes, &c, groups(c.regionW), groups(c.regionH));
            if (!last) {
                written(cmd);
                cur = other;
                std::swap(other, spare);
            }
        }
        endStage(cmd);
    }

    // run()'s depth image, output and staging buffers, kept while the size and format stay.
    struct RunImages {
        static constexpr vk::ImageUsageFlags kDepthUsage =
            vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst;
        static constexpr vk::ImageUsageFlags kOutUsage =
            vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eTransferSrc;
        DepthFormat format{};
        std::uint32_t w = 0, h = 0;
        vkx::Buffer upload, download, stages;
        vkx::Image depth, out;
        vk::raii::ImageView depthView{nullptr}, outView{nullptr};
    };

    RunImages& runImages(DepthFormat format, std::uint32_t w, std::uint32_t h, std::uint32_t ow, std::uint32_t oh) {
        if (run_ && run_->format == format && run_->w == w && run_->h == h) return *run_;
        run_.reset();
        vkx::Context& c = *ctx_;
        const vk::Format vf = depthVkFormat(format);
        const vk::FormatProperties props = c.physical.getFormatProperties(vf);
        if (!(props.optimalTilingFeatures & vk::FormatFeatureFlagBits::eSampledImage))
            throw Error(
                fmt::format("gpu::{}: this device cannot sample {} depth images", cfg_.name, vk::to_string(vf)));
        auto r = std::make_unique<RunImages>();
        r->format = format, r->w = w, r->h = h;
        const std::size_t texel = format == DepthFormat::D16 ? 2 : 4;
        r->upload = c.createBuffer(vk::DeviceSize(w) * h * texel, vk::BufferUsageFlagBits::eTransferSrc, true);
        r->download = c.createBuffer(vk::DeviceSize(ow) * oh * 4, vk::BufferUsageFlagBits::eTransferDst, true);
        r->depth = c.createImage(vf, w, h, RunImages::kDepthUsage, vk::ImageAspectFlagBits::eDepth);
        r->depthView = vk::raii::ImageView(
            c.device, vk::ImageViewCreateInfo({}, *r->depth.image, vk::ImageViewType::e2D, vf, {},
                                              vk::ImageSubresourceRange(vk::ImageAspectFlagBits::eDepth, 0, 1, 0, 1)));
        r->out = c.createImage(kOutputFormat, ow, oh, RunImages::kOutUsage, vk::ImageAspectFlagBits::eColor);
        r->outView = view2d(c, r->out, 0, 1);
        run_ = std::move(r);
        return *run_;
    }

    static void upload(RunImages& r, ImageView<const float> depth, DepthFormat format) {
        auto* bytes = static_cast<std::uint8_t*>(r.upload.mapped);
        for (int y = 0; y < depth.height(); ++y)
            for (int x = 0; x < depth.width(); ++x) {
                const double d = depth(x, y);
                const std::size_t i = std::size_t(y) * std::size_t(depth.width()) + std::size_t(x);
                if (format == DepthFormat::D16) {
                    const auto v = std::uint16_t(std::nearbyint(d * 65535.0));
                    std::memcpy(bytes + 2 * i, &v, 2);
                } else if (format == DepthFormat::D24) {
                    const auto v = std::uint32_t(std::nearbyint(d * 16777215.0));  // X8_D24: the low 24 bits
                    std::memcpy(bytes + 4 * i, &v, 4);
                } else {
                    const float v = float(d);
                    std::memcpy(bytes + 4 * i, &v, 4);
                }
            }
    }

    // runStages(): every scratch image (each level of z) copied into one host buffer after the passes.
    struct StageCopy {
        const vkx::Image* image;
        std::uint32_t level, w, h;
        vk::DeviceSize offset;
    };
    std::vector<StageCopy> stageCopies_;

    void recordStageCopies(const vk::raii::CommandBuffer& cmd) {
        Scratch& s = *scratch_;
        stageCopies_.clear();
        vk::DeviceSize total = 0;
        auto add = [&](const vkx::Image& img, std::uint32_t level) {
            const std::uint32_t w = std::max(1u, img.width >> level), h = std::max(1u, img.height >> level);
            stageCopies_.push_back({&img, level, w, h, total});
            total += vk::DeviceSize(w) * h * 4;
        };
        for (const vkx::Image* img : s.images())
            if (img->format == kZFormat)  // (GTAO's normals are not a stage of AoStages)
                for (std::uint32_t m = 0; m < img->levels; ++m) add(*img, m);
        RunImages& r = *run_;
        if (r.stages.size < total) r.stages = ctx_->createBuffer(total, vk::BufferUsageFlagBits::eTransferDst, true);
        // (The next recording drops these layouts with its own barrier from UNDEFINED.)
        std::vector<vk::ImageMemoryBarrier> toCopy;
        for (const vkx::Image* img : s.images())
            toCopy.emplace_back(A::eShaderWrite, A::eTransferRead, L::eGeneral, L::eTransferSrcOptimal,
                                VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, *img->image,
                                vk::ImageSubresourceRange(vk::ImageAspectFlagBits::eColor, 0, img->levels, 0, 1));
        cmd.pipelineBarrier(S::eComputeShader, S::eTransfer, {}, {}, {}, toCopy);
        for (const StageCopy& c : stageCopies_)
            cmd.copyImageToBuffer(*c.image->image, L::eTransferSrcOptimal, *r.stages.buffer,
                                  vk::BufferImageCopy(c.offset, 0, 0, {vk::ImageAspectFlagBits::eColor, c.level, 0, 1},
                                                      {0, 0, 0}, {c.w, c.h, 1}));
    }

    void readStages(AoStages& st, const ImageF& result) {
        const Scratch& s = *scratch_;
        auto read = [&](const StageCopy& c) {
            ImageF img(int(c.w), int(c.h));
            std::memcpy(img.data(), static_cast<const std::uint8_t*>(run_->stages.mapped) + c.offset,
                        std::size_t(c.w) * c.h * 4);
            return img;
        };
        st = AoStages{};
        st.work = s.work;
        for (const StageCopy& c : stageCopies_) {
            ImageF img = read(c);
            if (c.image == &s.z) {
                if (c.level == 0)
                    st.z = std::move(img);
                else
                    st.pyramid.push_back(std::move(img));
            } else if (c.image == &s.raw) {
                st.raw = std::move(img);
            } else if (cfg_.gtao) {
                continue;  // the denoiser's ping-pong images: no stage of their own
            } else if (c.image == &s.quad) {
                st.quad = std::move(img);
            } else if (c.image == &s.horiz) {
                st.horizontal = std::move(img);
            } else if (c.image == &s.key && cfg_.packing != 0) {  // the work region of the buffer-sized key
                st.zBlur = ImageF(s.work.width, s.work.height);
                for (int y = 0; y < s.work.height; ++y)
                    for (int x = 0; x < s.work.width; ++x) st.zBlur(x, y) = img(s.work.x0 + x, s.work.y0 + y);
            }
        }
        st.result = result;
    }

    std::shared_ptr<vkx::Context> ctx_;
    AoConfig cfg_;
    vk::raii::Sampler sampler_{nullptr};
    vkx::Buffer tables_;
    std::unique_ptr<vkx::ComputePipeline> depthToZ_, pyramid_, sample_, quad_, blurH_, blurV_;
    std::unique_ptr<vkx::ComputePipeline> chain_, edges_, main_, denoise_;  // GTAO
    vkx::Buffer gtaoTables_;
    std::unique_ptr<Scratch> scratch_;
    std::unique_ptr<RunImages> run_;
    std::unique_ptr<vkx::GpuTimer> timer_;
    bool profiling_ = false;
    std::vector<std::string> stageNames_;
    std::vector<AoDispatchTime> lastDispatches_;
    double lastMs_ = 0;
};

vk::Format depthVkFormat(DepthFormat format) {
    switch (format) {
        case DepthFormat::D16: return vk::Format::eD16Unorm;
        case DepthFormat::D24: return vk::Format::eX8D24UnormPack32;
        default: return vk::Format::eD32Sfloat;
    }
}

bool hasGpuAo(std::string_view method) { return method == "sao" || method == "alchemy" || method == "gtao"; }

namespace {
AoConfig configOf(std::string_view method, const ao::AoParams& params) {
    if (!hasGpuAo(method)) throw Error(fmt::format("{}: no GPU pass (the GPU has sao, alchemy and gtao)", method));
    if (method == "sao") {
        if (const auto* p = std::get_if<ao::SaoParams>(&params)) return configOf(*p);
    } else if (method == "gtao") {
        if (const auto* p = std::get_if<ao::GtaoParams>(&params)) return configOf(*p);
    } else if (const auto* p = std::get_if<ao::AlchemyParams>(&params)) {
        return configOf(*p);
    }
    throw Error(fmt::format("gpu::AoPass: the params are not {}'s", method));
}
}  // namespace

AoPass::AoPass(std::shared_ptr<vkx::Context> ctx, std::string_view method, const ao::AoParams& params)
    : impl_(std::make_unique<AoPipeline>(std::move(ctx), configOf(method, params))) {}
AoPass::~AoPass() = default;
void AoPass::record(const vk::raii::CommandBuffer& cmd, const ImageRef& depth, const Camera& camera,
                    const ImageRef& output) {
    impl_->record(cmd, depth, camera, output);
}
ImageF AoPass::run(ImageView<const float> depth, const Camera& camera, DepthFormat format) {
    return impl_->run(depth, camera, format, nullptr);
}
AoStages AoPass::runStages(ImageView<const float> depth, const Camera& camera, DepthFormat format) {
    AoStages st;
    impl_->run(depth, camera, format, &st);
    return st;
}
double AoPass::lastMilliseconds() const { return impl_->lastMilliseconds(); }
const std::vector<AoDispatchTime>& AoPass::lastDispatches() const { return impl_->lastDispatches(); }

}  // namespace ssfx::gpu
