// Timestamp queries (see ssfx/vk/timer.hpp).
#include "ssfx/vk/timer.hpp"

#include <algorithm>

namespace ssfx::vkx {

GpuTimer::GpuTimer(const Context& ctx, std::uint32_t intervals)
    : pool_(ctx.device, vk::QueryPoolCreateInfo({}, vk::QueryType::eTimestamp, 2 * intervals)),
      intervals_(intervals),
      periodNs_(ctx.timestampPeriodNs) {}

void GpuTimer::reset(const vk::raii::CommandBuffer& cmd) const { cmd.resetQueryPool(*pool_, 0, 2 * intervals_); }

void GpuTimer::begin(const vk::raii::CommandBuffer& cmd, std::uint32_t interval,
                     vk::PipelineStageFlagBits stage) const {
    cmd.writeTimestamp(stage, *pool_, 2 * interval);
}

void GpuTimer::end(const vk::raii::CommandBuffer& cmd, std::uint32_t interval, vk::PipelineStageFlagBits stage) const {
    cmd.writeTimestamp(stage, *pool_, 2 * interval + 1);
}

std::vector<double> GpuTimer::milliseconds(std::uint32_t used) const {
    const std::uint32_t n = used == 0 ? intervals_ : std::min(used, intervals_);
    std::vector<double> ms(n, 0.0);
    if (periodNs_ <= 0) return ms;
    const auto [status, ticks] =
        pool_.getResults<std::uint64_t>(0, 2 * n, 2 * n * sizeof(std::uint64_t), sizeof(std::uint64_t),
                                        vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
    if (status != vk::Result::eSuccess) return ms;
    for (std::uint32_t i = 0; i < n; ++i) ms[i] = double(ticks[2 * i + 1] - ticks[2 * i]) * periodNs_ * 1e-6;
    return ms;
}

}  // namespace ssfx::vkx
