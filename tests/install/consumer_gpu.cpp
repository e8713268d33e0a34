// A user of the installed GPU backend: ddaa2 as a Vulkan compute pass on a small image,
// compared with the CPU's bytes. Without a Vulkan device it says so and passes (linking
// and the installed headers are what this checks then).
#include <ssfx/aa/registry.hpp>
#include <ssfx/core/error.hpp>
#include <ssfx/gpu/aa.hpp>

#include <cstdio>

int main() {
    ssfx::ImageRgba8 img(32, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x)
            img(x, y) = (x * 2 + y) % 11 < 5 ? ssfx::Rgba8{10, 10, 10, 255} : ssfx::Rgba8{240, 240, 240, 255};
    std::shared_ptr<ssfx::vkx::Context> ctx;
    try {
        ctx = ssfx::vkx::Context::create();
    } catch (const ssfx::Error& e) {
        std::printf("consumer_gpu: no Vulkan device (%s): linked only\n", e.what());
        return 0;
    }
    ssfx::gpu::AaPass pass(ctx, "ddaa2");
    const ssfx::ImageRgba8 gpu = pass.run(img.view());
    const ssfx::ImageRgba8 cpu = ssfx::methodById("ddaa2").run(img.view(), {}, {});
    const bool same = gpu.pixels() == cpu.pixels();
    std::printf("consumer_gpu: ddaa2 on %s, %s the CPU's bytes\n", ctx->info.name.c_str(), same ? "equal to" : "NOT");
    return same ? 0 : 1;
}
