// The GPU tests' Vulkan context: one per test program (device creation is slow on lavapipe),
// with the validation layer and synchronization validation on; null when this machine has no
// Vulkan device, where the tests skip saying so (REQUIRE_DEVICE).
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "ssfx/core/error.hpp"
#include "ssfx/vk/context.hpp"

namespace ssfx::test {

//! A context with validation on, or null (saying why) where there is no such device.
inline std::shared_ptr<vkx::Context> createContextOrNull(bool graphics) {
    vkx::ContextOptions o;
    o.validation = true;
    o.graphics = graphics;
    try {
        return vkx::Context::create(o);
    } catch (const Error& e) {
        std::fprintf(stderr, "no Vulkan device%s: %s\n", graphics ? " with graphics" : "", e.what());
        return {};
    }
}

inline std::shared_ptr<vkx::Context> gpuContext() {
    static const std::shared_ptr<vkx::Context> ctx = createContextOrNull(false);
    return ctx;
}

//! A second shared context with a graphics queue, for tests where the renderer and the GPU
//! passes share one device (as a frame does); null where no device has graphics.
inline std::shared_ptr<vkx::Context> graphicsContext() {
    static const std::shared_ptr<vkx::Context> ctx = createContextOrNull(true);
    return ctx;
}

//! Fails the test when the validation layer has reported anything on `ctx` (default: the
//! shared context) since it was made.
inline void expectNoValidationMessages(const std::shared_ptr<vkx::Context>& ctx = gpuContext()) {
    const auto messages = ctx->validationMessages();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s), the first: " << messages.front();
}

}  // namespace ssfx::test

#define REQUIRE_DEVICE()                                                                   \
    do {                                                                                   \
        if (!::ssfx::test::gpuContext())                                                   \
            GTEST_SKIP() << "no Vulkan device (install mesa-vulkan-drivers for lavapipe)"; \
    } while (0)

#define REQUIRE_GRAPHICS()                                                                  \
    do {                                                                                    \
        if (!::ssfx::test::graphicsContext())                                               \
            GTEST_SKIP() << "no Vulkan device with graphics (install mesa-vulkan-drivers)"; \
    } while (0)
