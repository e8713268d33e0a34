// Vulkan instance, device choice and resources (see vk_context.hpp).
#include "vk_context.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>

#include "ssfx/core/error.hpp"

namespace ssfx::render::vkx {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* ctx = static_cast<Context*>(user);
    const char* level = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
    std::lock_guard lock(ctx->mutex);
    ctx->messages.push_back(fmt::format("{}: {}", level, data && data->pMessage ? data->pMessage : "(no message)"));
    return VK_FALSE;
}

std::string typeName(vk::PhysicalDeviceType t) {
    switch (t) {
        case vk::PhysicalDeviceType::eDiscreteGpu: return "discrete";
        case vk::PhysicalDeviceType::eIntegratedGpu: return "integrated";
        case vk::PhysicalDeviceType::eVirtualGpu: return "virtual";
        case vk::PhysicalDeviceType::eCpu: return "cpu";
        default: return "other";
    }
}

int typeRank(const std::string& t) {
    if (t == "discrete") return 0;
    if (t == "integrated") return 1;
    if (t == "virtual") return 2;
    if (t == "cpu") return 3;
    return 4;
}

bool usable(const vk::raii::PhysicalDevice& pd) {
    if (pd.getProperties().apiVersion < VK_API_VERSION_1_3) return false;
    const auto chain = pd.getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDeviceVulkan13Features>();
    if (!chain.get<vk::PhysicalDeviceVulkan13Features>().dynamicRendering) return false;
    for (const auto& q : pd.getQueueFamilyProperties())
        if (q.queueFlags & vk::QueueFlagBits::eGraphics) return true;
    return false;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

}  // namespace

vk::raii::Context makeContext() {
    try {
        return vk::raii::Context();
    } catch (const std::exception& e) {
        throw Error(fmt::format("no Vulkan loader ({}); install libvulkan1 and a driver such as mesa-vulkan-drivers",
                                e.what()));
    }
}

vk::raii::Instance makeInstance(const vk::raii::Context& context, bool validation) {
    std::vector<const char*> layers, extensions;
    if (validation) {
        bool found = false;
        for (const auto& l : context.enumerateInstanceLayerProperties())
            if (std::strcmp(l.layerName, kValidationLayer) == 0) found = true;
        if (!found)
            throw Error(fmt::format("validation requested but {} is not installed (Debian: vulkan-validationlayers)",
                                    kValidationLayer));
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    if (context.enumerateInstanceVersion() < VK_API_VERSION_1_3)
        throw Error("the Vulkan loader is older than 1.3; ssfx render needs Vulkan 1.3");
    const vk::ApplicationInfo app("ssfx", 1, "ssfx", 1, VK_API_VERSION_1_3);
    try {
        return vk::raii::Instance(context, vk::InstanceCreateInfo({}, &app, layers, extensions));
    } catch (const vk::SystemError& e) {
        throw Error(fmt::format("cannot create a Vulkan instance ({}); is a Vulkan driver installed "
                                "(mesa-vulkan-drivers)?", e.what()));
    }
}

std::vector<DeviceInfo> enumerateDevices(const vk::raii::Instance& instance) {
    std::vector<DeviceInfo> out;
    vk::raii::PhysicalDevices devices(instance);
    for (std::size_t i = 0; i < devices.size(); ++i) {
        const auto p = devices[i].getProperties();
        DeviceInfo d;
        d.index = int(i);
        d.name = p.deviceName.data();
        d.type = typeName(p.deviceType);
        d.api = fmt::format("{}.{}.{}", VK_API_VERSION_MAJOR(p.apiVersion), VK_API_VERSION_MINOR(p.apiVersion),
                            VK_API_VERSION_PATCH(p.apiVersion));
        d.usable = usable(devices[i]);
        d.maxImageDimension2D = int(p.limits.maxImageDimension2D);
        out.push_back(d);
    }
    return out;
}

Context::Context(const RendererOptions& options) : context(makeContext()) {
    const char* env = std::getenv("SSFX_VK_VALIDATION");
    const bool validation = options.validation || (env && std::string(env) == "1");
    instance = makeInstance(context, validation);
    if (validation) {
        using S = vk::DebugUtilsMessageSeverityFlagBitsEXT;
        using T = vk::DebugUtilsMessageTypeFlagBitsEXT;
        messenger = vk::raii::DebugUtilsMessengerEXT(
            instance, vk::DebugUtilsMessengerCreateInfoEXT({}, S::eWarning | S::eError,
                                                           T::eGeneral | T::eValidation | T::ePerformance,
                                                           &onValidationMessage, this));
    }
    const auto infos = enumerateDevices(instance);
    std::string listing;
    for (const auto& d : infos)
        listing += fmt::format("\n  {}: {} ({}, Vulkan {}{})", d.index, d.name, d.type, d.api, d.usable ? "" : ", unusable");
    if (infos.empty()) throw Error("no Vulkan device; install mesa-vulkan-drivers for the lavapipe CPU device");
    int chosen = -1;
    if (options.device.empty()) {
        for (const auto& d : infos)
            if (d.usable && (chosen < 0 || typeRank(d.type) < typeRank(infos[std::size_t(chosen)].type))) chosen = d.index;
        if (chosen < 0) throw Error("no Vulkan 1.3 device with dynamic rendering; devices:" + listing);
    } else {
        const bool isIndex = std::all_of(options.device.begin(), options.device.end(), [](unsigned char c) { return std::isdigit(c); });
        for (const auto& d : infos)
            if (isIndex ? std::to_string(d.index) == options.device : lower(d.name).find(lower(options.device)) != std::string::npos) {
                chosen = d.index;
                break;
            }
        if (chosen < 0) throw Error(fmt::format("no Vulkan device '{}'; devices:{}", options.device, listing));
        if (!infos[std::size_t(chosen)].usable)
            throw Error(fmt::format("device '{}' does not support Vulkan 1.3 with dynamic rendering", infos[std::size_t(chosen)].name));
    }
    info = infos[std::size_t(chosen)];
    physical = std::move(vk::raii::PhysicalDevices(instance)[std::size_t(chosen)]);

    const auto families = physical.getQueueFamilyProperties();
    for (std::uint32_t i = 0; i < families.size(); ++i)
        if (families[i].queueFlags & vk::QueueFlagBits::eGraphics) {
            queueFamily = i;
            break;
        }
    const auto props = physical.getProperties();
    timestampPeriodNs = families[queueFamily].timestampValidBits > 0 ? props.limits.timestampPeriod : 0.0;
    const auto supported = physical.getFeatures();
    anisotropy = supported.samplerAnisotropy;
    maxAnisotropy = props.limits.maxSamplerAnisotropy;

    const float priority = 1.0f;
    const vk::DeviceQueueCreateInfo queueInfo({}, queueFamily, 1, &priority);
    vk::PhysicalDeviceFeatures features;
    features.samplerAnisotropy = anisotropy;
    vk::PhysicalDeviceVulkan13Features features13;
    features13.dynamicRendering = VK_TRUE;
    // Lets a vertex output go unread by a fragment stage (the G-buffer pass ignores the world
    // position) without a validation performance warning; core in 1.3, optional to support.
    features13.maintenance4 = physical.getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDeviceVulkan13Features>()
                                  .get<vk::PhysicalDeviceVulkan13Features>()
                                  .maintenance4;
    vk::PhysicalDeviceFeatures2 features2(features, &features13);
    vk::DeviceCreateInfo deviceInfo({}, queueInfo, {}, {}, nullptr);
    deviceInfo.pNext = &features2;
    device = vk::raii::Device(physical, deviceInfo);
    queue = vk::raii::Queue(device, queueFamily, 0);
    pool = vk::raii::CommandPool(device, vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eTransient, queueFamily));
}

std::uint32_t Context::memoryType(std::uint32_t bits, vk::MemoryPropertyFlags wanted, vk::MemoryPropertyFlags preferred) const {
    const auto mem = physical.getMemoryProperties();
    for (int pass = 0; pass < 2; ++pass) {
        const auto need = pass == 0 ? wanted | preferred : wanted;
        for (std::uint32_t i = 0; i < mem.memoryTypeCount; ++i)
            if ((bits & (1u << i)) && (mem.memoryTypes[i].propertyFlags & need) == need) return i;
    }
    throw Error(fmt::format("Vulkan device '{}' has no suitable memory type", info.name));
}

Buffer Context::createBuffer(vk::DeviceSize size, vk::BufferUsageFlags usage, bool hostVisible) {
    Buffer b;
    b.size = size;
    b.buffer = vk::raii::Buffer(device, vk::BufferCreateInfo({}, size, usage, vk::SharingMode::eExclusive));
    const auto req = b.buffer.getMemoryRequirements();
    const auto flags = hostVisible ? vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent
                                   : vk::MemoryPropertyFlagBits::eDeviceLocal;
    // Reading back: cached host memory is much faster to read on discrete GPUs.
    const auto preferred = hostVisible ? vk::MemoryPropertyFlags(vk::MemoryPropertyFlagBits::eHostCached) : vk::MemoryPropertyFlags();
    b.memory = vk::raii::DeviceMemory(device, vk::MemoryAllocateInfo(req.size, memoryType(req.memoryTypeBits, flags, preferred)));
    b.buffer.bindMemory(*b.memory, 0);
    if (hostVisible) b.mapped = b.memory.mapMemory(0, VK_WHOLE_SIZE);
    return b;
}

Buffer Context::uploadBuffer(const void* bytes, vk::DeviceSize size, vk::BufferUsageFlags usage) {
    Buffer staging = createBuffer(size, vk::BufferUsageFlagBits::eTransferSrc, true);
    std::memcpy(staging.mapped, bytes, size);
    Buffer b = createBuffer(size, usage | vk::BufferUsageFlagBits::eTransferDst, false);
    submit([&](const vk::raii::CommandBuffer& cmd) { cmd.copyBuffer(*staging.buffer, *b.buffer, vk::BufferCopy(0, 0, size)); });
    return b;
}

Image Context::createImage(vk::Format format, std::uint32_t width, std::uint32_t height, vk::ImageUsageFlags usage,
                           vk::ImageAspectFlags aspect, std::uint32_t layers, std::uint32_t levels) {
    Image img;
    img.format = format;
    img.aspect = aspect;
    img.width = width;
    img.height = height;
    img.layers = layers;
    img.levels = levels;
    img.image = vk::raii::Image(device, vk::ImageCreateInfo({}, vk::ImageType::e2D, format, vk::Extent3D(width, height, 1),
                                                            levels, layers, vk::SampleCountFlagBits::e1,
                                                            vk::ImageTiling::eOptimal, usage));
    const auto req = img.image.getMemoryRequirements();
    img.memory = vk::raii::DeviceMemory(
        device, vk::MemoryAllocateInfo(req.size, memoryType(req.memoryTypeBits, vk::MemoryPropertyFlagBits::eDeviceLocal)));
    img.image.bindMemory(*img.memory, 0);
    img.view = vk::raii::ImageView(device, vk::ImageViewCreateInfo({}, *img.image,
                                                                   layers > 1 || (usage & vk::ImageUsageFlagBits::eSampled)
                                                                       ? vk::ImageViewType::e2DArray
                                                                       : vk::ImageViewType::e2D,
                                                                   format, {}, vk::ImageSubresourceRange(aspect, 0, levels, 0, layers)));
    return img;
}

void Context::submit(const std::function<void(const vk::raii::CommandBuffer&)>& record) {
    vk::raii::CommandBuffers cmds(device, vk::CommandBufferAllocateInfo(*pool, vk::CommandBufferLevel::ePrimary, 1));
    const vk::raii::CommandBuffer& cmd = cmds[0];
    cmd.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    record(cmd);
    cmd.end();
    vk::raii::Fence fence(device, vk::FenceCreateInfo());
    const vk::CommandBuffer handle = *cmd;
    queue.submit(vk::SubmitInfo({}, {}, handle), *fence);
    if (device.waitForFences(*fence, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess)
        throw Error("Vulkan: waiting for the GPU failed");
}

void Context::requireAttachmentFormat(vk::Format format, bool depth, const std::string& what) const {
    const auto props = physical.getFormatProperties(format);
    const auto need = (depth ? vk::FormatFeatureFlagBits::eDepthStencilAttachment : vk::FormatFeatureFlagBits::eColorAttachment) |
                      vk::FormatFeatureFlagBits::eTransferSrc;
    if ((props.optimalTilingFeatures & need) != need)
        throw Error(fmt::format("Vulkan device '{}' cannot render {} as {}", info.name, what, vk::to_string(format)));
}

void transition(const vk::raii::CommandBuffer& cmd, const Image& image, vk::ImageLayout from, vk::ImageLayout to,
                vk::PipelineStageFlags srcStage, vk::AccessFlags srcAccess, vk::PipelineStageFlags dstStage,
                vk::AccessFlags dstAccess) {
    const vk::ImageMemoryBarrier barrier(srcAccess, dstAccess, from, to, VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED,
                                         *image.image,
                                         vk::ImageSubresourceRange(image.aspect, 0, image.levels, 0, image.layers));
    cmd.pipelineBarrier(srcStage, dstStage, {}, {}, {}, barrier);
}

}  // namespace ssfx::render::vkx
