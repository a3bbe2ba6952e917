#include "view/ui_layer.h"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include "vk/commands.h"

namespace penumbra::view {
namespace {

// The frames whose UI vertex buffers may be in use at once: frames in flight plus the one recorded.
constexpr uint32_t kUiBufferSets = 3;

void checkResult(VkResult r) { VK_CHECK(r); }

VkRenderPass createRenderPass(VkDevice device, VkFormat format) {
    VkAttachmentDescription color{};
    color.format = format;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // the present blit's image
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;
    // Before: the caller's barrier made the image a colour attachment. After: `screenshot-ui` may
    // copy the image (transfer) before it is presented.
    VkSubpassDependency deps[2] = {};
    deps[0] = {VK_SUBPASS_EXTERNAL, 0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
               VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
               VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, 0};
    deps[1] = {0, VK_SUBPASS_EXTERNAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, 0};
    VkRenderPassCreateInfo ci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    ci.attachmentCount = 1;
    ci.pAttachments = &color;
    ci.subpassCount = 1;
    ci.pSubpasses = &subpass;
    ci.dependencyCount = 2;
    ci.pDependencies = deps;
    VkRenderPass pass;
    VK_CHECK(vkCreateRenderPass(device, &ci, nullptr, &pass));
    return pass;
}

}  // namespace

UiLayer::UiLayer(vk::Allocator& alloc, GLFWwindow* window, const vk::Swapchain& swapchain)
    : ctx_(alloc.context()) {
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16};
    VkDescriptorPoolCreateInfo pi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pi.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    pi.maxSets = 16;
    pi.poolSizeCount = 1;
    pi.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(ctx_.device(), &pi, nullptr, &pool_));
    renderPass_ = createRenderPass(ctx_.device(), swapchain.format());

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini written into the working directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForVulkan(window, true);
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = ctx_.instance();
    info.PhysicalDevice = ctx_.physicalDevice();
    info.Device = ctx_.device();
    info.QueueFamily = ctx_.queueFamily();
    info.Queue = ctx_.queue();
    info.DescriptorPool = pool_;
    info.MinImageCount = kUiBufferSets;
    info.ImageCount = kUiBufferSets;
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkResult;
    ImGui_ImplVulkan_Init(&info, renderPass_);
    vk::CommandContext cmd(alloc);
    cmd.submitAndWait([](VkCommandBuffer c) { ImGui_ImplVulkan_CreateFontsTexture(c); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
    rebuildFramebuffers(swapchain);
}

UiLayer::~UiLayer() {
    ctx_.waitIdle();
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(ctx_.device(), f, nullptr);
    vkDestroyRenderPass(ctx_.device(), renderPass_, nullptr);
    vkDestroyDescriptorPool(ctx_.device(), pool_, nullptr);
}

void UiLayer::rebuildFramebuffers(const vk::Swapchain& swapchain) {
    for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(ctx_.device(), f, nullptr);
    framebuffers_.clear();
    for (uint32_t i = 0; i < swapchain.imageCount(); ++i) {
        VkImageView view = swapchain.view(i);
        VkFramebufferCreateInfo fi{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fi.renderPass = renderPass_;
        fi.attachmentCount = 1;
        fi.pAttachments = &view;
        fi.width = swapchain.extent().width;
        fi.height = swapchain.extent().height;
        fi.layers = 1;
        VkFramebuffer f;
        VK_CHECK(vkCreateFramebuffer(ctx_.device(), &fi, nullptr, &f));
        framebuffers_.push_back(f);
    }
    generation_ = swapchain.generation();
}

void UiLayer::newFrame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void UiLayer::record(VkCommandBuffer cmd, const vk::Swapchain& swapchain, uint32_t index) {
    ImGui::Render();
    // Swapchain recreation waits for the device, so no frame in flight still uses the old ones.
    if (generation_ != swapchain.generation()) rebuildFramebuffers(swapchain);
    VkRenderPassBeginInfo bi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    bi.renderPass = renderPass_;
    bi.framebuffer = framebuffers_.at(index);
    bi.renderArea = {{0, 0}, swapchain.extent()};
    vkCmdBeginRenderPass(cmd, &bi, VK_SUBPASS_CONTENTS_INLINE);
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
    vkCmdEndRenderPass(cmd);
}

bool UiLayer::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool UiLayer::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace penumbra::view
