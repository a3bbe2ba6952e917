#include "rsm/rsm_pass.h"

#include <glm/gtc/matrix_inverse.hpp>

#include "rsm/bindings.h"
#include "vk/format_bytes.h"

namespace penumbra {

RsmPass::RsmPass(vk::Allocator& alloc, SceneGpu& scene, const RsmSettings& settings, uint32_t idResolution)
    : alloc_(alloc), scene_(scene), settings_(settings), idResolution_(idResolution) {
    vk::Context& ctx = alloc.context();
    std::vector<vk::Binding> bindings = SceneGpu::resolveSetBindings();
    bindings.push_back({RSM_RESOLVE_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    bindings.push_back({RSM_RESOLVE_LAYERS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    bindings.push_back({RSM_RESOLVE_SHADOW_IDS, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
    for (uint32_t k : {RSM_RESOLVE_DEPTH, RSM_RESOLVE_NORMAL, RSM_RESOLVE_FLUX, RSM_RESOLVE_VPLS})
        bindings.push_back({k, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE});
    layout_ = vk::DescriptorLayout(ctx, bindings);
    pipeline_ = vk::Pipeline::compute(ctx, "rsm/resolve.comp", SceneGpu::drawLayouts(ctx, layout_.handle()), sizeof(gpu::RsmResolvePush));
    nearest_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
    setLayers({}, 0);
}

uint64_t RsmPass::texelBytes() {
    return vk::texelBytes(kDepthFormat) + vk::texelBytes(kNormalFormat) + vk::texelBytes(kFluxFormat) +
           vk::texelBytes(kVplFormat);
}

void RsmPass::setLayers(const std::vector<RsmLayerSource>& layers, uint32_t slot) {
    sources_ = layers;
    const uint32_t n = std::max<uint32_t>(1, uint32_t(layers.size()));
    const uint32_t r = settings_.resolution;
    const VkImageUsageFlags target =
        VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_STORAGE_BIT;
    if (!depth_ || depth_.layers() != n) {
        depth_ = vk::Image(alloc_, {kDepthFormat, r, r, n, target, "rsm-depth", 1, true});
        normal_ = vk::Image(alloc_, {kNormalFormat, r, r, n, target, "rsm-normal", 1, true});
        flux_ = vk::Image(alloc_, {kFluxFormat, r, r, n, target, "rsm-flux", 1, true});
        vpls_ = vk::Image(alloc_, {kVplFormat, r, r, n, target, "rsm-vpls", 1, true});
        layerTable_ = vk::BufferRing(alloc_, sizeof(gpu::GpuRsmLayer) * n, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                     "rsm-layers");
    }
    layerTable_.select(slot);
    std::vector<gpu::GpuRsmLayer> table(n);
    for (size_t i = 0; i < layers.size(); ++i) {
        const RsmLayerSource& s = layers[i];
        // The projection's texel size is for the shadow map; RSM texels are larger by the ratio.
        const float texel = s.projection.texelSize * float(s.shadowResolution) / float(r);
        gpu::GpuRsmLayer& row = table[i];
        row.viewProj = s.projection.viewProj;
        row.invViewProj = glm::inverse(s.projection.viewProj);
        row.texelSize = texel;
        row.perspective = s.projection.perspective ? 1u : 0u;
        row.light = s.light;
        row.cascade = s.cascade;
        row.lastCascade = s.lastCascade ? 1u : 0u;
        row.radiusScale = s.radiusScale;
    }
    layerTable_.write(table.data(), table.size() * sizeof(gpu::GpuRsmLayer));
}

std::vector<uint32_t> RsmPass::shadowLayers() const {
    std::vector<uint32_t> out;
    for (const RsmLayerSource& s : sources_) out.push_back(s.viewIndex - 1);  // views row 0 is the camera
    return out;
}

void RsmPass::addTo(FrameGraph& graph) {
    const ImageHandle depth = graph.import(depth_), normal = graph.import(normal_), flux = graph.import(flux_),
                      vpls = graph.import(vpls_);
    const BufferHandle table = graph.import(layerTable_.current());
    graph.publish("rsm.depth", depth);
    graph.publish("rsm.normal", normal);
    graph.publish("rsm.flux", flux);
    graph.publish("rsm.vpls", vpls);
    graph.publish("rsm.layers", table);
    if (sources_.empty()) return;
    PassBuilder pass = graph.pass("rsm.resolve");
    pass.pipeline(pipeline_);
    scene_.declareDrawSet(pass, graph.buffer("views"));
    scene_.declareTriangles(pass);
    pass.storageBuffer(RSM_RESOLVE_LIGHTS, graph.buffer("lights"))
        .storageBuffer(RSM_RESOLVE_LAYERS, table)
        .sampled(RSM_RESOLVE_SHADOW_IDS, graph.image("shadow.ids"), nearest_.handle())
        .storageImage(RSM_RESOLVE_DEPTH, depth)
        .storageImage(RSM_RESOLVE_NORMAL, normal)
        .storageImage(RSM_RESOLVE_FLUX, flux)
        .storageImage(RSM_RESOLVE_VPLS, vpls);
    const uint32_t r = settings_.resolution;
    // Per texel: the shadow pass's visibility ID read, the four RSM images written.
    const VkDeviceSize texelBytes = vk::texelBytes(VK_FORMAT_R32_UINT) + vk::texelBytes(depth_.format()) +
                                    vk::texelBytes(normal_.format()) + vk::texelBytes(flux_.format()) +
                                    vk::texelBytes(vpls_.format());
    pass.bytes(VkDeviceSize(r) * r * sources_.size() * texelBytes);
    pass.record([this, r](PassContext& c) {
        pipeline_.push(c.cmd, gpu::RsmResolvePush{r, idResolution_, 0, 0});
        vkCmdDispatch(c.cmd, vk::divUp(r, 8), vk::divUp(r, 8), uint32_t(sources_.size()));
    });
}

}  // namespace penumbra
