#include <cmath>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

#include "api/convert.h"
#include "api/impl.h"
#include "io/image_io.h"
#include "renderer/render_options.h"
#include "renderer/renderer.h"
#include "vk/commands.h"

namespace penumbra::api {
namespace {

// An engine's settings get the checks of the command line's options (the ranges of each module's
// option table and the rules between modules) before anything is built.
penumbra::RenderSettings checked(const Settings& s) {
    penumbra::RenderSettings internal = toInternal(s);
    validateSettings(internal);
    return internal;
}

FrameInputs toInternal(const Frame& f) {
    FrameInputs in;
    in.camera = api::toInternal(f.camera);
    for (const Light& l : f.lights) in.lights.push_back(api::toInternal(l));
    for (const Mat4& m : f.instances) in.instances.push_back(glm::make_mat4(m.data()));
    return in;
}

}  // namespace

struct Renderer::Impl {
    vk::Context& ctx;
    Settings settings;
    penumbra::Renderer renderer;
    VkSemaphore ready = VK_NULL_HANDLE;
    vk::Image output;   // submitToImage's image (after `renderer`: destroyed before its allocator)
    vk::Image retired;  // the previous size's, kept until the frame that replaced it is done

    Impl(vk::Context& c, const penumbra::Scene& scene, const Settings& s)
        : ctx(c), settings(s), renderer(c, scene, checked(s)) {}
    ~Impl() {
        renderer.finish();
        if (ready) vkDestroySemaphore(ctx.device(), ready, nullptr);
    }

    // The engine's image at the settings' size, and the semaphore that says a frame is in it.
    void prepareOutput() {
        if (retired) {
            renderer.finish();
            retired.reset();
        }
        if (!ready) {
            VkSemaphoreCreateInfo ci{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
            VK_CHECK(vkCreateSemaphore(ctx.device(), &ci, nullptr, &ready));
        }
        if (output && output.width() == settings.width && output.height() == settings.height) return;
        retired = std::move(output);
        const VkImageUsageFlags usage =
            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        output = vk::Image(renderer.allocator(),
                           {VK_FORMAT_R8G8B8A8_UNORM, settings.width, settings.height, 1, usage, "engine-output"});
    }

    // After the frame's last pass: the tone-mapped image copied into the engine's, left ready to sample.
    void recordCopy(VkCommandBuffer cmd, vk::Image& ldr) {
        vk::transitionImage(cmd, ldr, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                            VK_ACCESS_2_TRANSFER_READ_BIT);
        // From the last use on this queue on (ALL_COMMANDS): an engine's reads submitted in between too.
        vk::transitionImage(cmd, output, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkImageCopy region{};
        region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.extent = {ldr.width(), ldr.height(), 1};
        vkCmdCopyImage(cmd, ldr.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, output.handle(),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        vk::transitionImage(cmd, output, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                            VK_ACCESS_2_NONE);
    }
};

Renderer::Renderer(Device& device, const SceneData& scene, const Settings& settings)
    : impl_(std::make_unique<Impl>(*device.impl_->ctx, scene.impl_->scene, settings)) {}

Renderer::~Renderer() = default;

void Renderer::apply(const Settings& settings) {
    impl_->renderer.apply(checked(settings));
    impl_->settings = settings;
}

const Settings& Renderer::settings() const { return impl_->settings; }

void Renderer::render(const Frame& frame) { impl_->renderer.render(toInternal(frame)); }
void Renderer::submit(const Frame& frame) { impl_->renderer.submit(toInternal(frame)); }
void Renderer::finish() { impl_->renderer.finish(); }

FrameImage Renderer::submitToImage(const Frame& frame, VkSemaphore engineDone) {
    Impl& m = *impl_;
    m.prepareOutput();
    FrameHooks hooks;
    hooks.record = [&m](VkCommandBuffer cmd, vk::Image& ldr) { m.recordCopy(cmd, ldr); };
    hooks.wait = engineDone;
    hooks.waitStage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    hooks.signal = m.ready;
    m.renderer.submit(toInternal(frame), hooks);
    return {m.output.handle(), m.output.view(), m.output.format(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            m.output.width(), m.output.height(), m.ready};
}

std::vector<uint8_t> Renderer::readRgba8() { return impl_->renderer.readLdr(); }
std::vector<float> Renderer::readRgba32f() { return impl_->renderer.readHdr(); }

void Renderer::setPassTimings(bool on) { impl_->renderer.setPassScopes(on); }

Timings Renderer::timings() const {
    const FrameTimings& t = impl_->renderer.frameTimings();
    Timings out{t.gpuMs, t.cpuMs, {}};
    for (const vk::ScopeTiming& s : t.passes) out.passes.push_back({s.name, s.ms});
    return out;
}

const std::vector<std::string>& Renderer::warnings() const { return impl_->renderer.warnings(); }

void writePng(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba8) {
    if (rgba8.size() != size_t(width) * height * 4)
        throw std::invalid_argument(fmt::format("{}: {} bytes are not {}x{} RGBA8 texels", path, rgba8.size(), width, height));
    penumbra::writePng(path, width, height, rgba8);
}

void writeExr(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& rgba32f) {
    if (rgba32f.size() != size_t(width) * height * 4)
        throw std::invalid_argument(fmt::format("{}: {} floats are not {}x{} RGBA32F texels", path, rgba32f.size(), width, height));
    penumbra::writeExr(path, width, height, rgba32f);
}

}  // namespace penumbra::api
