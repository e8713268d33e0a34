// The anti-aliasing methods as Vulkan compute passes (ssfx/gpu/aa.hpp; docs/gpu.md).
#include "ssfx/gpu/aa.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iterator>
#include <map>
#include <mutex>
#include <type_traits>

#include "src/gpu/shaders/aa/aa_constants.h"
#include "ssfx/aa/ddaa.hpp"
#include "ssfx/core/color.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/core/sample.hpp"
#include "ssfx/vk/compute.hpp"
#include "ssfx/vk/timer.hpp"

namespace ssfx::gpu {

namespace detail {

// The shared header's promise: member i at byte 4 i, in C++ as in GLSL's std430.
#define SSFX_AA_OFFSET(type, name) offsetof(AaConstants, name),
#define SSFX_AA_SIZE(type, name) sizeof(type),
constexpr std::size_t kOffsets[] = {SSFX_AA_CONSTANTS(SSFX_AA_OFFSET)};
constexpr std::size_t kSizes[] = {SSFX_AA_CONSTANTS(SSFX_AA_SIZE)};
constexpr bool fourByteMembersInOrder() {
    for (std::size_t i = 0; i < std::size(kOffsets); ++i)
        if (kOffsets[i] != 4 * i || kSizes[i] != 4) return false;
    return true;
}
static_assert(fourByteMembersInOrder(), "AaConstants: every member a 4-byte scalar, in order (std430)");
static_assert(sizeof(AaConstants) == 4 * std::size(kOffsets), "AaConstants: no padding");
static_assert(sizeof(AaConstants) <= 128, "AaConstants: within the guaranteed push-constant size");

// The specialization constants: constant_id i at byte 4 i.
#define SSFX_AA_SPEC_ENTRY(id, name, value) vk::SpecializationMapEntry(id, offsetof(AaSpecialization, name), 4),
const vk::SpecializationMapEntry kSpecEntries[] = {SSFX_AA_SPECIALIZATION(SSFX_AA_SPEC_ENTRY)};
#undef SSFX_AA_SPEC_ENTRY
static_assert(sizeof(AaSpecialization) == 4 * std::size(kSpecEntries), "AaSpecialization: no padding");

namespace {

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

void thresholds(AaConstants& c, float edgeThresholdMin, float edgeThreshold, float chromaWeight) {
    c.edgeThresholdMin = edgeThresholdMin;
    c.edgeThreshold = edgeThreshold;
    c.chromaWeight = chromaWeight;
}

void ddaa1Constants(AaConstants& c, const aa::Ddaa1Params& p) {
    thresholds(c, p.edgeThresholdMin, p.edgeThreshold, p.chromaWeight);
    c.strength = p.strength;
    c.maxDiffusion = p.maxDiffusion;
    c.ridgeFactor = p.ridgeFactor;
}

}  // namespace

// The one place where a method's CPU params become its shader constants.
AaConstants aaConstants(const AaParams& params, int width, int height, int outWidth, int outHeight) {
    AaConstants c{};
    c.width = width, c.height = height, c.outWidth = outWidth, c.outHeight = outHeight;
    c.fw = float(width), c.fh = float(height);
    c.invW = 1.0f / float(width), c.invH = 1.0f / float(height);  // as ssfx::Texture
    std::visit(Overloaded{
                   [](const std::monostate&) {},
                   [&](const aa::BlurParams& p) {
                       const aa::BlurWeights w = aa::blurWeights(p);  // the CPU's weights
                       c.blurW1 = w.w1, c.blurW2 = w.w2, c.blurNorm = w.norm;
                   },
                   [&](const aa::Fxaa3cParams& p) {
                       thresholds(c, p.edgeThresholdMin, p.edgeThreshold, p.chromaWeight);
                       c.edgeSharpness = p.edgeSharpness;
                       c.diagonalU = p.diagonalOffset * c.invW;  // as fxaa3c.cpp: du, dv
                       c.diagonalV = p.diagonalOffset * c.invH;
                   },
                   [&](const aa::Fxaa3dParams& p) {
                       thresholds(c, p.edgeThresholdMin, p.edgeThreshold, p.chromaWeight);
                       c.subpix = p.subpix;
                       c.paperSearchQuirk = p.paperSearchQuirk ? 1 : 0;
                   },
                   [&](const aa::Ddaa1Params& p) { ddaa1Constants(c, p); },
                   [&](const aa::Ddaa2Params& p) {
                       ddaa1Constants(c, p);
                       c.searchRounds = p.searchRounds;
                   },
                   [&](const aa::Ssaax2Params&) {},
                   [&](const aa::MitchellParams&) {},
               },
               params);
    return c;
}

TextureFormat textureOf(const AaParams& params) {
    return std::visit(
        [](const auto& p) {
            if constexpr (requires { p.texture; })
                return p.texture;
            else
                return TextureFormat::Unorm;
        },
        params);
}

// The choices that select shader code, from the same params (and the sampling mode).
AaSpecialization aaSpecialization(const AaParams& params, Sampling sampling) {
    const AaConstants c = aaConstants(params, 8, 8, 8, 8);  // (its checks, and chromaWeight)
    AaSpecialization s{};
    s.sampling = sampling == Sampling::Hardware ? 1 : 0;
    s.srgb = textureOf(params) == TextureFormat::Srgb ? 1 : 0;
    s.chroma = c.chromaWeight != 0.0f ? 1 : 0;
    if (const auto* p = std::get_if<aa::Fxaa3cParams>(&params)) s.diagonalsAtCentres = p->diagonalOffset == 1.0f;
    return s;
}

vk::SpecializationInfo specializationInfo(const AaSpecialization& s) {
    return vk::SpecializationInfo(std::uint32_t(std::size(kSpecEntries)), kSpecEntries, sizeof(s), &s);
}

}  // namespace detail

namespace {

using detail::AaConstants;

// Each method's shader twice: the model (exact arithmetic) and the hardware mode (the same
// source with SSFX_DEVICE_ARITHMETIC: the device's arithmetic; ppaa.glsl).
const std::uint32_t kNoaa[] = {
#include "shaders/noaa.comp.inc"
};
const std::uint32_t kNoaaDevice[] = {
#include "shaders/noaa.comp.device.inc"
};
const std::uint32_t kBlur[] = {
#include "shaders/blur.comp.inc"
};
const std::uint32_t kBlurDevice[] = {
#include "shaders/blur.comp.device.inc"
};
// The segments stage (EdgePath::Segments) of blur and the edge methods, in modules of their own.
const std::uint32_t kBlurSegments[] = {
#include "shaders/blur.comp.segments.inc"
};
const std::uint32_t kBlurSegmentsDevice[] = {
#include "shaders/blur.comp.segments.device.inc"
};
const std::uint32_t kFxaa3cSegments[] = {
#include "shaders/fxaa3c.comp.segments.inc"
};
const std::uint32_t kFxaa3cSegmentsDevice[] = {
#include "shaders/fxaa3c.comp.segments.device.inc"
};
const std::uint32_t kFxaa3dSegments[] = {
#include "shaders/fxaa3d.comp.segments.inc"
};
const std::uint32_t kFxaa3dSegmentsDevice[] = {
#include "shaders/fxaa3d.comp.segments.device.inc"
};
const std::uint32_t kDdaa1Segments[] = {
#include "shaders/ddaa1.comp.segments.inc"
};
const std::uint32_t kDdaa1SegmentsDevice[] = {
#include "shaders/ddaa1.comp.segments.device.inc"
};
const std::uint32_t kDdaa2Segments[] = {
#include "shaders/ddaa2.comp.segments.inc"
};
const std::uint32_t kDdaa2SegmentsDevice[] = {
#include "shaders/ddaa2.comp.segments.device.inc"
};
const std::uint32_t kFxaa3c[] = {
#include "shaders/fxaa3c.comp.inc"
};
const std::uint32_t kFxaa3cDevice[] = {
#include "shaders/fxaa3c.comp.device.inc"
};
const std::uint32_t kFxaa3d[] = {
#include "shaders/fxaa3d.comp.inc"
};
const std::uint32_t kFxaa3dDevice[] = {
#include "shaders/fxaa3d.comp.device.inc"
};
const std::uint32_t kDdaa1[] = {
#include "shaders/ddaa1.comp.inc"
};
const std::uint32_t kDdaa1Device[] = {
#include "shaders/ddaa1.comp.device.inc"
};
const std::uint32_t kDdaa2[] = {
#include "shaders/ddaa2.comp.inc"
};
const std::uint32_t kDdaa2Device[] = {
#include "shaders/ddaa2.comp.device.inc"
};
const std::uint32_t kSsaax2[] = {
#include "shaders/ssaax2.comp.inc"
};
const std::uint32_t kSsaax2Device[] = {
#include "shaders/ssaax2.comp.device.inc"
};
const std::uint32_t kSsaax4[] = {
#include "shaders/ssaax4.comp.inc"
};
const std::uint32_t kSsaax4Device[] = {
#include "shaders/ssaax4.comp.device.inc"
};

struct Shader {
    std::string_view id;
    std::span<const std::uint32_t> model, device;
    std::span<const std::uint32_t> segments = {}, segmentsDevice = {};  // blur's and the edge methods'
};
// ddaa2p is ddaa2's shader followed by ssaax2's (spec ppaa.md "ddaa2p").
const Shader kShaders[] = {{"noaa", kNoaa, kNoaaDevice},
                           {"blur", kBlur, kBlurDevice, kBlurSegments, kBlurSegmentsDevice},
                           {"fxaa3c", kFxaa3c, kFxaa3cDevice, kFxaa3cSegments, kFxaa3cSegmentsDevice},
                           {"fxaa3d", kFxaa3d, kFxaa3dDevice, kFxaa3dSegments, kFxaa3dSegmentsDevice},
                           {"ddaa1", kDdaa1, kDdaa1Device, kDdaa1Segments, kDdaa1SegmentsDevice},
                           {"ddaa2", kDdaa2, kDdaa2Device, kDdaa2Segments, kDdaa2SegmentsDevice},
                           {"ssaax2", kSsaax2, kSsaax2Device},
                           {"ssaax4", kSsaax4, kSsaax4Device},
                           {"ddaa2p", kDdaa2, kDdaa2Device, kDdaa2Segments, kDdaa2SegmentsDevice}};

// The method's module for the sampling mode: its segments stage's with `segments`.
std::span<const std::uint32_t> shaderFor(std::string_view id, Sampling sampling, bool segments = false) {
    for (const Shader& s : kShaders)
        if (s.id == id) {
            if (segments) return sampling == Sampling::Hardware ? s.segmentsDevice : s.segments;
            return sampling == Sampling::Hardware ? s.device : s.model;
        }
    throw Error(fmt::format("{}: no GPU pass", id));
}

const std::uint32_t kDecodeProbe[] = {
#include "shaders/decode_probe.comp.inc"
};

// Texel i of the probe image holds (i, 255 - i, i + 85 mod 256, 255) in memory order: each
// channel takes every value.
std::uint8_t probeByte(int texel, int memoryChannel) {
    const int v[3] = {texel, 255 - texel, (texel + 85) & 255};
    return std::uint8_t(v[memoryChannel]);
}

// The device's decode of every 8-bit value in `format`, fetched as the passes fetch
// (decode_probe.comp): per texel its R, G, B as floats, and the sRGB levels the passes
// recover from them (srgb.glsl).
struct DecodeProbe {
    float decoded[256 * 3];
    float levels[256 * 3];
};
DecodeProbe probeDecode(vkx::Context& c, const vk::raii::Sampler& sampler, vk::Format f) {
    using S = vk::PipelineStageFlagBits;
    using A = vk::AccessFlagBits;
    using L = vk::ImageLayout;
    std::uint8_t bytes[256 * 4];
    for (int i = 0; i < 256; ++i) {
        for (int k = 0; k < 3; ++k) bytes[4 * i + k] = probeByte(i, k);
        bytes[4 * i + 3] = 255;
    }
    const vkx::ComputePipeline probe(
        c, kDecodeProbe, {{vk::DescriptorType::eCombinedImageSampler}, {vk::DescriptorType::eStorageBuffer}}, 0,
        nullptr, true);
    const vkx::Buffer upload = c.uploadBuffer(bytes, sizeof bytes, vk::BufferUsageFlagBits::eTransferSrc);
    const vkx::Buffer out = c.createBuffer(sizeof(DecodeProbe), vk::BufferUsageFlagBits::eStorageBuffer, true);
    const vkx::Image image =
        c.createImage(f, 256, 1, vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst,
                      vk::ImageAspectFlagBits::eColor);
    const vk::raii::ImageView view(c.device, vk::ImageViewCreateInfo({}, *image.image, vk::ImageViewType::e2D, f, {},
                                                                     {vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1}));
    c.submit([&](const vk::raii::CommandBuffer& cmd) {
        vkx::transition(cmd, image, L::eUndefined, L::eTransferDstOptimal, S::eTopOfPipe, {}, S::eTransfer,
                        A::eTransferWrite);
        cmd.copyBufferToImage(
            *upload.buffer, *image.image, L::eTransferDstOptimal,
            vk::BufferImageCopy(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1}, {0, 0, 0}, {256, 1, 1}));
        vkx::transition(cmd, image, L::eTransferDstOptimal, L::eShaderReadOnlyOptimal, S::eTransfer, A::eTransferWrite,
                        S::eComputeShader, A::eShaderRead);
        const vk::DescriptorImageInfo imageInfo(*sampler, *view, L::eShaderReadOnlyOptimal);
        const vk::DescriptorBufferInfo outInfo(*out.buffer, 0, VK_WHOLE_SIZE);
        const vk::WriteDescriptorSet writes[] = {
            {{}, 0, 0, vk::DescriptorType::eCombinedImageSampler, imageInfo},
            {{}, 1, 0, vk::DescriptorType::eStorageBuffer, {}, outInfo},
        };
        probe.dispatchPushed(cmd, writes, nullptr, 4);
        const vk::MemoryBarrier toHost(A::eShaderWrite, A::eHostRead);
        cmd.pipelineBarrier(S::eComputeShader, S::eHost, {}, toHost, {}, {});
    });
    DecodeProbe result;
    std::memcpy(&result, out.mapped, sizeof result);
    return result;
}

// A device property decided by the probes (what `check` returns), once per device and driver
// (and property).
template <class Check, class T = std::invoke_result_t<Check>>
T probedOnce(vkx::Context& c, std::string_view property, Check check) {
    const vk::PhysicalDeviceProperties props = c.physical.getProperties();
    const std::string key = fmt::format("{}:{}:{}:{}:{}", property, props.vendorID, props.deviceID, props.driverVersion,
                                        std::string_view(props.deviceName));
    static std::mutex mutex;
    static std::map<std::string, T> known;
    {
        std::lock_guard lock(mutex);
        if (const auto it = known.find(key); it != known.end()) return it->second;
    }
    T found = check();
    std::lock_guard lock(mutex);
    known.emplace(key, found);
    return found;
}

// probeDecode's result for format f, dispatched once per device and driver: the properties
// below (exact decode, recovered bytes, the decode table) read the same probes.
DecodeProbe decodeOf(vkx::Context& c, const vk::raii::Sampler& sampler, vk::Format f) {
    return probedOnce(c, fmt::format("decode {}", vk::to_string(f)), [&] { return probeDecode(c, sampler, f); });
}

// For each texel of the probe, whether channel k's value passes `ok(probed value, the byte)`.
template <class Ok>
bool everyChannel(const float* values, vk::Format f, Ok ok) {
    const bool bgra = f == vk::Format::eB8G8R8A8Unorm || f == vk::Format::eB8G8R8A8Srgb;
    for (int i = 0; i < 256; ++i)
        for (int k = 0; k < 3; ++k)
            if (!ok(values[3 * i + k], probeByte(i, bgra ? 2 - k : k))) return false;  // channel k's byte in memory
    return true;
}

// A device's default that an environment variable set to exactly "0" or "1" overrides, for
// the tests and measurements of the other choice (docs/gpu.md); any other value leaves it.
bool envChoice(const char* name, bool byDefault) {
    const char* v = std::getenv(name);
    return v && (*v == '0' || *v == '1') && v[1] == 0 ? *v == '1' : byDefault;
}

// Whether the device's decode of an 8-bit texel channel is the model's level for every
// value, in both input formats of `texture`: unorm, v / 255 rounded to float32 (kUnorm8);
// sRGB, the CPU's kSrgb8. It is a function of 256 inputs, so checking each one decides it:
// where it holds, the model takes a fetched value as the texel's level (spec deviceDecode)
// instead of computing the level from the byte (ppaa.glsl's texelDecoded).
// SSFX_GPU_DEVICE_DECODE=0 turns it off, for the tests of the other paths and for measurements.
bool decodeIsExact(vkx::Context& c, const vk::raii::Sampler& sampler, TextureFormat texture) {
    if (const char* v = std::getenv("SSFX_GPU_DEVICE_DECODE"); v && std::string_view(v) == "0") return false;
    const bool srgb = texture == TextureFormat::Srgb;
    return probedOnce(c, srgb ? "srgb decode" : "unorm decode", [&] {
        const float* levels = decodeTable(texture);
        for (const vk::Format f : {srgb ? vk::Format::eR8G8B8A8Srgb : vk::Format::eR8G8B8A8Unorm,
                                   srgb ? vk::Format::eB8G8R8A8Srgb : vk::Format::eB8G8R8A8Unorm})
            if (!everyChannel(decodeOf(c, sampler, f).decoded, f, [&](float value, std::uint8_t byte) {
                    return std::bit_cast<std::uint32_t>(value) == std::bit_cast<std::uint32_t>(levels[byte]);
                }))
                return false;
        return true;
    });
}

const std::uint32_t kSubgroupProbe[] = {
#include "shaders/subgroup_probe.comp.inc"
};

// Whether the device's subgroups in a 16 x 16 work group are runs of consecutive invocations:
// every invocation's subgroup invocation id is its local invocation index modulo a subgroup
// size of 2 or more, a power of two, the same for all (subgroup_probe.comp). Vulkan does not
// promise this layout; blur's segments, which take the rows above and below from the
// neighbouring lanes, run only where the probe found it (once per device and driver).
bool subgroupsAreConsecutive(vkx::Context& c) {
    return probedOnce(c, "consecutive subgroups", [&] {
        constexpr std::uint32_t kInvocations = SSFX_AA_GROUP * SSFX_AA_GROUP;
        const vkx::ComputePipeline probe(c, kSubgroupProbe, {{vk::DescriptorType::eStorageBuffer}}, 0, nullptr, true);
        const vkx::Buffer out = c.createBuffer(2 * kInvocations * 4, vk::BufferUsageFlagBits::eStorageBuffer, true);
        c.submit([&](const vk::raii::CommandBuffer& cmd) {
            const vk::DescriptorBufferInfo outInfo(*out.buffer, 0, VK_WHOLE_SIZE);
            const vk::WriteDescriptorSet writes[] = {{{}, 0, 0, vk::DescriptorType::eStorageBuffer, {}, outInfo}};
            probe.dispatchPushed(cmd, writes, nullptr, 1);
            const vk::MemoryBarrier toHost(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eHostRead);
            cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eHost, {}, toHost,
                                {}, {});
        });
        std::array<std::uint32_t, 2 * kInvocations> lanes{};
        std::memcpy(lanes.data(), out.mapped, sizeof lanes);
        const std::uint32_t size = lanes[1];
        if (size < 2 || !std::has_single_bit(size)) return false;
        for (std::uint32_t i = 0; i < kInvocations; ++i)
            if (lanes[2 * i] != i % size || lanes[2 * i + 1] != size) return false;
        return true;
    });
}

// texture=srgb: whether the passes recover every texel's byte from the device's decode
// through an sRGB view (srgb.glsl's srgbLevelsDevice, in both sRGB formats). The model needs
// the bytes (devices' sRGB decodes are approximate: it decodes them with the CPU's table);
// Vulkan lets a device's decode err by far less than the half level this needs.
bool srgbBytesRecovered(vkx::Context& c, const vk::raii::Sampler& sampler) {
    return probedOnce(c, "srgb bytes", [&] {
        for (const vk::Format f : {vk::Format::eR8G8B8A8Srgb, vk::Format::eB8G8R8A8Srgb})
            if (!everyChannel(decodeOf(c, sampler, f).levels, f,
                              [](float level, std::uint8_t byte) { return level == float(byte); }))
                return false;
        return true;
    });
}

// texture=srgb, model, where the device's sRGB decode is not kSrgb8 itself: a lookup from the
// device's decoded value to the CPU's level, so that a texel read costs one table load
// instead of recovering the byte (a pow per channel) and then looking up kSrgb8. Indexed like
// encodeSrgb8's buckets (the floats in [2^-14, 1) by exponent and top 8 mantissa bits), entry
// bucket(d(b)) holds kSrgb8[b], where d(b) is the device's decode of byte b, probed for every
// byte in every channel of both sRGB formats; it exists only where every byte decodes to one
// float, 0 below 2^-14, 255 to 1 and no two bytes share a bucket, so the lookup gives every
// texel the CPU's level exactly (the shader's srgbLevelOfDecoded). Empty otherwise, or with
// SSFX_GPU_SRGB_DECODE_TABLE=0 (for the test of the other path, and for measurements).
std::vector<float> probeSrgbDecodeTable(vkx::Context& c, const vk::raii::Sampler& sampler) {
    if (const char* v = std::getenv("SSFX_GPU_SRGB_DECODE_TABLE"); v && std::string_view(v) == "0") return {};
    return probedOnce(c, "srgb decode table", [&]() -> std::vector<float> {
        using Encode = ssfx::detail::SrgbEncodeTable;
        std::array<std::uint32_t, 256> bits{};
        std::array<bool, 256> seen{};
        for (const vk::Format f : {vk::Format::eR8G8B8A8Srgb, vk::Format::eB8G8R8A8Srgb}) {
            const DecodeProbe p = decodeOf(c, sampler, f);
            bool same = true;
            everyChannel(p.decoded, f, [&](float value, std::uint8_t byte) {
                const std::uint32_t b = std::bit_cast<std::uint32_t>(value);
                same = same && (!seen[byte] || bits[byte] == b);
                seen[byte] = true, bits[byte] = b;
                return true;
            });
            if (!same) return {};
        }
        const float low = std::bit_cast<float>(Encode::kLowBits);
        if (std::bit_cast<float>(bits[0]) >= low || !(std::bit_cast<float>(bits[255]) >= 1.0f)) return {};
        std::vector<float> table(Encode::kBuckets, 0.0f);
        std::vector<bool> taken(Encode::kBuckets, false);
        for (int b = 1; b < 255; ++b) {
            const float v = std::bit_cast<float>(bits[std::size_t(b)]);
            if (!(v >= low && v < 1.0f)) return {};
            const std::size_t bucket = (bits[std::size_t(b)] - Encode::kLowBits) >> Encode::kShift;
            if (taken[bucket]) return {};
            taken[bucket] = true, table[bucket] = kSrgb8[std::size_t(b)];
        }
        return table;
    });
}

const std::vector<vkx::BindingSpec> kBindings{
    {vk::DescriptorType::eCombinedImageSampler},  // SSFX_AA_BINDING_INPUT
    {vk::DescriptorType::eStorageImage},          // SSFX_AA_BINDING_OUTPUT
    {vk::DescriptorType::eStorageBuffer},         // SSFX_AA_BINDING_TABLES
    {vk::DescriptorType::eStorageBuffer},         // SSFX_AA_BINDING_EDGES (the two-pass methods)
    {vk::DescriptorType::eStorageImage},          // SSFX_AA_BINDING_LUMA (the two-pass methods)
};
static_assert(SSFX_AA_BINDING_INPUT == 0 && SSFX_AA_BINDING_OUTPUT == 1 && SSFX_AA_BINDING_TABLES == 2 &&
              SSFX_AA_BINDING_EDGES == 3 && SSFX_AA_BINDING_LUMA == 4);

std::unique_ptr<vkx::ComputePipeline> makePipeline(const vkx::Context& c, std::span<const std::uint32_t> spirv,
                                                   const detail::AaSpecialization& spec) {
    const vk::SpecializationInfo info = detail::specializationInfo(spec);
    return std::make_unique<vkx::ComputePipeline>(c, spirv, kBindings, std::uint32_t(sizeof(AaConstants)), &info, true);
}

// The edge pass's most work groups on a CPU device (aa_constants.h: edgeGroups).
constexpr std::int32_t kCpuEdgeGroups = 256;

// The loop iterations one edge pixel's computation may run beyond the edge pass's own loop
// over the list. llvmpipe counts every pass of every loop that its compiler keeps, the pass
// that ends a loop included, so each is counted at its most:
//  - fxaa3d's walk (fxaa3d.comp): one side a step (spec sideSearch) 2 x 10 steps with a read and
//    the pass that ends the loop; both sides a step 11;
//  - ddaa2's search (ddaa2.comp): both sides a round, searchRounds rounds and the ending pass,
//    each round with its two loops over kBatch = 3 reads (and their ending passes) as if not
//    unrolled; one side a step (spec sideSearch), 2 x (2 + 3 (searchRounds - 1)) reads and
//    the ending pass; the larger;
//  - each division of the model (exact.glsl's correctlyRounded: at most 4 passes and the one
//    that ends its loop), as the shaders write them (centreU and centreV one each): fxaa3c 14
//    (8 of them its diagonals' off the pixel centres), fxaa3d 4, ddaa1 4, ddaa2 7.
// (lavapipe, 1024-wide stripes, one group, fxaa3d's walk one side a step: pixels were lost
// from 2560 a list invocation on, not at 2400: 26 or 27 iterations a pixel, 1 + 21 + 4
// divisions of one pass.)
int edgeLoopIterations(const AaParams& params) {
    constexpr int kDivision = 4 + 1;
    const auto searchLoops = [](int rounds) {
        return std::max((rounds + 1) * (1 + 2 * (3 + 1)), 2 * (2 + 3 * std::max(rounds - 1, 0)) + 1);
    };
    if (std::holds_alternative<aa::Fxaa3cParams>(params)) return 14 * kDivision;
    if (std::holds_alternative<aa::Fxaa3dParams>(params)) return 2 * 10 + 1 + 4 * kDivision;
    if (std::holds_alternative<aa::Ddaa1Params>(params)) return 4 * kDivision;
    if (const auto* p = std::get_if<aa::Ddaa2Params>(&params)) return searchLoops(p->searchRounds) + 7 * kDivision;
    return 0;
}

// The edge pass's fewest work groups for a list of up to `pixels`, so that no invocation runs
// more loop iterations than the device allows (vkx::Context::maxShaderLoopIterations; budget 0:
// no limit). lavapipe ends every loop of an invocation silently once its 65535 iterations are
// spent: with 256 groups, fxaa3d would lose edge pixels from about 90 million listed pixels
// (docs/gpu.md). A tenth of the budget is left for the short loops a compiler may keep.
std::uint32_t edgeGroupsFor(vk::DeviceSize pixels, int loopsPerPixel, std::uint32_t budget) {
    if (budget == 0) return 0;
    const vk::DeviceSize perInvocation =
        std::max<vk::DeviceSize>(1, (budget - budget / 10) / vk::DeviceSize(1 + loopsPerPixel));
    const vk::DeviceSize perGroup = perInvocation * SSFX_AA_EDGE_GROUP;
    return std::uint32_t(std::min<vk::DeviceSize>((pixels + perGroup - 1) / perGroup, SSFX_AA_EDGE_MAX_GROUPS));
}
// EdgePath::Auto's choice per kind of device, mode and method (docs/gpu.md: measured on
// lavapipe and an H200). On a CPU device, where the device has the segments' subgroup
// operations and layout, the segments (their rows shared across the subgroup) for fxaa3c and
// ddaa1 in both modes (segments / list on three images, two rounds: hardware 0.5 to 0.7,
// model 0.77 to 0.96 in 10 of 12 pairs) and for fxaa3d and ddaa2 in the hardware mode (fxaa3d
// with its walk one side a step 0.66 to 0.93, ddaa2 0.67 to 0.88); the list for fxaa3d and
// ddaa2 in the model (fxaa3d 0.86 to 1.18, ddaa2 0.91 to 1.19 with their searches one side a
// step; the atrium the slower each time), whose long searches gain least from the segments'
// shared rows.
EdgePath cpuEdgePath(std::string_view id, Sampling sampling, const std::function<bool()>& segmentsRun) {
    const bool hardware = sampling == Sampling::Hardware;
    const bool segments =
        (id == "fxaa3c" || id == "ddaa1" || (hardware && (id == "fxaa3d" || id == "ddaa2"))) && segmentsRun();
    return segments ? EdgePath::Segments : EdgePath::List;
}
constexpr EdgePath kGpuEdgePath = EdgePath::OnePass;

// The methods with a segments module (EdgePath::Segments): blur and the edge-test methods.
bool hasSegments(std::string_view id) {
    for (const Shader& s : kShaders)
        if (s.id == id) return !s.segments.empty();
    return false;
}

// The methods whose shaders have an edge test and run as three dispatches (edge_list.glsl).
bool hasEdgePass(std::string_view id) {
    return id == "fxaa3c" || id == "fxaa3d" || id == "ddaa1" || id == "ddaa2" || id == "ddaa2p";
}

constexpr vk::Format kOutputFormat = vk::Format::eR8G8B8A8Unorm;

// The input views record() takes: unorm for texture=unorm, sRGB for texture=srgb (the format
// says how the texels are read, as on the CPU).
bool inputFormatOk(vk::Format f, bool srgb) {
    if (srgb) return f == vk::Format::eR8G8B8A8Srgb || f == vk::Format::eB8G8R8A8Srgb;
    return f == vk::Format::eR8G8B8A8Unorm || f == vk::Format::eB8G8R8A8Unorm;
}
// run()'s input image, and ddaa2p's scratch image's sampled view.
vk::Format inputFormat(bool srgb) { return srgb ? vk::Format::eR8G8B8A8Srgb : vk::Format::eR8G8B8A8Unorm; }

std::uint32_t groups(std::uint32_t n) { return vkx::groupCount(n, SSFX_AA_GROUP); }

// The luma plane's width in texels (ppaa.glsl: lumaPlaneWidth).
std::uint32_t lumaPlaneWidth(int width) { return vkx::groupCount(std::uint32_t(width), SSFX_AA_LUMA_PACK); }

}  // namespace

std::string_view samplingName(Sampling s) { return s == Sampling::Hardware ? "hardware" : "model"; }

Sampling parseSampling(std::string_view name) {
    if (name == "model") return Sampling::Model;
    if (name == "hardware") return Sampling::Hardware;
    throw Error(fmt::format("sampling '{}': expected model or hardware", name));
}

std::string_view edgePathName(EdgePath p) {
    switch (p) {
        case EdgePath::List: return "list";
        case EdgePath::OnePass: return "one-pass";
        case EdgePath::Segments: return "segments";
        case EdgePath::Auto: break;
    }
    return "auto";
}

EdgePath parseEdgePath(std::string_view name) {
    if (name == "auto") return EdgePath::Auto;
    if (name == "list") return EdgePath::List;
    if (name == "one-pass") return EdgePath::OnePass;
    if (name == "segments") return EdgePath::Segments;
    throw Error(fmt::format("edges '{}': expected auto, list, one-pass or segments", name));
}

bool hasGpuPass(std::string_view method) {
    for (const Shader& s : kShaders)
        if (s.id == method) return true;
    return false;
}

struct AaPass::Impl {
    std::shared_ptr<vkx::Context> ctx;
    const MethodInfo* method = nullptr;
    AaParams params;
    Sampling sampling = Sampling::Model;
    EdgePath edgePath = EdgePath::List;  // resolved: List, OnePass or Segments
    bool deviceDecode = false;           // model: the probe found the device's decode of the input format exact
    bool srgb = false;                   // texture=srgb: sRGB input views (spec srgb)
    bool srgbDecodeTable = false;        // texture=srgb, model: the device's decoded values to levels by a table
    vk::raii::Sampler sampler{nullptr};
    vkx::Buffer tables;
    std::unique_ptr<vkx::ComputePipeline> pipeline, resolve;  // resolve: ddaa2p's ssaax2
    // The methods with an edge test: `lumaPass` writes the luma plane `luma`, `pipeline`
    // classifies (SSFX_AA_STAGE_CLASSIFY), `edgePass` computes the listed edge pixels
    // (edge_list.glsl); `edges` holds the list.
    std::unique_ptr<vkx::ComputePipeline> edgePass, lumaPass;
    // ddaa2 in model mode: its edge search reads only half-way positions (weight 128 across,
    // on a texel along) for every realistic size, which the CPU checks per size before its
    // vector kernel reads pair planes (aa::ddaa2SearchReadsArePairReads). Where the check
    // holds, `edgePass` reads those texel pairs by index (spec pairReads: the same values,
    // without coordinates or weights); `edgePassCoords` (made when first needed) reads at
    // coordinates, for the other sizes.
    std::unique_ptr<vkx::ComputePipeline> edgePassCoords;
    detail::AaSpecialization edgeSpec{};
    vkx::Image luma;  // the luma plane (rgba32f, 4 lumas per texel: ppaa.glsl)
    vk::raii::ImageView lumaView{nullptr};
    vkx::Buffer edges;
    vk::DeviceSize edgeCapacity = 0;  // pixels the list can hold
    // Larger images run the method in one pass (stage 0, made when first needed): the list
    // must fit in one storage-buffer descriptor (maxStorageBufferRange).
    vk::DeviceSize maxListPixels = 0;
    // Loop iterations an edge pixel's computation may run, and the device's loop budget
    // (edgeGroupsFor).
    int edgeLoops = 0;
    std::uint32_t loopBudget = 0;
    std::unique_ptr<vkx::ComputePipeline> onePass, onePassPairs;    // coordinate reads; ddaa2's pair reads
    std::unique_ptr<vkx::ComputePipeline> segments, segmentsPairs;  // EdgePath::Segments, the same two
    detail::AaSpecialization spec{};
    vkx::Image scratch;  // ddaa2p: ddaa2's 2x output
    // Its storage view (unorm), and the view the resolve samples: the same for texture=unorm,
    // an sRGB view of the same bytes for texture=srgb (the image's format is then mutable).
    vk::raii::ImageView scratchView{nullptr}, scratchSampled{nullptr};
    std::unique_ptr<vkx::GpuTimer> timer;
    double lastMs = 0;
    // run()'s profile: while `profiling`, each dispatch is bracketed by timer interval
    // 1 + its index and its stage named; the list's pixel count is copied for the host.
    static constexpr std::uint32_t kMaxDispatches = 6;
    bool profiling = false;
    std::vector<std::string> stages;
    std::vector<AaPass::DispatchTime> lastDispatches;
    vk::DeviceSize listedOf = 0;  // pixels the recorded list covers (0: no list)
    vkx::Buffer countReadback;    // the list header's pixel count, for the host
    vkx::Buffer listStandIn;      // the one-pass path's stand-in for the list (unused by stage 0)
    double lastEdgeShare = -1;

    // What a dispatch's invocations cover: the output's pixels, the luma plane's texels (the
    // luma and classify dispatches), the edge list (indirect), or row segments of
    // SSFX_AA_SEGMENT pixels (EdgePath::Segments).
    enum class Grid { Pixels, LumaTexels, EdgeList, Segments };

    // Records one dispatch of p over the output; `list`: the edge list (or, for a shader that
    // declares it without using it, a stand-in) at SSFX_AA_BINDING_EDGES, with the luma plane
    // (or its stand-in) at SSFX_AA_BINDING_LUMA: the edge methods' shaders declare both.
    void dispatch(const vkx::ComputePipeline& p, const vk::raii::CommandBuffer& cmd, vk::ImageView in,
                  vk::ImageLayout inLayout, vk::ImageView out, const AaConstants& c, vk::Buffer list = {},
                  Grid grid = Grid::Pixels, const char* stage = "method") {
        const bool timed = profiling && stages.size() < kMaxDispatches;
        if (timed) {
            stages.emplace_back(stage);
            timer->begin(cmd, std::uint32_t(stages.size()), vk::PipelineStageFlagBits::eComputeShader);
        }
        const vk::DescriptorImageInfo inInfo(*sampler, in, inLayout);
        const vk::DescriptorImageInfo outInfo(nullptr, out, vk::ImageLayout::eGeneral);
        const vk::DescriptorBufferInfo tableInfo(*tables.buffer, 0, VK_WHOLE_SIZE);
        const vk::DescriptorBufferInfo listInfo(list, 0, VK_WHOLE_SIZE);
        const vk::DescriptorImageInfo lumaInfo(nullptr, *lumaView, vk::ImageLayout::eGeneral);
        const vk::WriteDescriptorSet writes[] = {
            {{}, SSFX_AA_BINDING_INPUT, 0, vk::DescriptorType::eCombinedImageSampler, inInfo},
            {{}, SSFX_AA_BINDING_OUTPUT, 0, vk::DescriptorType::eStorageImage, outInfo},
            {{}, SSFX_AA_BINDING_TABLES, 0, vk::DescriptorType::eStorageBuffer, {}, tableInfo},
            {{}, SSFX_AA_BINDING_EDGES, 0, vk::DescriptorType::eStorageBuffer, {}, listInfo},
            {{}, SSFX_AA_BINDING_LUMA, 0, vk::DescriptorType::eStorageImage, lumaInfo},
        };
        const std::span<const vk::WriteDescriptorSet> used(writes, list ? 5 : 3);
        if (grid == Grid::EdgeList)
            p.dispatchPushedIndirect(cmd, used, &c, list, 0);
        else
            p.dispatchPushed(cmd, used, &c, groups(invocationsX(grid, c)), groups(std::uint32_t(c.outHeight)));
        if (timed) timer->end(cmd, std::uint32_t(stages.size()), vk::PipelineStageFlagBits::eComputeShader);
    }

    static std::uint32_t invocationsX(Grid grid, const AaConstants& c) {
        const auto w = std::uint32_t(c.outWidth);
        if (grid == Grid::LumaTexels) return lumaPlaneWidth(c.width);
        if (grid == Grid::Segments) return vkx::groupCount(w, SSFX_AA_SEGMENT);
        return w;
    }

    // Records the method's own shader (not ddaa2p's resolve) from `in` to `out`: for an
    // edge-test method its three dispatches, its dispatch over row segments
    // (EdgePath::Segments), or its one pass (EdgePath::OnePass, or an image whose list would
    // not fit).
    void dispatchMethod(const vk::raii::CommandBuffer& cmd, vk::ImageView in, vk::ImageLayout inLayout,
                        vk::ImageView out, const AaConstants& c) {
        if (!hasEdgePass(method->id)) {
            const bool segmented = edgePath == EdgePath::Segments;  // blur's rows
            dispatch(*pipeline, cmd, in, inLayout, out, c, {}, segmented ? Grid::Segments : Grid::Pixels,
                     segmented ? "segments" : "method");
            return;
        }
        const vk::DeviceSize pixels = vk::DeviceSize(c.outWidth) * vk::DeviceSize(c.outHeight);
        const bool segmented = edgePath == EdgePath::Segments;
        if (segmented || edgePath == EdgePath::OnePass || pixels > maxListPixels) {
            // Stand-ins for the list and the luma plane, which stage 0 and the segments declare
            // but do not use (their lumas are in the work group's tile or fetched).
            // (The list's is a buffer of its own: the shader declares the list writable, so
            // binding the tables there would count as a write of them for synchronization.)
            if (!*luma.image) ensureLuma(1, 1);
            if (!*listStandIn.buffer)
                listStandIn = ctx->createBuffer(16, vk::BufferUsageFlagBits::eStorageBuffer, false);
            cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eComputeShader,
                                {}, {}, {}, lumaDiscarded());
            dispatch(stagePipeline(segmented, c.width, c.height), cmd, in, inLayout, out, c, *listStandIn.buffer,
                     segmented ? Grid::Segments : Grid::Pixels, segmented ? "segments" : "one pass");
            return;
        }
        ensureEdges(pixels);
        ensureLuma(lumaPlaneWidth(c.width), std::uint32_t(c.height));
        AaConstants budgeted = c;
        budgeted.edgeGroupsMin = std::int32_t(edgeGroupsFor(pixels, edgeLoops, loopBudget));
        using S = vk::PipelineStageFlagBits;
        using A = vk::AccessFlagBits;
        // Before this recording's writes, an earlier recording's reads of the list and the luma
        // plane (an execution dependency is enough before a write).
        cmd.pipelineBarrier(S::eComputeShader | S::eDrawIndirect, S::eTransfer, {}, {}, {}, {});
        // The list's header: no groups (y = z = 1), no pixels.
        const std::uint32_t header[4] = {0, 1, 1, 0};
        cmd.updateBuffer<std::uint32_t>(*edges.buffer, 0, header);
        const vk::BufferMemoryBarrier cleared(A::eTransferWrite, A::eShaderRead | A::eShaderWrite,
                                              VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, *edges.buffer, 0,
                                              VK_WHOLE_SIZE);
        // The luma plane is written whole by the luma pass: its old contents are dropped.
        cmd.pipelineBarrier(S::eTransfer | S::eComputeShader, S::eComputeShader, {}, {}, cleared, lumaDiscarded());
        dispatch(*lumaPass, cmd, in, inLayout, out, budgeted, *edges.buffer, Grid::LumaTexels, "luma");
        // The luma plane, before the classify pass reads it.
        const vk::MemoryBarrier lumaWritten(A::eShaderWrite, A::eShaderRead | A::eShaderWrite);
        cmd.pipelineBarrier(S::eComputeShader, S::eComputeShader, {}, lumaWritten, {}, {});
        dispatch(*pipeline, cmd, in, inLayout, out, budgeted, *edges.buffer, Grid::LumaTexels, "classify");
        // The list and the unchanged pixels, before the indirect dispatch and the edge pixels.
        const vk::MemoryBarrier listed(A::eShaderWrite, A::eIndirectCommandRead | A::eShaderRead | A::eShaderWrite);
        cmd.pipelineBarrier(S::eComputeShader, S::eDrawIndirect | S::eComputeShader, {}, listed, {}, {});
        dispatch(edgePipeline(c.width, c.height), cmd, in, inLayout, out, budgeted, *edges.buffer, Grid::EdgeList,
                 "edges");
        listedOf = pixels;
    }

    // Stage 0 or the segments stage (made when first needed), with ddaa2's pair reads where
    // the edge pass would use them (edgePipeline).
    const vkx::ComputePipeline& stagePipeline(bool seg, int w, int h) {
        const bool pairs = edgeSpec.pairReads != 0 &&
                           aa::ddaa2SearchReadsArePairReads(w, h, std::get<aa::Ddaa2Params>(params).searchRounds);
        std::unique_ptr<vkx::ComputePipeline>& p =
            seg ? (pairs ? segmentsPairs : segments) : (pairs ? onePassPairs : onePass);
        if (!p) {
            detail::AaSpecialization s = spec;
            s.pairReads = pairs ? 1 : 0;
            p = makePipeline(*ctx, shaderFor(method->id, sampling, seg), s);
        }
        return *p;
    }

    const vkx::ComputePipeline& edgePipeline(int w, int h) {
        if (edgeSpec.pairReads == 0 ||
            aa::ddaa2SearchReadsArePairReads(w, h, std::get<aa::Ddaa2Params>(params).searchRounds))
            return *edgePass;
        if (!edgePassCoords) {
            detail::AaSpecialization coords = edgeSpec;
            coords.pairReads = 0;
            edgePassCoords = makePipeline(*ctx, shaderFor(method->id, sampling), coords);
        }
        return *edgePassCoords;
    }

    // The luma plane to GENERAL with its old contents dropped, after an earlier recording's reads.
    vk::ImageMemoryBarrier lumaDiscarded() const {
        return vk::ImageMemoryBarrier(vk::AccessFlagBits::eShaderRead, vk::AccessFlagBits::eShaderWrite,
                                      vk::ImageLayout::eUndefined, vk::ImageLayout::eGeneral, VK_QUEUE_FAMILY_IGNORED,
                                      VK_QUEUE_FAMILY_IGNORED, *luma.image,
                                      vk::ImageSubresourceRange(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1));
    }

    void ensureLuma(std::uint32_t w, std::uint32_t h) {
        if (*luma.image && luma.width == w && luma.height == h) return;
        luma = ctx->createImage(vk::Format::eR32G32B32A32Sfloat, w, h, vk::ImageUsageFlagBits::eStorage,
                                vk::ImageAspectFlagBits::eColor);
        lumaView = vk::raii::ImageView(
            ctx->device,
            vk::ImageViewCreateInfo({}, *luma.image, vk::ImageViewType::e2D, vk::Format::eR32G32B32A32Sfloat, {},
                                    vk::ImageSubresourceRange(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1)));
    }

    void ensureEdges(vk::DeviceSize pixels) {
        if (*edges.buffer && edgeCapacity >= pixels) return;
        edges = ctx->createBuffer(16 + 4 * pixels,
                                  vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eIndirectBuffer |
                                      vk::BufferUsageFlagBits::eTransferDst | vk::BufferUsageFlagBits::eTransferSrc,
                                  false);
        edgeCapacity = pixels;
    }

    // run()'s images and staging buffers, kept while the size stays the same (a sequence of
    // frames, a benchmark): new device memory for every call would be written for the first
    // time inside the pass, and first writes to fresh pages cost more than the pass itself
    // on a CPU device.
    struct RunImages {
        static constexpr vk::ImageUsageFlags kInUsage =
            vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst;
        static constexpr vk::ImageUsageFlags kResUsage =
            vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eTransferSrc;
        std::uint32_t w = 0, h = 0, ow = 0, oh = 0;
        vkx::Buffer upload, download;
        vkx::Image in, res;
        vk::raii::ImageView inView{nullptr}, resView{nullptr};
    };
    std::unique_ptr<RunImages> run;

    RunImages& runImages(std::uint32_t w, std::uint32_t h, std::uint32_t ow, std::uint32_t oh) {
        if (run && run->w == w && run->h == h && run->ow == ow && run->oh == oh) return *run;
        run.reset();
        auto r = std::make_unique<RunImages>();
        r->w = w, r->h = h, r->ow = ow, r->oh = oh;
        r->upload = ctx->createBuffer(vk::DeviceSize(w) * h * 4, vk::BufferUsageFlagBits::eTransferSrc, true);
        r->download = ctx->createBuffer(vk::DeviceSize(ow) * oh * 4, vk::BufferUsageFlagBits::eTransferDst, true);
        r->in = ctx->createImage(inputFormat(srgb), w, h, RunImages::kInUsage, vk::ImageAspectFlagBits::eColor);
        r->res = ctx->createImage(kOutputFormat, ow, oh, RunImages::kResUsage, vk::ImageAspectFlagBits::eColor);
        // 2-D views (createImage makes sampled images' views 2-D arrays).
        const vk::ImageSubresourceRange range(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1);
        auto view2d = [&](const vkx::Image& img) {
            return vk::raii::ImageView(
                ctx->device, vk::ImageViewCreateInfo({}, *img.image, vk::ImageViewType::e2D, img.format, {}, range));
        };
        r->inView = view2d(r->in);
        r->resView = view2d(r->res);
        run = std::move(r);
        return *run;
    }

    void ensureScratch(std::uint32_t w, std::uint32_t h) {
        if (*scratch.image && scratch.width == w && scratch.height == h) return;
        scratch =
            ctx->createImage(kOutputFormat, w, h, vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eSampled,
                             vk::ImageAspectFlagBits::eColor, 1, 1,
                             srgb ? vk::ImageCreateFlagBits::eMutableFormat : vk::ImageCreateFlags{});
        const vk::ImageSubresourceRange range(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1);
        scratchView = vk::raii::ImageView(
            ctx->device, vk::ImageViewCreateInfo({}, *scratch.image, vk::ImageViewType::e2D, kOutputFormat, {}, range));
        // (An sRGB format cannot be a storage image: the sRGB view is for sampling only.)
        const vk::ImageViewUsageCreateInfo sampledOnly(vk::ImageUsageFlagBits::eSampled);
        scratchSampled = vk::raii::ImageView(
            ctx->device, vk::ImageViewCreateInfo({}, *scratch.image, vk::ImageViewType::e2D, inputFormat(srgb), {},
                                                 range, srgb ? &sampledOnly : nullptr));
    }
};

AaPass::AaPass(std::shared_ptr<vkx::Context> ctx, std::string_view method, const MethodSettings& settings,
               Sampling sampling, EdgePath edges)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    if (!ctx) throw Error("gpu::AaPass: no Vulkan context");
    m.ctx = std::move(ctx);
    m.method = &methodById(method);
    if (!hasGpuPass(m.method->id)) throw Error(fmt::format("{}: no GPU pass", m.method->id));
    if (settings.filtering != Filtering::Gpu)
        throw Error(
            fmt::format("{}: exact filtering is a CPU option; on the GPU use sampling=model (the GPU "
                        "sampling model) or sampling=hardware",
                        m.method->id));
    m.params = resolveParams(m.method->id, settings);
    m.sampling = sampling;
    // Validates the params now (the constants' checks).
    detail::AaSpecialization spec = detail::aaSpecialization(m.params, sampling);
    vkx::Context& c = *m.ctx;
    const bool cpuDevice = c.physical.getProperties().deviceType == vk::PhysicalDeviceType::eCpu;
    // The segments (blur.comp, edge_list.glsl) sum and shuffle across a subgroup, whose lanes
    // must be consecutive invocations of the work group (they share rows): a probe, made when
    // the segments are first wanted on a device.
    const bool subgroupOps =
        c.computeSubgroupOps(vk::SubgroupFeatureFlagBits::eBasic | vk::SubgroupFeatureFlagBits::eArithmetic |
                             vk::SubgroupFeatureFlagBits::eShuffle);
    const auto segmentsRun = [&] { return subgroupOps && subgroupsAreConsecutive(c); };
    const auto noSegments = [&] {
        return Error(
            fmt::format("{}: edges=segments needs subgroup arithmetic and shuffles in compute shaders, with a "
                        "subgroup's lanes consecutive invocations of the work group, which this device does not "
                        "have ({} run on it)",
                        m.method->id, hasEdgePass(m.method->id) ? "edges=list or one-pass" : "edges=one-pass"));
    };
    if (std::holds_alternative<aa::Ddaa2Params>(m.params)) {
        // ddaa2's batched search rounds: faster on lavapipe, slower on the H200 (ddaa2.comp).
        // SSFX_GPU_BATCHED_SEARCH=0|1 forces either, for tests and measurements (docs/gpu.md).
        spec.batchedSearch = envChoice("SSFX_GPU_BATCHED_SEARCH", cpuDevice) ? 1 : 0;
    }
    {
        // fxaa3d's walk one side a step on a CPU device, and ddaa2's search there in the model
        // (fxaa3d.comp, ddaa2.comp): fewer reads a SIMD lane group, but more loop passes, which
        // cost ddaa2's cheap reads of the hardware mode more than they save (lavapipe, paired
        // runs; docs/gpu.md). Both sides a step, as the paper's shaders, on a GPU (unmeasured
        // there). SSFX_GPU_SIDE_SEARCH=0|1 forces either (docs/gpu.md).
        const bool fxaa3d = std::holds_alternative<aa::Fxaa3dParams>(m.params);
        const bool ddaa2 = std::holds_alternative<aa::Ddaa2Params>(m.params);
        if (fxaa3d || ddaa2)
            spec.sideSearch =
                envChoice("SSFX_GPU_SIDE_SEARCH", cpuDevice && (fxaa3d || sampling == Sampling::Model)) ? 1 : 0;
    }
    vkx::guarded("creating the GPU pass", [&] {
        m.sampler = vk::raii::Sampler(
            c.device,
            vk::SamplerCreateInfo({}, vk::Filter::eLinear, vk::Filter::eLinear, vk::SamplerMipmapMode::eNearest,
                                  vk::SamplerAddressMode::eClampToEdge, vk::SamplerAddressMode::eClampToEdge,
                                  vk::SamplerAddressMode::eClampToEdge));
        m.srgb = spec.srgb != 0;
        if (m.srgb && !srgbBytesRecovered(c, m.sampler))
            throw Error(
                fmt::format("{}: texture=srgb: this device's sRGB decode does not give the texels' bytes "
                            "back (gpu.md, \"sRGB textures\"); use --backend cpu",
                            m.method->id));
        m.deviceDecode = sampling == Sampling::Model &&
                         decodeIsExact(c, m.sampler, m.srgb ? TextureFormat::Srgb : TextureFormat::Unorm);
        spec.deviceDecode = m.deviceDecode ? 1 : 0;
        // The tables: the x4 resolve's weights, the CPU's own floats; texture=srgb's decoded
        // levels and encode thresholds.
        std::vector<float> t;
        aa::MitchellParams mp;
        if (const auto* p = std::get_if<aa::MitchellParams>(&m.params)) mp = *p;
        // Tap d of the x4 resolve, from output centre f = 2 (any pixel gives the same t = d + 0.5).
        for (int d = -8; d <= 7; ++d) t.push_back(aa::mitchell((float(2 + d) + 0.5f - 2.0f) / 4.0f, mp.B, mp.C));
        static_assert(SSFX_AA_MITCHELL4_COUNT == 16);
        using Encode = ssfx::detail::SrgbEncodeTable;
        static_assert(SSFX_AA_SRGB_LEVELS == kSrgb8.size() && SSFX_AA_SRGB_BUCKETS == Encode::kBuckets &&
                      SSFX_AA_SRGB_LOW_BITS == Encode::kLowBits && SSFX_AA_SRGB_SHIFT == Encode::kShift &&
                      SSFX_AA_SRGB_OFFSET_MASK == Encode::kOffsetMask && Encode::kNoThreshold <= 0xFFFF);
        t.insert(t.end(), kSrgb8.begin(), kSrgb8.end());
        for (const std::int32_t k : ssfx::detail::srgbEncodeTable().packed) t.push_back(std::bit_cast<float>(k));
        // texture=srgb, model: the device's decoded values to the levels (zeros where unused).
        const std::vector<float> decodeTable = m.srgb && sampling == Sampling::Model && !m.deviceDecode
                                                   ? probeSrgbDecodeTable(c, m.sampler)
                                                   : std::vector<float>{};
        m.srgbDecodeTable = !decodeTable.empty();
        spec.srgbDecodeTable = m.srgbDecodeTable ? 1 : 0;
        if (m.srgbDecodeTable)
            t.insert(t.end(), decodeTable.begin(), decodeTable.end());
        else
            t.resize(t.size() + Encode::kBuckets, 0.0f);
        m.tables = c.uploadBuffer(t.data(), t.size() * sizeof(float), vk::BufferUsageFlagBits::eStorageBuffer);
        detail::AaSpecialization first = spec;
        if (hasEdgePass(m.method->id)) {
            first.stage = SSFX_AA_STAGE_CLASSIFY;
            // A CPU device (lavapipe) pays for every work group it starts, so its edge pass
            // runs few groups that loop over the list; a GPU gets one pixel per invocation.
            // (lavapipe at 1920x1080: fxaa3c's edge pass about half as long with 256 groups
            // as with one group per 64 listed pixels; docs/gpu.md.)
            if (cpuDevice) first.edgeGroups = kCpuEdgeGroups;
            // Tests of the loop budget lower it (SSFX_GPU_EDGE_GROUPS; docs/gpu.md).
            if (const char* v = std::getenv("SSFX_GPU_EDGE_GROUPS")) first.edgeGroups = std::max(1, std::atoi(v));
            // Auto: where a driver runs shaders as masked SIMD code on a CPU (it runs the edge
            // computation for every lane group holding one edge pixel) the segments, which
            // spread a subgroup's edge pixels over its lanes, or the list, which spreads the
            // image's (cpuEdgePath); one pass on a GPU (no atomics, no plane, no barriers
            // between dispatches). docs/gpu.md gives the measurements behind each.
            m.edgePath = edges != EdgePath::Auto ? edges
                         : cpuDevice             ? cpuEdgePath(m.method->id, sampling, segmentsRun)
                                                 : kGpuEdgePath;
            if (edges == EdgePath::Segments && !segmentsRun()) throw noSegments();
        } else {
            // blur: its segments (a texel fetched 2.5 times a pixel, not 9) on a CPU device,
            // where an invocation and a fetch cost most (docs/gpu.md), where its subgroups are
            // runs of consecutive invocations (the segments' lanes share rows); a pixel an
            // invocation on a GPU. The methods without a segments module: one pass.
            const bool wanted =
                hasSegments(m.method->id) && (edges == EdgePath::Segments || (edges == EdgePath::Auto && cpuDevice));
            const bool rows = wanted && segmentsRun();
            if (wanted && edges == EdgePath::Segments && !rows) throw noSegments();
            m.edgePath = rows ? EdgePath::Segments : EdgePath::OnePass;
        }
        // The list's three pipelines only for the list path (the others' one pipeline is made
        // when first used): a pipeline takes lavapipe about a second to compile.
        const bool list = hasEdgePass(m.method->id) && m.edgePath == EdgePath::List;
        if (!hasEdgePass(m.method->id) || list)
            m.pipeline = makePipeline(c, shaderFor(m.method->id, sampling, m.edgePath == EdgePath::Segments), first);
        if (hasEdgePass(m.method->id)) {
            m.spec = spec;
            const vk::DeviceSize range = c.physical.getProperties().limits.maxStorageBufferRange;
            m.maxListPixels = (range - 16) / 4;
            m.edgeLoops = edgeLoopIterations(m.params);
            m.loopBudget = c.maxShaderLoopIterations;
            // A smaller limit for tests of the one-pass path (docs/gpu.md).
            if (const char* v = std::getenv("SSFX_GPU_EDGE_LIST_MAX_PIXELS"))
                m.maxListPixels = std::min<vk::DeviceSize>(m.maxListPixels, std::strtoull(v, nullptr, 10));
            detail::AaSpecialization second = spec;
            second.stage = SSFX_AA_STAGE_EDGES;
            second.groupX = SSFX_AA_EDGE_GROUP;
            second.groupY = 1;
            // ddaa2's search reads as texel pairs by index (ppaa.glsl's pairRead): always in the
            // model (the same bytes, without the model's coordinates and weights); in the
            // hardware mode on a CPU device, where two fetches cost less than one filtered read
            // (lavapipe: ddaa2's edge dispatch about 0.75 of its time, paired runs), while a
            // GPU's texture unit filters in one instruction (unmeasured: SSFX_GPU_COORDINATE_READS=0
            // forces the pairs there). (fxaa3d's walk as quad reads by index was slower on
            // lavapipe in a paired A/B run: its four fetches stay, and the coordinate path's
            // arithmetic is cheap there. In the hardware mode too: its pairs and quads by index
            // took the photograph's edge dispatch from 26-29 to 33-35 ms, docs/gpu.md.)
            // SSFX_GPU_COORDINATE_READS=1 forces the reads at coordinates (tests), =0 the pairs
            // (measurements of the hardware mode on a GPU; docs/gpu.md).
            const bool pairs = !envChoice("SSFX_GPU_COORDINATE_READS", !(sampling == Sampling::Model || cpuDevice));
            second.pairReads = std::holds_alternative<aa::Ddaa2Params>(m.params) && pairs;
            m.edgeSpec = second;
            if (list) {
                m.edgePass = makePipeline(c, shaderFor(m.method->id, sampling), second);
                detail::AaSpecialization lumaSpec = spec;
                lumaSpec.stage = SSFX_AA_STAGE_LUMA;
                m.lumaPass = makePipeline(c, shaderFor(m.method->id, sampling), lumaSpec);
            }
        }
        aa::Ssaax2Params resolveParams;  // ddaa2p's resolve reads ddaa2's output in the pass's format
        resolveParams.texture = detail::textureOf(m.params);
        if (m.method->id == "ddaa2p")
            m.resolve =
                makePipeline(c, shaderFor("ssaax2", sampling), detail::aaSpecialization(resolveParams, sampling));
        m.timer = std::make_unique<vkx::GpuTimer>(c, 1 + Impl::kMaxDispatches);
        m.countReadback = c.createBuffer(16, vk::BufferUsageFlagBits::eTransferDst, true);
    });
}

AaPass::~AaPass() = default;

const MethodInfo& AaPass::method() const { return *impl_->method; }
Sampling AaPass::sampling() const { return impl_->sampling; }
EdgePath AaPass::edgePath() const { return impl_->edgePath; }
bool AaPass::deviceDecode() const { return impl_->deviceDecode; }
bool AaPass::srgbDecodeTable() const { return impl_->srgbDecodeTable; }
double AaPass::lastMilliseconds() const { return impl_->lastMs; }
const std::vector<AaPass::DispatchTime>& AaPass::lastDispatches() const { return impl_->lastDispatches; }
double AaPass::lastEdgeShare() const { return impl_->lastEdgeShare; }

void AaPass::record(const vk::raii::CommandBuffer& cmd, const ImageRef& input, const ImageRef& output) {
    Impl& m = *impl_;
    const std::string_view id = m.method->id;
    const std::uint32_t scale = std::uint32_t(m.method->inputScale);
    if (!input.view || !output.view) throw Error(fmt::format("{}: record() without an input or output view", id));
    if (!inputFormatOk(input.format, m.srgb))
        throw Error(m.srgb ? fmt::format("{}: input format {} (texture=srgb: expected R8G8B8A8_SRGB or B8G8R8A8_SRGB, "
                                         "the view that decodes the texels)",
                                         id, vk::to_string(input.format))
                           : fmt::format("{}: input format {} (expected R8G8B8A8_UNORM or B8G8R8A8_UNORM; sRGB "
                                         "views are for texture=srgb, which decodes the texels)",
                                         id, vk::to_string(input.format)));
    if (!(input.usage & vk::ImageUsageFlagBits::eSampled))
        throw Error(fmt::format("{}: the input image needs SAMPLED usage", id));
    if (input.layout != vk::ImageLayout::eShaderReadOnlyOptimal && input.layout != vk::ImageLayout::eGeneral)
        throw Error(fmt::format("{}: input layout {} (expected SHADER_READ_ONLY_OPTIMAL or GENERAL)", id,
                                vk::to_string(input.layout)));
    if (output.format != kOutputFormat)
        throw Error(fmt::format("{}: output format {} (expected R8G8B8A8_UNORM)", id, vk::to_string(output.format)));
    if (!(output.usage & vk::ImageUsageFlagBits::eStorage))
        throw Error(fmt::format("{}: the output image needs STORAGE usage", id));
    if (output.layout != vk::ImageLayout::eGeneral)
        throw Error(fmt::format("{}: output layout {} (expected GENERAL)", id, vk::to_string(output.layout)));
    if (input.width == 0 || input.height == 0) throw Error(fmt::format("{}: empty input image", id));
    if (input.width % scale != 0 || input.height % scale != 0)
        throw Error(fmt::format("{}: input size {}x{} is not divisible by {} (the method takes the {}x render)", id,
                                input.width, input.height, scale, scale));
    if (output.width != input.width / scale || output.height != input.height / scale)
        throw Error(fmt::format("{}: output is {}x{}, expected {}x{}", id, output.width, output.height,
                                input.width / scale, input.height / scale));
    m.ctx->requireImageSize(input.width, input.height, fmt::format("{} input", id));
    const int w = int(input.width), h = int(input.height);
    vkx::guarded("recording the GPU pass", [&] {
        if (id == "ddaa2p") {
            // ddaa2 on the 2x input into the pass's scratch image, then ssaax2 from it.
            m.ensureScratch(input.width, input.height);
            const vk::ImageSubresourceRange range(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1);
            const vk::ImageMemoryBarrier toGeneral(
                vk::AccessFlagBits::eShaderRead, vk::AccessFlagBits::eShaderWrite, vk::ImageLayout::eUndefined,
                vk::ImageLayout::eGeneral, VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, *m.scratch.image, range);
            // (Also orders this recording's writes after an earlier recording's reads.)
            cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eComputeShader,
                                {}, {}, {}, toGeneral);
            m.dispatchMethod(cmd, input.view, input.layout, *m.scratchView, detail::aaConstants(m.params, w, h, w, h));
            const vk::ImageMemoryBarrier written(
                vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eShaderRead, vk::ImageLayout::eGeneral,
                vk::ImageLayout::eGeneral, VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, *m.scratch.image, range);
            cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eComputeShader,
                                {}, {}, {}, written);
            m.dispatch(*m.resolve, cmd, *m.scratchSampled, vk::ImageLayout::eGeneral, output.view,
                       detail::aaConstants(aa::Ssaax2Params{}, w, h, w / 2, h / 2), {}, Impl::Grid::Pixels, "resolve");
            return;
        }
        m.dispatchMethod(cmd, input.view, input.layout, output.view,
                         detail::aaConstants(m.params, w, h, w / int(scale), h / int(scale)));
    });
}

ImageRgba8 AaPass::run(ImageView<const Rgba8> input) {
    Impl& m = *impl_;
    vkx::Context& c = *m.ctx;
    const std::string_view id = m.method->id;
    checkDimensions(input.width(), input.height(), fmt::format("{} input", id));
    const std::uint32_t w = std::uint32_t(input.width()), h = std::uint32_t(input.height());
    const std::uint32_t scale = std::uint32_t(m.method->inputScale);
    if (w % scale != 0 || h % scale != 0)
        throw Error(fmt::format("{}: input size {}x{} is not divisible by {} (the method takes the {}x render)", id, w,
                                h, scale, scale));
    c.requireImageSize(w, h, fmt::format("{} input", id));
    const std::uint32_t ow = w / scale, oh = h / scale;
    ImageRgba8 out{int(ow), int(oh)};
    vkx::guarded("running the GPU pass", [&] {
        Impl::RunImages& r = m.runImages(w, h, ow, oh);
        for (std::uint32_t y = 0; y < h; ++y)
            std::memcpy(static_cast<std::uint8_t*>(r.upload.mapped) + std::size_t(y) * w * 4, input.row(int(y)),
                        std::size_t(w) * 4);
        using S = vk::PipelineStageFlagBits;
        using A = vk::AccessFlagBits;
        using L = vk::ImageLayout;
        c.submit([&](const vk::raii::CommandBuffer& cmd) {
            // (All commands before: a previous call's reads of the kept images.)
            vkx::transition(cmd, r.in, L::eUndefined, L::eTransferDstOptimal, S::eAllCommands, {}, S::eTransfer,
                            A::eTransferWrite);
            const vk::BufferImageCopy inCopy(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1}, {0, 0, 0}, {w, h, 1});
            cmd.copyBufferToImage(*r.upload.buffer, *r.in.image, L::eTransferDstOptimal, inCopy);
            vkx::transition(cmd, r.in, L::eTransferDstOptimal, L::eShaderReadOnlyOptimal, S::eTransfer,
                            A::eTransferWrite, S::eComputeShader, A::eShaderRead);
            vkx::transition(cmd, r.res, L::eUndefined, L::eGeneral, S::eAllCommands, {}, S::eComputeShader,
                            A::eShaderWrite);
            m.timer->reset(cmd);
            m.timer->begin(cmd, 0, S::eComputeShader);
            m.profiling = true;
            m.stages.clear();
            m.listedOf = 0;
            struct NotProfiling {  // record() may throw: later recordings are not profiled
                Impl& m;
                ~NotProfiling() { m.profiling = false; }
            } notProfiling{m};
            record(cmd, ImageRef{*r.inView, r.in.format, Impl::RunImages::kInUsage, w, h, L::eShaderReadOnlyOptimal},
                   ImageRef{*r.resView, kOutputFormat, Impl::RunImages::kResUsage, ow, oh, L::eGeneral});
            m.timer->end(cmd, 0, S::eComputeShader);
            if (m.listedOf > 0) {  // the list's pixel count (header word 3), for lastEdgeShare()
                const vk::BufferMemoryBarrier listed(A::eShaderWrite, A::eTransferRead, VK_QUEUE_FAMILY_IGNORED,
                                                     VK_QUEUE_FAMILY_IGNORED, *m.edges.buffer, 0, 16);
                cmd.pipelineBarrier(S::eComputeShader, S::eTransfer, {}, {}, listed, {});
                cmd.copyBuffer(*m.edges.buffer, *m.countReadback.buffer, vk::BufferCopy(0, 0, 16));
            }
            vkx::transition(cmd, r.res, L::eGeneral, L::eTransferSrcOptimal, S::eComputeShader, A::eShaderWrite,
                            S::eTransfer, A::eTransferRead);
            const vk::BufferImageCopy outCopy(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1}, {0, 0, 0},
                                              {ow, oh, 1});
            cmd.copyImageToBuffer(*r.res.image, L::eTransferSrcOptimal, *r.download.buffer, outCopy);
            const vk::MemoryBarrier toHost(A::eTransferWrite, A::eHostRead);
            cmd.pipelineBarrier(S::eTransfer, S::eHost, {}, toHost, {}, {});
        });
        const auto ms = m.timer->milliseconds(1 + std::uint32_t(m.stages.size()));
        m.lastMs = ms.empty() ? 0.0 : ms[0];
        m.lastDispatches.clear();
        for (std::size_t k = 0; k < m.stages.size(); ++k)
            m.lastDispatches.push_back({m.stages[k], k + 1 < ms.size() ? ms[k + 1] : 0.0});
        m.lastEdgeShare = -1;
        if (m.listedOf > 0) {
            std::uint32_t header[4];
            std::memcpy(header, m.countReadback.mapped, sizeof header);
            m.lastEdgeShare = double(header[3]) / double(m.listedOf);
        }
        for (std::uint32_t y = 0; y < oh; ++y)
            std::memcpy(out.view().row(int(y)),
                        static_cast<const std::uint8_t*>(r.download.mapped) + std::size_t(y) * ow * 4,
                        std::size_t(ow) * 4);
    });
    return out;
}

}  // namespace ssfx::gpu
