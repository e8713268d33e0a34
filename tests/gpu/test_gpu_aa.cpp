// The GPU backend (ssfx/gpu/aa.hpp) on lavapipe or any Vulkan device, with the validation
// layer and synchronization validation on (a validation message fails the test):
//  - model sampling: every method's output bytes equal the CPU's (MethodInfo::run) on the
//    reference drawings and on generated images of awkward sizes;
//  - hardware sampling: the agreement with the CPU, within a tolerance from the sub-texel
//    precision the device reports;
//  - bad input: clear ssfx::Errors.
// Skips with a message only when there is no Vulkan device at all.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "ssfx/core/error.hpp"
#include "ssfx/gpu/aa.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/registry.hpp"
#include "tests/support/test_support.hpp"

namespace ssfx {
namespace {

// One validated compute context per program (device creation is slow on lavapipe); null
// when this machine has no Vulkan device.
std::shared_ptr<vkx::Context> context() {
    static std::shared_ptr<vkx::Context> ctx = [] {
        vkx::ContextOptions o;
        o.validation = true;
        try {
            return vkx::Context::create(o);
        } catch (const Error& e) {
            std::fprintf(stderr, "no Vulkan device: %s\n", e.what());
            return std::shared_ptr<vkx::Context>();
        }
    }();
    return ctx;
}

#define REQUIRE_DEVICE()                                                                               \
    do {                                                                                               \
        if (!context()) GTEST_SKIP() << "no Vulkan device (install mesa-vulkan-drivers for lavapipe)"; \
    } while (0)

void expectNoValidationMessages() {
    const auto messages = context()->validationMessages();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s), the first: " << messages.front();
}

// Pixels that differ, and the largest channel difference (RGBA).
struct Diff {
    std::int64_t pixels = 0;
    int largest = 0;
};
Diff compare(const ImageRgba8& a, const ImageRgba8& b) {
    Diff d;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const Rgba8 p = a(x, y), q = b(x, y);
            const int e =
                std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)});
            d.pixels += e > 0;
            d.largest = std::max(d.largest, e);
        }
    return d;
}

// The generated inputs: sizes at 1x (the method's input is scale times larger).
struct Case {
    std::string name;
    int w, h;
};
const Case kCases[] = {{"random 64x48", 64, 48},
                       {"flat", 24, 16},
                       {"1x1", 1, 1},
                       {"1x17", 1, 17},
                       {"19x1", 19, 1},
                       {"odd 37x23", 37, 23},
                       {"65x33 (not a multiple of the 8x8 group)", 65, 33},
                       {"4097 wide", 4097, 3}};

ImageRgba8 inputFor(const Case& c, int scale, unsigned seed) {
    if (c.name == "flat") return test::solid(c.w * scale, c.h * scale, Rgba8{90, 140, 200, 255});
    // A 4097-wide 1x image is 16388 wide at x4, beyond a 16384 device limit: the resolves
    // then take an input just over 4096 wide instead (1025 x 4 = 4100).
    const int w = c.w * scale > context()->info.maxImageDimension2D ? 4100 / scale : c.w;
    // Random pixels with blocks of edges: half noise, half a hard-edged pattern.
    ImageRgba8 img = test::noise(w * scale, c.h * scale, seed);
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width() / 2; ++x) {
            const bool dark = ((x * 3 + y * 5) / 7) % 3 == 0;
            img(x, y) = dark ? Rgba8{20, 30, 40, 255} : Rgba8{230, 220, 210, 255};
        }
    return img;
}

class GpuModelParity : public ::testing::TestWithParam<const MethodInfo*> {};

TEST_P(GpuModelParity, GeneratedImagesGiveTheCpuBytes) {
    REQUIRE_DEVICE();
    const MethodInfo& m = *GetParam();
    gpu::AaPass pass(context(), m.id);
    unsigned seed = 7;
    for (const Case& c : kCases) {
        const ImageRgba8 in = inputFor(c, m.inputScale, seed++);
        const ImageRgba8 cpu = m.run(in.view(), {}, Exec{});
        const ImageRgba8 gpu = pass.run(in.view());
        ASSERT_EQ(gpu.width(), cpu.width());
        ASSERT_EQ(gpu.height(), cpu.height());
        const Diff d = compare(gpu, cpu);
        EXPECT_EQ(d.pixels, 0) << m.id << " on " << c.name << ": " << d.pixels << " pixels differ, by up to "
                               << d.largest;
    }
    expectNoValidationMessages();
}

TEST_P(GpuModelParity, ReferenceDrawingsGiveTheCpuBytes) {
    REQUIRE_DEVICE();
    const auto dir = test::sharedDir("reference/ppaa");
    if (!dir) GTEST_SKIP() << "../shared/reference/ppaa is absent";
    const MethodInfo& m = *GetParam();
    gpu::AaPass pass(context(), m.id);
    const char* suffix = m.inputScale == 4 ? "x4" : m.inputScale == 2 ? "x2" : "";
    for (const char* name : {"lines", "circles"}) {
        const ImageRgba8 in = io::readPng(fmt::format("{}/{}{}.png", *dir, name, suffix));
        const Diff d = compare(pass.run(in.view()), m.run(in.view(), {}, Exec{}));
        EXPECT_EQ(d.pixels, 0) << m.id << " on " << name << ": " << d.pixels << " pixels differ, by up to "
                               << d.largest;
    }
    expectNoValidationMessages();
}

// The shaders write the paper's decimal constants as GLSL literals, which glslang reads
// in double and rounds to float; C++ rounds `0.299f` once. The two agree for these values.
TEST(GpuShaders, DecimalLiteralsRoundTheSameInGlslAndCpp) {
    const std::pair<double, float> literals[] = {{0.299, 0.299f},           {0.587, 0.587f},
                                                 {0.114, 0.114f},           {1e-6, 1e-6f},
                                                 {0.746677, 0.746677f},     {0.269867, 0.269867f},
                                                 {2.886093, 2.886093f},     {0.746066, 0.746066f},
                                                 {-0.009934, -0.009934f},   {1.0 / 384.0, 1.0f / 384.0f},
                                                 {1.0 / 12.0, 1.0f / 12.0f}};
    for (const auto& [d, f] : literals) EXPECT_EQ(float(d), f) << d;
}

std::string methodName(const ::testing::TestParamInfo<const MethodInfo*>& info) { return std::string(info.param->id); }
std::vector<const MethodInfo*> allMethods() {
    std::vector<const MethodInfo*> v;
    for (const MethodInfo& m : methods()) v.push_back(&m);
    return v;
}
INSTANTIATE_TEST_SUITE_P(Methods, GpuModelParity, ::testing::ValuesIn(allMethods()), methodName);

TEST(GpuAa, SettingsReachTheShader) {
    REQUIRE_DEVICE();
    // A non-default preset and parameters change the output exactly as on the CPU.
    const ImageRgba8 in = inputFor(kCases[0], 1, 3);
    MethodSettings s;
    s.preset = aa::Preset::Extreme;
    s.params = {{"strength", 1.5}, {"searchRounds", 2}, {"chromaWeight", 0.5}};
    const MethodInfo& m = methodById("ddaa2");
    gpu::AaPass pass(context(), "ddaa2", s);
    const ImageRgba8 cpu = m.run(in.view(), s, Exec{});
    EXPECT_EQ(compare(pass.run(in.view()), cpu).pixels, 0);
    EXPECT_GT(compare(cpu, m.run(in.view(), {}, Exec{})).pixels, 0) << "the settings must matter";
    MethodSettings q;
    q.params = {{"paperSearchQuirk", 0}, {"subpix", 0.25}};
    gpu::AaPass fxaa(context(), "fxaa3d", q);
    EXPECT_EQ(compare(fxaa.run(in.view()), methodById("fxaa3d").run(in.view(), q, Exec{})).pixels, 0);
    MethodSettings d;
    d.params = {{"diagonalOffset", 0.5}};
    gpu::AaPass console(context(), "fxaa3c", d);
    EXPECT_EQ(compare(console.run(in.view()), methodById("fxaa3c").run(in.view(), d, Exec{})).pixels, 0);
    expectNoValidationMessages();
}

TEST(GpuAa, BadInputGivesClearErrors) {
    REQUIRE_DEVICE();
    EXPECT_NE(test::errorOf([] { gpu::AaPass(context(), "nosuch"); }).find("nosuch"), std::string::npos);
    MethodSettings srgb;
    srgb.params = {{"texture", 1}};
    EXPECT_NE(test::errorOf([&] { gpu::AaPass(context(), "ddaa1", srgb); }).find("srgb"), std::string::npos);
    MethodSettings exact;
    exact.filtering = Filtering::Exact;
    EXPECT_NE(test::errorOf([&] { gpu::AaPass(context(), "blur", exact); }).find("exact filtering"), std::string::npos);
    gpu::AaPass ssaa(context(), "ssaax2");
    const ImageRgba8 odd = test::noise(5, 4, 1);
    EXPECT_NE(test::errorOf([&] { ssaa.run(odd.view()); }).find("not divisible by 2"), std::string::npos);
    gpu::AaPass blur(context(), "blur");
    const int limit = context()->info.maxImageDimension2D;
    const ImageRgba8 wide(limit + 1, 1);
    EXPECT_NE(test::errorOf([&] { blur.run(wide.view()); }).find("exceeds the device's limit"), std::string::npos);
    EXPECT_NE(test::errorOf([] { gpu::parseSampling("linear"); }).find("model or hardware"), std::string::npos);
    expectNoValidationMessages();
}

}  // namespace
}  // namespace ssfx
