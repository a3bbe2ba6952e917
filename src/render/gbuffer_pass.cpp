#include "render/gbuffer_pass.h"

#include "render/raster.h"

namespace penumbra {

GBufferPass::GBufferPass(vk::Allocator& alloc, SceneGpu& scene, uint32_t width, uint32_t height,
                         VkDescriptorSetLayout drawLayout, bool drawBlended)
    : alloc_(alloc), scene_(scene), drawBlended_(drawBlended) {
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

void GBufferPass::addTo(FrameGraph& graph) {
    const ImageHandle a = graph.import(albedo), n = graph.import(normal), d = graph.import(depth);
    graph.publish("gbuffer.albedo", a);
    graph.publish("gbuffer.normal", n);
    graph.publish("gbuffer.depth", d);
    PassBuilder pass = graph.pass("gbuffer", PassKind::Raster);
    pass.pipeline(pipeline_).use(a, Use::ColorAttachment).use(n, Use::ColorAttachment).use(d, Use::DepthAttachment);
    scene_.declareDrawSet(pass, graph.buffer("views"));
    pass.record([this, a, n, d](PassContext& c) {
        beginRaster(c.cmd, {c.image(a).extent(),
                            {{c.image(a).view(), {{0, 0, 0, 0}}}, {c.image(n).view(), {{0, 0, 0, 0}}}},
                            c.image(d).view()});
        scene_.draw(
            c.cmd, [&](const Draw& draw) { pipeline_.push(c.cmd, gpu::DrawPush{0, draw.material, 0, 0}); },
            // Blended materials: drawn like masked ones, or left to the camera translucency passes.
            [this](const Material& m) { return drawBlended_ || m.alphaMode != AlphaMode::Blend; });
        vkCmdEndRendering(c.cmd);
    });
}

}  // namespace penumbra
