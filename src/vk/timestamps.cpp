#include "vk/timestamps.h"

namespace penumbra::vk {

GpuTimer::GpuTimer(Context& ctx, uint32_t maxScopes) : ctx_(ctx), max_(maxScopes) {
    VkQueryPoolCreateInfo ci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    ci.queryType = VK_QUERY_TYPE_TIMESTAMP;
    ci.queryCount = 2 * maxScopes;
    VK_CHECK(vkCreateQueryPool(ctx.device(), &ci, nullptr, &pool_));
    reset();
}

GpuTimer::~GpuTimer() { vkDestroyQueryPool(ctx_.device(), pool_, nullptr); }

void GpuTimer::reset() {
    vkResetQueryPool(ctx_.device(), pool_, 0, 2 * max_);
    names_.clear();
}

uint32_t GpuTimer::begin(VkCommandBuffer cmd, const std::string& name) {
    if (names_.size() >= max_) throw VulkanError("GpuTimer: too many timed scopes in one frame");
    uint32_t scope = static_cast<uint32_t>(names_.size());
    names_.push_back(name);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 2 * scope);
    return scope;
}

void GpuTimer::end(VkCommandBuffer cmd, uint32_t scope) {
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 2 * scope + 1);
}

std::vector<ScopeTiming> GpuTimer::results() {
    std::vector<ScopeTiming> out;
    if (names_.empty()) return out;
    std::vector<uint64_t> ticks(2 * names_.size());
    VK_CHECK(vkGetQueryPoolResults(ctx_.device(), pool_, 0, static_cast<uint32_t>(ticks.size()),
                                   ticks.size() * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const double nsPerTick = ctx_.timestampPeriodNs();
    for (size_t i = 0; i < names_.size(); ++i)
        out.push_back({names_[i], double(ticks[2 * i + 1] - ticks[2 * i]) * nsPerTick * 1e-6});
    return out;
}

}  // namespace penumbra::vk
