// Buffers and images with their memory, as the vk module's Context creates them.
#pragma once

#include <cstdint>
#include <vulkan/vulkan_raii.hpp>

namespace ssfx::vkx {

struct Buffer {
    vk::raii::Buffer buffer{nullptr};
    vk::raii::DeviceMemory memory{nullptr};
    vk::DeviceSize size = 0;
    void* mapped = nullptr;  //!< for host-visible buffers: persistently mapped
};

struct Image {
    vk::raii::Image image{nullptr};
    vk::raii::DeviceMemory memory{nullptr};
    vk::raii::ImageView view{nullptr};
    vk::Format format = vk::Format::eUndefined;
    vk::ImageAspectFlags aspect;
    std::uint32_t width = 0, height = 0, layers = 1, levels = 1;
};

//! Image layout transition for all levels and layers of `image`.
void transition(const vk::raii::CommandBuffer& cmd, const Image& image, vk::ImageLayout from, vk::ImageLayout to,
                vk::PipelineStageFlags srcStage, vk::AccessFlags srcAccess, vk::PipelineStageFlags dstStage,
                vk::AccessFlags dstAccess);

}  // namespace ssfx::vkx
