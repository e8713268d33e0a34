// Adaptive shading on the GPU (gpu::AdaptiveShading) against the CPU's deferred methods, on
// lavapipe with the validation layer: k, the metrics, the image and the counts.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ssfx/core/error.hpp"
#include "ssfx/deferred/adaptive.hpp"
#include "ssfx/gpu/deferred.hpp"
#include "ssfx/render/renderer.hpp"
#include "ssfx/scene/scene.hpp"
#include "tests/deferred/hand_made_gbuffer.hpp"
#include "tests/gpu/gpu_context.hpp"

namespace ssfx::test {
namespace {

struct Diff {
    double max = 0, mean = 0;
};
Diff diff(const deferred::ImageRgbF& a, const deferred::ImageRgbF& b) {
    Diff d;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double e = std::abs(double(a.pixels[i][c]) - double(b.pixels[i][c]));
            d.max = std::max(d.max, e);
            d.mean += e;
        }
    d.mean /= 3.0 * double(a.pixels.size());
    return d;
}

// Whether the CPU's k at a pixel sits on a float tie: its largest metric within a relative
// 1e-5 of a rounding boundary (a half-integer), or the luminance range within 1e-5 of FXAA's
// threshold (where the shading metric switches between 0 and c r).
bool tie(const deferred::DeferredResult& cpu, const deferred::DeferredResult& gpu, int x, int y) {
    for (const float k : {std::max({cpu.kDepth(x, y), cpu.kNormal(x, y), cpu.kShading(x, y)}),
                          std::max({gpu.kDepth(x, y), gpu.kNormal(x, y), gpu.kShading(x, y)})}) {
        const double boundary = std::floor(double(k)) + 0.5;
        if (std::abs(double(k) - boundary) <= 1e-5 * std::max(1.0, double(k))) return true;
    }
    return (cpu.kShading(x, y) == 0.0f) != (gpu.kShading(x, y) == 0.0f);  // the threshold test flipped
}

// The GPU's k, metrics, image and counts against the CPU's on rendered G-buffers (the model
// lookup). Bounds, from the measured agreement on lavapipe (docs/gpu.md):
//  - k: equal but at ties, at most 0.01 % of the pixels (the bound); measured 0;
//  - the metrics: within a relative 1e-5 (measured 1.3e-6: float rounding of the device's
//    sqrt, division and the variance's order against the CPU's double);
//  - the image: within 1e-4 per channel (measured 2.9e-6: the device's pow, normalize and
//    division, a few ulp of values up to about 1.5); mean within 1e-6.
TEST(GpuDeferred, AdaptiveOnRenderedGBuffersIsTheCpus) {
    REQUIRE_GRAPHICS();
    auto ctx = test::graphicsContext();
    render::Renderer renderer(ctx);
    for (const auto& [name, viewName] : {std::pair{"atrium", "nave"}, std::pair{"cornell", "corner"}}) {
        const scene::Scene scene = scene::loadScene(name);
        gpu::AdaptiveShading shading(ctx, scene);
        for (const int m : {2, 3, 4}) {
            SCOPED_TRACE(fmt::format("{}:{} m = {}", name, viewName, m));
            const int w = 160, h = 120;
            const scene::GBuffer g = renderer.renderGBuffer(scene, scene.view(viewName), w, h, m);
            const deferred::AdaptiveParams p;
            const auto cpu = deferred::adaptiveSupersampling(scene, g, p);
            const auto gpu = shading.adaptive(g, p);
            int kDiffer = 0, notTies = 0;
            double metricMax = 0;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    for (const auto plane : {&deferred::DeferredResult::kDepth, &deferred::DeferredResult::kNormal,
                                             &deferred::DeferredResult::kShading}) {
                        const float a = (gpu.*plane)(x, y), b = (cpu.*plane)(x, y);
                        metricMax = std::max(metricMax, std::abs(double(a) - double(b)) / std::max(1.0, double(b)));
                    }
                    if (gpu.samples(x, y) != cpu.samples(x, y)) {
                        ++kDiffer;
                        notTies += tie(cpu, gpu, x, y) ? 0 : 1;
                    }
                }
            EXPECT_LE(kDiffer, int(1e-4 * w * h));
            EXPECT_EQ(notTies, 0);
            EXPECT_LE(metricMax, 1e-5);
            const Diff d = diff(gpu.image, cpu.image);
            EXPECT_LE(d.max, 1e-4);
            EXPECT_LE(d.mean, 1e-6);
            if (kDiffer == 0) {
                EXPECT_EQ(gpu.shaded, cpu.shaded);
            }
            EXPECT_EQ(gpu.possible, cpu.possible);
            // Lane counts: the busy lane-iterations are the rest pass's samples.
            EXPECT_EQ(std::int64_t(gpu.busyLanes), gpu.shaded - std::int64_t(w) * h);
            EXPECT_GE(gpu.issuedLanes, gpu.busyLanes);
            EXPECT_GE(gpu.subgroupSize, 1);

            // The tiled variant: the same image and samples, fewer idle lanes.
            deferred::AdaptiveParams tiled = p;
            tiled.tiled = true;
            const auto t = shading.adaptive(g, tiled);
            EXPECT_EQ(t.image, gpu.image);
            EXPECT_EQ(t.shaded, gpu.shaded);
            EXPECT_EQ(t.busyLanes, gpu.busyLanes);
            EXPECT_LT(t.idleLaneShare(), gpu.idleLaneShare());
            // The sample list: the same image, samples and busy lanes; idle lanes only in the
            // last partial subgroup of the shade stage.
            const auto l = shading.adaptive(g, p, gpu::Schedule::SampleList);
            EXPECT_EQ(l.image, gpu.image);
            EXPECT_EQ(l.samples.pixels(), gpu.samples.pixels());
            EXPECT_EQ(l.shaded, gpu.shaded);
            EXPECT_EQ(l.busyLanes, gpu.busyLanes);
            EXPECT_LT(l.issuedLanes - l.busyLanes, std::uint64_t(l.subgroupSize));
            // Its three dispatches' timestamps lie inside the rest pass's (lavapipe has
            // timestamps); the other schedules have none.
            EXPECT_GT(l.listShadeMs, 0.0);
            EXPECT_GT(l.listEnqueueMs, 0.0);
            EXPECT_GT(l.listResolveMs, 0.0);
            EXPECT_LE(l.listEnqueueMs + l.listShadeMs + l.listResolveMs, l.restMs + 1e-6);
            EXPECT_EQ(gpu.listShadeMs, 0.0);

            // Brute force on the GPU against the CPU's, within the same bounds.
            const auto bf = shading.bruteForce(g, p.shading);
            const Diff db = diff(bf.image, deferred::bruteForceSupersampling(scene, g, p.shading).image);
            EXPECT_LE(db.max, 1e-4);
            EXPECT_EQ(bf.shaded, std::int64_t(w) * h * m * m);
            EXPECT_EQ(bf.busyLanes, std::uint64_t(bf.shaded));

            // Stall changes the cost, not the image.
            deferred::AdaptiveParams stalled = p;
            stalled.shading.stall = 20;
            EXPECT_EQ(shading.adaptive(g, stalled).image, gpu.image);
        }
    }
    expectNoValidationMessages(ctx);
}

// The device's sampler (textureGrad): trilinear here (maxAnisotropy 1), since lavapipe's
// anisotropic filtering takes about 30 s for a 40x30 m = 4 image (docs/gpu.md); against the
// CPU's sampler model the image differs where the device's filter does (its own level of
// detail and 8-bit weights): PSNR at least 30 dB (measured 32.3 dB on the atrium at m = 4),
// and the samples are the model's but where S differs enough to move the shading metric.
TEST(GpuDeferred, HardwareLookupIsCloseToTheModel) {
    REQUIRE_GRAPHICS();
    auto ctx = test::graphicsContext();
    render::Renderer renderer(ctx);
    const scene::Scene scene = scene::atrium();
    const scene::GBuffer g = renderer.renderGBuffer(scene, scene.view("nave"), 160, 120, 4);
    deferred::AdaptiveParams p;
    p.shading.maxAnisotropy = 1;
    gpu::AdaptiveShading hardware(ctx, scene, gpu::Sampling::Hardware);
    EXPECT_EQ(hardware.lookup(), gpu::Sampling::Hardware);
    const auto hw = hardware.adaptive(g, p);
    const auto cpu = deferred::adaptiveSupersampling(scene, g, p);
    EXPECT_GE(10.0 * std::log10(1.0 / deferred::mse(hw.image, cpu.image)), 30.0);
    EXPECT_LE(std::abs(hw.shadedPercent() - cpu.shadedPercent()), 2.0);
    // An untextured scene: no lookup, the model's image within the model's bound.
    const scene::Scene cornell = scene::cornellBox();
    const scene::GBuffer gc = renderer.renderGBuffer(cornell, cornell.views.at(0).second, 64, 48, 2);
    gpu::AdaptiveShading hwCornell(ctx, cornell, gpu::Sampling::Hardware);
    EXPECT_LE(diff(hwCornell.adaptive(gc, p).image, deferred::adaptiveSupersampling(cornell, gc, p).image).max, 1e-4);
    expectNoValidationMessages(ctx);
}

// record() on the renderer's G-buffer where the draw left it (no read-back, no upload), in
// the draw's command buffer, against adaptive() on the same draw read back and uploaded. The
// only difference is the normals: the device decodes the SNORM attachment itself where the
// host path uploads the renderer's decoded floats (max(c / 32767, -1) both, within an ulp),
// so the bound is the parity test's: k equal, the image within 1e-4 per channel.
TEST(GpuDeferred, RecordOnTheRenderersGBufferInGpuMemoryIsTheUploadedRun) {
    REQUIRE_GRAPHICS();
    auto ctx = test::graphicsContext();
    render::Renderer renderer(ctx);
    const scene::Scene scene = scene::atrium();
    const scene::View& view = scene.view("nave");
    gpu::AdaptiveShading shading(ctx, scene);
    const int w = 96, h = 72, m = 3;
    deferred::AdaptiveParams p;
    p.tiled = true;
    const auto uploaded = shading.adaptive(renderer.renderGBuffer(scene, view, w, h, m), p);

    using F = vk::Format;
    using L = vk::ImageLayout;
    using S = vk::PipelineStageFlagBits;
    using A = vk::AccessFlagBits;
    const auto usage = vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eTransferSrc;
    vkx::Image out = ctx->createImage(F::eR32G32B32A32Sfloat, std::uint32_t(w), std::uint32_t(h), usage,
                                      vk::ImageAspectFlagBits::eColor);
    vkx::Buffer down = ctx->createBuffer(vk::DeviceSize(w) * h * 16, vk::BufferUsageFlagBits::eTransferDst, true);
    const scene::GBuffer frame = renderer.renderGBufferOnDevice(
        scene, view, w, h, m, [&](const vk::raii::CommandBuffer& cmd, const render::DeviceGBufferImages& images) {
            // What record() refuses, before it records anything: an AO plane of the wrong format
            // and size (the depth's), m = 5, an output of the wrong size.
            const gpu::ImageRef output{*out.view,        F::eR32G32B32A32Sfloat, usage,
                                       std::uint32_t(w), std::uint32_t(h),       L::eGeneral};
            gpu::DeviceGBuffer bad = gpu::deviceGBuffer(images);
            bad.ambientOcclusion = gpu::ImageRef{images.depth.view,  images.depth.format, images.depth.usage,
                                                 images.depth.width, images.depth.height, images.depth.layout};
            EXPECT_THROW(shading.record(cmd, bad, p, output), Error);
            bad = gpu::deviceGBuffer(images);
            bad.m = 5;
            EXPECT_THROW(shading.record(cmd, bad, p, output), Error);
            gpu::ImageRef narrow = output;
            narrow.width -= 1;
            EXPECT_THROW(shading.record(cmd, gpu::deviceGBuffer(images), p, narrow), Error);
            vkx::transition(cmd, out, L::eUndefined, L::eGeneral, S::eTopOfPipe, {}, S::eComputeShader,
                            A::eShaderWrite);
            // The sample list: its indirect dispatch in the caller's command buffer.
            shading.record(cmd, gpu::deviceGBuffer(images), p, output, gpu::Schedule::SampleList);
            vkx::transition(cmd, out, L::eGeneral, L::eTransferSrcOptimal, S::eComputeShader, A::eShaderWrite,
                            S::eTransfer, A::eTransferRead);
            cmd.copyImageToBuffer(*out.image, L::eTransferSrcOptimal, *down.buffer,
                                  vk::BufferImageCopy(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1}, {0, 0, 0},
                                                      {std::uint32_t(w), std::uint32_t(h), 1}));
        });
    EXPECT_EQ(frame.width, w);
    EXPECT_EQ(frame.m, m);
    EXPECT_TRUE(frame.depth.empty() && frame.normal.empty());  // nothing was read back
    deferred::ImageRgbF recorded(w, h);
    const auto* texels = static_cast<const float*>(down.mapped);
    for (std::size_t i = 0; i < recorded.pixels.size(); ++i) {
        recorded.pixels[i] = {texels[4 * i], texels[4 * i + 1], texels[4 * i + 2]};
        ASSERT_EQ(texels[4 * i + 3], 1.0f);
    }
    const Diff d = diff(recorded, uploaded.image);
    EXPECT_LE(d.max, 1e-4);
    EXPECT_LE(d.mean, 1e-6);
    std::fprintf(stderr, "record on the renderer's G-buffer against the uploaded run: max %.3g, mean %.3g\n", d.max,
                 d.mean);
    // Nothing to record, or a bad m: refused before any draw.
    EXPECT_THROW(renderer.renderGBufferOnDevice(scene, view, w, h, m, {}), Error);
    EXPECT_THROW(renderer.renderGBufferOnDevice(scene, view, w, h, 5, [](auto&&...) {}), Error);
    expectNoValidationMessages(ctx);
}

// GBuffer::ambientOcclusion on the GPU: the ambient term of each sample times its pixel's
// value, as the CPU does (the same product of floats); the parity bounds of the test above.
TEST(GpuDeferred, AmbientOcclusionScalesTheAmbientTermAsTheCpuDoes) {
    REQUIRE_GRAPHICS();
    auto ctx = test::graphicsContext();
    render::Renderer renderer(ctx);
    const scene::Scene scene = scene::atrium();
    gpu::AdaptiveShading shading(ctx, scene);
    const int w = 96, h = 72;
    scene::GBuffer g = renderer.renderGBuffer(scene, scene.view("nave"), w, h, 2);
    const deferred::AdaptiveParams p;
    const auto plain = shading.adaptive(g, p);
    g.ambientOcclusion = ImageF(w, h, 1.0f);
    EXPECT_EQ(shading.adaptive(g, p).image, plain.image);  // 1: the same bits as without
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) g.ambientOcclusion(x, y) = 0.2f + 0.05f * float((7 * x + 13 * y) % 17);
    const auto gpu = shading.adaptive(g, p, gpu::Schedule::SampleList);
    const auto cpu = deferred::adaptiveSupersampling(scene, g, p);
    EXPECT_NE(gpu.image, plain.image);
    int kDiffer = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (gpu.samples(x, y) != cpu.samples(x, y)) {
                ++kDiffer;
                EXPECT_TRUE(tie(cpu, gpu, x, y)) << x << "," << y;
            }
    EXPECT_LE(kDiffer, int(1e-4 * w * h));
    const Diff d = diff(gpu.image, cpu.image);
    EXPECT_LE(d.max, 1e-4);
    EXPECT_LE(d.mean, 1e-6);
    EXPECT_LE(
        diff(shading.bruteForce(g, p.shading).image, deferred::bruteForceSupersampling(scene, g, p.shading).image).max,
        1e-4);
    g.ambientOcclusion(5, 5) = NAN;
    EXPECT_THROW(shading.adaptive(g, p), Error);
    expectNoValidationMessages(ctx);
}

TEST(GpuDeferred, AllSamplesAreBruteForceBitForBit) {
    REQUIRE_DEVICE();
    auto ctx = gpuContext();
    const scene::Scene scene = scene::atrium();
    gpu::AdaptiveShading shading(ctx, scene);
    for (int m = 1; m <= 4; ++m) {
        SCOPED_TRACE(m);
        const scene::GBuffer g = test::handMadeGBuffer(scene, 19, 13, m, true);  // partial 8 x 8 tiles
        deferred::AdaptiveParams p;
        p.cDepth = 1e9f;
        for (const gpu::Schedule schedule :
             {gpu::Schedule::PerPixel, gpu::Schedule::Tiled, gpu::Schedule::SampleList}) {
            const auto a = shading.adaptive(g, p, schedule);
            const auto r = shading.bruteForce(g, p.shading);
            for (auto k : a.samples.pixels()) ASSERT_EQ(k, m * m);
            EXPECT_EQ(a.image, r.image);
            // Every sample, plus the first one again where k > 1 (textured: its footprint changed).
            EXPECT_EQ(a.shaded, std::int64_t(19 * 13) * (m * m + (m > 1 ? 1 : 0)));
            EXPECT_LE(diff(a.image, deferred::adaptiveSupersampling(scene, g, p).image).max, 1e-4);
        }
    }
    expectNoValidationMessages(ctx);
}

// lavapipe ends an invocation's loops once they have run 65535 iterations together
// (vkx::Context::maxShaderLoopIterations). The stall runs 16 of its steps a loop iteration, so
// brute force at m = 4 with a stall of 4200 (16 x 4200 single steps a pixel: lavapipe cut
// the sample loop short, 3058 of 3072 pixels wrong at 64 x 48, before) is the CPU's; on a
// device with such a budget, a stall past it is refused by name, not shaded wrong.
TEST(GpuDeferred, StallsWithinTheLoopBudgetAreTheCpusAndOthersAreRefused) {
    REQUIRE_DEVICE();
    auto ctx = gpuContext();
    const scene::Scene scene = scene::atrium();
    gpu::AdaptiveShading shading(ctx, scene);
    const scene::GBuffer g = test::handMadeGBuffer(scene, 9, 7, 4, true);
    deferred::ShadingParams sp;
    sp.stall = 4200;
    EXPECT_LE(diff(shading.bruteForce(g, sp).image, deferred::bruteForceSupersampling(scene, g, sp).image).max, 1e-4);
    if (ctx->maxShaderLoopIterations > 0) {
        sp.stall = 100000;
        try {
            shading.bruteForce(g, sp);
            ADD_FAILURE() << "no error for a stall past the loop budget";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("65535 loop iterations"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("the stall can be at most"), std::string::npos) << e.what();
        }
    }
    expectNoValidationMessages(ctx);
}

TEST(GpuDeferred, BadInputIsRefusedByName) {
    REQUIRE_DEVICE();
    auto ctx = gpuContext();
    const scene::Scene scene = scene::atrium();
    gpu::AdaptiveShading shading(ctx, scene);
    const scene::GBuffer good = test::handMadeGBuffer(scene, 8, 6, 2, true);
    auto expectError = [&](const scene::GBuffer& g, const deferred::AdaptiveParams& p, const std::string& part) {
        try {
            shading.adaptive(g, p);
            ADD_FAILURE() << "no error for " << part;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        }
    };
    scene::GBuffer bad = good;
    bad.depth(3, 2) = std::nanf("");
    expectError(bad, {}, "(3, 2)");
    bad = good;
    bad.uvGrad[bad.index(5, 1)].z = INFINITY;
    expectError(bad, {}, "(5, 1)");
    bad = good;
    bad.material[7] = 999;
    expectError(bad, {}, "material 999");
    bad = good;
    bad.normal.pop_back();
    expectError(bad, {}, "do not match its size");
    deferred::AdaptiveParams p;
    p.cDepth = -1.0f;
    expectError(good, p, "cDepth");
    p = {};
    p.shading.maxAnisotropy = 17;
    expectError(good, p, "maxAnisotropy");
    bad = good;
    bad.m = 5;
    EXPECT_THROW(shading.adaptive(bad, {}), Error);
    EXPECT_THROW(gpu::AdaptiveShading(nullptr, scene), Error);
    expectNoValidationMessages(ctx);
}

}  // namespace
}  // namespace ssfx::test
