// The model sampling mode's exact float helpers (src/gpu/shaders/common/exact.glsl) on the device:
// crDiv and crSqrt must return the correctly rounded (IEEE) result, bit for bit as the CPU
// computes it, whatever the device's own division and square root return; toUnorm8 must be
// ssfx::toUnorm8. The inputs cover the values the passes divide and take roots of (texture
// coordinates, lumas, edge-search distances) and a wide random spread; the test also says
// how often the device's own result was not the correctly rounded one (on lavapipe a
// division by a constant is a multiplication by its reciprocal). Starting values 1-2 ulp
// off (from the correct result) exercise the correction loop itself, which an exact device
// never needs. A device that flushes subnormal floats to zero (Vulkan allows it unless the
// shader asks for the float-controls DenormPreserve mode; the H200 does) sees a subnormal
// input as 0: its roots are then out of crSqrt's domain there, and counted, not checked. No
// value of the model is subnormal (the smallest non-zero luma is above 2^-16). levelOver4080
// (the model's k / 4080 and v / 255 in integer arithmetic) must give ssfx::kSixteenthLevels.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <random>

#include "ssfx/core/color.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/core/sample.hpp"
#include "ssfx/vk/compute.hpp"
#include "ssfx/vk/context.hpp"

namespace ssfx {
namespace {

const std::uint32_t kExact[] = {
#include "shaders/exact.comp.inc"
};

TEST(GpuShaders, ExactHelpersMatchIeee) {
    vkx::ContextOptions o;
    o.validation = true;
    std::shared_ptr<vkx::Context> ctx;
    try {
        ctx = vkx::Context::create(o);
    } catch (const Error& e) {
        GTEST_SKIP() << "no Vulkan device: " << e.what();
    }
    // (a, b): pixel centres over image sizes, luma-like values, distances, random magnitudes.
    std::vector<float> pairs;
    auto add = [&](float a, float b) { pairs.insert(pairs.end(), {a, b}); };
    for (int n : {1, 3, 7, 37, 600, 1080, 1920, 4097, 16384})
        for (int x = 0; x < std::min(n, 2000); ++x) add(float(x) + 0.5f, float(n));
    for (int k = 0; k <= 4080; ++k) add(float(k), 4080.0f);
    for (int v = 0; v <= 255; ++v) add(float(v), 255.0f);
    for (int d1 = 1; d1 <= 16; ++d1)
        for (int d2 = 1; d2 <= 16; ++d2) add(float(std::min(d1, d2)), float(d1 + d2));
    std::mt19937 rng(20261202);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uniform_int_distribution<int> expo(-20, 20);
    for (int i = 0; i < 200000; ++i) add(std::ldexp(unit(rng), expo(rng)), std::ldexp(0.5f + unit(rng), expo(rng)));
    for (int i = 0; i < 20000; ++i) add(unit(rng), 1.0f);  // the bytes of values in [0, 1]
    // Square roots near powers of two (the root's binade changes) and of subnormals. (Their
    // quotients are checked only inside crDiv's domain, exact.glsl's twoProduct: the passes
    // divide values far from both ends of the float range.)
    for (int e = -126; e <= 126; ++e)
        for (int d = -3; d <= 3; ++d)
            add(std::bit_cast<float>(std::bit_cast<std::uint32_t>(std::ldexp(1.0f, e)) + std::uint32_t(d)), 1.0f);
    for (int i = 0; i < 2000; ++i) add(std::ldexp(unit(rng), -126 - i % 24), 1.0f);
    const auto count = std::uint32_t(pairs.size() / 2);

    vkx::Buffer in =
        ctx->uploadBuffer(pairs.data(), pairs.size() * sizeof(float), vk::BufferUsageFlagBits::eStorageBuffer);
    constexpr std::uint32_t kPer = 10;  // results per pair (exact.comp)
    const vk::DeviceSize outBytes = vk::DeviceSize(count) * kPer * 4;
    vkx::Buffer out = ctx->createBuffer(outBytes, vk::BufferUsageFlagBits::eStorageBuffer, true);
    vkx::Buffer levels = ctx->createBuffer(4081 * 4, vk::BufferUsageFlagBits::eStorageBuffer, true);
    vkx::ComputePipeline pipe(*ctx, kExact,
                              {{vk::DescriptorType::eStorageBuffer},
                               {vk::DescriptorType::eStorageBuffer},
                               {vk::DescriptorType::eStorageBuffer}},
                              sizeof(std::uint32_t));
    vkx::DescriptorSets sets = pipe.makeSets();
    sets.bind(0, 0, in);
    sets.bind(0, 1, out);
    sets.bind(0, 2, levels);
    ctx->submit([&](const vk::raii::CommandBuffer& cmd) {
        pipe.dispatch(cmd, sets[0], &count, vkx::groupCount(count, 64));
        const vk::MemoryBarrier toHost(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eHostRead);
        cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eHost, {}, toHost, {},
                            {});
    });
    const auto* r = static_cast<const std::uint32_t*>(out.mapped);
    std::int64_t rawDivOff = 0, rawSqrtOff = 0, divWrong = 0, sqrtWrong = 0, byteWrong = 0, fromWrong = 0;
    std::int64_t flushed = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
        const float a = pairs[2 * i], b = pairs[2 * i + 1];
        const std::uint32_t* res = r + kPer * i;
        // A subnormal a that the device multiplied to 0: it flushes subnormals.
        const bool flushes = a != 0.0f && std::fabs(a) < 0x1p-126f && b == 1.0f && std::bit_cast<float>(res[9]) == 0.0f;
        flushed += flushes;
        const std::uint32_t q = std::bit_cast<std::uint32_t>(a / b), s = std::bit_cast<std::uint32_t>(std::sqrt(a));
        rawDivOff += res[0] != q;
        rawSqrtOff += res[1] != s;
        const auto inDomain = [](float v) {
            return v == 0.0f || (std::fabs(v) > 0x1p-100f && std::fabs(v) < 0x1p100f);
        };
        const bool divDomain = inDomain(a) && inDomain(b) && inDomain(a / b);
        if (divDomain && res[2] != q && divWrong++ < 5)
            ADD_FAILURE() << "crDiv(" << a << ", " << b << ") = " << std::bit_cast<float>(res[2]) << ", IEEE " << a / b;
        if (!flushes && res[3] != s && sqrtWrong++ < 5)
            ADD_FAILURE() << "crSqrt(" << a << ") = " << std::bit_cast<float>(res[3]) << ", IEEE " << std::sqrt(a);
        for (int k = 5; k <= 6; ++k)
            if (divDomain && res[k] != q && fromWrong++ < 5)
                ADD_FAILURE() << "crDivFrom(" << a << ", " << b << ", 2 ulp off) = " << std::bit_cast<float>(res[k]);
        for (int k = 7; k <= 8; ++k)
            if (!flushes && res[k] != s && fromWrong++ < 5)
                ADD_FAILURE() << "crSqrtFrom(" << a << ", " << (i % 2 ? 7 : 1)
                              << " ulp off) = " << std::bit_cast<float>(res[k]);
        if (res[4] != toUnorm8(a) && byteWrong++ < 5)
            ADD_FAILURE() << "toUnorm8(" << a << ") = " << res[4] << ", CPU " << int(toUnorm8(a));
    }
    std::printf(
        "%u pairs on %s: the device's own a / b was not the IEEE result in %lld, its sqrt in %lld; "
        "crDiv, crSqrt and toUnorm8 wrong in %lld, %lld, %lld; subnormal inputs flushed to zero: %lld\n",
        count, ctx->info.name.c_str(), (long long)rawDivOff, (long long)rawSqrtOff, (long long)divWrong,
        (long long)sqrtWrong, (long long)byteWrong, (long long)flushed);
    EXPECT_EQ(divWrong, 0);
    EXPECT_EQ(sqrtWrong, 0);
    EXPECT_EQ(byteWrong, 0);
    EXPECT_EQ(fromWrong, 0) << "the correction from wrong starting values";
    const auto* lv = static_cast<const std::uint32_t*>(levels.mapped);
    int levelsWrong = 0;
    for (int k = 0; k <= 4080; ++k)
        if (lv[k] != std::bit_cast<std::uint32_t>(kSixteenthLevels[std::size_t(k)]) && levelsWrong++ < 5)
            ADD_FAILURE() << "levelOver4080(" << k << ") = " << std::bit_cast<float>(lv[k]) << ", CPU "
                          << kSixteenthLevels[std::size_t(k)];
    EXPECT_EQ(levelsWrong, 0);
    const auto messages = ctx->validationMessages();
    EXPECT_TRUE(messages.empty()) << messages.front();
}

}  // namespace
}  // namespace ssfx
