// Compute pipelines and descriptor sets (see ssfx/vk/compute.hpp).
#include "ssfx/vk/compute.hpp"

#include <fmt/format.h>

#include <map>

#include "ssfx/core/error.hpp"

namespace ssfx::vkx {

vk::raii::DescriptorSetLayout makeSetLayout(const Context& ctx, std::span<const BindingSpec> bindings,
                                            vk::DescriptorSetLayoutCreateFlags flags) {
    std::vector<vk::DescriptorSetLayoutBinding> list;
    for (std::size_t i = 0; i < bindings.size(); ++i)
        list.emplace_back(std::uint32_t(i), bindings[i].type, 1, bindings[i].stages);
    return vk::raii::DescriptorSetLayout(ctx.device, vk::DescriptorSetLayoutCreateInfo(flags, list));
}

vk::raii::ShaderModule makeShaderModule(const Context& ctx, std::span<const std::uint32_t> spirv) {
    // SPIR-V's magic number (SPIR-V spec 3.1): a wrong include is caught here, not by the driver.
    if (spirv.empty() || spirv[0] != 0x07230203u) throw Error("not a SPIR-V module (no magic number)");
    return vk::raii::ShaderModule(ctx.device, vk::ShaderModuleCreateInfo({}, spirv.size_bytes(), spirv.data()));
}

DescriptorSets::DescriptorSets(const Context& ctx, const vk::raii::DescriptorSetLayout& layout,
                               std::span<const BindingSpec> bindings, std::uint32_t count)
    : ctx_(&ctx), bindings_(bindings.begin(), bindings.end()) {
    std::map<vk::DescriptorType, std::uint32_t> perType;
    for (const auto& b : bindings_) perType[b.type] += count;
    std::vector<vk::DescriptorPoolSize> sizes;
    for (const auto& [type, n] : perType) sizes.emplace_back(type, n);
    pool_ = vk::raii::DescriptorPool(
        ctx.device, vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, count, sizes));
    const std::vector<vk::DescriptorSetLayout> layouts(count, *layout);
    sets_ = vk::raii::DescriptorSets(ctx.device, vk::DescriptorSetAllocateInfo(*pool_, layouts));
}

vk::DescriptorType DescriptorSets::typeOf(std::uint32_t binding) const {
    if (binding >= bindings_.size()) throw Error(fmt::format("descriptor binding {} of {}", binding, bindings_.size()));
    return bindings_[binding].type;
}

void DescriptorSets::bind(std::size_t set, std::uint32_t binding, const Buffer& buffer) {
    const vk::DescriptorBufferInfo info(*buffer.buffer, 0, VK_WHOLE_SIZE);
    ctx_->device.updateDescriptorSets(vk::WriteDescriptorSet(*sets_[set], binding, 0, typeOf(binding), {}, info), {});
}

void DescriptorSets::bind(std::size_t set, std::uint32_t binding, vk::ImageView view, vk::ImageLayout layout,
                          vk::Sampler sampler) {
    const vk::DescriptorImageInfo info(sampler, view, layout);
    ctx_->device.updateDescriptorSets(vk::WriteDescriptorSet(*sets_[set], binding, 0, typeOf(binding), info), {});
}

ComputePipeline::ComputePipeline(const Context& ctx, std::span<const std::uint32_t> spirv,
                                 std::vector<BindingSpec> bindings, std::uint32_t pushConstantBytes,
                                 const vk::SpecializationInfo* specialization, bool pushDescriptors)
    : ctx_(&ctx), bindings_(std::move(bindings)), pushBytes_(pushConstantBytes) {
    if (pushDescriptors && !ctx.pushDescriptors)
        throw Error(fmt::format("Vulkan device '{}' has no VK_KHR_push_descriptor", ctx.info.name));
    setLayout = makeSetLayout(ctx, bindings_,
                              pushDescriptors ? vk::DescriptorSetLayoutCreateFlagBits::ePushDescriptorKHR
                                              : vk::DescriptorSetLayoutCreateFlags{});
    const vk::DescriptorSetLayout layouts[] = {*setLayout};
    std::vector<vk::PushConstantRange> push;
    if (pushConstantBytes) push.emplace_back(vk::ShaderStageFlagBits::eCompute, 0, pushConstantBytes);
    layout = vk::raii::PipelineLayout(ctx.device, vk::PipelineLayoutCreateInfo({}, layouts, push));
    const vk::raii::ShaderModule module = makeShaderModule(ctx, spirv);
    const vk::PipelineShaderStageCreateInfo stage({}, vk::ShaderStageFlagBits::eCompute, *module, "main",
                                                  specialization);
    pipeline = vk::raii::Pipeline(ctx.device, nullptr, vk::ComputePipelineCreateInfo({}, stage, *layout));
}

void ComputePipeline::dispatch(const vk::raii::CommandBuffer& cmd, vk::DescriptorSet set, const void* push,
                               std::uint32_t groupsX, std::uint32_t groupsY, std::uint32_t groupsZ) const {
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *layout, 0, set, {});
    pushConstants(cmd, push);
    cmd.dispatch(groupsX, groupsY, groupsZ);
}

void ComputePipeline::dispatchPushed(const vk::raii::CommandBuffer& cmd, std::span<const vk::WriteDescriptorSet> writes,
                                     const void* push, std::uint32_t groupsX, std::uint32_t groupsY,
                                     std::uint32_t groupsZ) const {
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline);
    cmd.pushDescriptorSetKHR(vk::PipelineBindPoint::eCompute, *layout, 0,
                             vk::ArrayProxy<const vk::WriteDescriptorSet>(std::uint32_t(writes.size()), writes.data()));
    pushConstants(cmd, push);
    cmd.dispatch(groupsX, groupsY, groupsZ);
}

void ComputePipeline::dispatchPushedIndirect(const vk::raii::CommandBuffer& cmd,
                                             std::span<const vk::WriteDescriptorSet> writes, const void* push,
                                             vk::Buffer args, vk::DeviceSize offset) const {
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline);
    cmd.pushDescriptorSetKHR(vk::PipelineBindPoint::eCompute, *layout, 0,
                             vk::ArrayProxy<const vk::WriteDescriptorSet>(std::uint32_t(writes.size()), writes.data()));
    pushConstants(cmd, push);
    cmd.dispatchIndirect(args, offset);
}

void ComputePipeline::pushConstants(const vk::raii::CommandBuffer& cmd, const void* push) const {
    if (!pushBytes_) return;
    if (!push) throw Error("compute dispatch without its push constants");
    cmd.pushConstants<std::uint8_t>(
        *layout, vk::ShaderStageFlagBits::eCompute, 0,
        vk::ArrayProxy<const std::uint8_t>(pushBytes_, static_cast<const std::uint8_t*>(push)));
}

void computeBarrier(const vk::raii::CommandBuffer& cmd, vk::PipelineStageFlags dstStage, vk::AccessFlags dstAccess) {
    const vk::MemoryBarrier barrier(vk::AccessFlagBits::eShaderWrite, dstAccess);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, dstStage, {}, barrier, {}, {});
}

}  // namespace ssfx::vkx
