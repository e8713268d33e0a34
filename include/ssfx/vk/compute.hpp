// Compute pipelines, their descriptor sets and dispatch: what a GPU effect needs besides the
// Context. Bindings are numbered by their position in the list that describes them.
#pragma once

#include <cstdint>
#include <span>
#include <vector>
#include <vulkan/vulkan_raii.hpp>

#include "ssfx/vk/context.hpp"

namespace ssfx::vkx {

//! Binding i of a descriptor set layout: its type and the stages that read it.
struct BindingSpec {
    vk::DescriptorType type;
    vk::ShaderStageFlags stages = vk::ShaderStageFlagBits::eCompute;
};

//! flags: ePushDescriptorKHR for a layout whose descriptors are pushed (ComputePipeline::push).
vk::raii::DescriptorSetLayout makeSetLayout(const Context& ctx, std::span<const BindingSpec> bindings,
                                            vk::DescriptorSetLayoutCreateFlags flags = {});

//! A shader module from SPIR-V words: the `.inc` files that ssfx_add_shaders() (CMake)
//! compiles at build time are included as the body of a `const std::uint32_t[]`.
vk::raii::ShaderModule makeShaderModule(const Context& ctx, std::span<const std::uint32_t> spirv);

//! `count` descriptor sets of one layout, in a pool of their own.
class DescriptorSets {
public:
    DescriptorSets(const Context& ctx, const vk::raii::DescriptorSetLayout& layout,
                   std::span<const BindingSpec> bindings, std::uint32_t count = 1);
    vk::DescriptorSet operator[](std::size_t i) const { return *sets_[i]; }
    std::size_t size() const { return sets_.size(); }
    //! Points binding `binding` of set `set` at a whole buffer.
    void bind(std::size_t set, std::uint32_t binding, const Buffer& buffer);
    //! Points binding `binding` of set `set` at an image view (sampler: for combined samplers).
    void bind(std::size_t set, std::uint32_t binding, vk::ImageView view, vk::ImageLayout layout,
              vk::Sampler sampler = nullptr);

private:
    //! The type of `binding`; an ssfx::Error when the layout has no such binding.
    vk::DescriptorType typeOf(std::uint32_t binding) const;

    const Context* ctx_;
    std::vector<BindingSpec> bindings_;
    vk::raii::DescriptorPool pool_{nullptr};
    vk::raii::DescriptorSets sets_{nullptr};
};

//! A compute shader with one descriptor set (BindingSpec list) and push constants.
class ComputePipeline {
public:
    //! pushDescriptors: the set's descriptors are pushed with dispatchPushed() (needs
    //! Context::pushDescriptors) instead of bound from a DescriptorSets.
    ComputePipeline(const Context& ctx, std::span<const std::uint32_t> spirv, std::vector<BindingSpec> bindings,
                    std::uint32_t pushConstantBytes = 0, const vk::SpecializationInfo* specialization = nullptr,
                    bool pushDescriptors = false);

    DescriptorSets makeSets(std::uint32_t count = 1) const {
        return DescriptorSets(*ctx_, setLayout, bindings_, count);
    }
    //! Binds the pipeline and `set`, pushes `push` (pushConstantBytes long) and dispatches
    //! groups x groupsY x groupsZ work groups.
    void dispatch(const vk::raii::CommandBuffer& cmd, vk::DescriptorSet set, const void* push, std::uint32_t groupsX,
                  std::uint32_t groupsY = 1, std::uint32_t groupsZ = 1) const;

    //! Binds the pipeline, pushes the descriptors `writes` (their dstSet is ignored) and the
    //! push constants, and dispatches (a pipeline made with pushDescriptors).
    void dispatchPushed(const vk::raii::CommandBuffer& cmd, std::span<const vk::WriteDescriptorSet> writes,
                        const void* push, std::uint32_t groupsX, std::uint32_t groupsY = 1,
                        std::uint32_t groupsZ = 1) const;
    //! As dispatchPushed, with the group counts read by the device from `args` at `offset`
    //! (a VkDispatchIndirectCommand; the buffer needs INDIRECT_BUFFER usage).
    void dispatchPushedIndirect(const vk::raii::CommandBuffer& cmd, std::span<const vk::WriteDescriptorSet> writes,
                                const void* push, vk::Buffer args, vk::DeviceSize offset = 0) const;

    vk::raii::DescriptorSetLayout setLayout{nullptr};
    vk::raii::PipelineLayout layout{nullptr};
    vk::raii::Pipeline pipeline{nullptr};

private:
    void pushConstants(const vk::raii::CommandBuffer& cmd, const void* push) const;

    const Context* ctx_;
    std::vector<BindingSpec> bindings_;
    std::uint32_t pushBytes_ = 0;
};

//! Work groups of `size` invocations that cover n items.
constexpr std::uint32_t groupCount(std::uint32_t n, std::uint32_t size) { return (n + size - 1) / size; }

//! A barrier between a compute shader's writes and later compute reads or transfers.
void computeBarrier(const vk::raii::CommandBuffer& cmd,
                    vk::PipelineStageFlags dstStage = vk::PipelineStageFlagBits::eComputeShader,
                    vk::AccessFlags dstAccess = vk::AccessFlagBits::eShaderRead);

}  // namespace ssfx::vkx
