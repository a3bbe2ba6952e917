#include "view/viewer.h"

#include <chrono>
#include <fstream>

#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include "io/image_io.h"
#include "vk/commands.h"

namespace penumbra::view {
namespace {

// A drawable size the window system has not granted after this many short waits is an error in
// script mode (the screenshot would not be the requested size); interactively the window wins.
constexpr int kSizeWaits = 100;
constexpr double kSizeWaitSeconds = 0.05;

VkPresentModeKHR presentMode(const std::string& name) {
    if (name == "fifo") return VK_PRESENT_MODE_FIFO_KHR;
    if (name == "mailbox") return VK_PRESENT_MODE_MAILBOX_KHR;
    if (name == "immediate") return VK_PRESENT_MODE_IMMEDIATE_KHR;
    throw std::invalid_argument(fmt::format("presentation mode '{}': expected fifo, mailbox or immediate", name));
}

VkSemaphore createSemaphore(VkDevice device) {
    VkSemaphoreCreateInfo ci{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore s;
    VK_CHECK(vkCreateSemaphore(device, &ci, nullptr, &s));
    return s;
}

// A layout change of a swapchain image (not a vk::Image: the swapchain owns it).
void swapchainBarrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                      VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage,
                      VkAccessFlags2 dstAccess) {
    vk::imageBarrier(cmd, image, {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}, from, to, srcStage, srcAccess, dstStage,
                     dstAccess);
}

}  // namespace

Viewer::Viewer(const ViewOptions& options, std::vector<FrameArg> args, ParsedFrame parsed)
    : window_(parsed.settings.width, parsed.settings.height, "penumbra view"),
      ctx_(window_.presentationOptions(options.vulkan)),
      alloc_(ctx_, VkDeviceSize(16) << 20),
      swapchain_(ctx_, window_.createSurface(ctx_.instance()), presentMode(options.present)),
      session_(ctx_, std::move(args), std::move(parsed)),
      ui_(alloc_, window_.handle(), (swapchain_.recreate(window_.drawableSize()), swapchain_)) {
    if (!options.script.empty()) {
        script_.emplace(options.script);
        session_.playing = false;  // script mode starts paused at t = 0
        session_.time = 0.0f;
    }
    for (VkSemaphore& s : acquired_) s = createSemaphore(ctx_.device());
    sessionSize_ = {session_.settings().width, session_.settings().height};
    control_.reset(session_.camera(), session_.scene().bounds);
    fmt::print("penumbra: view '{}' on {} ({} present)\n", session_.scene().name, ctx_.info().name,
               vk::presentModeName(swapchain_.presentMode()));
}

Viewer::~Viewer() {
    ctx_.waitIdle();
    for (VkSemaphore s : acquired_) vkDestroySemaphore(ctx_.device(), s, nullptr);
    for (VkSemaphore s : rendered_) vkDestroySemaphore(ctx_.device(), s, nullptr);
}

// The renderer renders at the options' size; the window follows a size the options ask for
// (--width/--height, `set width`), and the options follow a window the user resizes. False while
// the frame should wait (minimised, or a requested size not there yet).
bool Viewer::followDrawableSize() {
    const VkExtent2D drawable = window_.drawableSize();
    if (drawable.width == 0 || drawable.height == 0) return false;
    const VkExtent2D wanted{session_.settings().width, session_.settings().height};
    if (wanted.width != sessionSize_.width || wanted.height != sessionSize_.height) {
        window_.requestDrawableSize(wanted.width, wanted.height);
        sessionSize_ = wanted;
        sizeWaits_ = kSizeWaits;
    }
    const bool matches = drawable.width == wanted.width && drawable.height == wanted.height;
    if (sizeWaits_ > 0 && !matches) {
        if (--sizeWaits_ == 0 && script_)
            throw std::runtime_error(fmt::format("the window system did not grant a {}x{} drawable (got {}x{})",
                                                 wanted.width, wanted.height, drawable.width, drawable.height));
        window_.waitEventsTimeout(kSizeWaitSeconds);
        return sizeWaits_ == 0 ? followDrawableSize() : false;
    }
    sizeWaits_ = 0;
    if (!matches) {
        session_.resize(drawable.width, drawable.height);
        sessionSize_ = drawable;
    }
    const VkExtent2D have = swapchain_.extent();
    if (!swapchain_.valid() || have.width != drawable.width || have.height != drawable.height)
        return swapchain_.recreate(drawable);
    return true;
}

void Viewer::run() {
    auto last = std::chrono::steady_clock::now();
    while (!window_.shouldClose()) {
        window_.pollEvents();
        const auto now = std::chrono::steady_clock::now();
        const double dt = std::chrono::duration<double>(now - last).count();
        last = now;
        if (script_ && step_.kind == ScriptStep::Frames && step_.frames == 0) runScript();
        if (window_.shouldClose()) break;
        for (const std::string& path : window_.takeDroppedFiles()) panels_.loadScene(session_, path);
        if (!followDrawableSize()) {
            if (window_.drawableSize().width == 0 || window_.drawableSize().height == 0)
                window_.waitEvents();  // minimised: no work until something happens
            continue;
        }
        handleInput(dt);
        panels_.recordFrameTime(dt * 1000.0);
        if (drawFrame() && script_) finishScriptStep();
    }
    ctx_.waitIdle();
    if (ctx_.validationMessages() > 0)
        throw std::runtime_error(fmt::format("{} validation message(s) reported", ctx_.validationMessages()));
}

void Viewer::handleInput(double dt) {
    GLFWwindow* w = window_.handle();
    const bool mouse = !ui_.wantsMouse(), keys = !ui_.wantsKeyboard();
    const bool ctrl = glfwGetKey(w, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
    double x, y;
    glfwGetCursorPos(w, &x, &y);
    if (ctrl && mouse && glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS)
        panels_.dragSun(session_, float(x - cursor_.x), float(y - cursor_.y));
    cursor_ = {x, y};
    if (!session_.probePinned) session_.probePixel = mouse ? imagePixel(x, y) : std::nullopt;
    Camera camera = session_.camera();
    if (control_.update(w, dt, window_.takeScroll(), mouse && !ctrl, keys, camera)) session_.setCamera(camera);
    if (session_.playing) session_.time += float(dt);
    panels_.animate(session_, dt);
    const bool f12 = glfwGetKey(window_.handle(), GLFW_KEY_F12) == GLFW_PRESS;
    if (f12 && !f12Down_) f12Screenshot();
    f12Down_ = f12;
    const bool f1 = glfwGetKey(window_.handle(), GLFW_KEY_F1) == GLFW_PRESS;
    if (f1 && !f1Down_) session_.showPanels = !session_.showPanels;
    f1Down_ = f1;
}

// The rendered image's pixel under a window position (the image fills the window), or none outside.
std::optional<glm::uvec2> Viewer::imagePixel(double x, double y) const {
    int w = 0, h = 0;
    glfwGetWindowSize(window_.handle(), &w, &h);
    const RenderSettings& s = session_.settings();
    if (w <= 0 || h <= 0 || x < 0.0 || y < 0.0 || x >= w || y >= h) return std::nullopt;
    return glm::uvec2(std::min(uint32_t(x / w * s.width), s.width - 1), std::min(uint32_t(y / h * s.height), s.height - 1));
}

bool Viewer::drawFrame() {
    VkSemaphore acquired = acquired_[frame_ % acquired_.size()];
    const std::optional<uint32_t> index = swapchain_.acquire(acquired);
    if (!index) {
        swapchain_.recreate(window_.drawableSize());
        return false;
    }
    while (rendered_.size() < swapchain_.imageCount()) rendered_.push_back(createSemaphore(ctx_.device()));
    ui_.newFrame();
    panels_.draw(session_, control_, swapchain_);
    drawOverlays(panels_.overlays(), session_.renderer(), session_.camera(), session_.settings().width,
                 session_.settings().height);
    FrameHooks hooks;
    hooks.record = [&](VkCommandBuffer cmd, vk::Image& ldr) { recordPresent(cmd, ldr, *index); };
    hooks.wait = acquired;
    hooks.waitStage = VK_PIPELINE_STAGE_2_TRANSFER_BIT;  // the blit is the first write to the image
    hooks.signal = rendered_[*index];
    session_.submit(hooks);
    ++frame_;
    if (!swapchain_.present(*index, rendered_[*index])) swapchain_.recreate(window_.drawableSize());
    return true;
}

void Viewer::recordPresent(VkCommandBuffer cmd, vk::Image& ldr, uint32_t index) {
    const VkImage target = swapchain_.image(index);
    const VkExtent2D extent = swapchain_.extent();
    vk::transitionImage(cmd, ldr, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_READ_BIT);
    swapchainBarrier(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT);
    // The blit converts RGBA to the swapchain's BGRA (or RGBA) order; equal sizes copy texels 1:1.
    // Columns [from, to) of `src` (a fraction of its width) go to the same fraction of the target.
    auto blitColumns = [&](vk::Image& src, float from, float to) {
        VkImageBlit blit{};
        blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        blit.srcOffsets[0] = {int32_t(from * float(src.width())), 0, 0};
        blit.srcOffsets[1] = {int32_t(to * float(src.width())), int32_t(src.height()), 1};
        blit.dstOffsets[0] = {int32_t(from * float(extent.width)), 0, 0};
        blit.dstOffsets[1] = {int32_t(to * float(extent.width)), int32_t(extent.height), 1};
        const bool same = src.width() == extent.width && src.height() == extent.height;
        vkCmdBlitImage(cmd, src.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, same ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
    };
    if (Renderer* b = session_.rendererB()) {
        // A/B split: B's frame was submitted first on the same queue; the barrier orders its writes.
        vk::transitionImage(cmd, b->ldr(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                            VK_ACCESS_2_TRANSFER_READ_BIT);
        blitColumns(ldr, 0.0f, 0.5f);
        blitColumns(b->ldr(), 0.5f, 1.0f);
    } else {
        blitColumns(ldr, 0.0f, 1.0f);
    }
    swapchainBarrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                     VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    ui_.record(cmd, swapchain_, index);  // leaves PRESENT_SRC
    if (!uiShotPending_) return;
    // `screenshot-ui`: the image as it will be presented, UI included.
    uiShot_ = vk::Buffer(alloc_, VkDeviceSize(extent.width) * extent.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                         true, "screenshot-ui");
    swapchainBarrier(cmd, target, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                     VK_ACCESS_2_TRANSFER_READ_BIT);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, uiShot_.handle(), 1, &copy);
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                      VK_ACCESS_2_HOST_READ_BIT);
    swapchainBarrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                     VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE);
    uiShotPending_ = false;
    uiShotExtent_ = extent;
}

// Applies script lines up to the next one that needs a frame.
void Viewer::runScript() {
    step_ = script_->run(session_);
    if (step_.kind == ScriptStep::Quit) window_.requestClose();
    if (step_.kind == ScriptStep::ScreenshotUi) uiShotPending_ = true;
}

// After a frame was submitted: count it, or save the screenshot it was rendered for (the frames in
// flight drained first, so the image is this frame's, rendered after every earlier line).
void Viewer::finishScriptStep() {
    if (step_.kind == ScriptStep::Frames) {
        if (step_.frames > 0) --step_.frames;
        return;
    }
    session_.renderer().finish();
    if (step_.kind == ScriptStep::PanelsState) {
        writePanelsState(step_.path);
        step_ = {ScriptStep::Frames, 0, {}};
        return;
    }
    if (step_.kind == ScriptStep::Screenshot) session_.writeImage(step_.path);
    else writeUiScreenshot(step_.path);
    fmt::print("penumbra: screenshot {}\n", step_.path);
    step_ = {ScriptStep::Frames, 0, {}};
}

void Viewer::writeUiScreenshot(const std::string& path) {
    const VkExtent2D e = uiShotExtent_;
    std::vector<uint8_t> rgba(uiShot_.mapped(), uiShot_.mapped() + size_t(e.width) * e.height * 4);
    const bool bgra = swapchain_.format() == VK_FORMAT_B8G8R8A8_UNORM;
    for (size_t i = 0; i < rgba.size(); i += 4) {
        if (bgra) std::swap(rgba[i], rgba[i + 2]);
        rgba[i + 3] = 255;  // the swapchain's alpha is not the image's
    }
    writePng(path, e.width, e.height, rgba);
}

// `panels-state`: what the panels showed in the frame just drawn, as text.
void Viewer::writePanelsState(const std::string& path) {
    std::ofstream out(path);
    out << panels_.state().text();
    out.flush();
    if (!out) throw std::runtime_error(fmt::format("cannot write {}", path));
}

// F12: the rendered image without the UI, tone-mapped (PNG) and linear (EXR).
void Viewer::f12Screenshot() {
    session_.renderer().finish();
    for (const char* ext : {".png", ".exr"}) {
        const std::string path = fmt::format("penumbra-view-{:03}{}", f12Count_, ext);
        session_.writeImage(path);
        fmt::print("penumbra: screenshot {}\n", path);
    }
    ++f12Count_;
}

}  // namespace penumbra::view
