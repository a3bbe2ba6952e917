// GPU timestamp queries, two per timed scope; results in milliseconds. The query pools grow as a frame
// opens more scopes (e.g. one per LPV propagation step), so there is no limit on the pass count.
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
    explicit GpuTimer(Context& ctx, uint32_t scopesPerPool = 128);
    ~GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    void reset();  // host-side reset; call before recording a frame
    uint32_t begin(VkCommandBuffer cmd, const std::string& name);
    void end(VkCommandBuffer cmd, uint32_t scope);
    std::vector<ScopeTiming> results();  // after the frame's submission completed

private:
    void addPool();
    Context& ctx_;
    std::vector<VkQueryPool> pools_;  // scope i: pool i / perPool_, queries 2 (i % perPool_) and +1
    uint32_t perPool_;
    std::vector<std::string> names_;
};

}  // namespace penumbra::vk
