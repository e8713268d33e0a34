// The Vulkan context of the renderer (internal): instance, device, queue, memory and
// one-shot command submission, through Vulkan-Hpp's RAII wrappers.
#pragma once

#include <functional>
#include <mutex>
#include <string>
#include <vector>
#include <vulkan/vulkan_raii.hpp>

#include "ssfx/render/renderer.hpp"

namespace ssfx::render::vkx {

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

class Context {
public:
    explicit Context(const RendererOptions& options);

    vk::raii::Context context;
    vk::raii::Instance instance{nullptr};
    vk::raii::DebugUtilsMessengerEXT messenger{nullptr};
    vk::raii::PhysicalDevice physical{nullptr};
    vk::raii::Device device{nullptr};
    vk::raii::Queue queue{nullptr};
    vk::raii::CommandPool pool{nullptr};
    std::uint32_t queueFamily = 0;
    DeviceInfo info;
    double timestampPeriodNs = 0;  //!< 0 when the queue has no timestamps
    bool anisotropy = false;
    float maxAnisotropy = 1.0f;

    //! Validation messages; the callback appends under the mutex.
    std::vector<std::string> messages;
    mutable std::mutex mutex;

    //! Host-visible (mapped, coherent) when hostVisible, else device-local.
    Buffer createBuffer(vk::DeviceSize size, vk::BufferUsageFlags usage, bool hostVisible);
    //! A device-local buffer holding `bytes` (copied through a staging buffer).
    Buffer uploadBuffer(const void* bytes, vk::DeviceSize size, vk::BufferUsageFlags usage);
    Image createImage(vk::Format format, std::uint32_t width, std::uint32_t height, vk::ImageUsageFlags usage,
                      vk::ImageAspectFlags aspect, std::uint32_t layers = 1, std::uint32_t levels = 1);
    //! Records with `record`, submits, and waits for completion.
    void submit(const std::function<void(const vk::raii::CommandBuffer&)>& record);
    //! Throws ssfx::Error unless `format` can be a colour or depth attachment that can be copied from.
    void requireAttachmentFormat(vk::Format format, bool depth, const std::string& what) const;

private:
    std::uint32_t memoryType(std::uint32_t bits, vk::MemoryPropertyFlags wanted, vk::MemoryPropertyFlags preferred = {}) const;
};

//! Image layout transition for all levels and layers of `image`.
void transition(const vk::raii::CommandBuffer& cmd, const Image& image, vk::ImageLayout from, vk::ImageLayout to,
                vk::PipelineStageFlags srcStage, vk::AccessFlags srcAccess, vk::PipelineStageFlags dstStage,
                vk::AccessFlags dstAccess);

//! The loader (ssfx::Error naming what to install when there is none).
vk::raii::Context makeContext();
//! A Vulkan 1.3 instance, with the Khronos validation layer and debug utils when asked.
vk::raii::Instance makeInstance(const vk::raii::Context& context, bool validation);
std::vector<DeviceInfo> enumerateDevices(const vk::raii::Instance& instance);

}  // namespace ssfx::render::vkx
