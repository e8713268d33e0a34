// The whole frame on one device (gpu::FrameRenderer) against the same stages run one by one on
// the CPU (what ssfx render/ao/deferred/aa do), on lavapipe with the validation layer.
//
// The bounds, from the stages' own parity (docs/frame.md):
//  - AO: the GPU passes are within 4/255 of the CPU's A everywhere (tests/gpu/test_gpu_ao.cpp);
//    the shading multiplies A into the ambient term only (ambient x albedo <= 0.15 in the
//    built-in scenes), so A moves a colour by at most 0.6/255; the shading itself is within
//    1e-4 of the CPU (tests/gpu/test_gpu_deferred.cpp). So every encoded byte is within 1 of
//    the CPU chain's (a value near a rounding boundary flips), and few bytes differ at all.
//  - AA: the GPU pass gives the CPU's bytes for the same input (tests/gpu/test_gpu_aa.cpp), so
//    the frame with AA is exactly the CPU's AA of the frame without it.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cstdlib>

#include "ssfx/aa/registry.hpp"
#include "ssfx/ao/sao.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/deferred/adaptive.hpp"
#include "ssfx/deferred/shading.hpp"
#include "ssfx/gpu/frame.hpp"
#include "ssfx/render/renderer.hpp"
#include "ssfx/scene/camera_path.hpp"
#include "ssfx/scene/scene.hpp"
#include "tests/gpu/gpu_context.hpp"

namespace ssfx::test {
namespace {

struct ByteDiff {
    int max = 0;
    double share = 0;  // of the RGB bytes that differ
};
ByteDiff byteDiff(const ImageRgba8& a, const ImageRgba8& b) {
    ByteDiff d;
    EXPECT_EQ(a.width(), b.width());
    EXPECT_EQ(a.height(), b.height());
    if (a.width() != b.width() || a.height() != b.height()) return {255, 1.0};
    std::int64_t differ = 0;
    const auto* pa = reinterpret_cast<const std::uint8_t*>(a.data());
    const auto* pb = reinterpret_cast<const std::uint8_t*>(b.data());
    for (std::int64_t i = 0; i < 4 * a.pixelCount(); ++i) {
        const int e = std::abs(int(pa[i]) - int(pb[i]));
        d.max = std::max(d.max, e);
        differ += e != 0;
    }
    d.share = double(differ) / (3.0 * double(a.pixelCount()));
    return d;
}

// The size for the frame tests: 320x180.
gpu::FrameSettings smallFrame(const char* ao, const char* aa, int m) {
    gpu::FrameSettings fs;
    fs.width = 320;
    fs.height = 180;
    fs.m = m;
    fs.ao = ao;
    if (fs.ao == "sao") {
        ao::SaoParams p;
        p.guardBand = 16;
        fs.aoParams = p;
    }
    fs.aa = aa;
    return fs;
}

// The stages one by one on the CPU, on the renderer's read-back buffers: depth -> SAO ->
// G-buffer -> adaptive shading with A -> 8 bits (what ssfx ao, ssfx deferred --ao-image do).
ImageRgba8 cpuChain(render::Renderer& renderer, const scene::Scene& scene, const scene::View& view,
                    const gpu::FrameSettings& fs) {
    scene::GBuffer g = renderer.renderGBuffer(scene, view, fs.width, fs.height, fs.m);
    if (fs.ao == "sao") {
        const auto& p = std::get<ao::SaoParams>(fs.aoParams);
        const auto d = renderer.renderDepth(scene, view, fs.width, fs.height, DepthFormat::D32F, p.guardBand);
        g.ambientOcclusion = ao::sao(d.depth.view(), d.camera.camera, p);
    }
    return deferred::toRgba8(deferred::adaptiveSupersampling(scene, g, fs.shading).image);
}

TEST(GpuFrame, FramesAreTheStagesRunOneByOne) {
    REQUIRE_GRAPHICS();
    auto ctx = graphicsContext();
    const scene::Scene scene = scene::atrium();
    const auto views = scene::orbit(scene.views.at(0).second, 4);  // 4 frames of the built-in orbit
    gpu::FrameRenderer plain(ctx, scene, smallFrame("sao", "none", 4));
    gpu::FrameRenderer withAa(ctx, scene, smallFrame("sao", "ddaa2", 4));
    render::Renderer renderer(ctx);
    const MethodInfo& ddaa2 = methodById("ddaa2");
    for (std::size_t f = 0; f < views.size(); ++f) {
        const gpu::FrameResult r = plain.render(views[f]);
        const ImageRgba8 chain = cpuChain(renderer, scene, views[f], plain.settings());
        const ByteDiff d = byteDiff(r.image, chain);
        EXPECT_LE(d.max, 1) << "frame " << f;
        EXPECT_LE(d.share, 0.01) << "frame " << f;
        // The passes, in order, each timed.
        std::vector<std::string> names;
        for (const auto& p : r.passes) {
            names.push_back(p.pass);
            EXPECT_GE(p.milliseconds, 0.0) << p.pass;
        }
        EXPECT_EQ(names,
                  (std::vector<std::string>{"depth draw", "gbuffer draw", "ao", "shading", "encode", "readback"}));
        EXPECT_GT(r.totalMs(), 0.0);
        // With DDAA2: the CPU's DDAA2 of the frame without it, byte for byte.
        const gpu::FrameResult a = withAa.render(views[f]);
        EXPECT_EQ(a.image, ddaa2.run(r.image.view(), {}, {})) << "frame " << f;
        EXPECT_EQ(a.passes.size(), 7u);
    }
    expectNoValidationMessages(ctx);
}

TEST(GpuFrame, NoAoNoAaOneSampleIsThePlainRender) {
    // --ao none --aa none --ss 1: the G-buffer's one sample per pixel, shaded: the deferred
    // renderer's plain image (ssfx deferred --ss 1), within the shading's parity.
    REQUIRE_GRAPHICS();
    auto ctx = graphicsContext();
    const scene::Scene scene = scene::cornellBox();
    const gpu::FrameSettings fs = smallFrame("none", "none", 1);
    gpu::FrameRenderer frame(ctx, scene, fs);
    render::Renderer renderer(ctx);
    const scene::View& view = scene.views.at(0).second;
    const gpu::FrameResult r = frame.render(view);
    const scene::GBuffer g = renderer.renderGBuffer(scene, view, fs.width, fs.height, 1);
    const ImageRgba8 plain = deferred::toRgba8(deferred::bruteForceSupersampling(scene, g, fs.shading.shading).image);
    const ByteDiff d = byteDiff(r.image, plain);
    EXPECT_LE(d.max, 1);
    EXPECT_LE(d.share, 1e-3);
    EXPECT_EQ(r.passes.size(), 4u);  // gbuffer draw, shading, encode, readback
    expectNoValidationMessages(ctx);
}

TEST(GpuFrame, BadSettingsAreRefusedByName) {
    REQUIRE_GRAPHICS();
    auto ctx = graphicsContext();
    const scene::Scene scene = scene::cornellBox();
    const auto refused = [&](gpu::FrameSettings fs, const char* words) {
        try {
            gpu::FrameRenderer frame(ctx, scene, fs);
            ADD_FAILURE() << "accepted; expected an error with '" << words << "'";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    auto fs = smallFrame("sao", "ddaa2", 4);
    fs.ao = "raytraced";
    refused(fs, "raytraced");
    fs = smallFrame("none", "ssaax2", 4);
    refused(fs, "ssaax2");
    fs = smallFrame("none", "nosuch", 4);
    refused(fs, "nosuch");
    fs = smallFrame("none", "none", 5);
    refused(fs, "--ss 5");
    fs = smallFrame("none", "none", 4);
    fs.width = ctx->info.maxImageDimension2D / 2;  // the 4x4 G-buffer is beyond the device's limit
    fs.height = 8;
    refused(fs, "G-buffer");
    expectNoValidationMessages(ctx);
}

}  // namespace
}  // namespace ssfx::test
