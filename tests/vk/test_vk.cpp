// The vk module on lavapipe (or any Vulkan 1.3 device): device choice, compute pipelines,
// recorded submissions, timestamps, a context shared with the renderer, and the validation
// layer's synchronization validation (proved on, by a missing barrier it must report).
#include <gtest/gtest.h>

#include <cstring>
#include <numeric>

#include "ssfx/core/error.hpp"
#include "ssfx/render/renderer.hpp"
#include "ssfx/scene/scene.hpp"
#include "ssfx/vk/compute.hpp"
#include "ssfx/vk/context.hpp"
#include "ssfx/vk/timer.hpp"
#include "tests/support/test_support.hpp"

namespace ssfx {
namespace {

const std::uint32_t kAffine[] = {
#include "shaders/affine.comp.inc"
};

struct Push {
    float a;
    std::uint32_t count;
};

const std::vector<vkx::BindingSpec> kAffineBindings = {{vk::DescriptorType::eStorageBuffer},
                                                       {vk::DescriptorType::eStorageBuffer}};

vkx::ContextOptions validated(bool graphics) {
    vkx::ContextOptions options;
    options.validation = true;
    options.graphics = graphics;
    return options;
}

// A compute-only context with validation; one per program (device creation is slow on lavapipe).
vkx::Context& computeContext() {
    static std::shared_ptr<vkx::Context> ctx = vkx::Context::create(validated(false));
    return *ctx;
}

// Records: dispatch the affine shader over `in` into `out`, then copy `out` to `host`.
// `barrier` = false leaves out the barrier between the shader's write and the copy's read.
void recordAffine(const vk::raii::CommandBuffer& cmd, const vkx::ComputePipeline& pipe, const vkx::DescriptorSets& sets,
                  const Push& push, const vkx::Buffer& out, const vkx::Buffer& host, bool barrier = true) {
    pipe.dispatch(cmd, sets[0], &push, vkx::groupCount(push.count, 64));
    if (barrier) vkx::computeBarrier(cmd, vk::PipelineStageFlagBits::eTransfer, vk::AccessFlagBits::eTransferRead);
    cmd.copyBuffer(*out.buffer, *host.buffer, vk::BufferCopy(0, 0, out.size));
    const vk::MemoryBarrier toHost(vk::AccessFlagBits::eTransferWrite, vk::AccessFlagBits::eHostRead);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eHost, {}, toHost, {}, {});
}

struct AffineRun {
    explicit AffineRun(vkx::Context& ctx, std::uint32_t n)
        : pipe(ctx, kAffine, kAffineBindings, sizeof(Push)), sets(pipe.makeSets()) {
        std::vector<float> values(n);
        for (std::uint32_t i = 0; i < n; ++i) values[i] = float(i % 97) - 40.0f;
        in = ctx.uploadBuffer(values.data(), n * sizeof(float), vk::BufferUsageFlagBits::eStorageBuffer);
        out = ctx.createBuffer(n * sizeof(float),
                               vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferSrc, false);
        host = ctx.createBuffer(n * sizeof(float), vk::BufferUsageFlagBits::eTransferDst, true);
        sets.bind(0, 0, in);
        sets.bind(0, 1, out);
        input = values;
    }
    std::vector<float> result() const {
        std::vector<float> r(input.size());
        std::memcpy(r.data(), host.mapped, r.size() * sizeof(float));
        return r;
    }
    // a * x + i, exactly: small integers and a = -3 are exact in float.
    std::vector<float> expected(float a) const {
        std::vector<float> e(input.size());
        for (std::size_t i = 0; i < e.size(); ++i) e[i] = a * input[i] + float(i);
        return e;
    }
    vkx::ComputePipeline pipe;
    vkx::DescriptorSets sets;
    vkx::Buffer in, out, host;
    std::vector<float> input;
};

class VkTest : public ::testing::Test {
protected:
    void SetUp() override { seen_ = computeContext().validationMessages().size(); }
    void TearDown() override {
        const auto messages = computeContext().validationMessages();
        EXPECT_EQ(messages.size(), seen_) << "validation layer: " << (messages.size() > seen_ ? messages.back() : "");
    }
    std::size_t seen_ = 0;
};

TEST(VkDevices, ListsAComputeDevice) {
    const auto devices = vkx::listDevices();
    ASSERT_FALSE(devices.empty()) << "no Vulkan device (mesa-vulkan-drivers gives lavapipe)";
    bool compute = false;
    for (const auto& d : devices) {
        EXPECT_FALSE(d.name.empty());
        EXPECT_TRUE(!d.graphics || d.compute) << d.name << ": graphics-capable but not compute-capable";
        compute = compute || d.compute;
    }
    EXPECT_TRUE(compute);
}

TEST(VkDevices, UnknownDeviceIsAClearError) {
    const std::string message = test::errorOf([] {
        vkx::ContextOptions options;
        options.device = "no-such-gpu";
        vkx::Context ctx(options);
    });
    EXPECT_NE(message.find("no Vulkan device 'no-such-gpu'"), std::string::npos) << message;
    EXPECT_NE(message.find("devices:"), std::string::npos) << message;
}

TEST_F(VkTest, ComputeContextHasNoGraphicsQueueByDefault) {
    EXPECT_FALSE(computeContext().graphics);
    EXPECT_TRUE(computeContext().info.compute);
}

TEST_F(VkTest, DispatchCoversEveryItemAndNoMore) {
    // 1000 = 15 groups of 64 and 40 items: the last group must stop at count.
    vkx::Context& ctx = computeContext();
    AffineRun run(ctx, 1000);
    const Push push{-3.0f, 1000};
    ctx.submit(
        [&](const vk::raii::CommandBuffer& cmd) { recordAffine(cmd, run.pipe, run.sets, push, run.out, run.host); });
    EXPECT_EQ(run.result(), run.expected(-3.0f));
}

TEST_F(VkTest, RecordingRunsAgainOnNewData) {
    vkx::Context& ctx = computeContext();
    AffineRun run(ctx, 256);
    const Push push{2.0f, 256};
    vkx::Recording recording(ctx, [&](const vk::raii::CommandBuffer& cmd) {
        recordAffine(cmd, run.pipe, run.sets, push, run.out, run.host);
    });
    recording.run();
    EXPECT_EQ(run.result(), run.expected(2.0f));
    // New input through a fresh upload into the same buffer: the recording reads it.
    std::vector<float> ones(256, 1.0f);
    vkx::Buffer staging = ctx.createBuffer(256 * sizeof(float), vk::BufferUsageFlagBits::eTransferSrc, true);
    std::memcpy(staging.mapped, ones.data(), 256 * sizeof(float));
    ctx.submit([&](const vk::raii::CommandBuffer& cmd) {
        cmd.copyBuffer(*staging.buffer, *run.in.buffer, vk::BufferCopy(0, 0, 256 * sizeof(float)));
    });
    run.input = ones;
    recording.run();
    EXPECT_EQ(run.result(), run.expected(2.0f));
}

TEST_F(VkTest, TimerMeasuresTheDispatch) {
    vkx::Context& ctx = computeContext();
    AffineRun run(ctx, 4096);
    const vkx::GpuTimer timer(ctx, 2);
    const Push push{1.0f, 4096};
    ctx.submit([&](const vk::raii::CommandBuffer& cmd) {
        timer.reset(cmd);
        timer.begin(cmd, 0);
        recordAffine(cmd, run.pipe, run.sets, push, run.out, run.host);
        timer.end(cmd, 0);
        timer.begin(cmd, 1);
        timer.end(cmd, 1);
    });
    const auto ms = timer.milliseconds();
    ASSERT_EQ(ms.size(), 2u);
    if (!timer.available()) GTEST_SKIP() << "the queue has no timestamps";
    EXPECT_GE(ms[0], 0.0);
    EXPECT_LT(ms[0], 10000.0);  // a sanity bound: a wrapped or garbage tick count is far larger
    EXPECT_GE(ms[1], 0.0);
}

TEST_F(VkTest, SynchronizationValidationReportsAMissingBarrier) {
    // The compute write and the transfer read of `out` with no barrier between them: a
    // read-after-write hazard that synchronization validation must report. This proves the
    // layer is on with synchronization validation, so that the other tests' silence counts.
    vkx::Context& ctx = computeContext();
    AffineRun run(ctx, 128);
    const Push push{1.0f, 128};
    ctx.submit([&](const vk::raii::CommandBuffer& cmd) {
        recordAffine(cmd, run.pipe, run.sets, push, run.out, run.host, false);
    });
    const auto messages = ctx.validationMessages();
    bool hazard = false;
    for (std::size_t i = seen_; i < messages.size(); ++i)
        hazard = hazard || messages[i].find("SYNC-HAZARD") != std::string::npos;
    EXPECT_TRUE(hazard) << "no SYNC-HAZARD message among " << messages.size() - seen_ << " new messages";
    seen_ = messages.size();  // expected messages: not a failure of TearDown
}

TEST_F(VkTest, RejectsWordsThatAreNotSpirv) {
    const std::uint32_t words[] = {1, 2, 3};
    const std::string message = test::errorOf([&] { (void)vkx::makeShaderModule(computeContext(), words); });
    EXPECT_NE(message.find("SPIR-V"), std::string::npos) << message;
}

TEST_F(VkTest, RendererNeedsAGraphicsContext) {
    auto compute = std::shared_ptr<vkx::Context>(&computeContext(), [](vkx::Context*) {});
    const std::string message = test::errorOf([&] { render::Renderer r(compute); });
    EXPECT_NE(message.find("no graphics queue"), std::string::npos) << message;
}

TEST(VkShared, RendererAndComputeShareOneContext) {
    auto ctx = vkx::Context::create(validated(true));
    render::Renderer renderer(ctx);
    EXPECT_EQ(renderer.context().get(), ctx.get());
    EXPECT_EQ(renderer.device().name, ctx->info.name);
    const scene::Scene scene = scene::builtinScene("cornell");
    const auto color = renderer.renderColor(scene, scene.views.at(0).second, 32, 24);
    EXPECT_EQ(color.color.width(), 32);
    AffineRun run(*ctx, 300);
    const Push push{0.5f, 300};
    ctx->submit(
        [&](const vk::raii::CommandBuffer& cmd) { recordAffine(cmd, run.pipe, run.sets, push, run.out, run.host); });
    EXPECT_EQ(run.result(), run.expected(0.5f));
    const auto messages = ctx->validationMessages();
    EXPECT_TRUE(messages.empty()) << messages.size()
                                  << " messages, the first: " << (messages.empty() ? "" : messages[0]);
}

}  // namespace
}  // namespace ssfx
