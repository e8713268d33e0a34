// The GPU backend (ssfx/gpu/aa.hpp) on lavapipe or any Vulkan device, with the validation
// layer and synchronization validation on (a validation message fails the test):
//  - model sampling: every method's output bytes equal the CPU's (MethodInfo::run) on the
//    reference drawings and on generated images of awkward sizes;
//  - hardware sampling: the agreement with the CPU, within a tolerance from the sub-texel
//    precision the device reports;
//  - bad input: clear ssfx::Errors.
// Skips with a message only when there is no Vulkan device at all.
#include <gtest/gtest.h>

#include "tests/gpu/gpu_context.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <initializer_list>

#include "ssfx/aa/registry.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/eval/synthetic.hpp"
#include "ssfx/gpu/aa.hpp"
#include "ssfx/io/png.hpp"
#include "ssfx/vk/resources.hpp"
#include "tests/support/test_support.hpp"

namespace ssfx {
namespace {

using test::expectNoValidationMessages;
std::shared_ptr<vkx::Context> context() { return test::gpuContext(); }

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

// The edge-test methods' paths (Auto picks one per kind of device and method).
const gpu::EdgePath kEdgePaths[] = {gpu::EdgePath::List, gpu::EdgePath::OnePass, gpu::EdgePath::Segments};

// Every path of the edge-test methods (gpu::EdgePath) on every generated image: half noise,
// so that whole subgroups of segments hold nothing but edge pixels, and widths that end
// inside a segment.
TEST_P(GpuModelParity, GeneratedImagesGiveTheCpuBytes) {
    REQUIRE_DEVICE();
    const MethodInfo& m = *GetParam();
    for (const gpu::EdgePath path : kEdgePaths) {
        gpu::AaPass pass(context(), m.id, {}, gpu::Sampling::Model, path);
        if (pass.edgePath() != path) continue;  // blur: two paths, the others without an edge test one
        unsigned seed = 7;
        for (const Case& c : kCases) {
            const ImageRgba8 in = inputFor(c, m.inputScale, seed++);
            const ImageRgba8 cpu = m.run(in.view(), {}, Exec{});
            const ImageRgba8 gpu = pass.run(in.view());
            ASSERT_EQ(gpu.width(), cpu.width());
            ASSERT_EQ(gpu.height(), cpu.height());
            const Diff d = compare(gpu, cpu);
            EXPECT_EQ(d.pixels, 0) << m.id << " (edges=" << gpu::edgePathName(path) << ") on " << c.name << ": "
                                   << d.pixels << " pixels differ, by up to " << d.largest;
        }
    }
    expectNoValidationMessages();
}

TEST_P(GpuModelParity, ReferenceDrawingsGiveTheCpuBytes) {
    REQUIRE_DEVICE();
    const auto dir = test::sharedDir("reference/ppaa");
    if (!dir) GTEST_SKIP() << "../shared/reference/ppaa is absent";
    const MethodInfo& m = *GetParam();
    const char* suffix = m.inputScale == 4 ? "x4" : m.inputScale == 2 ? "x2" : "";
    for (const gpu::EdgePath path : kEdgePaths) {
        gpu::AaPass pass(context(), m.id, {}, gpu::Sampling::Model, path);
        if (pass.edgePath() != path) continue;  // blur: two paths, the others without an edge test one
        for (const char* name : {"lines", "circles"}) {
            const ImageRgba8 in = io::readPng(fmt::format("{}/{}{}.png", *dir, name, suffix));
            const Diff d = compare(pass.run(in.view()), m.run(in.view(), {}, Exec{}));
            EXPECT_EQ(d.pixels, 0) << m.id << " (edges=" << gpu::edgePathName(path) << ") on " << name << ": "
                                   << d.pixels << " pixels differ, by up to " << d.largest;
        }
    }
    expectNoValidationMessages();
}

// texture=srgb (issue #34 item 4): the input view is sRGB and the methods filter in linear
// light, decoding with the CPU's exact table and encoding to the nearest level. The model
// recovers each texel's byte from the device's decode (the pass's probe checks it can) and
// then computes as the CPU does: the CPU's texture=srgb bytes on every generated image, on
// every edge path.
class GpuSrgbParity : public GpuModelParity {};  // the methods that read a texture (not noaa)

TEST_P(GpuSrgbParity, SrgbTexturesGiveTheCpuBytes) {
    REQUIRE_DEVICE();
    const MethodInfo& m = *GetParam();
    MethodSettings srgb;
    srgb.params = {{"texture", 1}};
    for (const gpu::EdgePath path : kEdgePaths) {
        gpu::AaPass pass(context(), m.id, srgb, gpu::Sampling::Model, path);
        if (pass.edgePath() != path) continue;  // blur: two paths, the others without an edge test one
        unsigned seed = 300;
        for (const Case& c : kCases) {
            const ImageRgba8 in = inputFor(c, m.inputScale, seed++);
            const ImageRgba8 cpu = m.run(in.view(), srgb, Exec{});
            const Diff d = compare(pass.run(in.view()), cpu);
            EXPECT_EQ(d.pixels, 0) << m.id << " texture=srgb (edges=" << gpu::edgePathName(path) << ") on " << c.name
                                   << ": " << d.pixels << " pixels differ, by up to " << d.largest;
            if (&c == &kCases[0]) {
                EXPECT_GT(compare(cpu, m.run(in.view(), {}, Exec{})).pixels, 0) << m.id << ": texture=srgb must matter";
            }
        }
    }
    expectNoValidationMessages();
}

// Runs `ids` on `cases` (random images, seeds from `seed`) with the environment variable
// `var` set to `value` (read when a pass is made), on every edge path and the `textures` the
// variable concerns (0 unorm, 1 srgb; both by default): each output must be the CPU's bytes.
void expectCpuBytesWith(const char* var, const char* value, std::initializer_list<const char*> ids,
                        std::initializer_list<Case> cases, unsigned seed,
                        std::initializer_list<int> textures = {0, 1}) {
    ASSERT_EQ(setenv(var, value, 1), 0);
    for (const char* id : ids)
        for (const int texture : textures)
            for (const gpu::EdgePath path : kEdgePaths) {
                const MethodInfo& m = methodById(id);
                MethodSettings settings;
                settings.params = {{"texture", texture}};
                gpu::AaPass pass(context(), m.id, settings, gpu::Sampling::Model, path);
                unsigned s = seed;
                for (const Case& c : cases) {
                    const ImageRgba8 in = inputFor(c, m.inputScale, s++);
                    const Diff d = compare(pass.run(in.view()), m.run(in.view(), settings, Exec{}));
                    EXPECT_EQ(d.pixels, 0)
                        << m.id << " texture=" << (texture ? "srgb" : "unorm") << " (edges=" << gpu::edgePathName(path)
                        << ") on " << c.name << " with " << var << "=" << value << ": " << d.pixels
                        << " pixels differ, by up to " << d.largest;
                }
            }
    unsetenv(var);
    expectNoValidationMessages();
}

// The edge-test methods list their edge pixels for a second pass; an image with more pixels
// than a storage buffer's list could hold runs them in one pass instead. A lowered limit
// (SSFX_GPU_EDGE_LIST_MAX_PIXELS) sends these images down that path, and a small one down
// the list's: both must give the CPU's bytes.
TEST(GpuModelParityOnePass, ImagesOverTheListLimitGiveTheCpuBytes) {
    REQUIRE_DEVICE();
    expectCpuBytesWith("SSFX_GPU_EDGE_LIST_MAX_PIXELS", "1000", {"fxaa3c", "fxaa3d", "ddaa1", "ddaa2", "ddaa2p"},
                       {Case{"random 64x48, one pass", 64, 48}, Case{"random 30x20, two passes", 30, 20}}, 40);
}

// ddaa2's search reads texel pairs by index where the CPU's per-size check says its
// coordinates land half-way (every size above, as for the CPU's vector kernel); other sizes
// read at coordinates. SSFX_GPU_COORDINATE_READS=1 sends every size down the coordinate
// reads: the same bytes.
TEST(GpuModelParityCoordinateReads, SearchReadsAtCoordinatesGiveTheCpuBytes) {
    REQUIRE_DEVICE();
    expectCpuBytesWith("SSFX_GPU_COORDINATE_READS", "1", {"ddaa2", "ddaa2p"},
                       {Case{"random 64x48", 64, 48}, Case{"random 37x23", 37, 23}}, 60);
}

// lavapipe ends every loop of a shader invocation once its loops together have run 65535
// iterations (vkx::Context::maxShaderLoopIterations), without an error. The edge pass's
// invocations loop over the list, so the pass gives it enough work groups that the method's
// own loops fit (edgeGroupsFor). SSFX_GPU_EDGE_GROUPS=1 leaves a single group of 64
// invocations to that rule: on these stripes (every pixel an edge, every fxaa3d walk its ten
// reads a side, 20 loop iterations one side a step as on a CPU device) each invocation would
// run 8192 list entries, about 172 000 loop iterations, where fxaa3d lost the entries past the
// budget (before the rule, with 11 iterations a walk: 260 096 of the 524 288 pixels differed).
// The budget is llvmpipe's; elsewhere the test checks the same bytes with one group.
TEST(GpuModelParityLoopBudget, OneGroupOverAnEdgeDenseImageGivesTheCpuBytes) {
    REQUIRE_DEVICE();
    ImageRgba8 in(1024, 512);
    for (int y = 0; y < in.height(); ++y)
        for (int x = 0; x < in.width(); ++x)
            in(x, y) = (y / 2) % 2 ? Rgba8{220, 210, 200, 255} : Rgba8{30, 40, 50, 255};
    ASSERT_EQ(setenv("SSFX_GPU_EDGE_GROUPS", "1", 1), 0);
    for (const char* id : {"fxaa3c", "fxaa3d", "ddaa1", "ddaa2"}) {
        const MethodInfo& m = methodById(id);
        gpu::AaPass pass(context(), m.id, {}, gpu::Sampling::Model, gpu::EdgePath::List);
        const ImageRgba8 cpu = m.run(in.view(), {}, Exec{});
        const Diff d = compare(pass.run(in.view()), cpu);
        EXPECT_EQ(d.pixels, 0) << id << " with one edge group: " << d.pixels << " pixels differ, by up to "
                               << d.largest;
        EXPECT_GT(pass.lastEdgeShare(), 0.9) << id << ": the stripes must be edges";
    }
    unsetenv("SSFX_GPU_EDGE_GROUPS");
    expectNoValidationMessages();
}

// ddaa2's search by rounds, both sides in step, issues a round's reads before testing them on
// a CPU device and one at a time on a GPU (spec batchedSearch); SSFX_GPU_BATCHED_SEARCH forces
// either: the same bytes. (The rounds, not the model's one side a step on a CPU device:
// SSFX_GPU_SIDE_SEARCH=0.)
TEST(GpuModelParityBatchedSearch, BothSearchOrdersGiveTheCpuBytes) {
    REQUIRE_DEVICE();
    ASSERT_EQ(setenv("SSFX_GPU_SIDE_SEARCH", "0", 1), 0);
    for (const char* mode : {"0", "1"})
        expectCpuBytesWith("SSFX_GPU_BATCHED_SEARCH", mode, {"ddaa2", "ddaa2p"},
                           {Case{"random 64x48", 64, 48}, Case{"random 37x23", 37, 23}}, 80);
    unsetenv("SSFX_GPU_SIDE_SEARCH");
}

// fxaa3d's walk moves one side a step on a CPU device, and ddaa2's search there in the model;
// both sides a step, as the paper's shaders, elsewhere (spec sideSearch); SSFX_GPU_SIDE_SEARCH
// forces either: the same bytes. The inputs' hard-edged half gives walks and searches of every
// length; the stripes of GpuModelParityLoopBudget, every one its longest.
TEST(GpuModelParitySideSearch, BothSearchOrdersGiveTheCpuBytes) {
    REQUIRE_DEVICE();
    for (const char* mode : {"0", "1"})
        expectCpuBytesWith("SSFX_GPU_SIDE_SEARCH", mode, {"fxaa3d", "ddaa2", "ddaa2p"},
                           {Case{"random 64x48", 64, 48}, Case{"random 37x23", 37, 23}, Case{"odd 131x67", 131, 67}},
                           90);
}

// The model takes fetched values as the texels' levels where the pass's probe found the
// device's decode of the input's format exact for all 256 values (gpu::AaPass::deviceDecode;
// unorm: v / 255, lavapipe's is not: 254 decodes one ulp off; texture=srgb: the CPU's kSrgb8);
// SSFX_GPU_DEVICE_DECODE=0 forces the computed levels. On a device whose decode is exact,
// this and the other parity tests cover every path.
TEST(GpuModelParityDeviceDecode, ComputedLevelsGiveTheCpuBytes) {
    REQUIRE_DEVICE();
    expectCpuBytesWith("SSFX_GPU_DEVICE_DECODE", "0", {"blur", "fxaa3c", "fxaa3d", "ddaa1", "ddaa2", "ssaax4"},
                       {Case{"random 64x48", 64, 48}, Case{"random 37x23", 37, 23}}, 100);
    MethodSettings srgb;
    srgb.params = {{"texture", 1}};
    ASSERT_EQ(setenv("SSFX_GPU_DEVICE_DECODE", "0", 1), 0);
    EXPECT_FALSE(gpu::AaPass(context(), "blur").deviceDecode());
    EXPECT_FALSE(gpu::AaPass(context(), "blur", srgb).deviceDecode());
    unsetenv("SSFX_GPU_DEVICE_DECODE");
    EXPECT_FALSE(gpu::AaPass(context(), "blur", {}, gpu::Sampling::Hardware).deviceDecode());
    EXPECT_FALSE(gpu::AaPass(context(), "blur", srgb, gpu::Sampling::Hardware).deviceDecode());
    std::printf("the device's decode, probed: unorm %s, sRGB %s\n",
                gpu::AaPass(context(), "blur").deviceDecode() ? "exact (used)" : "not exact (levels computed)",
                gpu::AaPass(context(), "blur", srgb).deviceDecode() ? "exact (used)" : "not exact");
}

// texture=srgb, model: where the device's sRGB decode is not kSrgb8 itself, a texel's level
// comes from the pass's table of the device's decoded values (gpu::AaPass::srgbDecodeTable,
// built where a probe of every byte shows that it gives each one exactly: lavapipe's does);
// SSFX_GPU_SRGB_DECODE_TABLE=0 forces the other path, the byte recovered with the device's
// pow and its level looked up. Both give the CPU's bytes (GpuSrgbParity covers the default).
TEST(GpuModelParitySrgbDecodeTable, TheRecoveredBytesPathGivesTheCpuBytes) {
    REQUIRE_DEVICE();
    MethodSettings srgb;
    srgb.params = {{"texture", 1}};
    const gpu::AaPass probe(context(), "blur", srgb);
    std::printf("sRGB levels from the device's decode by a table: %s\n", probe.srgbDecodeTable() ? "yes"
                                                                         : probe.deviceDecode()
                                                                             ? "no (the decode is exact)"
                                                                             : "no");
    expectCpuBytesWith("SSFX_GPU_SRGB_DECODE_TABLE", "0", {"blur", "fxaa3c", "fxaa3d", "ddaa1", "ddaa2", "ssaax4"},
                       {Case{"random 64x48", 64, 48}, Case{"random 37x23", 37, 23}}, 120, {1});  // srgb reads only
    ASSERT_EQ(setenv("SSFX_GPU_SRGB_DECODE_TABLE", "0", 1), 0);
    EXPECT_FALSE(gpu::AaPass(context(), "blur", srgb).srgbDecodeTable());
    unsetenv("SSFX_GPU_SRGB_DECODE_TABLE");
    EXPECT_FALSE(gpu::AaPass(context(), "blur", srgb, gpu::Sampling::Hardware).srgbDecodeTable());
    EXPECT_FALSE(gpu::AaPass(context(), "blur").srgbDecodeTable());  // unorm
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
std::vector<const MethodInfo*> textureMethods() {
    std::vector<const MethodInfo*> v;
    for (const MethodInfo* m : allMethods())
        if (m->id != "noaa") v.push_back(m);
    return v;
}
INSTANTIATE_TEST_SUITE_P(Methods, GpuSrgbParity, ::testing::ValuesIn(textureMethods()), methodName);

// Hardware mode: the device's texture unit filters with subTexelPrecisionBits of sub-texel
// weight (VkPhysicalDeviceLimits) and rounds in its own way, so a bilinear read may differ
// from the model by e = 255 / 2^bits levels (the weight error, up to half a step on each
// axis, times a texel difference of at most 255). The mode also uses the device's own
// arithmetic (fused and reordered operations, division within 2.5 ulp, its unorm decode and
// float-to-unorm conversion): a few ulp of values of at most 1, delta = 0.01 levels is far
// above it, plus, for ssaax2, whose read coordinates are a division, 2.5 ulp of u (2.5
// 2^-24) times W texels times 255 levels per texel times 1.159. So, with 1 level for the
// final rounding:
//  - methods that read texels only (noaa, blur, ssaax4) are within 1 + delta levels;
//  - ssaax2 (12 bilinear reads whose weights sum to 1.159 in magnitude), 1 + 1.159 e + delta;
//  - the luma methods also decide on read values (early exit, edge side, search ends), and a
//    decision that flips on a near tie moves that pixel far: for them the test asserts that
//    at least 99 % of the pixels are within 1 + e + delta levels, and prints the largest
//    difference.
// texture=srgb reads through an sRGB view with the device's own decode, which Vulkan lets
// be approximate (lavapipe's is; the pass's probe makes sure it is within half a level of
// the texel in sRGB terms, which the model needs to recover the byte) and encodes with the
// device's pow. A texel's half-level decode error stays at most half a level through the
// filters' convex weights in linear light (sRGB's encode is concave: where a bright texel's
// linear error is larger, its weight in a darker result is smaller in the same proportion),
// so the methods that read texels only are within 1.5 + delta levels; a bilinear weight
// error is not so bounded in sRGB terms (a dark result beside a bright texel magnifies it up
// to 12.92 times), so ssaax2 joins the deciding methods' 99 % rule, at 1.5 + e + delta.
// ddaa2's search reads are either the device's filtered reads (a GPU's default) or, on a CPU
// device, the mean of the two texels they lie half-way between (pairRead: what the filter
// returns there up to its rounding); both run here, each under the same rule
// (SSFX_GPU_COORDINATE_READS=1 and =0).
TEST(GpuAa, HardwareSamplingAgreesWithinTheDevicePrecision) {
    REQUIRE_DEVICE();
    const auto props = context()->physical.getProperties();
    const int bits = int(props.limits.subTexelPrecisionBits);
    const double e = 255.0 / std::ldexp(1.0, bits);
    const auto dir = test::sharedDir("reference/ppaa");
    for (const int texture : {0, 1})
        for (const MethodInfo& m : methods()) {
            if (texture && m.id == "noaa") continue;
            const bool texelsOnly = m.id == "noaa" || m.id == "blur" || m.id == "ssaax4";
            const bool bounded = texelsOnly || (m.id == "ssaax2" && !texture);
            MethodSettings settings;
            if (texture) settings.params = {{"texture", 1}};
            const char* suffix = m.inputScale == 4 ? "x4" : m.inputScale == 2 ? "x2" : "";
            // The inputs and the CPU's outputs, once for every way of reading.
            std::vector<std::pair<std::string, ImageRgba8>> inputs;
            if (dir)
                for (const char* name : {"lines", "circles"})
                    inputs.emplace_back(name, io::readPng(fmt::format("{}/{}{}.png", *dir, name, suffix)));
            else  // the evaluation's synthetic drawing (random noise would be all near-ties, not a drawing)
                inputs.emplace_back("synthetic", eval::syntheticScene(256, 144, m.inputScale));
            std::vector<ImageRgba8> cpuOutputs;
            for (const auto& input : inputs) cpuOutputs.push_back(m.run(input.second.view(), settings, Exec{}));
            const bool searches = m.id == "ddaa2" || m.id == "ddaa2p";
            // ddaa2's search reads (SSFX_GPU_COORDINATE_READS): "1" the filtered reads, "0" the
            // pairs; the other methods run once, as they are.
            const std::vector<const char*> searchReads =
                searches ? std::vector<const char*>{"1", "0"} : std::vector<const char*>{nullptr};
            // blur on both its paths (a pixel an invocation, its segments); the others as they are.
            const std::vector<gpu::EdgePath> paths = m.id == "blur"
                                                         ? std::vector{gpu::EdgePath::OnePass, gpu::EdgePath::Segments}
                                                         : std::vector{gpu::EdgePath::Auto};
            for (const gpu::EdgePath path : paths)
                for (const char* coordinates : searchReads) {
                    if (coordinates) {
                        ASSERT_EQ(setenv("SSFX_GPU_COORDINATE_READS", coordinates, 1), 0);
                    }
                    gpu::AaPass pass(context(), m.id, settings, gpu::Sampling::Hardware, path);
                    unsetenv("SSFX_GPU_COORDINATE_READS");
                    const std::string label =
                        std::string(m.id) +
                        (path == gpu::EdgePath::Auto ? "" : fmt::format(" {}", gpu::edgePathName(path))) +
                        (!coordinates          ? ""
                         : *coordinates == '1' ? ", filtered search reads"
                                               : ", pair search reads");
                    for (std::size_t i = 0; i < inputs.size(); ++i) {
                        const auto& [name, in] = inputs[i];
                        const double delta =
                            0.01 + (m.id == "ssaax2" ? 2.5 * 0x1p-24 * in.width() * 255.0 * 1.159 : 0.0);
                        const double decode = texture ? 0.5 : 0.0;
                        const int within = int(std::floor(1.0 + decode +
                                                          (texelsOnly         ? 0.0
                                                           : m.id == "ssaax2" ? 1.159 * e
                                                                              : e) +
                                                          delta));
                        const ImageRgba8& cpu = cpuOutputs[i];
                        const ImageRgba8 gpu = pass.run(in.view());
                        std::int64_t identical = 0, close = 0;
                        int largest = 0;
                        for (int y = 0; y < cpu.height(); ++y)
                            for (int x = 0; x < cpu.width(); ++x) {
                                const Rgba8 p = cpu(x, y), q = gpu(x, y);
                                const int d = std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b)});
                                identical += d == 0;
                                close += d <= within;
                                largest = std::max(largest, d);
                            }
                        const double n = double(cpu.pixelCount());
                        std::printf(
                            "hardware %-7s %-5s %-8s: %.3f %% identical, %.3f %% within %d levels, largest difference "
                            "%d "
                            "(%d-bit sub-texel precision)\n",
                            label.c_str(), texture ? "srgb" : "unorm", name.c_str(), 100.0 * double(identical) / n,
                            100.0 * double(close) / n, within, largest, bits);
                        if (bounded)
                            EXPECT_LE(largest, within) << label << " on " << name;
                        else
                            EXPECT_GE(double(close) / n, 0.99) << label << " on " << name;
                    }
                }
        }
    expectNoValidationMessages();
}

// Integration as an engine does it: its own device (here a validated vkx::Context standing
// in for the engine's), borrowed by ssfx without owning it; its own command buffer with its
// own commands before and after the pass; the barriers around the pass are the caller's.
TEST(GpuAa, RecordsIntoTheCallersCommandBufferOnTheCallersDevice) {
    REQUIRE_DEVICE();
    vkx::ContextOptions o;
    o.validation = true;
    auto engine = vkx::Context::create(o);
    const ImageRgba8 drawing = inputFor(kCases[5], 1, 5);  // 37x23
    const auto w = std::uint32_t(drawing.width()), h = std::uint32_t(drawing.height());
    const ImageRgba8 expected = methodById("ddaa2").run(drawing.view(), {}, Exec{});
    {
        auto borrowed = vkx::Context::borrow({*engine->instance, *engine->physical, *engine->device, *engine->queue,
                                              engine->queueFamily, engine->pushDescriptors});
        gpu::AaPass pass(borrowed, "ddaa2");
        using U = vk::ImageUsageFlagBits;
        using L = vk::ImageLayout;
        using S = vk::PipelineStageFlagBits;
        using A = vk::AccessFlagBits;
        const vk::ImageUsageFlags inUsage = U::eSampled | U::eTransferDst, outUsage = U::eStorage | U::eTransferSrc;
        vkx::Image in = engine->createImage(vk::Format::eR8G8B8A8Unorm, w, h, inUsage, vk::ImageAspectFlagBits::eColor);
        vkx::Image out =
            engine->createImage(vk::Format::eR8G8B8A8Unorm, w, h, outUsage, vk::ImageAspectFlagBits::eColor);
        const vk::ImageSubresourceRange range(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1);
        auto view2d = [&](const vkx::Image& img) {
            return vk::raii::ImageView(engine->device, vk::ImageViewCreateInfo({}, *img.image, vk::ImageViewType::e2D,
                                                                               vk::Format::eR8G8B8A8Unorm, {}, range));
        };
        const vk::raii::ImageView inView = view2d(in), outView = view2d(out);
        vkx::Buffer upload =
            engine->createBuffer(drawing.pixels().size() * 4, vk::BufferUsageFlagBits::eTransferSrc, true);
        std::memcpy(upload.mapped, drawing.data(), drawing.pixels().size() * 4);
        vkx::Buffer readback = engine->createBuffer(upload.size, vk::BufferUsageFlagBits::eTransferDst, true);
        engine->submit([&](const vk::raii::CommandBuffer& cmd) {
            // The engine's pass before: clear, then upload its frame.
            vkx::transition(cmd, in, L::eUndefined, L::eTransferDstOptimal, S::eTopOfPipe, {}, S::eTransfer,
                            A::eTransferWrite);
            cmd.clearColorImage(*in.image, L::eTransferDstOptimal,
                                vk::ClearColorValue(std::array{1.0f, 0.0f, 0.0f, 1.0f}), range);
            const vk::MemoryBarrier cleared(A::eTransferWrite, A::eTransferWrite);
            cmd.pipelineBarrier(S::eTransfer, S::eTransfer, {}, cleared, {}, {});
            cmd.copyBufferToImage(
                *upload.buffer, *in.image, L::eTransferDstOptimal,
                vk::BufferImageCopy(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1}, {0, 0, 0}, {w, h, 1}));
            // The caller's barriers into the pass's contract.
            vkx::transition(cmd, in, L::eTransferDstOptimal, L::eShaderReadOnlyOptimal, S::eTransfer, A::eTransferWrite,
                            S::eComputeShader, A::eShaderRead);
            vkx::transition(cmd, out, L::eUndefined, L::eGeneral, S::eTopOfPipe, {}, S::eComputeShader,
                            A::eShaderWrite);
            pass.record(cmd, {*inView, vk::Format::eR8G8B8A8Unorm, inUsage, w, h, L::eShaderReadOnlyOptimal},
                        {*outView, vk::Format::eR8G8B8A8Unorm, outUsage, w, h, L::eGeneral});
            // The engine's pass after: read the result back.
            vkx::transition(cmd, out, L::eGeneral, L::eTransferSrcOptimal, S::eComputeShader, A::eShaderWrite,
                            S::eTransfer, A::eTransferRead);
            cmd.copyImageToBuffer(
                *out.image, L::eTransferSrcOptimal, *readback.buffer,
                vk::BufferImageCopy(0, 0, 0, {vk::ImageAspectFlagBits::eColor, 0, 0, 1}, {0, 0, 0}, {w, h, 1}));
            const vk::MemoryBarrier toHost(A::eTransferWrite, A::eHostRead);
            cmd.pipelineBarrier(S::eTransfer, S::eHost, {}, toHost, {}, {});
        });
        ImageRgba8 result{int(w), int(h)};
        std::memcpy(result.data(), readback.mapped, readback.size);
        EXPECT_EQ(compare(result, expected).pixels, 0);
        // A wrong image for the contract: a clear error, nothing recorded.
        const gpu::ImageRef goodIn{*inView, vk::Format::eR8G8B8A8Unorm, inUsage, w, h, L::eShaderReadOnlyOptimal};
        const gpu::ImageRef goodOut{*outView, vk::Format::eR8G8B8A8Unorm, outUsage, w, h, L::eGeneral};
        engine->submit([&](const vk::raii::CommandBuffer& cmd) {
            auto errorOf = [&](const gpu::ImageRef& input, const gpu::ImageRef& output) {
                return test::errorOf([&] { pass.record(cmd, input, output); });
            };
            gpu::ImageRef srgb = goodIn, unsampled = goodIn, transferLayout = goodOut, narrow = goodOut;
            srgb.format = vk::Format::eR8G8B8A8Srgb;
            unsampled.usage = U::eTransferDst;
            transferLayout.layout = L::eTransferSrcOptimal;
            narrow.width = w - 1;
            EXPECT_NE(errorOf(srgb, goodOut).find("sRGB views are for texture=srgb"), std::string::npos);
            // texture=srgb takes sRGB views only (run(), which the parity tests use, records
            // through an R8G8B8A8_SRGB view).
            MethodSettings srgbTexture;
            srgbTexture.params = {{"texture", 1}};
            gpu::AaPass srgbPass(borrowed, "ddaa2", srgbTexture);
            EXPECT_NE(test::errorOf([&] {
                          srgbPass.record(cmd, goodIn, goodOut);
                      }).find("texture=srgb: expected R8G8B8A8_SRGB or B8G8R8A8_SRGB"),
                      std::string::npos);
            EXPECT_NE(errorOf(unsampled, goodOut).find("SAMPLED"), std::string::npos);
            EXPECT_NE(errorOf(goodIn, transferLayout).find("output layout"), std::string::npos);
            EXPECT_NE(errorOf(goodIn, narrow).find("expected 37x23"), std::string::npos);
        });
    }
    // ssfx's borrowed context and pass are gone; the engine's device still works.
    vkx::Buffer after = engine->createBuffer(64, vk::BufferUsageFlagBits::eTransferDst, true);
    engine->submit([&](const vk::raii::CommandBuffer& cmd) { cmd.fillBuffer(*after.buffer, 0, 64, 0x01020304u); });
    EXPECT_EQ(static_cast<const std::uint32_t*>(after.mapped)[15], 0x01020304u);
    const auto messages = engine->validationMessages();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s), the first: " << messages.front();
    EXPECT_NE(test::errorOf([] { vkx::Context::borrow({}); }).find("must all be given"), std::string::npos);
}

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

// The profile of run() (issue #34 item 1, ssfx bench --backend vulkan): each dispatch named
// in order, and the share of pixels the classify dispatch listed, which on a black/white
// split at column 16 of a 32-wide image is the two columns beside it (2/32) for every edge
// test (contrast 1 is above every threshold), none on a flat image, and no list for blur.
TEST(GpuAa, RunReportsItsDispatchesAndTheListedShare) {
    REQUIRE_DEVICE();
    ImageRgba8 split(32, 8), flat(32, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 32; ++x) {
            const std::uint8_t v = x < 16 ? 0 : 255;
            split(x, y) = {v, v, v, 255};
            flat(x, y) = {90, 90, 90, 255};
        }
    for (const char* id : {"fxaa3c", "fxaa3d", "ddaa1", "ddaa2"}) {
        gpu::AaPass pass(context(), id, {}, gpu::Sampling::Model, gpu::EdgePath::List);
        EXPECT_EQ(pass.edgePath(), gpu::EdgePath::List);
        (void)pass.run(split.view());
        std::vector<std::string> stages;
        for (const auto& d : pass.lastDispatches()) {
            stages.push_back(d.stage);
            EXPECT_GE(d.milliseconds, 0.0) << id;
        }
        EXPECT_EQ(stages, (std::vector<std::string>{"luma", "classify", "edges"})) << id;
        EXPECT_DOUBLE_EQ(pass.lastEdgeShare(), 2.0 / 32.0) << id;
        (void)pass.run(flat.view());
        EXPECT_DOUBLE_EQ(pass.lastEdgeShare(), 0.0) << id;
        // The one-pass path: one dispatch, no list.
        gpu::AaPass one(context(), id, {}, gpu::Sampling::Model, gpu::EdgePath::OnePass);
        (void)one.run(split.view());
        ASSERT_EQ(one.lastDispatches().size(), 1u) << id;
        EXPECT_EQ(one.lastDispatches()[0].stage, "one pass") << id;
        EXPECT_EQ(one.lastEdgeShare(), -1.0) << id;
        // The segments: one dispatch, no list.
        gpu::AaPass seg(context(), id, {}, gpu::Sampling::Model, gpu::EdgePath::Segments);
        (void)seg.run(split.view());
        ASSERT_EQ(seg.lastDispatches().size(), 1u) << id;
        EXPECT_EQ(seg.lastDispatches()[0].stage, "segments") << id;
        EXPECT_EQ(seg.lastEdgeShare(), -1.0) << id;
    }
    // Auto: on a CPU device the segments for fxaa3c and ddaa1, and for fxaa3d and ddaa2 in the
    // hardware mode, else the list; one pass on a GPU.
    const bool cpuDevice = context()->physical.getProperties().deviceType == vk::PhysicalDeviceType::eCpu;
    const auto hardware = [](const char* id) {
        return gpu::AaPass(context(), id, {}, gpu::Sampling::Hardware).edgePath();
    };
    EXPECT_EQ(gpu::AaPass(context(), "ddaa2").edgePath(), cpuDevice ? gpu::EdgePath::List : gpu::EdgePath::OnePass);
    EXPECT_EQ(gpu::AaPass(context(), "fxaa3c").edgePath(),
              cpuDevice ? gpu::EdgePath::Segments : gpu::EdgePath::OnePass);
    EXPECT_EQ(hardware("ddaa1"), cpuDevice ? gpu::EdgePath::Segments : gpu::EdgePath::OnePass);
    EXPECT_EQ(hardware("ddaa2"), cpuDevice ? gpu::EdgePath::Segments : gpu::EdgePath::OnePass);
    EXPECT_EQ(hardware("fxaa3d"), cpuDevice ? gpu::EdgePath::Segments : gpu::EdgePath::OnePass);
    EXPECT_EQ(gpu::AaPass(context(), "fxaa3d").edgePath(), cpuDevice ? gpu::EdgePath::List : gpu::EdgePath::OnePass);
    // blur: one dispatch, no list; its segments on a CPU device (auto), one pixel an invocation
    // on a GPU or with one-pass (or list, which it has not).
    gpu::AaPass blur(context(), "blur");
    EXPECT_EQ(blur.edgePath(), cpuDevice ? gpu::EdgePath::Segments : gpu::EdgePath::OnePass);
    (void)blur.run(split.view());
    ASSERT_EQ(blur.lastDispatches().size(), 1u);
    EXPECT_EQ(blur.lastDispatches()[0].stage, cpuDevice ? "segments" : "method");
    EXPECT_EQ(blur.lastEdgeShare(), -1.0);
    for (const gpu::EdgePath path : {gpu::EdgePath::List, gpu::EdgePath::OnePass}) {
        gpu::AaPass perPixel(context(), "blur", {}, gpu::Sampling::Model, path);
        EXPECT_EQ(perPixel.edgePath(), gpu::EdgePath::OnePass);
        (void)perPixel.run(split.view());
        ASSERT_EQ(perPixel.lastDispatches().size(), 1u);
        EXPECT_EQ(perPixel.lastDispatches()[0].stage, "method");
    }
    // noaa has no segments: one pass on any path.
    EXPECT_EQ(gpu::AaPass(context(), "noaa", {}, gpu::Sampling::Model, gpu::EdgePath::Segments).edgePath(),
              gpu::EdgePath::OnePass);
    ImageRgba8 split2(64, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 64; ++x) split2(x, y) = x < 32 ? Rgba8{0, 0, 0, 255} : Rgba8{255, 255, 255, 255};
    gpu::AaPass ddaa2p(context(), "ddaa2p", {}, gpu::Sampling::Model, gpu::EdgePath::List);
    (void)ddaa2p.run(split2.view());
    std::vector<std::string> stages;
    for (const auto& d : ddaa2p.lastDispatches()) stages.push_back(d.stage);
    EXPECT_EQ(stages, (std::vector<std::string>{"luma", "classify", "edges", "resolve"}));
    EXPECT_DOUBLE_EQ(ddaa2p.lastEdgeShare(), 2.0 / 64.0);  // of the 2x image
    expectNoValidationMessages();
}

}  // namespace
}  // namespace ssfx
