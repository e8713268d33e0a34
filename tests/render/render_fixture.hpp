// One validated Vulkan renderer per test program; every test ends by checking that the
// Khronos validation layer said nothing.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "ssfx/render/renderer.hpp"

namespace ssfx::test {

class RenderTest : public ::testing::Test {
protected:
    static render::Renderer& renderer() {
        static std::unique_ptr<render::Renderer> r =
            std::make_unique<render::Renderer>(render::RendererOptions{"", true});
        return *r;
    }
    void TearDown() override {
        const auto messages = renderer().validationMessages();
        EXPECT_EQ(messages.size(), seen_) << "validation layer: " << (messages.empty() ? "" : messages.back());
    }
    void SetUp() override { seen_ = renderer().validationMessages().size(); }

private:
    std::size_t seen_ = 0;
};

}  // namespace ssfx::test
