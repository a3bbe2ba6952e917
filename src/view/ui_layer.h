// Dear ImGui on the swapchain (Debian's imgui 1.86: GLFW and Vulkan backends). Its Vulkan backend
// draws inside a VkRenderPass: one over the swapchain image that loads what the present blit wrote
// and leaves it ready to present.
#pragma once
#include <vector>

#include "vk/memory.h"
#include "vk/swapchain.h"

struct GLFWwindow;

namespace penumbra::view {

class UiLayer {
public:
    UiLayer(vk::Allocator& alloc, GLFWwindow* window, const vk::Swapchain& swapchain);
    ~UiLayer();
    UiLayer(const UiLayer&) = delete;
    UiLayer& operator=(const UiLayer&) = delete;

    void newFrame();  // before any ImGui:: call of the frame
    // Ends the ImGui frame and draws it over swapchain image `index` (COLOR_ATTACHMENT_OPTIMAL),
    // leaving it PRESENT_SRC_KHR.
    void record(VkCommandBuffer cmd, const vk::Swapchain& swapchain, uint32_t index);
    // Whether ImGui wants the mouse / keyboard (the camera controls leave them alone then).
    bool wantsMouse() const;
    bool wantsKeyboard() const;

private:
    void rebuildFramebuffers(const vk::Swapchain& swapchain);

    vk::Context& ctx_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    std::vector<VkFramebuffer> framebuffers_;
    uint32_t generation_ = 0;
};

}  // namespace penumbra::view
