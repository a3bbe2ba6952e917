#include "dsm/deep_shadow_build.h"

#include "render/raster.h"

namespace penumbra {

DeepShadowBuildPass::DeepShadowBuildPass(vk::Allocator& alloc, SceneGpu& scene, const HairGpu* hair,
                                         DsmResources& res)
    : alloc_(alloc), scene_(scene), hair_(hair), res_(res) {
    for (const Material& m : scene.scene().materials) hasBlended_ |= m.alphaMode == AlphaMode::Blend;
    // Set 0: the scene's draw set (views = the DSM views, materials, textures), the hair buffers,
    // then heads, nodes and counters.
    std::vector<vk::Binding> b = SceneGpu::drawSetBindings();
    for (const vk::Binding& h : HairGpu::bindings()) b.push_back(h);
    for (uint32_t i = 5; i <= 7; ++i) b.push_back({i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    vk::Context& ctx = alloc.context();
    layout_ = vk::DescriptorLayout(ctx, b);
    if (hair) {
        hairPipeline_ = vk::Pipeline::graphics(ctx, HairGpu::pipelineDesc("dsm/build_hair.frag"), {layout_.handle()},
                                               sizeof(gpu::HairDrawPush));
    }
    if (hasBlended_) {
        vk::GraphicsDesc d;
        d.vertexShader = "render/scene.vert";
        d.fragmentShader = "dsm/build_mesh.frag";
        d.vertexStride = SceneGpu::vertexStride();
        d.vertexAttributes = SceneGpu::vertexAttributes();
        d.dynamicCullMode = true;  // single-sided blended surfaces cast only from their front
        d.frontFace = SceneGpu::sceneFrontFace(false);
        meshPipeline_ = vk::Pipeline::graphics(ctx, d, {layout_.handle()}, sizeof(gpu::HairDrawPush));
    }
}

void DeepShadowBuildPass::recordLayer(VkCommandBuffer cmd, uint32_t layer) const {
    const DsmLayer& l = res_.layers[layer];
    RasterTarget target{{res_.resolution, res_.resolution}, {}, VK_NULL_HANDLE};  // no attachments
    beginRaster(cmd, target);
    gpu::HairDrawPush push{{layer, 0, layer, uint32_t(res_.capacity)}, l.view.viewer, l.view.footprint};
    push.footprint.z = float(res_.resolution);
    for (const vk::Pipeline* p : {&hairPipeline_, &meshPipeline_}) {
        if (!p->handle()) continue;
        p->bind(cmd);
        vk::DescriptorWrites w = scene_.drawSetWrites(res_.views);
        if (hair_) hair_->write(w);
        w.storageBuffer(5, res_.heads).storageBuffer(6, res_.nodes).storageBuffer(7, res_.stats);
        w.push(alloc_.context(), cmd, *p);
        if (p == &hairPipeline_) {
            hair_->draw(cmd, *p, push);
            continue;
        }
        scene_.draw(
            cmd,
            [&](const Draw& d) {
                push.ids.y = d.material;
                p->push(cmd, push);
            },
            [](const Material& m) { return m.alphaMode == AlphaMode::Blend; });
    }
    vkCmdEndRendering(cmd);
}

void DeepShadowBuildPass::addTo(FrameGraph& graph) {
    PassDesc clear{"dsm.clear", PassKind::Transfer, {}, {}, {}};
    clear.buffers = {{&res_.heads, Use::TransferDst}, {&res_.stats, Use::TransferDst}};
    clear.bytes = res_.heads.size();  // a fill: bound by memory bandwidth
    clear.record = [this](VkCommandBuffer cmd) {
        vkCmdFillBuffer(cmd, res_.heads.handle(), 0, VK_WHOLE_SIZE, DSM_NONE);
        vkCmdFillBuffer(cmd, res_.stats.handle(), 0, VK_WHOLE_SIZE, 0);
    };
    graph.add(std::move(clear));

    PassDesc build{"dsm.build", PassKind::Raster, {}, {}, {}};
    build.images = {{&scene_.textures(), Use::Sampled}};
    build.buffers = {{&res_.views, Use::StorageRead}, {&scene_.materials(), Use::StorageRead},
                     {&res_.heads, Use::StorageWrite}, {&res_.nodes, Use::StorageWrite},
                     {&res_.stats, Use::StorageWrite}};
    if (hair_) {
        build.buffers.push_back({&hair_->points(), Use::StorageRead});
        build.buffers.push_back({&hair_->strands(), Use::StorageRead});
    }
    build.record = [this](VkCommandBuffer cmd) {
        for (uint32_t layer = 0; layer < res_.layerCount(); ++layer) recordLayer(cmd, layer);
    };
    graph.add(std::move(build));
}

}  // namespace penumbra
