#include "vk/timestamps.h"

#include <algorithm>

namespace penumbra::vk {

GpuTimer::GpuTimer(Context& ctx, uint32_t scopesPerPool) : ctx_(ctx), perPool_(std::max(1u, scopesPerPool)) {
    addPool();
}

GpuTimer::~GpuTimer() {
    for (VkQueryPool pool : pools_) vkDestroyQueryPool(ctx_.device(), pool, nullptr);
}

// A new pool may be created while a frame records: its queries are reset on the host before any use.
void GpuTimer::addPool() {
    VkQueryPoolCreateInfo ci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    ci.queryType = VK_QUERY_TYPE_TIMESTAMP;
    ci.queryCount = 2 * perPool_;
    VkQueryPool pool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateQueryPool(ctx_.device(), &ci, nullptr, &pool));
    vkResetQueryPool(ctx_.device(), pool, 0, 2 * perPool_);
    pools_.push_back(pool);
}

void GpuTimer::reset() {
    for (VkQueryPool pool : pools_) vkResetQueryPool(ctx_.device(), pool, 0, 2 * perPool_);
    names_.clear();
}

uint32_t GpuTimer::begin(VkCommandBuffer cmd, const std::string& name) {
    const uint32_t scope = static_cast<uint32_t>(names_.size());
    if (scope / perPool_ >= pools_.size()) addPool();
    names_.push_back(name);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pools_[scope / perPool_], 2 * (scope % perPool_));
    return scope;
}

void GpuTimer::end(VkCommandBuffer cmd, uint32_t scope) {
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pools_[scope / perPool_],
                         2 * (scope % perPool_) + 1);
}

std::vector<ScopeTiming> GpuTimer::results() {
    std::vector<ScopeTiming> out;
    const double nsPerTick = ctx_.timestampPeriodNs();
    std::vector<uint64_t> ticks(2 * perPool_);
    for (size_t first = 0; first < names_.size(); first += perPool_) {
        const uint32_t count = uint32_t(std::min<size_t>(perPool_, names_.size() - first));
        VK_CHECK(vkGetQueryPoolResults(ctx_.device(), pools_[first / perPool_], 0, 2 * count,
                                       2 * count * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
                                       VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
        for (uint32_t i = 0; i < count; ++i)
            out.push_back({names_[first + i], double(ticks[2 * i + 1] - ticks[2 * i]) * nsPerTick * 1e-6});
    }
    return out;
}

}  // namespace penumbra::vk
