// The viewer's view of the renderer: a scene uploaded once, settings applied as they change, and
// frames whose last commands (the present blit and the UI) the viewer records itself.
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "render/renderer.h"

namespace penumbra::view {

// Recorded into a frame after the renderer's last pass; `ldr` holds the tone-mapped RGBA8 image
// (sRGB-encoded values in a UNORM image). The frame's submission waits for `wait` at `waitStage`
// (the swapchain image's acquisition) and signals `signal` (its presentation waits for that).
struct PresentHooks {
    std::function<void(VkCommandBuffer, vk::Image& ldr)> record;
    VkSemaphore wait = VK_NULL_HANDLE;
    VkPipelineStageFlags2 waitStage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkSemaphore signal = VK_NULL_HANDLE;
};

class FrameAdapter {
public:
    FrameAdapter(vk::Context& ctx, const Scene& scene, const std::vector<Light>& lights, const RenderSettings& settings);
    ~FrameAdapter();

    void apply(const RenderSettings& settings);
    // Records and submits one frame of `camera` and `lights` with the viewer's commands after it.
    void submit(const Camera& camera, const std::vector<Light>& lights, const PresentHooks& hooks);
    // Waits for every submitted frame.
    void finish();

    Renderer& renderer() { return *renderer_; }
    std::vector<uint8_t> readLdr() { return renderer_->readLdr(); }
    std::vector<float> readHdr() { return renderer_->readHdr(); }

private:
    void rebuild(const std::vector<Light>& lights);

    vk::Context& ctx_;
    Scene scene_;  // with the lights the renderer was built for
    RenderSettings settings_;
    std::unique_ptr<Renderer> renderer_;
    // Interim, until the frame layer's submit(hooks) lands: the renderer's LDR copied here through
    // the host, and the viewer's commands in a submission of their own.
    void submitHooks(const PresentHooks& hooks);
    vk::Allocator alloc_;
    vk::CommandContext cmd_;
    vk::Image ldr_;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer hookCmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
};

}  // namespace penumbra::view
