#include "lighting/gbuffer_pass.h"

#include "core/raster.h"
#include "lighting/gbuffer_bindings.h"
#include "vk/format_bytes.h"

namespace penumbra {

GBufferPass::GBufferPass(vk::Allocator& alloc, SceneGpu& scene, uint32_t width, uint32_t height,
                         VkDescriptorSetLayout drawLayout, CameraPath path, bool drawBlended, bool computeRaster,
                         bool rasterAfter)
    : alloc_(alloc), scene_(scene), path_(path), drawBlended_(drawBlended) {
    vk::Context& ctx = alloc.context();
    const bool visibility = path == CameraPath::Visibility;
    const bool computeDepth = visibility && computeRaster && !rasterAfter;
    // Hair ribbons are drawn into albedo and normal after either path (src/dsm): both stay attachments.
    const VkImageUsageFlags target = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                     VK_IMAGE_USAGE_TRANSFER_SRC_BIT | (visibility ? VK_IMAGE_USAGE_STORAGE_BIT : 0);
    // sRGB formats cannot be storage images: the resolve writes linear half floats.
    albedo = vk::Image(alloc, {visibility ? VK_FORMAT_R16G16B16A16_SFLOAT : VK_FORMAT_R8G8B8A8_SRGB, width, height,
                               1, target, "gbuffer-albedo"});
    normal = vk::Image(alloc, {VK_FORMAT_R16G16B16A16_SFLOAT, width, height, 1, target, "gbuffer-normal"});
    depth = vk::Image(alloc, {computeDepth ? VK_FORMAT_R32_SFLOAT : VK_FORMAT_D32_SFLOAT, width, height, 1,
                              VkImageUsageFlags(computeDepth ? VK_IMAGE_USAGE_STORAGE_BIT
                                                             : VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT) |
                                  VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                  VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                              "gbuffer-depth"});
    vk::GraphicsDesc d;
    d.vertexShader = "core/scene.vert";
    d.fragmentShader = visibility ? "core/visibility.frag" : "lighting/gbuffer.frag";
    d.depthFormat = VK_FORMAT_D32_SFLOAT;
    d.vertexStride = SceneGpu::vertexStride();
    d.vertexAttributes = SceneGpu::vertexAttributes();
    d.dynamicCullMode = true;
    d.frontFace = SceneGpu::sceneFrontFace(true);
    if (!visibility) {
        d.colorFormats = {albedo.format(), normal.format()};
        pipeline_ = vk::Pipeline::graphics(ctx, d, SceneGpu::drawLayouts(ctx, drawLayout), sizeof(gpu::DrawPush));
        return;
    }
    ids = vk::Image(alloc, {VK_FORMAT_R32_UINT, width, height, 1,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_STORAGE_BIT,
                            "gbuffer-ids"});
    if (computeRaster) {  // the compute rasterizer draws the IDs: no raster pipelines
        compute_ = makeDepthRaster(alloc, scene, VkExtent2D{width, height}, 1, DepthRaster::Views::Camera);
    } else {
        d.colorFormats = {ids.format()};
        pipeline_ = vk::Pipeline::graphics(ctx, d, SceneGpu::drawLayouts(ctx, drawLayout), sizeof(gpu::DrawPush));
        d.fragmentShader = "core/visibility_masked.frag";
        masked_ = vk::Pipeline::graphics(ctx, d, SceneGpu::drawLayouts(ctx, drawLayout), sizeof(gpu::DrawPush));
    }
    std::vector<vk::Binding> bindings = SceneGpu::resolveSetBindings();
    bindings.push_back({VISIBILITY_RESOLVE_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER});
    bindings.push_back({VISIBILITY_RESOLVE_IDS, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
    bindings.push_back({VISIBILITY_RESOLVE_ALBEDO, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE});
    bindings.push_back({VISIBILITY_RESOLVE_NORMAL, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE});
    resolveLayout_ = vk::DescriptorLayout(ctx, bindings);
    resolve_ = vk::Pipeline::compute(ctx, "lighting/visibility_resolve.comp",
                                     SceneGpu::drawLayouts(ctx, resolveLayout_.handle()),
                                     sizeof(gpu::VisibilityResolvePush));
    nearest_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
}

void GBufferPass::addTo(FrameGraph& graph, uint32_t slot) {
    const ImageHandle a = graph.import(albedo), n = graph.import(normal), d = graph.import(depth);
    graph.publish("gbuffer.albedo", a);
    graph.publish("gbuffer.normal", n);
    graph.publish("gbuffer.depth", d);
    if (path_ == CameraPath::Visibility) return addVisibility(graph, a, n, d, slot);
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

void GBufferPass::addVisibility(FrameGraph& graph, ImageHandle a, ImageHandle n, ImageHandle d, uint32_t slot) {
    const ImageHandle id = graph.import(ids);
    graph.publish("gbuffer.ids", id);
    if (compute_) {
        // One layer, the camera's row of "views" (0), with IDs; blended materials as the raster's filter.
        compute_->setViews({{0, 0, 1, !drawBlended_, 0}}, slot);
        compute_->addTo(graph, "visibility.raster", d, graph.buffer("views"), {}, id);
    } else {
        addVisibilityRaster(graph, id, d);
    }
    addResolve(graph, a, n, id);
}

void GBufferPass::addVisibilityRaster(FrameGraph& graph, ImageHandle id, ImageHandle d) {
    PassBuilder raster = graph.pass("visibility", PassKind::Raster);
    raster.pipeline(pipeline_).use(id, Use::ColorAttachment).use(d, Use::DepthAttachment);
    scene_.declareDrawSet(raster, graph.buffer("views"));
    raster.record([this, id, d](PassContext& c) {
        beginRaster(c.cmd, {c.image(id).extent(), {{c.image(id).view(), {{0, 0, 0, 0}}}}, c.image(d).view()});
        // In the scene's order, as the classic path (equal depths keep the same triangle): opaque (and
        // blended ones without camera translucency) without discard, so early depth testing stays on;
        // alpha-masked ones test alpha in their own pipeline.
        const vk::Pipeline* bound = &pipeline_;
        scene_.draw(
            c.cmd,
            [&](const Draw& draw) {
                const vk::Pipeline* p =
                    scene_.scene().materials[draw.material].alphaMode == AlphaMode::Mask ? &masked_ : &pipeline_;
                if (p != bound) p->bind(c.cmd), bound = p;
                p->push(c.cmd, gpu::DrawPush{0, draw.material, 0, scene_.triangleBase(draw)});
            },
            [this](const Material& m) { return drawBlended_ || m.alphaMode != AlphaMode::Blend; });
        vkCmdEndRendering(c.cmd);
    });
}

void GBufferPass::addResolve(FrameGraph& graph, ImageHandle a, ImageHandle n, ImageHandle id) {
    const uint32_t w = albedo.width(), h = albedo.height();
    PassBuilder resolve = graph.pass("visibility.resolve");
    resolve.pipeline(resolve_);
    scene_.declareDrawSet(resolve, graph.buffer("views"));
    scene_.declareTriangles(resolve);
    resolve.uniform(VISIBILITY_RESOLVE_FRAME, graph.buffer("frame"))
        .sampled(VISIBILITY_RESOLVE_IDS, id, nearest_.handle())
        .storageImage(VISIBILITY_RESOLVE_ALBEDO, a)
        .storageImage(VISIBILITY_RESOLVE_NORMAL, n)
        .bytes(VkDeviceSize(w) * h *
               (vk::texelBytes(ids.format()) + vk::texelBytes(albedo.format()) + vk::texelBytes(normal.format())))
        .record([this, w, h](PassContext& c) {
            resolve_.push(c.cmd, gpu::VisibilityResolvePush{w, h, 0, 0});
            vkCmdDispatch(c.cmd, vk::divUp(w, 8), vk::divUp(h, 8), 1);
        });
}

}  // namespace penumbra
