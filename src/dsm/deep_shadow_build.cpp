#include "dsm/deep_shadow_build.h"

#include <string>

#include "core/raster.h"
#include "dsm/bindings.h"

namespace penumbra {

DeepShadowBuildPass::DeepShadowBuildPass(vk::Allocator& alloc, SceneGpu& scene, const HairGpu* hair,
                                         DsmResources& res, bool depthTest, bool computeHair)
    : alloc_(alloc), scene_(scene), hair_(hair), res_(res), hasBlended_(scene.scene().hasBlendedMaterials()),
      casters_(scene.scene().translucentCasterBounds()), depthTest_(depthTest) {
    // Set 0: the scene's draw set (views = the DSM views, materials; set 1 the textures), the hair buffers,
    // then buckets, runs and counters, and for the depth test the lights, the shadow lights and layers
    // and the opaque casters' shadow map (DSM_BUILD_*: both builds, raster and compute, write the lists there).
    std::vector<vk::Binding> lists;
    for (uint32_t i : {DSM_BUILD_BUCKETS, DSM_BUILD_RUNS, DSM_BUILD_STATS, DSM_BUILD_LIGHTS, DSM_BUILD_SHADOW_LIGHTS,
                       DSM_BUILD_SHADOW_LAYERS})
        lists.push_back({i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    lists.push_back({DSM_BUILD_SHADOW_MAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
    std::vector<vk::Binding> b = SceneGpu::drawSetBindings();
    for (const vk::Binding& h : HairGpu::bindings()) b.push_back(h);
    b.insert(b.end(), lists.begin(), lists.end());
    nearest_ = vk::Sampler(alloc.context(), {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
    vk::Context& ctx = alloc.context();
    layout_ = vk::DescriptorLayout(ctx, b);
    if (hair && computeHair) {
        hairKernel_ = HairGpu::segmentKernel(ctx, "dsm/build_hair.comp", lists, sizeof(gpu::DsmBuildPush));
    } else if (hair) {
        hairPipeline_ = vk::Pipeline::graphics(ctx, HairGpu::pipelineDesc("dsm/build_hair.frag"), SceneGpu::drawLayouts(ctx, layout_.handle()),
                                               sizeof(gpu::DsmBuildPush));
    }
    const VkDescriptorType ssbo = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    offsets_ = vk::ComputeKernel(ctx, "dsm/offsets.comp",
                                 std::vector<vk::Binding>{{DSM_OFFSETS_HEADS, ssbo},
                                                          {DSM_OFFSETS_STATS, ssbo},
                                                          {DSM_OFFSETS_WORK, ssbo},
                                                          {DSM_OFFSETS_BUCKETS, ssbo}},
                                 sizeof(gpu::DsmPush));
    if (hasBlended_) {
        vk::GraphicsDesc d;
        d.vertexShader = "core/scene.vert";
        d.fragmentShader = "dsm/build_mesh.frag";
        d.vertexStride = SceneGpu::vertexStride();
        d.vertexAttributes = SceneGpu::vertexAttributes();
        d.dynamicCullMode = true;  // single-sided blended surfaces cast only from their front
        d.frontFace = SceneGpu::sceneFrontFace(false);
        meshPipeline_ = vk::Pipeline::graphics(ctx, d, SceneGpu::drawLayouts(ctx, layout_.handle()),
                                               sizeof(gpu::DsmBuildPush));
    }
}

// The casters' depth range as dsm/dsm_common.glsl measures depth from `viewer` (from a spot light,
// along a directional one): the depth buckets' (dsm/depth_buckets.glsl). Only how much the buckets
// leave out depends on it, not what is kept.
glm::vec2 DeepShadowBuildPass::casterDepthRange(const RibbonView& view) const {
    const glm::vec3 eye = view.viewer;
    const bool fromPoint = view.viewerIsPoint != 0;
    glm::vec2 range{1e30f, -1e30f};
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p = casters_.corner(corner);
        const float d = fromPoint ? glm::distance(p, eye) : -glm::dot(p, eye);
        range = {std::min(range.x, d), std::max(range.y, d)};
    }
    if (fromPoint) range.x = glm::distance(glm::clamp(eye, casters_.min, casters_.max), eye);  // the box's nearest point
    return range;
}

gpu::DsmBuildPush DeepShadowBuildPass::layerPush(uint32_t layer, BuildStep step) const {
    const DsmLayer& l = res_.layers[layer];
    const uint32_t depthTestLight = depthTest_ ? l.light : DSM_NONE;
    return {layer, 0, depthTestLight, res_.resolution, l.view,
            depthBuckets(casterDepthRange(l.view), res_.bucketCount, step)};
}

void DeepShadowBuildPass::recordLayer(VkCommandBuffer cmd, uint32_t layer, BuildStep step) const {
    RasterTarget target{{res_.resolution, res_.resolution}, {}, VK_NULL_HANDLE};  // no attachments
    beginRaster(cmd, target);
    gpu::DsmBuildPush push = layerPush(layer, step);
    // Both pipelines share one set layout: the set the pass pushed stays bound across them.
    for (const vk::Pipeline* p : {&hairPipeline_, &meshPipeline_}) {
        if (!p->handle()) continue;
        p->bind(cmd);
        if (p == &hairPipeline_) {
            hair_->draw(cmd, *p, push);
            continue;
        }
        scene_.draw(
            cmd,
            [&](const Draw& d) {
                push.material = d.material;
                p->push(cmd, push);
            },
            [](const Material& m) { return m.alphaMode == AlphaMode::Blend; });
    }
    vkCmdEndRendering(cmd);
}

void DeepShadowBuildPass::addTo(FrameGraph& graph) {
    const BufferHandle heads = graph.import(res_.heads), stats = graph.import(res_.stats),
                       work = graph.import(res_.work), buckets = graph.import(res_.buckets);
    // The counts are zeroed here once; then the resolve zeroes every texel that had fragments.
    const bool zeroCounts = !res_.countsZeroed;
    res_.countsZeroed = true;
    graph.pass("dsm.clear", PassKind::Transfer)
        .use(buckets, Use::TransferDst)
        .use(stats, Use::TransferDst)
        .use(work, Use::TransferDst)
        .bytes(zeroCounts ? res_.buckets.size() : 0)  // a fill: bound by memory bandwidth
        .record([buckets, stats, work, zeroCounts](PassContext& c) {
            if (zeroCounts) vkCmdFillBuffer(c.cmd, c.buffer(buckets).handle(), 0, VK_WHOLE_SIZE, 0);
            vkCmdFillBuffer(c.cmd, c.buffer(stats).handle(), 0, VK_WHOLE_SIZE, 0);
            vkCmdFillBuffer(c.cmd, c.buffer(work).handle(), 0, 16, 0);  // no texels listed yet
        });
    buckets_ = buckets, runs_ = graph.import(res_.runs), stats_ = stats;
    addRasterPasses(graph, BuildStep::Count);
    PassBuilder offsets = graph.pass("dsm.offsets");
    offsets.storageBuffer(DSM_OFFSETS_HEADS, heads, Use::StorageWrite)  // each texel's run
        .storageBuffer(DSM_OFFSETS_STATS, stats, Use::StorageWrite)
        .storageBuffer(DSM_OFFSETS_WORK, work, Use::StorageWrite)
        .storageBuffer(DSM_OFFSETS_BUCKETS, buckets, Use::StorageWrite)  // counts in, places out
        .pipeline(offsets_.pipeline)
        .record([this](PassContext& c) {
            offsets_.pipeline.push(c.cmd, res_.push());
            vkCmdDispatch(c.cmd, vk::divUp(res_.resolution, 8), vk::divUp(res_.resolution, 8), res_.layerCount());
        });
    addRasterPasses(graph, BuildStep::Store);
}

// The raster build of the BLEND meshes (and, without computeHair, the hair) and the compute build of
// the hair, for one step: the same pipelines both times, so that both steps make the same fragments.
void DeepShadowBuildPass::addRasterPasses(FrameGraph& graph, BuildStep step) {
    const std::string name = step == BuildStep::Count ? "dsm.count" : "dsm.build";
    if (hasBlended_ || hairPipeline_.handle()) {
        PassBuilder build = graph.pass(name, PassKind::Raster);
        build.pipeline(setLayoutPipeline());
        scene_.declareDrawSet(build, graph.import(res_.views.current()));
        if (hairPipeline_.handle()) hair_->declare(build);
        declareLists(build).record([this, step](PassContext& c) {
            for (uint32_t layer = 0; layer < res_.layerCount(); ++layer) recordLayer(c.cmd, layer, step);
        });
    }
    if (hairKernel_.pipeline.handle()) {
        PassBuilder build = graph.pass(name + ".hair");
        build.pipeline(hairKernel_.pipeline).storageBuffer(HAIR_VIEWS, graph.import(res_.views.current()));
        hair_->declare(build);
        declareLists(build).record([this, step](PassContext& c) {
            for (uint32_t layer = 0; layer < res_.layerCount(); ++layer)
                hair_->dispatchSegments(c.cmd, hairKernel_.pipeline, layerPush(layer, step));
        });
    }
}

// The lists of both builds (DSM_BUILD_*): buckets and runs, and what the depth test reads.
PassBuilder& DeepShadowBuildPass::declareLists(PassBuilder& pass) const {
    FrameGraph& graph = pass.graph();
    return pass.storageBuffer(DSM_BUILD_BUCKETS, buckets_, Use::StorageWrite)
        .storageBuffer(DSM_BUILD_RUNS, runs_, Use::StorageWrite)
        .storageBuffer(DSM_BUILD_STATS, stats_, Use::StorageWrite)
        .storageBuffer(DSM_BUILD_LIGHTS, graph.buffer("lights"))
        .storageBuffer(DSM_BUILD_SHADOW_LIGHTS, graph.buffer("shadow.lights"))
        .storageBuffer(DSM_BUILD_SHADOW_LAYERS, graph.buffer("shadow.layers"))
        .sampled(DSM_BUILD_SHADOW_MAP, graph.image("shadow.map"), nearest_.handle());
}

}  // namespace penumbra
