// The sky on the GPU for the frame's passes: its radiance in world orientation as an equirectangular
// RGBA16F texture behind the geometry (core/sky.h's layout at each row's mid polar angle, rotation
// applied; no sun disk: the sun is the directional light, which has no size), and its order-2 SH
// (names::kSkySh) for the sky light. Both are made again only when the sky changes.
//
// An analytic sky (a moving sun: a new one every frame) costs the host only its Perez coefficients:
//   sky.analytic  Preetham's radiance at every texel of the background and of core/sky.h's table
//                 (RGBA32F, Sky::analytic's texels), and each table row's share of the SH (sky/analytic.comp)
//   sky.sh        the rows' shares summed into the nine coefficients (sky/sh_sum.comp)
// A map or a uniform sky changes only with the settings: made on the CPU (core/sky.h) and uploaded,
//   sky.upload    the background from a per-frame staging copy, the SH in the command buffer.
#pragma once
#include "core/frame_graph.h"
#include "core/sky.h"
#include "sky/types.h"  // shaders/sky
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace penumbra {

class GpuSky {
public:
    static constexpr uint32_t kWidth = SKY_TABLE_WIDTH, kHeight = SKY_TABLE_HEIGHT;
    static_assert(kWidth == Sky::kAnalyticWidth && kHeight == Sky::kAnalyticHeight);

    GpuSky(vk::Allocator& alloc, vk::CommandContext& cmd);
    // A sky made on the CPU (none, uniform, map): written into frame slot `slot`'s staging copy.
    void set(const Sky& sky, uint32_t slot);
    // An analytic sky, evaluated on the GPU.
    void set(const AnalyticSkyModel& model);
    // The passes that bring a sky set since the last call onto the GPU (none when it did not change),
    // ahead of every pass that reads it; publishes names::kSkySh. Returns the background.
    ImageHandle addTo(FrameGraph& graph);

    // For read-back: the analytic sky's table (RGBA32F, top row first), the background, the SH.
    vk::Image& table() { return table_; }
    vk::Image& background() { return background_; }
    const vk::Buffer& sh() const { return sh_; }

private:
    enum class Pending { None, Upload, Analytic };
    void addUpload(FrameGraph& graph, ImageHandle skyImage, BufferHandle sh);
    void addAnalytic(FrameGraph& graph, ImageHandle skyImage, BufferHandle sh);

    vk::ComputeKernel analytic_, shSum_;
    vk::Image background_, table_;
    vk::Buffer layout_, rowSh_, sh_;
    vk::BufferRing staging_;
    Pending pending_ = Pending::None;
    uint32_t pendingSlot_ = 0;
    std::array<glm::vec4, SKY_SH_COEFFICIENTS> uploadSh_{};
    gpu::SkyAnalyticPush analyticPush_{};
};

}  // namespace penumbra
