// One Vulkan instance, device and queue, shared by everything that runs on that device: the
// renderer (ssfx/render) and the GPU effects. Vulkan-Hpp's RAII wrappers throughout. A
// Context is used from one thread at a time (its command pool and queue are not locked).
//
//     vkx::ContextOptions options;
//     options.graphics = true;                  // the renderer needs a graphics queue
//     auto ctx = vkx::Context::create(options);
//     render::Renderer renderer(ctx);           // rasterises on ctx's device
//     ...                                        // GPU effects take the same ctx
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>
#include <vulkan/vulkan_raii.hpp>

#include "ssfx/vk/device.hpp"
#include "ssfx/vk/resources.hpp"

namespace ssfx::vkx {

class Context {
    // First, so that they outlive the device and the messenger, whose destruction can report.
    std::vector<std::string> messages_;
    mutable std::mutex mutex_;
    friend struct ValidationSink;

public:
    //! Chooses a device (ContextOptions::device) that has what `options` asks for and creates
    //! one queue on it: graphics and compute when options.graphics, else compute. Throws
    //! ssfx::Error naming the problem: no loader, no driver, no such device, no validation layer.
    explicit Context(const ContextOptions& options = {});
    static std::shared_ptr<Context> create(const ContextOptions& options = {});

    //! A caller's Vulkan objects, which a borrowed Context uses without owning them.
    struct External {
        VkInstance instance = VK_NULL_HANDLE;
        VkPhysicalDevice physical = VK_NULL_HANDLE;
        VkDevice device = VK_NULL_HANDLE;  //!< created with VK_KHR_push_descriptor for the GPU effects
        VkQueue queue = VK_NULL_HANDLE;    //!< a queue with compute of family queueFamily
        std::uint32_t queueFamily = 0;
        bool pushDescriptors = false;  //!< the device has VK_KHR_push_descriptor enabled
    };
    //! Wraps the caller's instance, device and queue (how an engine shares its device with
    //! ssfx): the Context creates its own command pool and uses the caller's queue from the
    //! caller's thread; it destroys none of the caller's objects. The caller keeps them alive
    //! until every Context and pass made from them is gone. Throws ssfx::Error for null handles.
    static std::shared_ptr<Context> borrow(const External& external);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    vk::raii::Context context;
    vk::raii::Instance instance{nullptr};
    vk::raii::DebugUtilsMessengerEXT messenger{nullptr};
    vk::raii::PhysicalDevice physical{nullptr};
    vk::raii::Device device{nullptr};
    vk::raii::Queue queue{nullptr};
    vk::raii::CommandPool pool{nullptr};  //!< resettable command buffers of `queue`'s family
    std::uint32_t queueFamily = 0;
    DeviceInfo info;
    bool graphics = false;         //!< the queue has graphics and the device dynamic rendering
    double timestampPeriodNs = 0;  //!< 0 when the queue has no timestamps
    bool anisotropy = false;
    float maxAnisotropy = 1.0f;
    bool pushDescriptors = false;  //!< VK_KHR_push_descriptor is enabled (the GPU effects need it)
    //! The most loop iterations one shader invocation may run, all its loops together, before
    //! the driver silently ends them; 0 where none is known. llvmpipe (lavapipe): 65535, Mesa's
    //! LP_MAX_TGSI_LOOP_ITERATIONS (its loop limiter, set at a shader's start and counted down by
    //! every loop's every iteration). Passes whose invocations loop size their dispatches by it.
    std::uint32_t maxShaderLoopIterations = 0;
    bool borrowed = false;  //!< instance, device and queue are the caller's (borrow())

    //! Validation messages (warnings and errors) since creation; empty when validation is off.
    std::vector<std::string> validationMessages() const;

    //! Host-visible (mapped, coherent; cached when there is such memory) when hostVisible,
    //! else device-local.
    Buffer createBuffer(vk::DeviceSize size, vk::BufferUsageFlags usage, bool hostVisible);
    //! A device-local buffer holding `bytes` (copied through a staging buffer).
    Buffer uploadBuffer(const void* bytes, vk::DeviceSize size, vk::BufferUsageFlags usage);
    //! A 2-D (array) image with its view: e2DArray when layered or sampled, else e2D.
    Image createImage(vk::Format format, std::uint32_t width, std::uint32_t height, vk::ImageUsageFlags usage,
                      vk::ImageAspectFlags aspect, std::uint32_t layers = 1, std::uint32_t levels = 1,
                      vk::ImageCreateFlags flags = {});
    //! One-shot submission: records with `record`, submits, and waits for completion.
    void submit(const std::function<void(const vk::raii::CommandBuffer&)>& record);
    //! Submits an already recorded command buffer and waits for completion.
    void submit(const vk::raii::CommandBuffer& recorded);
    //! Throws ssfx::Error unless `format` can be a colour or depth attachment that can be copied from.
    void requireAttachmentFormat(vk::Format format, bool depth, const std::string& what) const;
    //! Throws ssfx::Error when width or height exceeds the device's 2-D image limit.
    void requireImageSize(std::uint32_t width, std::uint32_t height, const std::string& what) const;
    //! Whether compute shaders on this device have every subgroup operation in `ops`.
    bool computeSubgroupOps(vk::SubgroupFeatureFlags ops) const;

private:
    struct BorrowTag {};
    Context(const External& external, BorrowTag);
    std::uint32_t memoryType(std::uint32_t bits, vk::MemoryPropertyFlags wanted,
                             vk::MemoryPropertyFlags preferred = {}) const;
};

//! Commands recorded once and submitted any number of times (a benchmark's loop, a frame).
class Recording {
public:
    Recording(Context& ctx, const std::function<void(const vk::raii::CommandBuffer&)>& record);
    //! Submits and waits.
    void run();
    const vk::raii::CommandBuffer& commands() const { return buffers_[0]; }

private:
    Context* ctx_;
    vk::raii::CommandBuffers buffers_;
};

//! Vulkan-Hpp reports API failures as its own exceptions; callers of ssfx see ssfx::Error.
//! Runs f() and rethrows a vk::SystemError as ssfx::Error("Vulkan: WHAT failed: ...").
template <class F>
auto guarded(const char* what, F&& f) -> decltype(f());
[[noreturn]] void rethrowVulkanError(const char* what, const vk::SystemError& e);

template <class F>
auto guarded(const char* what, F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const vk::SystemError& e) {
        rethrowVulkanError(what, e);
    }
}

}  // namespace ssfx::vkx
