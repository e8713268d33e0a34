// Image layout transitions (see ssfx/vk/resources.hpp).
#include "ssfx/vk/resources.hpp"

namespace ssfx::vkx {

void transition(const vk::raii::CommandBuffer& cmd, const Image& image, vk::ImageLayout from, vk::ImageLayout to,
                vk::PipelineStageFlags srcStage, vk::AccessFlags srcAccess, vk::PipelineStageFlags dstStage,
                vk::AccessFlags dstAccess) {
    const vk::ImageMemoryBarrier barrier(srcAccess, dstAccess, from, to, VK_QUEUE_FAMILY_IGNORED,
                                         VK_QUEUE_FAMILY_IGNORED, *image.image,
                                         vk::ImageSubresourceRange(image.aspect, 0, image.levels, 0, image.layers));
    cmd.pipelineBarrier(srcStage, dstStage, {}, {}, {}, barrier);
}

}  // namespace ssfx::vkx
