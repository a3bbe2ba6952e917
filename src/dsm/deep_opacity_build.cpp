#include "dsm/deep_opacity_build.h"

#include <algorithm>

#include "dsm/bindings.h"

namespace penumbra {

DeepOpacityBuildPass::DeepOpacityBuildPass(vk::Allocator& alloc, const HairGpu& hair, DsmResources& res)
    : hair_(hair), res_(res) {
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    kernel_ = HairGpu::segmentKernel(alloc.context(), "dsm/opacity_build.comp",
                                     {{DOM_BUILD_FIRST_DEPTHS, storage}, {DOM_BUILD_LAYERS, storage}},
                                     sizeof(gpu::DomBuildPush));
}

float DeepOpacityBuildPass::layerThickness(const Scene& scene) {
    Bounds b;
    for (const glm::vec3& p : scene.strandPoints) b.extend(p);
    const float diameter = b.empty() ? 1.0f : 2.0f * b.radius();
    return std::max(0.5f * diameter / float(DOM_LAYERS), 1e-6f);
}

void DeepOpacityBuildPass::addTo(FrameGraph& graph) {
    const BufferHandle heads = graph.import(res_.heads), layers = graph.import(res_.nodes),
                       views = graph.import(res_.views.current());
    const VkDeviceSize layerBytes =
        VkDeviceSize(res_.resolution) * res_.resolution * res_.layerCount() * DOM_LAYERS * sizeof(float);
    graph.pass("dom.clear", PassKind::Transfer)
        .use(heads, Use::TransferDst)
        .use(layers, Use::TransferDst)
        .bytes(res_.heads.size() + layerBytes)
        .record([heads, layers, layerBytes](PassContext& c) {
            vkCmdFillBuffer(c.cmd, c.buffer(heads).handle(), 0, VK_WHOLE_SIZE, DSM_NONE);  // "no strand"
            vkCmdFillBuffer(c.cmd, c.buffer(layers).handle(), 0, layerBytes, 0);
        });
    for (uint32_t step : {0u, 1u}) {  // first depths, then the layers behind them
        PassBuilder pass = graph.pass(step == 0 ? "dom.depth" : "dom.layers");
        pass.pipeline(kernel_.pipeline).storageBuffer(HAIR_VIEWS, views);
        hair_.declare(pass);
        pass.storageBuffer(DOM_BUILD_FIRST_DEPTHS, heads, step == 0 ? Use::StorageWrite : Use::StorageRead)
            .storageBuffer(DOM_BUILD_LAYERS, layers, Use::StorageWrite)
            .record([this, step](PassContext& c) {
                for (uint32_t layer = 0; layer < res_.layerCount(); ++layer) {
                    const DsmLayer& l = res_.layers[layer];
                    const gpu::DomBuildPush push{layer, step, res_.opacityLayer, res_.resolution, l.view};
                    hair_.dispatchSegments(c.cmd, kernel_.pipeline, push);
                }
            });
    }
}

}  // namespace penumbra
