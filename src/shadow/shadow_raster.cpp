#include "shadow/shadow_raster.h"

#include <algorithm>
#include <cmath>

namespace penumbra {

ShadowRaster::ShadowRaster(vk::Context& ctx, const SceneGpu& scene, const ShadowSettings& settings,
                           VkDescriptorSetLayout drawLayout)
    : scene_(scene), settings_(settings) {
    vk::GraphicsDesc d;
    d.vertexShader = "shadow/shadow.vert";
    d.depthFormat = VK_FORMAT_D32_SFLOAT;
    d.vertexStride = SceneGpu::vertexStride();
    d.vertexAttributes = SceneGpu::vertexAttributes();
    d.depthBias = true;
    d.dynamicCullMode = true;
    // Light views (orthographic, perspective and paraboloid alike) keep y up: see sceneFrontFace.
    d.frontFace = SceneGpu::sceneFrontFace(false);
    layered_ = make(ctx, d, drawLayout);
    d.vertexShader = "shadow/paraboloid.vert";
    // Position and uv only: the paraboloid stages have no use for the normal.
    std::erase_if(d.vertexAttributes, [](const VkVertexInputAttributeDescription& a) { return a.location == 1; });
    d.tessControlShader = "shadow/paraboloid.tesc";
    d.tessEvalShader = "shadow/paraboloid.tese";
    paraboloid_ = make(ctx, d, drawLayout);
}

ShadowRaster::Pipelines ShadowRaster::make(vk::Context& ctx, vk::GraphicsDesc d,
                                           VkDescriptorSetLayout drawLayout) const {
    Pipelines p;
    p.opaque = vk::Pipeline::graphics(ctx, d, {drawLayout}, sizeof(gpu::ShadowDrawPush));
    d.fragmentShader = "shadow/shadow_mask.frag";
    p.masked = vk::Pipeline::graphics(ctx, d, {drawLayout}, sizeof(gpu::ShadowDrawPush));
    return p;
}

void ShadowRaster::drawLight(VkCommandBuffer cmd, const Pipelines& pipelines, const gpu::ShadowDrawPush& push,
                             uint32_t instances, bool blended) const {
    // Every pipeline here shares the draw set's layout: the set pushed for the pass stays bound.
    for (const vk::Pipeline* p : {&pipelines.opaque, &pipelines.masked}) {
        const bool maskedPass = p == &pipelines.masked;
        p->bind(cmd);
        scene_.draw(
            cmd,
            [&](const Draw& d) {
                gpu::ShadowDrawPush dp = push;
                dp.material = d.material;
                dp.layerCount = instances;
                p->push(cmd, dp);
            },
            // Blended materials cast like masked ones, unless the light's deep shadow map takes them.
            [&](const Material& m) {
                return (m.alphaMode != AlphaMode::Opaque) == maskedPass && (blended || m.alphaMode != AlphaMode::Blend);
            },
            instances);
    }
}

bool ShadowRaster::drawsBlended(uint32_t light) const {
    return std::find(deepShadowLights_.begin(), deepShadowLights_.end(), light) == deepShadowLights_.end();
}

void ShadowRaster::record(VkCommandBuffer cmd, vk::Image& map, uint32_t firstView, const ShadowLayout& layout,
                          bool paraboloidOnly) const {
    const uint32_t res = settings_.resolution;
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = map.view();  // all layers: the draws pick theirs with gl_Layer
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depth.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, {res, res}};
    ri.layerCount = map.layers();
    ri.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &ri);
    VkViewport vp{0, 0, float(res), float(res), 0, 1};
    VkRect2D sc{{0, 0}, {res, res}};
    vkCmdSetViewport(cmd, 0, 1, &vp);
    vkCmdSetScissor(cmd, 0, 1, &sc);
    vkCmdSetDepthBias(cmd, settings_.depthBiasConstant, 0.0f, settings_.depthBiasSlope);
    const float maxEdge = settings_.paraboloidMaxEdgeDegrees * 3.14159265f / 180.0f;
    for (const ShadowedLight& s : layout.shadowed()) {
        const LightProjection& first = layout.layers()[s.firstLayer].projection;
        gpu::ShadowDrawPush push{firstView + s.firstLayer, 0, s.firstLayer, 0, {}};
        const bool paraboloid = s.kind == SHADOW_KIND_PARABOLOID;
        if (paraboloidOnly && !paraboloid) continue;
        if (paraboloid)
            push.paraboloid = {first.zNear, first.zFar, first.discScale, maxEdge};
        drawLight(cmd, paraboloid ? paraboloid_ : layered_, push, s.layerCount, drawsBlended(s.light));
    }
    vkCmdEndRendering(cmd);
}

}  // namespace penumbra
