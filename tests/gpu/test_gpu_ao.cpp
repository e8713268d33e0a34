// The GPU AO passes (ssfx/gpu/ao.hpp) against the CPU's (ssfx/ao/sao.hpp, alchemy.hpp), on
// lavapipe or any Vulkan device, with the validation layer and synchronization validation on
// (a validation message fails the test).
//
// Pass by pass, each GPU pass is compared with the CPU pass run on the GPU's own input (its
// previous stage read back), so each comparison isolates one pass:
//  - depth -> z: the CPU evaluates eq. 2 in double and rounds once to float; the GPU in float
//    pairs of about 46 bits (depth_to_z.comp) and rounds once. The two floats differ only
//    where the exact z lies within about 2^-40 relative (the CPU's own error near a finite far
//    plane) of a rounding boundary, and then by one ulp: the test asserts every z within one
//    ulp (2^-23 |z|) and at least 99.99 % of them bit for bit. A device's decode of a D16 or
//    D24 value may also be one ulp of d off (Vulkan lets it round; lavapipe does for D16),
//    which moves z by |dz/dd| ulp(d): the bound adds that where the format is not D32F, and
//    the bit-for-bit share is not asserted there.
//  - the pyramid, the 2x2 quad pass, the packing and both bilateral passes: every operation
//    is the CPU's, in its order, correctly rounded and not fused: the same float bits.
//  - the sample pass: the same floats but for the hash rotation's sine and cosine, which
//    are the device's (Vulkan leaves their precision to the implementation) where the CPU
//    takes double ones. The CPU's own vector kernel differs from its scalar oracle in the same
//    way (tests/ao/test_sao.cpp: every pixel within 2e-3, mean below 1e-6): a tap whose
//    truncated offset sits on a pixel boundary can move by one pixel. The same bounds here.
//  - the whole pipeline: the issue's bound, at least 99.9 % of pixels within 1/255 and none
//    beyond 4/255 (here the only differences are the sample pass's, filtered by the blur).
#include <gtest/gtest.h>

#include "tests/gpu/gpu_context.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "ssfx/ao/alchemy.hpp"
#include "ssfx/ao/gtao.hpp"
#include "ssfx/ao/raytraced.hpp"
#include "ssfx/ao/sao.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/gpu/ao.hpp"
#include "ssfx/render/renderer.hpp"
#include "ssfx/scene/analytic.hpp"
#include "ssfx/scene/scene.hpp"
#include "ssfx/vk/resources.hpp"
#include "tests/support/test_support.hpp"

namespace ssfx {
namespace {

using test::expectNoValidationMessages;
std::shared_ptr<vkx::Context> context() { return test::gpuContext(); }

template <class F>
void forEachPixel(ImageF& img, F f) {
    float* p = img.data();
    for (std::int64_t i = 0; i < img.pixelCount(); ++i) f(p[i]);
}

bool sameBits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

// Pixels whose bits differ (NaN never appears here; -inf equals -inf).
std::int64_t bitsDiffer(const ImageF& a, const ImageF& b, std::string* first = nullptr) {
    EXPECT_EQ(a.width(), b.width());
    EXPECT_EQ(a.height(), b.height());
    std::int64_t n = 0;
    for (int y = 0; y < std::min(a.height(), b.height()); ++y)
        for (int x = 0; x < std::min(a.width(), b.width()); ++x)
            if (!sameBits(a(x, y), b(x, y)) && n++ == 0 && first)
                *first = fmt::format("({}, {}): {} vs {}", x, y, a(x, y), b(x, y));
    return n;
}

struct AbsDiff {
    double max = 0, mean = 0, within1 = 0;  // within1: the share within 1/255
};
AbsDiff absDiff(const ImageF& a, const ImageF& b) {
    EXPECT_EQ(a.width(), b.width());
    EXPECT_EQ(a.height(), b.height());
    AbsDiff d;
    double sum = 0;
    std::int64_t close = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i) {
        const double e = std::abs(double(a.pixels()[i]) - double(b.pixels()[i]));
        d.max = std::max(d.max, e), sum += e;
        close += e <= 1.0 / 255.0;
    }
    d.mean = sum / double(a.pixels().size());
    d.within1 = double(close) / double(a.pixels().size());
    return d;
}

// A depth buffer of an analytic scene, with a sky band (depth 1) cut into its top rows and a
// sky column, so that every pass meets sky next to geometry.
ImageF sceneDepth(const char* scene, const Camera& cam, int w, int h) {
    ImageF d = scene::castGeometry(scene::analyticSceneByName(scene), cam, w, h).depth;
    for (int y = 0; y < h / 6; ++y)
        for (int x = w / 3; x < w; ++x) d(x, y) = 1.0f;
    for (int y = 0; y < h; ++y) d(w / 2, y) = 1.0f;
    return d;
}

// The depth a buffer of `format` stores, as floats (what the CPU reads).
ImageF quantized(const ImageF& depth, DepthFormat format) {
    ImageF q = depth;
    forEachPixel(q, [&](float& v) { v = float(quantizeDepth(v, format)); });
    return q;
}

// |z_gpu - z_cpu| within the bound derived at the top, sky for sky.
void expectZWithinBound(const ImageF& gpu, const ImageF& depth, const Camera& cam, DepthFormat format,
                        const std::string& what) {
    const ImageF cpu = ao::depthToZ(depth.view(), cam);
    std::int64_t bad = 0, identical = 0;
    std::string first;
    for (int y = 0; y < cpu.height(); ++y)
        for (int x = 0; x < cpu.width(); ++x) {
            const double zc = cpu(x, y), zg = gpu(x, y), d = depth(x, y);
            identical += sameBits(cpu(x, y), gpu(x, y));
            if (std::isinf(zc) || std::isinf(zg)) {
                if (!sameBits(float(zc), float(zg)) && bad++ == 0)
                    first = fmt::format("({}, {}): {} vs {}", x, y, zg, zc);
                continue;
            }
            double bound = std::abs(zc) * std::ldexp(1.0, -23);  // one ulp
            if (format != DepthFormat::D32F) {
                // |dz/dd| = |z| |zn - zf| / |zf (1 - d) + zn d| (finite), |z| / (1 - d) (infinite).
                const double slope = std::isinf(cam.zFar) ? std::abs(zc) / (1.0 - d)
                                                          : std::abs(zc) * std::abs(cam.zNear - cam.zFar) /
                                                                std::abs(cam.zFar * (1.0 - d) + cam.zNear * d);
                bound += slope * std::ldexp(1.0, std::ilogb(std::max(d, 1e-30)) - 23);  // one ulp of d
            }
            if (!(std::abs(zg - zc) <= bound) && bad++ == 0)
                first = fmt::format("({}, {}): {} vs {} (bound {})", x, y, zg, zc, bound);
        }
    EXPECT_EQ(bad, 0) << what << ": first " << first;
    if (format == DepthFormat::D32F) {
        EXPECT_GE(double(identical) / double(cpu.pixelCount()), 0.9999) << what;
    }
}

ao::SaoParams saoWith(const char* preset, int guardBand) {
    ao::SaoParams p = ao::saoPreset(preset);
    p.guardBand = guardBand;
    return p;
}

// Every SAO stage against the CPU pass on the GPU's previous stage.
void expectStagesMatch(const ao::SaoParams& p, const char* scene, const Camera& cam, int w, int h,
                       DepthFormat format = DepthFormat::D32F) {
    const std::string what =
        fmt::format("{} {}x{} guard {} filter {} pyramid {} packing {}{} far {} {}", scene, w, h, p.guardBand,
                    ao::kPyramidFilterNames[std::size_t(p.pyramidFilter)], p.usePyramid, p.packBlurInput,
                    p.releasedPacking ? " (released)" : "", cam.zFar, int(format));
    SCOPED_TRACE(what);
    const ImageF depth = quantized(sceneDepth(scene, cam, w, h), format);
    gpu::Sao sao(context(), p);
    const gpu::AoStages st = sao.runStages(depth.view(), cam, format);
    const Projection proj = projection(cam, w, h);
    // depth -> z
    expectZWithinBound(st.z, depth, cam, format, what);
    // the pyramid, from the GPU's z
    const int levels = p.usePyramid ? p.maxMip : 0;
    ASSERT_EQ(int(st.pyramid.size()), levels);
    const std::vector<ImageF> pyr = ao::zPyramid(st.z.view(), levels, p.pyramidFilter);
    std::string first;
    for (int m = 1; m <= levels; ++m)
        EXPECT_EQ(bitsDiffer(st.pyramid[std::size_t(m) - 1], pyr[std::size_t(m)], &first), 0)
            << "level " << m << ": " << first;
    // the sample pass, on the GPU's pyramid
    const ao::Region out{p.guardBand, p.guardBand, w - 2 * p.guardBand, h - 2 * p.guardBand};
    const ao::Region work = ao::quadAligned(out, w, h);
    EXPECT_EQ(st.work.x0, work.x0);
    EXPECT_EQ(st.work.width, work.width);
    std::vector<ImageF> gpuPyr{st.z};
    for (const ImageF& l : st.pyramid) gpuPyr.push_back(l);
    const ImageF raw = ao::saoSamplePass(gpuPyr, proj, work, p);
    const AbsDiff dr = absDiff(st.raw, raw);
    if (std::getenv("SSFX_TEST_VERBOSE")) std::printf("%s: sample max %.3g mean %.3g\n", what.c_str(), dr.max, dr.mean);
    EXPECT_LE(dr.max, 2e-3) << "sample pass";
    EXPECT_LE(dr.mean, 1e-6) << "sample pass";
    // the 2x2 quad pass (and the packing), on the GPU's raw A
    ImageF quad = st.raw;
    ao::quadBilateral(quad, st.z.view(), work, p.quadThreshold);
    ImageF zBlur = st.z;
    if (p.packBlurInput) {
        forEachPixel(quad, [](float& v) { v = ao::packAo(v); });
        ImageF key(work.width, work.height);
        for (int y = 0; y < work.height; ++y)
            for (int x = 0; x < work.width; ++x) {
                const float z = st.z(work.x0 + x, work.y0 + y);
                key(x, y) = zBlur(work.x0 + x, work.y0 + y) =
                    p.releasedPacking ? ao::releasedKey(z, p.packZMin) : ao::packZ(z, p.packZMin);
            }
        EXPECT_EQ(bitsDiffer(st.zBlur, key, &first), 0) << "packed z: " << first;
    }
    EXPECT_EQ(bitsDiffer(st.quad, quad, &first), 0) << "quad pass: " << first;
    // the bilateral passes, on the GPU's previous pass
    ImageF hz = ao::bilateralPass(st.quad, zBlur.view(), work, p.blur, true);
    if (p.releasedPacking) forEachPixel(hz, [](float& v) { v = ao::packAo(v); });
    EXPECT_EQ(bitsDiffer(st.horizontal, hz, &first), 0) << "horizontal blur: " << first;
    const ImageF vt = ao::bilateralPass(st.horizontal, zBlur.view(), work, p.blur, false);
    ImageF cropped(out.width, out.height);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) cropped(x, y) = vt(x + out.x0 - work.x0, y + out.y0 - work.y0);
    EXPECT_EQ(bitsDiffer(st.result, cropped, &first), 0) << "vertical blur: " << first;
    // and the whole pipeline against the CPU's
    const AbsDiff df = absDiff(st.result, ao::sao(depth.view(), cam, p));
    if (std::getenv("SSFX_TEST_VERBOSE"))
        std::printf("%s: pipeline max %.3g within 1/255 %.5f\n", what.c_str(), df.max, df.within1);
    EXPECT_GE(df.within1, 0.999) << "whole pipeline";
    EXPECT_LE(df.max, 4.0 / 255.0) << "whole pipeline";
}

TEST(GpuAo, SaoStagesMatchTheCpuPassByPass) {
    REQUIRE_DEVICE();
    Camera cam;
    expectStagesMatch(saoWith("paper", 0), "room", cam, 96, 64);
    expectStagesMatch(saoWith("released", 8), "room", cam, 112, 80);
    // Odd sizes and an odd guard band: the work region grows by a row and a column.
    expectStagesMatch(saoWith("paper", 5), "corner", cam, 101, 77);
    cam.zFar = -40.0;  // a finite far plane
    expectStagesMatch(saoWith("paper", 3), "corner", cam, 97, 61);
    expectNoValidationMessages();
}

TEST(GpuAo, EveryPyramidFilterAndSamplingOption) {
    REQUIRE_DEVICE();
    Camera cam;
    for (std::size_t f = 0; f < ao::kPyramidFilterNames.size(); ++f) {
        ao::SaoParams p = saoWith("paper", 4);
        p.pyramidFilter = ao::PyramidFilter(f);
        expectStagesMatch(p, "room", cam, 90, 70);
    }
    ao::SaoParams p = saoWith("paper", 2);
    p.usePyramid = false;  // "SAO without the pyramid": every tap reads level 0
    expectStagesMatch(p, "room", cam, 90, 70);
    p = saoWith("paper", 2);
    p.packBlurInput = true;  // the paper's 16-bit key, without the released storage
    p.radius = 2.5f, p.intensity = 1.7f, p.numSamples = 13, p.numSpiralTurns = ao::spiralTurnsFor(13);
    p.logQ = 2, p.maxMip = 3;
    expectStagesMatch(p, "corner", cam, 90, 70);
    p = saoWith("released", 6);
    p.blur.blurZeroOutside = false;
    p.blur.blurEpsilon = 0;
    expectStagesMatch(p, "room", cam, 90, 70);
    expectNoValidationMessages();
}

TEST(GpuAo, DepthFormats) {
    REQUIRE_DEVICE();
    Camera cam;
    for (const DepthFormat f : {DepthFormat::D16, DepthFormat::D24, DepthFormat::D32F}) {
        expectStagesMatch(saoWith("paper", 4), "room", cam, 80, 60, f);
        Camera finite = cam;
        finite.zFar = -60.0;
        expectStagesMatch(saoWith("released", 4), "corner", finite, 80, 60, f);
    }
    expectNoValidationMessages();
}

TEST(GpuAo, AlchemyStagesMatchTheCpu) {
    REQUIRE_DEVICE();
    Camera cam;
    for (const int g : {0, 7}) {
        ao::AlchemyParams p;
        p.guardBand = g;
        const int w = 99, h = 75;
        SCOPED_TRACE(fmt::format("guard {}", g));
        const ImageF depth = sceneDepth("room", cam, w, h);
        gpu::Alchemy alchemy(context(), p);
        const gpu::AoStages st = alchemy.runStages(depth.view(), cam);
        expectZWithinBound(st.z, depth, cam, DepthFormat::D32F, "alchemy");
        EXPECT_TRUE(st.pyramid.empty());
        const ao::Region out{g, g, w - 2 * g, h - 2 * g};
        EXPECT_EQ(st.work.x0, out.x0);
        EXPECT_EQ(st.work.width, out.width);
        const ImageF raw = ao::alchemySamplePass(st.z.view(), projection(cam, w, h), out, p);
        const AbsDiff dr = absDiff(st.raw, raw);
        EXPECT_LE(dr.max, 2e-3);
        EXPECT_LE(dr.mean, 1e-6);
        std::string first;
        const ImageF hz = ao::bilateralPass(st.raw, st.z.view(), out, p.blur, true);
        EXPECT_EQ(bitsDiffer(st.horizontal, hz, &first), 0) << "horizontal: " << first;
        const ImageF vt = ao::bilateralPass(st.horizontal, st.z.view(), out, p.blur, false);
        EXPECT_EQ(bitsDiffer(st.result, vt, &first), 0) << "vertical: " << first;
        const AbsDiff df = absDiff(st.result, ao::alchemy(depth.view(), cam, p));
        EXPECT_GE(df.within1, 0.999);
        EXPECT_LE(df.max, 4.0 / 255.0);
        // run() gives runStages()'s result
        EXPECT_EQ(bitsDiffer(alchemy.run(depth.view(), cam), st.result), 0);
    }
    expectNoValidationMessages();
}

TEST(GpuAo, WholePipelineOnLargerViews) {
    // The issue's bound on whole frames: at least 99.9 % of pixels within 1/255, none beyond
    // 4/255, SAO (both presets) and AlchemyAO, with the paper's guard band ratio.
    REQUIRE_DEVICE();
    Camera cam;
    for (const char* scene : {"room", "corner"}) {
        const ImageF depth = sceneDepth(scene, cam, 320 + 32, 180 + 32);
        for (const char* preset : {"paper", "released"}) {
            const ao::SaoParams p = saoWith(preset, 16);
            gpu::Sao sao(context(), p);
            const AbsDiff d = absDiff(sao.run(depth.view(), cam), ao::sao(depth.view(), cam, p));
            EXPECT_GE(d.within1, 0.999) << scene << " " << preset;
            EXPECT_LE(d.max, 4.0 / 255.0) << scene << " " << preset;
            EXPECT_GT(sao.lastDispatches().size(), 4u);
        }
        ao::AlchemyParams ap;
        ap.guardBand = 16;
        gpu::Alchemy alchemy(context(), ap);
        const AbsDiff d = absDiff(alchemy.run(depth.view(), cam), ao::alchemy(depth.view(), cam, ap));
        EXPECT_GE(d.within1, 0.999) << scene << " alchemy";
        EXPECT_LE(d.max, 4.0 / 255.0) << scene << " alchemy";
    }
    expectNoValidationMessages();
}

// GTAO (gpu::Gtao against ao::gtao): the chain is the CPU's floats from the GPU's z (z is the
// CPU's but in rare pixels one ulp off, see the top; such a pixel moves its chain texels by
// about an ulp), so each level is compared bit for bit on at least 99.9 % of texels and
// within 1e-5 relative everywhere; the main pass's transcendentals are the device's, so the
// whole pipeline is held to the issue's bound: at least 99.9 % of pixels within 1/255, none
// beyond 4/255.
void expectGtaoMatches(const std::shared_ptr<vkx::Context>& ctx, const ImageF& depth, const Camera& cam,
                       const ao::GtaoParams& p, DepthFormat format, const std::string& what) {
    SCOPED_TRACE(what);
    gpu::Gtao gtao(ctx, p);
    const gpu::AoStages st = gtao.runStages(depth.view(), cam, format);
    const ImageF q = quantized(depth, format);
    ao::GtaoStages cpu;
    const ImageF a = ao::gtao(q.view(), cam, p, Exec{}, {}, &cpu);
    ASSERT_EQ(st.pyramid.size(), 4u);
    for (std::size_t m = 1; m <= 4; ++m) {
        const ImageF& g = st.pyramid[m - 1];
        const ImageF& c = cpu.chain[m];
        ASSERT_EQ(g.width(), c.width());
        ASSERT_EQ(g.height(), c.height());
        std::int64_t same = 0, far = 0;
        for (std::size_t i = 0; i < g.pixels().size(); ++i) {
            const float t = -g.pixels()[i], tc = c.pixels()[i];
            same += sameBits(t, tc);
            far += !(std::isinf(tc) ? t == tc : std::abs(t - tc) <= 1e-5f * tc);
        }
        EXPECT_GE(double(same) / double(g.pixels().size()), 0.999) << "chain level " << m;
        EXPECT_EQ(far, 0) << "chain level " << m;
    }
    EXPECT_EQ(st.work.x0, cpu.work.x0);
    EXPECT_EQ(st.work.width, cpu.work.width);
    const AbsDiff raw = absDiff(st.raw, cpu.raw);
    const AbsDiff d = absDiff(st.result, a);
    if (std::getenv("SSFX_TEST_VERBOSE"))
        std::printf("%s: raw max %.3g mean %.3g; result max %.3g mean %.3g within 1/255 %.5f\n", what.c_str(), raw.max,
                    raw.mean, d.max, d.mean, d.within1);
    // The main pass alone (measured on lavapipe: mean <= 1.03e-4, max 4.9e-4 but 8-bit storage
    // flips of 1.5/255): mean <= 2e-4.
    EXPECT_LE(raw.mean, 2e-4) << "main pass";
    EXPECT_GE(d.within1, 0.999) << "whole pipeline";
    EXPECT_LE(d.max, 4.0 / 255.0) << "whole pipeline";
    // Not a blank image: the scenes' corners occlude.
    EXPECT_LT(*std::min_element(st.result.pixels().begin(), st.result.pixels().end()), 0.8f);
}

TEST(GpuAo, GtaoMatchesTheCpuWithinTheIssuesBound) {
    REQUIRE_DEVICE();
    Camera cam;
    struct Config {
        std::string name;
        ao::GtaoParams p;
    };
    std::vector<Config> configs;
    for (const char* preset : {"low", "high", "ultra", "ideal", "paper"})
        configs.push_back({preset, ao::gtaoPreset(preset)});
    configs.push_back({"high, fastAcos, discard, no denoiser", ao::gtaoPreset("high")});
    configs.back().p.fastAcos = true, configs.back().p.offscreen = ao::Offscreen::Discard;
    configs.back().p.denoisePasses = 0;
    configs.push_back({"high, xegtaoStorage, 3 passes, R = 2 m, thin occluders", ao::gtaoPreset("high")});
    configs.back().p.xegtaoStorage = true, configs.back().p.denoisePasses = 3, configs.back().p.radius = 2.0f;
    configs.back().p.thinOccluderCompensation = 0.4f;
    configs.push_back({"high, sampleDistributionPower 1.5, 2 passes", ao::gtaoPreset("high")});
    configs.back().p.sampleDistributionPower = 1.5f, configs.back().p.denoisePasses = 2;
    for (const char* scene : {"room", "corner"}) {
        const ImageF depth = sceneDepth(scene, cam, 160 + 32, 96 + 32);
        for (Config& c : configs) {
            c.p.guardBand = 16;
            expectGtaoMatches(context(), depth, cam, c.p, DepthFormat::D32F, fmt::format("{} {}", scene, c.name));
        }
        expectGtaoMatches(context(), depth, cam, configs[1].p, DepthFormat::D16, fmt::format("{} high D16", scene));
    }
    // A guard band of 0: the work region is the whole buffer, neighbours clamp at its edge.
    ao::GtaoParams p = ao::gtaoPreset("high");
    p.guardBand = 0, p.denoisePasses = 2;
    expectGtaoMatches(context(), sceneDepth("room", cam, 97, 61), cam, p, DepthFormat::D32F, "room, no guard band");
    expectNoValidationMessages();
}

TEST(GpuAo, BadInputsGiveErrors) {
    REQUIRE_DEVICE();
    Camera cam;
    gpu::Sao sao(context(), saoWith("paper", 4));
    ImageF depth(16, 12, 0.5f);
    depth(3, 2) = std::nanf("");
    EXPECT_THROW(
        {
            try {
                sao.run(depth.view(), cam);
            } catch (const Error& e) {
                EXPECT_NE(std::string(e.what()).find("pixel (3, 2)"), std::string::npos) << e.what();
                throw;
            }
        },
        Error);
    depth(3, 2) = 1.5f;
    EXPECT_THROW(sao.run(depth.view(), cam), Error);
    // No pixels inside the guard band.
    EXPECT_THROW(sao.run(ImageF(8, 8, 0.5f).view(), cam), Error);
    // A bad camera, a bad parameter.
    Camera bad;
    bad.zNear = 0.1;
    EXPECT_THROW(sao.run(ImageF(16, 12, 0.5f).view(), bad), Error);
    ao::SaoParams p;
    p.numSamples = 0;
    EXPECT_THROW(gpu::Sao(context(), p), Error);

    // record()'s contract: formats, usage, layouts, sizes.
    vkx::Context& c = *context();
    const vkx::Image d = c.createImage(vk::Format::eD32Sfloat, 16, 12,
                                       vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eTransferDst,
                                       vk::ImageAspectFlagBits::eDepth);
    const vk::raii::ImageView dv(
        c.device, vk::ImageViewCreateInfo({}, *d.image, vk::ImageViewType::e2D, vk::Format::eD32Sfloat, {},
                                          {vk::ImageAspectFlagBits::eDepth, 0, 1, 0, 1}));
    const vkx::Image o =
        c.createImage(vk::Format::eR32Sfloat, 8, 4, vk::ImageUsageFlagBits::eStorage, vk::ImageAspectFlagBits::eColor);
    const vk::raii::ImageView ov(
        c.device, vk::ImageViewCreateInfo({}, *o.image, vk::ImageViewType::e2D, vk::Format::eR32Sfloat, {},
                                          {vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1}));
    const gpu::ImageRef goodDepth{*dv,
                                  vk::Format::eD32Sfloat,
                                  vk::ImageUsageFlagBits::eSampled,
                                  16,
                                  12,
                                  vk::ImageLayout::eDepthStencilReadOnlyOptimal};
    const gpu::ImageRef goodOut{*ov, vk::Format::eR32Sfloat,   vk::ImageUsageFlagBits::eStorage, 8,
                                4,   vk::ImageLayout::eGeneral};
    auto expectError = [&](gpu::ImageRef depthRef, gpu::ImageRef outRef, const char* needle) {
        vkx::Recording rec(c, [&](const vk::raii::CommandBuffer& cmd) {
            try {
                sao.record(cmd, depthRef, cam, outRef);
                ADD_FAILURE() << "no error for: " << needle;
            } catch (const Error& e) {
                EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
            }
        });
    };
    gpu::ImageRef r = goodDepth;
    r.format = vk::Format::eR32Sfloat;
    expectError(r, goodOut, "depth format");
    r = goodDepth;
    r.usage = vk::ImageUsageFlagBits::eStorage;
    expectError(r, goodOut, "SAMPLED");
    r = goodDepth;
    r.layout = vk::ImageLayout::eTransferDstOptimal;
    expectError(r, goodOut, "depth layout");
    gpu::ImageRef out = goodOut;
    out.format = vk::Format::eR8Unorm;
    expectError(goodDepth, out, "output format");
    out = goodOut;
    out.width = 9;
    expectError(goodDepth, out, "expected 8x4");
    out = goodOut;
    out.layout = vk::ImageLayout::eShaderReadOnlyOptimal;
    expectError(goodDepth, out, "output layout");
    expectNoValidationMessages();
}

// The renderer's depth image read in place (DEPTH_READ_ONLY_OPTIMAL, recorded into the draw's
// command buffer) by `pass`, read back; the draw is the renderer's own view `view` of `scene`.
ImageF aoOnTheRenderersDepth(render::Renderer& renderer, gpu::AoPass& pass, const scene::Scene& scene,
                             const scene::View& view, int w, int h, int g, DepthFormat format) {
    vkx::Context& ctx = *renderer.context();
    const vk::ImageUsageFlags usage = vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eTransferSrc;
    const vkx::Image out = ctx.createImage(vk::Format::eR32Sfloat, w, h, usage, vk::ImageAspectFlagBits::eColor);
    const vk::raii::ImageView outView(
        ctx.device, vk::ImageViewCreateInfo({}, *out.image, vk::ImageViewType::e2D, vk::Format::eR32Sfloat, {},
                                            {vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1}));
    const vkx::Buffer download =
        ctx.createBuffer(vk::DeviceSize(w) * h * 4, vk::BufferUsageFlagBits::eTransferDst, true);
    using S = vk::PipelineStageFlagBits;
    using A = vk::AccessFlagBits;
    using L = vk::ImageLayout;
    const scene::CameraSetup setup = scene::cameraSetup(view, w, h, g);
    const std::uint32_t uw = std::uint32_t(w), uh = std::uint32_t(h);
    renderer.renderDepthOnDevice(
        scene, view, w, h, format, g, [&](const vk::raii::CommandBuffer& cmd, const render::DeviceDepth& d) {
            vkx::transition(cmd, out, L::eUndefined, L::eGeneral, S::eTopOfPipe, {}, S::eComputeShader,
                            A::eShaderWrite);
            pass.record(cmd, {d.view, d.format, d.usage, d.width, d.height, d.layout}, setup.camera,
                        {*outView, vk::Format::eR32Sfloat, usage, uw, uh, L::eGeneral});
            vkx::transition(cmd, out, L::eGeneral, L::eTransferSrcOptimal, S::eComputeShader, A::eShaderWrite,
                            S::eTransfer, A::eTransferRead);
            cmd.copyImageToBuffer(
                *out.image, L::eTransferSrcOptimal, *download.buffer,
                vk::BufferImageCopy(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1}, {0, 0, 0}, {uw, uh, 1}));
        });
    ImageF a(w, h);
    std::memcpy(a.data(), download.mapped, std::size_t(w) * h * 4);
    return a;
}

TEST(GpuAo, RendererAndAoOnOneDevice) {
    // Rendered atrium and Cornell views (and Sponza and the bunny where ../shared/assets is
    // present), the GPU passes reading the depth where the draw left it, against the CPU's
    // on the same draw read back: the whole pipeline's bound.
    REQUIRE_DEVICE();
    vkx::ContextOptions o;
    o.validation = true;
    o.graphics = true;
    std::shared_ptr<vkx::Context> ctx;
    try {
        ctx = vkx::Context::create(o);
    } catch (const Error& e) {
        GTEST_SKIP() << "no Vulkan device with graphics: " << e.what();
    }
    render::Renderer renderer(ctx);
    std::vector<std::pair<std::string, std::string>> scenes{{"atrium", "colonnade"}, {"cornell", "corner"}};
    if (test::sharedDir("assets")) {
        const std::filesystem::path root = std::filesystem::path(SSFX_SOURCE_DIR) / "scenes";
        scenes.emplace_back((root / "sponza.json").string(), "arcade");
        scenes.emplace_back((root / "bunny.json").string(), "front");
    } else {
        std::fprintf(stderr, "../shared/assets is absent: Sponza and the bunny are skipped\n");
    }
    const int w = 160, h = 90, g = 12;
    for (const auto& [name, viewName] : scenes) {
        const scene::Scene sc = scene::loadScene(name);
        const scene::View view = sc.view(viewName);
        for (const DepthFormat format : {DepthFormat::D32F, DepthFormat::D16}) {
            SCOPED_TRACE(fmt::format("{}:{} format {}", name, viewName, int(format)));
            const render::DepthRender cpuDepth = renderer.renderDepth(sc, view, w, h, format, g);
            const ao::SaoParams sp = saoWith(format == DepthFormat::D32F ? "paper" : "released", g);
            gpu::Sao sao(ctx, sp);
            const ImageF a = aoOnTheRenderersDepth(renderer, sao, sc, view, w, h, g, format);
            const AbsDiff d = absDiff(a, ao::sao(cpuDepth.depth.view(), cpuDepth.camera.camera, sp));
            EXPECT_GE(d.within1, 0.999);
            EXPECT_LE(d.max, 4.0 / 255.0);
            double sum = 0;  // not a blank image
            for (const float v : a.pixels()) sum += v;
            EXPECT_LT(sum / double(a.pixelCount()), 0.99);
            ao::AlchemyParams ap;
            ap.guardBand = g;
            gpu::Alchemy alchemy(ctx, ap);
            const AbsDiff da = absDiff(aoOnTheRenderersDepth(renderer, alchemy, sc, view, w, h, g, format),
                                       ao::alchemy(cpuDepth.depth.view(), cpuDepth.camera.camera, ap));
            EXPECT_GE(da.within1, 0.999);
            EXPECT_LE(da.max, 4.0 / 255.0);
            ao::GtaoParams gp = ao::gtaoPreset("high");
            gp.guardBand = g;
            gpu::Gtao gtao(ctx, gp);
            const AbsDiff dg = absDiff(aoOnTheRenderersDepth(renderer, gtao, sc, view, w, h, g, format),
                                       ao::gtao(cpuDepth.depth.view(), cpuDepth.camera.camera, gp));
            if (std::getenv("SSFX_TEST_VERBOSE"))
                std::printf("%s %d gtao: max %.3g within 1/255 %.5f\n", name.c_str(), int(format), dg.max, dg.within1);
            EXPECT_GE(dg.within1, 0.999);
            EXPECT_LE(dg.max, 4.0 / 255.0);
        }
    }
    expectNoValidationMessages(ctx);
}

double psnrAgainst(const ImageF& a, const ImageF& truth) {
    double se = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i) {
        const double e = double(a.pixels()[i]) - double(truth.pixels()[i]);
        se += e * e;
    }
    return 10.0 * std::log10(1.0 / (se / double(a.pixels().size())));
}

TEST(GpuAo, AccuracyAgainstTheRayTracedTruthAsTheCpu) {
    // docs/results.md 7.3's accuracy, reproduced by the GPU path within 0.05 dB (the issue's
    // bound) on the analytic scenes, for SAO (both presets) and AlchemyAO.
    REQUIRE_DEVICE();
    Camera cam;
    const int w = 192, h = 108, g = 16;
    for (const char* name : {"corner", "room"}) {
        const scene::AnalyticScene sc = scene::analyticSceneByName(name);
        const ImageF depth = scene::castGeometry(sc, cam, w + 2 * g, h + 2 * g).depth;
        ao::RaytracedParams rp;
        rp.raysPerPixel = 32, rp.guardBand = g;
        const ImageF truth = ao::raytraced(sc, cam, w + 2 * g, h + 2 * g, rp);
        for (const char* preset : {"paper", "released"}) {
            const ao::SaoParams p = saoWith(preset, g);
            const double cpu = psnrAgainst(ao::sao(depth.view(), cam, p), truth);
            const double gpuDb = psnrAgainst(gpu::Sao(context(), p).run(depth.view(), cam), truth);
            EXPECT_NEAR(gpuDb, cpu, 0.05) << name << " " << preset;
            EXPECT_GT(cpu, 15.0) << name << " " << preset;  // a real comparison, not two blank images
        }
        ao::AlchemyParams ap;
        ap.guardBand = g;
        const double cpu = psnrAgainst(ao::alchemy(depth.view(), cam, ap), truth);
        EXPECT_NEAR(psnrAgainst(gpu::Alchemy(context(), ap).run(depth.view(), cam), truth), cpu, 0.05) << name;
    }
    expectNoValidationMessages();
}

}  // namespace
}  // namespace ssfx
