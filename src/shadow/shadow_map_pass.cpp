#include "shadow/shadow_map_pass.h"

namespace penumbra {

ShadowMapPass::ShadowMapPass(vk::Allocator& alloc, SceneGpu& scene, const ShadowSettings& settings,
                             VkDescriptorSetLayout drawLayout)
    : alloc_(alloc), scene_(scene), settings_(settings), drawLayout_(drawLayout) {
    vk::GraphicsDesc d;
    d.vertexShader = "render/scene.vert";
    d.depthFormat = VK_FORMAT_D32_SFLOAT;
    d.vertexStride = SceneGpu::vertexStride();
    d.vertexAttributes = SceneGpu::vertexAttributes();
    d.depthBias = true;
    d.dynamicCullMode = true;
    d.frontFace = SceneGpu::sceneFrontFace(false);
    vk::Context& ctx = alloc.context();
    // Opaque casters need no fragment shader at all; alpha-masked ones discard their cut-outs.
    opaque_ = vk::Pipeline::graphics(ctx, d, {drawLayout}, sizeof(gpu::DrawPush));
    d.fragmentShader = "shadow/shadow_mask.frag";
    masked_ = vk::Pipeline::graphics(ctx, d, {drawLayout}, sizeof(gpu::DrawPush));
    ensureLayers(1);
}

void ShadowMapPass::ensureLayers(uint32_t layers) {
    layers = std::max(layers, 1u);
    if (map_ && map_.layers() == layers) return;
    map_ = vk::Image(alloc_, {VK_FORMAT_D32_SFLOAT, settings_.resolution, settings_.resolution, layers,
                              VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              "shadow-map", 1, true});
}

void ShadowMapPass::assign(const std::vector<Light>& lights, std::vector<int>& layerOfLight,
                           std::vector<LightProjection>& projections, std::vector<std::string>& unsupported) {
    const Bounds& b = scene_.scene().bounds;
    layerOfLight.assign(lights.size(), -1);
    for (size_t i = 0; i < lights.size(); ++i) {
        const Light& l = lights[i];
        if (!l.castsShadow) continue;
        if (l.type == LightType::Point) {
            unsupported.push_back(l.name.empty() ? "point light " + std::to_string(i) : l.name);
            continue;
        }
        layerOfLight[i] = static_cast<int>(projections.size());
        projections.push_back(l.type == LightType::Directional
                                  ? directionalProjection(l.direction, b, settings_.resolution)
                                  : spotProjection(l, b, settings_.resolution));
    }
    ensureLayers(static_cast<uint32_t>(projections.size()));
}

void ShadowMapPass::addTo(FrameGraph& graph, const vk::Buffer& views, uint32_t firstView, uint32_t layerCount) {
    PassDesc pass;
    pass.name = "shadow.map";
    pass.kind = PassKind::Raster;
    pass.images = {{&map_, Use::DepthAttachment}, {&scene_.textures(), Use::Sampled}};
    pass.buffers = {{&views, Use::StorageRead}, {&scene_.materials(), Use::StorageRead}};
    pass.record = [this, &views, firstView, layerCount](VkCommandBuffer cmd) {
        const uint32_t res = settings_.resolution;
        for (uint32_t layer = 0; layer < layerCount; ++layer) {
            VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
            depth.imageView = map_.layerView(layer);
            depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
            depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
            depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
            depth.clearValue.depthStencil = {1.0f, 0};
            VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
            ri.renderArea = {{0, 0}, {res, res}};
            ri.layerCount = 1;
            ri.pDepthAttachment = &depth;
            vkCmdBeginRendering(cmd, &ri);
            VkViewport vp{0, 0, float(res), float(res), 0, 1};
            VkRect2D sc{{0, 0}, {res, res}};
            vkCmdSetViewport(cmd, 0, 1, &vp);
            vkCmdSetScissor(cmd, 0, 1, &sc);
            vkCmdSetDepthBias(cmd, settings_.depthBiasConstant, 0.0f, settings_.depthBiasSlope);
            for (const vk::Pipeline* p : {&opaque_, &masked_}) {
                const bool maskedPass = p == &masked_;
                p->bind(cmd);
                scene_.pushDrawSet(cmd, *p, views);
                scene_.draw(
                    cmd, [&](const Draw& d) { p->push(cmd, gpu::DrawPush{firstView + layer, d.material, 0, 0}); },
                    [&](const Material& m) {
                        // Blended materials cast like masked ones until deep shadow maps handle them.
                        return (m.alphaMode != AlphaMode::Opaque) == maskedPass;
                    });
            }
            vkCmdEndRendering(cmd);
        }
    };
    graph.add(std::move(pass));
}

}  // namespace penumbra
