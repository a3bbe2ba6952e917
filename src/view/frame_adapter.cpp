#include "view/frame_adapter.h"

namespace penumbra::view {
namespace {

bool sameLights(const std::vector<Light>& a, const std::vector<Light>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        const Light &x = a[i], &y = b[i];
        if (x.type != y.type || x.position != y.position || x.direction != y.direction || x.color != y.color ||
            x.intensity != y.intensity || x.range != y.range || x.innerConeAngle != y.innerConeAngle ||
            x.outerConeAngle != y.outerConeAngle || x.castsShadow != y.castsShadow ||
            x.shadowFilter != y.shadowFilter)
            return false;
    }
    return true;
}

}  // namespace

FrameAdapter::FrameAdapter(vk::Context& ctx, const Scene& scene, const std::vector<Light>& lights,
                           const RenderSettings& settings)
    : ctx_(ctx), scene_(scene), settings_(settings), alloc_(ctx, VkDeviceSize(8) << 20), cmd_(alloc_) {
    rebuild(lights);
    VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pi.queueFamilyIndex = ctx.queueFamily();
    VK_CHECK(vkCreateCommandPool(ctx.device(), &pi, nullptr, &pool_));
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = pool_;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(ctx.device(), &ai, &hookCmd_));
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(ctx.device(), &fi, nullptr, &fence_));
}

FrameAdapter::~FrameAdapter() {
    ctx_.waitIdle();
    vkDestroyFence(ctx_.device(), fence_, nullptr);
    vkDestroyCommandPool(ctx_.device(), pool_, nullptr);
}

void FrameAdapter::submitHooks(const PresentHooks& hooks) {
    VK_CHECK(vkResetCommandBuffer(hookCmd_, 0));
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(hookCmd_, &bi));
    hooks.record(hookCmd_, ldr_);
    VK_CHECK(vkEndCommandBuffer(hookCmd_));
    VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    wait.semaphore = hooks.wait;
    wait.stageMask = hooks.waitStage;
    VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signal.semaphore = hooks.signal;
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkCommandBufferSubmitInfo cb{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cb.commandBuffer = hookCmd_;
    VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    si.waitSemaphoreInfoCount = hooks.wait ? 1 : 0;
    si.pWaitSemaphoreInfos = &wait;
    si.signalSemaphoreInfoCount = hooks.signal ? 1 : 0;
    si.pSignalSemaphoreInfos = &signal;
    si.commandBufferInfoCount = 1;
    si.pCommandBufferInfos = &cb;
    VK_CHECK(vkQueueSubmit2(ctx_.queue(), 1, &si, fence_));
    VK_CHECK(vkWaitForFences(ctx_.device(), 1, &fence_, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(ctx_.device(), 1, &fence_));
}

void FrameAdapter::rebuild(const std::vector<Light>& lights) {
    renderer_.reset();
    scene_.lights = lights;
    renderer_ = std::make_unique<Renderer>(ctx_, scene_, settings_);
}

void FrameAdapter::apply(const RenderSettings& settings) {
    settings_ = settings;
    rebuild(scene_.lights);
}

void FrameAdapter::submit(const Camera& camera, const std::vector<Light>& lights, const PresentHooks& hooks) {
    if (!sameLights(lights, scene_.lights)) rebuild(lights);
    renderer_->render(camera);
    if (!hooks.record) return;
    const uint32_t w = settings_.width, h = settings_.height;
    if (!ldr_ || ldr_.width() != w || ldr_.height() != h)
        ldr_ = vk::Image(alloc_, {VK_FORMAT_R8G8B8A8_UNORM, w, h, 1,
                                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                      VK_IMAGE_USAGE_SAMPLED_BIT, "view-ldr"});
    const std::vector<uint8_t> pixels = renderer_->readLdr();
    cmd_.uploadImage(ldr_, pixels.data(), pixels.size());
    submitHooks(hooks);
}

void FrameAdapter::finish() {}

}  // namespace penumbra::view
