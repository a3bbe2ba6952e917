// GPU timestamp queries, two per timed scope; results in milliseconds.
#pragma once
#include <string>
#include <vector>

#include "vk/context.h"

namespace penumbra::vk {

struct ScopeTiming {
    std::string name;
    double ms;
};

class GpuTimer {
public:
    explicit GpuTimer(Context& ctx, uint32_t maxScopes = 128);
    ~GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    void reset();  // host-side reset; call before recording a frame
    uint32_t begin(VkCommandBuffer cmd, const std::string& name);
    void end(VkCommandBuffer cmd, uint32_t scope);
    std::vector<ScopeTiming> results();  // after the frame's submission completed

private:
    Context& ctx_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint32_t max_;
    std::vector<std::string> names_;
};

}  // namespace penumbra::vk
