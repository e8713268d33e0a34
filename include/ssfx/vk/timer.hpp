// GPU time of recorded work from timestamp queries: the figures of the GPU benchmarks.
#pragma once

#include <cstdint>
#include <vector>
#include <vulkan/vulkan_raii.hpp>

#include "ssfx/vk/context.hpp"

namespace ssfx::vkx {

//! `intervals` begin/end pairs in one query pool.
class GpuTimer {
public:
    GpuTimer(const Context& ctx, std::uint32_t intervals = 1);
    //! Resets the pool; record before the first begin() of a submission.
    void reset(const vk::raii::CommandBuffer& cmd) const;
    void begin(const vk::raii::CommandBuffer& cmd, std::uint32_t interval = 0,
               vk::PipelineStageFlagBits stage = vk::PipelineStageFlagBits::eTopOfPipe) const;
    void end(const vk::raii::CommandBuffer& cmd, std::uint32_t interval = 0,
             vk::PipelineStageFlagBits stage = vk::PipelineStageFlagBits::eBottomOfPipe) const;
    //! Milliseconds of the first `used` intervals (0: all) after the submission completed;
    //! all 0 when the queue has no timestamps. Waits for their queries: every interval read
    //! must have been begun and ended in the submission.
    std::vector<double> milliseconds(std::uint32_t used = 0) const;
    bool available() const { return periodNs_ > 0; }

private:
    vk::raii::QueryPool pool_{nullptr};
    std::uint32_t intervals_;
    double periodNs_;
};

}  // namespace ssfx::vkx
