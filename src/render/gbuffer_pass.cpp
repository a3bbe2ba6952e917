#include "render/gbuffer_pass.h"

#include "render/raster.h"

namespace penumbra {

GBufferPass::GBufferPass(vk::Allocator& alloc, SceneGpu& scene, uint32_t width, uint32_t height,
                         VkDescriptorSetLayout drawLayout)
    : alloc_(alloc), scene_(scene) {
    const VkImageUsageFlags target = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                     VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    albedo = vk::Image(alloc, {VK_FORMAT_R8G8B8A8_SRGB, width, height, 1, target, "gbuffer-albedo"});
    normal = vk::Image(alloc, {VK_FORMAT_R16G16B16A16_SFLOAT, width, height, 1, target, "gbuffer-normal"});
    depth = vk::Image(alloc, {VK_FORMAT_D32_SFLOAT, width, height, 1,
                              VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              "gbuffer-depth"});
    vk::GraphicsDesc d;
    d.vertexShader = "render/scene.vert";
    d.fragmentShader = "render/gbuffer.frag";
    d.colorFormats = {albedo.format(), normal.format()};
    d.depthFormat = depth.format();
    d.vertexStride = SceneGpu::vertexStride();
    d.vertexAttributes = SceneGpu::vertexAttributes();
    d.dynamicCullMode = true;
    d.frontFace = SceneGpu::sceneFrontFace(true);
    pipeline_ = vk::Pipeline::graphics(alloc.context(), d, {drawLayout},
                                       sizeof(gpu::DrawPush));
}

void GBufferPass::addTo(FrameGraph& graph, const vk::Buffer& views) {
    PassDesc pass;
    pass.name = "gbuffer";
    pass.kind = PassKind::Raster;
    pass.images = {{&albedo, Use::ColorAttachment}, {&normal, Use::ColorAttachment}, {&depth, Use::DepthAttachment}};
    pass.images.push_back({&scene_.textures(), Use::Sampled});
    pass.buffers = {{&views, Use::StorageRead}, {&scene_.materials(), Use::StorageRead}};
    pass.record = [this, &views](VkCommandBuffer cmd) {
        beginRaster(cmd, {albedo.extent(),
                          {{albedo.view(), {{0, 0, 0, 0}}}, {normal.view(), {{0, 0, 0, 0}}}},
                          depth.view()});
        pipeline_.bind(cmd);
        scene_.pushDrawSet(cmd, pipeline_, views);
        scene_.draw(
            cmd, [&](const Draw& d) { pipeline_.push(cmd, gpu::DrawPush{0, d.material, 0, 0}); },
            // Blended materials are drawn like masked ones until the deep-shadow-map issue.
            [](const Material&) { return true; });
        vkCmdEndRendering(cmd);
    };
    graph.add(std::move(pass));
}

}  // namespace penumbra
