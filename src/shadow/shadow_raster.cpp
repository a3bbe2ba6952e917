#include "shadow/shadow_raster.h"

#include <algorithm>
#include <cmath>

#include "core/raster.h"

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
    vk::GraphicsDesc id = d;
    id.colorFormats = {VK_FORMAT_R32_UINT};
    id.fragmentShader = "core/visibility.frag";
    ids_.opaque = vk::Pipeline::graphics(ctx, id, SceneGpu::drawLayouts(ctx, drawLayout), sizeof(gpu::ShadowDrawPush));
    id.fragmentShader = "core/visibility_masked.frag";
    ids_.masked = vk::Pipeline::graphics(ctx, id, SceneGpu::drawLayouts(ctx, drawLayout), sizeof(gpu::ShadowDrawPush));
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
    p.opaque = vk::Pipeline::graphics(ctx, d, SceneGpu::drawLayouts(ctx, drawLayout), sizeof(gpu::ShadowDrawPush));
    d.fragmentShader = "shadow/shadow_mask.frag";
    p.masked = vk::Pipeline::graphics(ctx, d, SceneGpu::drawLayouts(ctx, drawLayout), sizeof(gpu::ShadowDrawPush));
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
                dp.triangleBase = scene_.triangleBase(d);
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

void ShadowRaster::setRasterState(VkCommandBuffer cmd) const {
    const uint32_t res = settings_.resolution;
    VkViewport vp{0, 0, float(res), float(res), 0, 1};
    VkRect2D sc{{0, 0}, {res, res}};
    vkCmdSetViewport(cmd, 0, 1, &vp);
    vkCmdSetScissor(cmd, 0, 1, &sc);
    vkCmdSetDepthBias(cmd, settings_.depthBiasConstant, 0.0f, settings_.depthBiasSlope);
}

void ShadowRaster::record(VkCommandBuffer cmd, vk::Image& map, uint32_t firstView, const ShadowLayout& layout,
                          bool paraboloidOnly, const std::function<bool(uint32_t)>& draws) const {
    // Runs of consecutive drawn layers per light: one instanced draw per run and mesh.
    struct Run {
        const ShadowedLight* light;
        uint32_t first, count;
    };
    std::vector<Run> runs;
    for (const ShadowedLight& s : layout.shadowed()) {
        if (paraboloidOnly && s.kind != SHADOW_KIND_PARABOLOID) continue;
        for (uint32_t k = 0; k < s.layerCount; ++k) {
            if (!draws(s.firstLayer + k)) continue;
            if (!runs.empty() && runs.back().light == &s && runs.back().first + runs.back().count == s.firstLayer + k)
                ++runs.back().count;
            else
                runs.push_back({&s, s.firstLayer + k, 1});
        }
    }
    if (runs.empty()) return;
    const uint32_t res = settings_.resolution;
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = map.view();  // all layers: the draws pick theirs with gl_Layer
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // layers not drawn keep their depth
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, {res, res}};
    ri.layerCount = map.layers();
    ri.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &ri);
    setRasterState(cmd);
    const float maxEdge = settings_.paraboloidMaxEdgeDegrees * 3.14159265f / 180.0f;
    for (const Run& run : runs) {
        VkClearAttachment clear{VK_IMAGE_ASPECT_DEPTH_BIT, 0, {}};
        clear.clearValue.depthStencil = {1.0f, 0};
        const VkClearRect rect{{{0, 0}, {res, res}}, run.first, run.count};
        vkCmdClearAttachments(cmd, 1, &clear, 1, &rect);
        const ShadowedLight& s = *run.light;
        const bool paraboloid = s.kind == SHADOW_KIND_PARABOLOID;
        gpu::ShadowDrawPush push{firstView + run.first, 0, run.first, 0, {}};
        if (paraboloid) {
            const LightProjection& first = layout.layers()[s.firstLayer].projection;
            push.paraboloidNear = first.zNear;
            push.paraboloidFar = first.zFar;
            push.paraboloidDiscScale = first.discScale;
            push.maxEdgeAngle = maxEdge;
        }
        drawLight(cmd, paraboloid ? paraboloid_ : layered_, push, run.count, drawsBlended(s.light));
    }
    vkCmdEndRendering(cmd);
}

void ShadowRaster::recordIds(VkCommandBuffer cmd, vk::Image& map, vk::Image& ids, uint32_t layer, uint32_t idLayer,
                             uint32_t viewRow, uint32_t light) const {
    const uint32_t res = settings_.resolution;
    RasterTarget target{{res, res}};
    target.colors = {{ids.layerView(idLayer), {{0, 0, 0, 0}}}};
    target.depth = map.layerView(layer);
    beginRaster(cmd, target);
    setRasterState(cmd);
    drawLight(cmd, ids_, gpu::ShadowDrawPush{viewRow, 0, 0, 0, {}}, 1, drawsBlended(light));
    vkCmdEndRendering(cmd);
}

}  // namespace penumbra
