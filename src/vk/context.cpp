// Vulkan instance, device choice, the queue and submission (see ssfx/vk/context.hpp).
#include "ssfx/vk/context.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "ssfx/core/error.hpp"

namespace ssfx::vkx {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

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

// The queue family for a context: graphics with compute (every graphics-capable device has
// such a family, Vulkan spec 5.1) when asked, else the first with compute.
std::optional<std::uint32_t> queueFamilyFor(const vk::raii::PhysicalDevice& pd, bool graphics) {
    const auto families = pd.getQueueFamilyProperties();
    vk::QueueFlags need = vk::QueueFlagBits::eCompute;
    if (graphics) need |= vk::QueueFlagBits::eGraphics;
    for (std::uint32_t i = 0; i < families.size(); ++i)
        if ((families[i].queueFlags & need) == need) return i;
    return std::nullopt;
}

bool hasDynamicRendering(const vk::raii::PhysicalDevice& pd) {
    const auto chain = pd.getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDeviceVulkan13Features>();
    return chain.get<vk::PhysicalDeviceVulkan13Features>().dynamicRendering;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

vk::raii::Context makeLoader() {
    try {
        return vk::raii::Context();
    } catch (const std::exception& e) {
        throw Error(fmt::format("no Vulkan loader ({}); install libvulkan1 and a driver such as mesa-vulkan-drivers",
                                e.what()));
    }
}

bool hasLayerExtension(const vk::raii::Context& context, const char* layer, const char* extension) {
    for (const auto& e : context.enumerateInstanceExtensionProperties(std::string(layer)))
        if (std::strcmp(e.extensionName, extension) == 0) return true;
    return false;
}

// A Vulkan 1.3 instance; with validation: the Khronos layer with synchronization validation
// (VK_EXT_validation_features) and debug utils for its messages.
vk::raii::Instance makeInstance(const vk::raii::Context& context, bool validation) {
    std::vector<const char*> layers, extensions;
    const std::array<vk::ValidationFeatureEnableEXT, 1> enables = {
        vk::ValidationFeatureEnableEXT::eSynchronizationValidation};
    vk::ValidationFeaturesEXT features(enables, {});
    const void* next = nullptr;
    if (validation) {
        bool found = false;
        for (const auto& l : context.enumerateInstanceLayerProperties())
            if (std::strcmp(l.layerName, kValidationLayer) == 0) found = true;
        if (!found)
            throw Error(fmt::format("validation requested but {} is not installed (Debian: vulkan-validationlayers)",
                                    kValidationLayer));
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        if (!hasLayerExtension(context, kValidationLayer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME))
            throw Error(
                fmt::format("{} has no {} (needed for synchronization validation); update vulkan-validationlayers",
                            kValidationLayer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME));
        extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
        next = &features;
    }
    if (context.enumerateInstanceVersion() < VK_API_VERSION_1_3)
        throw Error("the Vulkan loader is older than 1.3; ssfx needs Vulkan 1.3");
    const vk::ApplicationInfo app("ssfx", 1, "ssfx", 1, VK_API_VERSION_1_3);
    vk::InstanceCreateInfo info({}, &app, layers, extensions);
    info.pNext = next;
    try {
        return vk::raii::Instance(context, info);
    } catch (const vk::SystemError& e) {
        throw Error(
            fmt::format("cannot create a Vulkan instance ({}); is a Vulkan driver installed "
                        "(mesa-vulkan-drivers)?",
                        e.what()));
    }
}

std::vector<DeviceInfo> enumerate(const vk::raii::Instance& instance) {
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
        const bool v13 = p.apiVersion >= VK_API_VERSION_1_3;
        d.compute = v13 && queueFamilyFor(devices[i], false).has_value();
        d.graphics = d.compute && queueFamilyFor(devices[i], true).has_value() && hasDynamicRendering(devices[i]);
        d.maxImageDimension2D = int(p.limits.maxImageDimension2D);
        out.push_back(d);
    }
    return out;
}

// Context::maxShaderLoopIterations: llvmpipe's loop limiter (Mesa, gallivm's
// LP_MAX_TGSI_LOOP_ITERATIONS = 65535, shared by every loop of a shader invocation).
std::uint32_t shaderLoopLimit(const vk::PhysicalDeviceProperties& props) {
    const std::string_view name = props.deviceName.data();
    return props.deviceType == vk::PhysicalDeviceType::eCpu && name.starts_with("llvmpipe") ? 65535u : 0u;
}

}  // namespace

// The debug-utils callback appends to the context's messages under its mutex.
struct ValidationSink {
    static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                    VkDebugUtilsMessageTypeFlagsEXT,
                                                    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
        auto* ctx = static_cast<Context*>(user);
        const char* level = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
        std::lock_guard lock(ctx->mutex_);
        ctx->messages_.push_back(
            fmt::format("{}: {}", level, data && data->pMessage ? data->pMessage : "(no message)"));
        return VK_FALSE;
    }
};

void rethrowVulkanError(const char* what, const vk::SystemError& e) {
    throw Error(fmt::format("Vulkan: {} failed: {}", what, e.what()));
}

std::vector<DeviceInfo> listDevices() {
    return guarded("listing devices", [] {
        const vk::raii::Context context = makeLoader();
        return enumerate(makeInstance(context, false));
    });
}

std::shared_ptr<Context> Context::create(const ContextOptions& options) { return std::make_shared<Context>(options); }

Context::Context(const ContextOptions& options) : context(makeLoader()) {
    guarded("creating the device", [&] {
        const char* env = std::getenv("SSFX_VK_VALIDATION");
        const bool validation = options.validation || (env && std::string(env) == "1");
        instance = makeInstance(context, validation);
        if (validation) {
            using S = vk::DebugUtilsMessageSeverityFlagBitsEXT;
            using T = vk::DebugUtilsMessageTypeFlagBitsEXT;
            messenger = vk::raii::DebugUtilsMessengerEXT(
                instance, vk::DebugUtilsMessengerCreateInfoEXT({}, S::eWarning | S::eError,
                                                               T::eGeneral | T::eValidation | T::ePerformance,
                                                               &ValidationSink::onMessage, this));
        }
        const auto infos = enumerate(instance);
        const auto fits = [&](const DeviceInfo& d) { return options.graphics ? d.graphics : d.compute; };
        const char* need = options.graphics ? "Vulkan 1.3 with a graphics queue and dynamic rendering"
                                            : "Vulkan 1.3 with a compute queue";
        std::string listing;
        for (const auto& d : infos)
            listing += fmt::format("\n  {}: {} ({}, Vulkan {}{})", d.index, d.name, d.type, d.api,
                                   fits(d) ? "" : ", unsuitable");
        if (infos.empty()) throw Error("no Vulkan device; install mesa-vulkan-drivers for the lavapipe CPU device");
        int chosen = -1;
        if (options.device.empty()) {
            for (const auto& d : infos)
                if (fits(d) && (chosen < 0 || typeRank(d.type) < typeRank(infos[std::size_t(chosen)].type)))
                    chosen = d.index;
            if (chosen < 0) throw Error(fmt::format("no device with {}; devices:{}", need, listing));
        } else {
            // Blank text is a substring of every name with a space: it would pick any device.
            if (std::all_of(options.device.begin(), options.device.end(),
                            [](unsigned char c) { return std::isspace(c); }))
                throw Error(fmt::format("device '{}' is blank: give an index or part of a name; devices:{}",
                                        options.device, listing));
            const bool isIndex = std::all_of(options.device.begin(), options.device.end(),
                                             [](unsigned char c) { return std::isdigit(c); });
            for (const auto& d : infos)
                if (isIndex ? std::to_string(d.index) == options.device
                            : lower(d.name).find(lower(options.device)) != std::string::npos) {
                    chosen = d.index;
                    break;
                }
            if (chosen < 0) throw Error(fmt::format("no Vulkan device '{}'; devices:{}", options.device, listing));
            if (!fits(infos[std::size_t(chosen)]))
                throw Error(fmt::format("device '{}' does not support {}", infos[std::size_t(chosen)].name, need));
        }
        info = infos[std::size_t(chosen)];
        physical = std::move(vk::raii::PhysicalDevices(instance)[std::size_t(chosen)]);
        graphics = options.graphics;
        queueFamily = *queueFamilyFor(physical, options.graphics);

        const auto families = physical.getQueueFamilyProperties();
        const auto props = physical.getProperties();
        timestampPeriodNs = families[queueFamily].timestampValidBits > 0 ? props.limits.timestampPeriod : 0.0;
        const auto supported = physical.getFeatures();
        anisotropy = supported.samplerAnisotropy;
        maxAnisotropy = props.limits.maxSamplerAnisotropy;
        maxShaderLoopIterations = shaderLoopLimit(props);

        const float priority = 1.0f;
        const vk::DeviceQueueCreateInfo queueInfo({}, queueFamily, 1, &priority);
        vk::PhysicalDeviceFeatures features;
        features.samplerAnisotropy = anisotropy;
        vk::PhysicalDeviceVulkan13Features features13;
        features13.dynamicRendering = options.graphics ? VK_TRUE : VK_FALSE;
        // Lets a vertex output go unread by a fragment stage (the G-buffer pass ignores the world
        // position) without a validation performance warning; core in 1.3, optional to support.
        features13.maintenance4 =
            physical.getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDeviceVulkan13Features>()
                .get<vk::PhysicalDeviceVulkan13Features>()
                .maintenance4;
        vk::PhysicalDeviceFeatures2 features2(features, &features13);
        // Push descriptors: the GPU effects record without descriptor pools (ssfx/gpu/aa.hpp).
        std::vector<const char*> extensions;
        for (const auto& e : physical.enumerateDeviceExtensionProperties())
            if (std::strcmp(e.extensionName, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME) == 0) pushDescriptors = true;
        if (pushDescriptors) extensions.push_back(VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME);
        vk::DeviceCreateInfo deviceInfo({}, queueInfo, {}, extensions, nullptr);
        deviceInfo.pNext = &features2;
        device = vk::raii::Device(physical, deviceInfo);
        queue = vk::raii::Queue(device, queueFamily, 0);
        pool = vk::raii::CommandPool(
            device, vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eResetCommandBuffer, queueFamily));
    });
}

std::shared_ptr<Context> Context::borrow(const External& e) {
    if (!e.instance || !e.physical || !e.device || !e.queue)
        throw Error("vkx::Context::borrow: the instance, physical device, device and queue must all be given");
    return std::shared_ptr<Context>(new Context(e, BorrowTag{}));
}

Context::Context(const External& e, BorrowTag) : context(makeLoader()) {
    guarded("borrowing the caller's device", [&] {
        borrowed = true;
        instance = vk::raii::Instance(context, e.instance);
        physical = vk::raii::PhysicalDevice(instance, e.physical);
        device = vk::raii::Device(physical, e.device);
        queue = vk::raii::Queue(device, e.queue);
        queueFamily = e.queueFamily;
        pushDescriptors = e.pushDescriptors;
        const auto props = physical.getProperties();
        info.name = props.deviceName.data();
        info.type = typeName(props.deviceType);
        info.api = fmt::format("{}.{}.{}", VK_API_VERSION_MAJOR(props.apiVersion),
                               VK_API_VERSION_MINOR(props.apiVersion), VK_API_VERSION_PATCH(props.apiVersion));
        info.compute = true;
        info.maxImageDimension2D = int(props.limits.maxImageDimension2D);
        maxShaderLoopIterations = shaderLoopLimit(props);
        const auto families = physical.getQueueFamilyProperties();
        if (queueFamily >= families.size() || !(families[queueFamily].queueFlags & vk::QueueFlagBits::eCompute))
            throw Error(fmt::format("vkx::Context::borrow: queue family {} has no compute", queueFamily));
        timestampPeriodNs = families[queueFamily].timestampValidBits > 0 ? props.limits.timestampPeriod : 0.0;
        pool = vk::raii::CommandPool(
            device, vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eResetCommandBuffer, queueFamily));
    });
}

Context::~Context() {
    if (!borrowed) return;  // owned: the members destroy everything, device last
    // Ours go first, while the device's dispatcher still exists; the caller's are released.
    pool.clear();
    (void)queue.release();
    (void)device.release();
    (void)physical.release();
    (void)instance.release();
}

std::vector<std::string> Context::validationMessages() const {
    std::lock_guard lock(mutex_);
    return messages_;
}

std::uint32_t Context::memoryType(std::uint32_t bits, vk::MemoryPropertyFlags wanted,
                                  vk::MemoryPropertyFlags preferred) const {
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
    const auto flags = hostVisible
                           ? vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent
                           : vk::MemoryPropertyFlagBits::eDeviceLocal;
    // Reading back: cached host memory is much faster to read on discrete GPUs.
    const auto preferred =
        hostVisible ? vk::MemoryPropertyFlags(vk::MemoryPropertyFlagBits::eHostCached) : vk::MemoryPropertyFlags();
    b.memory = vk::raii::DeviceMemory(
        device, vk::MemoryAllocateInfo(req.size, memoryType(req.memoryTypeBits, flags, preferred)));
    b.buffer.bindMemory(*b.memory, 0);
    if (hostVisible) b.mapped = b.memory.mapMemory(0, VK_WHOLE_SIZE);
    return b;
}

Buffer Context::uploadBuffer(const void* bytes, vk::DeviceSize size, vk::BufferUsageFlags usage) {
    Buffer staging = createBuffer(size, vk::BufferUsageFlagBits::eTransferSrc, true);
    std::memcpy(staging.mapped, bytes, size);
    Buffer b = createBuffer(size, usage | vk::BufferUsageFlagBits::eTransferDst, false);
    submit([&](const vk::raii::CommandBuffer& cmd) {
        cmd.copyBuffer(*staging.buffer, *b.buffer, vk::BufferCopy(0, 0, size));
    });
    return b;
}

Image Context::createImage(vk::Format format, std::uint32_t width, std::uint32_t height, vk::ImageUsageFlags usage,
                           vk::ImageAspectFlags aspect, std::uint32_t layers, std::uint32_t levels,
                           vk::ImageCreateFlags flags) {
    Image img;
    img.format = format;
    img.aspect = aspect;
    img.width = width;
    img.height = height;
    img.layers = layers;
    img.levels = levels;
    img.image = vk::raii::Image(
        device, vk::ImageCreateInfo(flags, vk::ImageType::e2D, format, vk::Extent3D(width, height, 1), levels, layers,
                                    vk::SampleCountFlagBits::e1, vk::ImageTiling::eOptimal, usage));
    const auto req = img.image.getMemoryRequirements();
    img.memory = vk::raii::DeviceMemory(
        device,
        vk::MemoryAllocateInfo(req.size, memoryType(req.memoryTypeBits, vk::MemoryPropertyFlagBits::eDeviceLocal)));
    img.image.bindMemory(*img.memory, 0);
    img.view = vk::raii::ImageView(
        device,
        vk::ImageViewCreateInfo({}, *img.image,
                                layers > 1 || (usage & vk::ImageUsageFlagBits::eSampled) ? vk::ImageViewType::e2DArray
                                                                                         : vk::ImageViewType::e2D,
                                format, {}, vk::ImageSubresourceRange(aspect, 0, levels, 0, layers)));
    return img;
}

void Context::submit(const vk::raii::CommandBuffer& recorded) {
    vk::raii::Fence fence(device, vk::FenceCreateInfo());
    const vk::CommandBuffer handle = *recorded;
    queue.submit(vk::SubmitInfo({}, {}, handle), *fence);
    if (device.waitForFences(*fence, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess)
        throw Error("Vulkan: waiting for the GPU failed");
}

void Context::submit(const std::function<void(const vk::raii::CommandBuffer&)>& record) {
    vk::raii::CommandBuffers cmds(device, vk::CommandBufferAllocateInfo(*pool, vk::CommandBufferLevel::ePrimary, 1));
    const vk::raii::CommandBuffer& cmd = cmds[0];
    cmd.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    record(cmd);
    cmd.end();
    submit(cmd);
}

void Context::requireAttachmentFormat(vk::Format format, bool depth, const std::string& what) const {
    const auto props = physical.getFormatProperties(format);
    const auto need =
        (depth ? vk::FormatFeatureFlagBits::eDepthStencilAttachment : vk::FormatFeatureFlagBits::eColorAttachment) |
        vk::FormatFeatureFlagBits::eTransferSrc;
    if ((props.optimalTilingFeatures & need) != need)
        throw Error(fmt::format("Vulkan device '{}' cannot render {} as {}", info.name, what, vk::to_string(format)));
}

bool Context::computeSubgroupOps(vk::SubgroupFeatureFlags ops) const {
    const auto subgroup = physical.getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceSubgroupProperties>()
                              .get<vk::PhysicalDeviceSubgroupProperties>();
    return (subgroup.supportedStages & vk::ShaderStageFlagBits::eCompute) &&
           (subgroup.supportedOperations & ops) == ops;
}

void Context::requireImageSize(std::uint32_t width, std::uint32_t height, const std::string& what) const {
    const std::uint32_t limit = std::uint32_t(info.maxImageDimension2D);
    if (width > limit || height > limit)
        throw Error(
            fmt::format("{} {}x{} exceeds the device's limit of {} pixels per side", what, width, height, limit));
}

Recording::Recording(Context& ctx, const std::function<void(const vk::raii::CommandBuffer&)>& record)
    : ctx_(&ctx), buffers_(ctx.device, vk::CommandBufferAllocateInfo(*ctx.pool, vk::CommandBufferLevel::ePrimary, 1)) {
    const vk::raii::CommandBuffer& cmd = buffers_[0];
    cmd.begin(vk::CommandBufferBeginInfo());
    record(cmd);
    cmd.end();
}

void Recording::run() { ctx_->submit(buffers_[0]); }

}  // namespace ssfx::vkx
