#include "sky_light/sky_light_technique.h"


namespace penumbra {
namespace {

constexpr VkFormat kClearRaysFormat = VK_FORMAT_R32G32_UINT;  // the mask, the receiver's depth
constexpr VkFormat kShareFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kIrradianceFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr uint64_t kClearRaysBytes = 2 * sizeof(uint32_t), kShareBytes = 4 * sizeof(uint16_t),
                   kIrradianceBytes = 4 * sizeof(float);
constexpr uint32_t kTracePhases = 4;  // a 2x2 block's texels, one a frame

// Each pass reads the frame and the G-buffer's normal and depth (bindings 0 to 2) and one input,
// and writes one image; the weigh and the upsample read the sky's SH too.
std::vector<vk::Binding> passBindings(uint32_t input, uint32_t out, VkDescriptorType inputType, bool readsSky = false) {
    constexpr VkDescriptorType tex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    std::vector<vk::Binding> bindings{{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}, {1, tex}, {2, tex}, {input, inputType},
                                      {out, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
    if (readsSky) bindings.push_back({SKY_WEIGH_SKY_SH, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER});
    return bindings;
}

}  // namespace

static_assert(SKY_TRACE_FRAME == 0 && SKY_WEIGH_FRAME == 0 && SKY_FILTER_FRAME == 0 && SKY_UPSAMPLE_FRAME == 0);
static_assert(SKY_TRACE_GBUFFER_NORMAL == 1 && SKY_WEIGH_GBUFFER_NORMAL == 1 && SKY_FILTER_GBUFFER_NORMAL == 1 &&
              SKY_UPSAMPLE_GBUFFER_NORMAL == 1);
static_assert(SKY_WEIGH_SKY_SH == SKY_UPSAMPLE_SKY_SH);
static_assert(SKY_TRACE_GBUFFER_DEPTH == 2 && SKY_WEIGH_GBUFFER_DEPTH == 2 && SKY_FILTER_GBUFFER_DEPTH == 2 &&
              SKY_UPSAMPLE_GBUFFER_DEPTH == 2);

SkyLightTechnique::SkyLightTechnique(const TechniqueBuild& b, const SkyLightSettings& s) : settings_(s) {
    vk::Context& ctx = b.alloc.context();
    const size_t push = sizeof(gpu::SkyLightPush);
    trace_ = vk::ComputeKernel(ctx, "sky_light/trace.comp",
                               passBindings(SKY_TRACE_OCCUPANCY, SKY_TRACE_OUT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER), push);
    weigh_ = vk::ComputeKernel(ctx, "sky_light/weigh.comp",
                               passBindings(SKY_WEIGH_CLEAR_RAYS, SKY_WEIGH_OUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, true), push);
    constexpr VkDescriptorType tex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    filter_ = vk::ComputeKernel(ctx, "sky_light/filter.comp", passBindings(SKY_FILTER_SHARE, SKY_FILTER_OUT, tex), push);
    upsample_ = vk::ComputeKernel(ctx, "sky_light/upsample.comp",
                                  passBindings(SKY_UPSAMPLE_SHARE, SKY_UPSAMPLE_OUT, tex, true), push);
    point_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    const uint32_t tracedW = vk::divUp(b.core.width, s.traceStep), tracedH = vk::divUp(b.core.height, s.traceStep);
    clearRays_ = vk::Image(b.alloc, {kClearRaysFormat, tracedW, tracedH, 1, VK_IMAGE_USAGE_STORAGE_BIT, "sky-clear-rays"});
    share_ = vk::Image(b.alloc, {kShareFormat, tracedW, tracedH, 1, usage, "sky-share"});
    filtered_ = vk::Image(b.alloc, {kShareFormat, tracedW, tracedH, 1, usage, "sky-share-filtered"});
    irradiance_ = vk::Image(b.alloc, {kIrradianceFormat, b.core.width, b.core.height, 1,
                                      usage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "sky-irradiance"});
    noVoxels_ = vk::Buffer(b.alloc, sizeof(gpu::GpuOccupancyGrid),
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false, "sky-no-voxels");
    b.cmd.submitAndWait([&](VkCommandBuffer c) {
        vkCmdFillBuffer(c, noVoxels_.handle(), 0, VK_WHOLE_SIZE, 0);
        vk::memoryBarrier(c, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    });
}

uint64_t SkyLightTechnique::bytes(uint64_t width, uint64_t height, uint32_t traceStep) {
    const uint64_t traced = ((width + traceStep - 1) / traceStep) * ((height + traceStep - 1) / traceStep);
    return traced * (kClearRaysBytes + 2 * kShareBytes) + width * height * kIrradianceBytes;
}

void SkyLightTechnique::setSettings(const SkyLightSettings& s) {
    settings_ = s;
    cached_ = false;
}

gpu::SkyLightPush SkyLightTechnique::constants() const {
    gpu::SkyLightPush p{};
    p.rays = settings_.visibility == SkyVisibility::None ? 0u : settings_.rays;
    p.startOffset = settings_.startOffset;
    p.filterRadius = settings_.filterRadius;
    p.traceStep = settings_.traceStep;
    return p;
}

void SkyLightTechnique::addPasses(const FrameContext& f) {
    const SkyLight* sky = f.board.get(names::kSkyLight);
    if (!sky || !sky->enabled) return;
    const ImageHandle out = f.graph.import(irradiance_);
    f.graph.publish(names::kSkyIrradiance, out);
    const OccupancyState* voxels = f.board.get(names::kOccupancyState);
    const TraceKey key{f.uniforms.viewProj, voxels ? voxels->generation : 0};
    // A new view traces every receiver; geometry that moves under a still view, one texel of each
    // 2x2 block a frame, so that its shadow on the sky catches up over four frames.
    const bool fullTrace = !cached_ || key.viewProj != traced_.viewProj;
    if (fullTrace) stalePhases_ = 0;
    else if (key.occupancy != traced_.occupancy) stalePhases_ = kTracePhases;
    if (!fullTrace && stalePhases_ == 0 && sky->generation == weighedSky_) return;
    gpu::SkyLightPush push = constants();
    push.tracePhase = SKY_TRACE_EVERY_TEXEL;
    if (stalePhases_ > 0) {
        push.tracePhase = nextPhase_;
        nextPhase_ = (nextPhase_ + 1) % kTracePhases;
        --stalePhases_;
    }
    const ImageHandle clearRays = f.graph.import(clearRays_), share = f.graph.import(share_);
    const ImageHandle filtered = f.graph.import(filtered_);
    if (fullTrace || push.tracePhase != SKY_TRACE_EVERY_TEXEL) addTrace(f.graph, clearRays, push);
    addShareFilters(f.graph, clearRays, share, filtered, push);
    addUpsample(f.graph, filtered, out, push);
    traced_ = key;
    weighedSky_ = sky->generation;
    cached_ = true;
}

void SkyLightTechnique::addTrace(FrameGraph& graph, ImageHandle clearRays, const gpu::SkyLightPush& push) {
    const bool voxels = push.rays > 0 && graph.has(names::kOccupancy);
    graph.pass("sky.trace")
        .pipeline(trace_.pipeline)
        .uniform(SKY_TRACE_FRAME, graph.buffer(names::kFrame))
        .sampled(SKY_TRACE_GBUFFER_NORMAL, graph.image(names::kGbufferNormal), point_.handle())
        .sampled(SKY_TRACE_GBUFFER_DEPTH, graph.image(names::kGbufferDepth), point_.handle())
        .storageBuffer(SKY_TRACE_OCCUPANCY, voxels ? graph.buffer(names::kOccupancy) : graph.import(noVoxels_))
        .storageImage(SKY_TRACE_OUT, clearRays)
        .record([this, push](PassContext& c) {
            trace_.pipeline.push(c.cmd, push);
            vkCmdDispatch(c.cmd, vk::divUp(clearRays_.width(), 8), vk::divUp(clearRays_.height(), 8), 1);
        });
}

// A pass of the sky-light kind: the frame, the G-buffer's normal and depth, one input, one output
// image (and the sky's SH where its kernel reads them), one thread per texel of `size`.
void SkyLightTechnique::addImagePass(FrameGraph& graph, const char* name, vk::ComputeKernel& kernel, uint32_t inputBinding,
                                     ImageHandle input, bool inputSampled, uint32_t outBinding, ImageHandle out,
                                     const vk::Image& size, const gpu::SkyLightPush& push) {
    PassBuilder pass = graph.pass(name);
    pass.pipeline(kernel.pipeline)
        .uniform(0, graph.buffer(names::kFrame))
        .sampled(1, graph.image(names::kGbufferNormal), point_.handle())
        .sampled(2, graph.image(names::kGbufferDepth), point_.handle());
    if (inputSampled)
        pass.sampled(inputBinding, input, point_.handle());
    else
        pass.storageImage(inputBinding, input, Use::StorageRead);
    if (&kernel == &weigh_ || &kernel == &upsample_) pass.uniform(SKY_WEIGH_SKY_SH, graph.buffer(names::kSkySh));
    pass.storageImage(outBinding, out).record([&kernel, &size, push](PassContext& c) {
        kernel.pipeline.push(c.cmd, push);
        vkCmdDispatch(c.cmd, vk::divUp(size.width(), 8), vk::divUp(size.height(), 8), 1);
    });
}

void SkyLightTechnique::addShareFilters(FrameGraph& graph, ImageHandle clearRays, ImageHandle share,
                                        ImageHandle filtered, const gpu::SkyLightPush& push) {
    addImagePass(graph, "sky.weigh", weigh_, SKY_WEIGH_CLEAR_RAYS, clearRays, false, SKY_WEIGH_OUT, share, share_, push);
    addImagePass(graph, "sky.filter", filter_, SKY_FILTER_SHARE, share, true, SKY_FILTER_OUT, filtered, filtered_, push);
}

void SkyLightTechnique::addUpsample(FrameGraph& graph, ImageHandle filtered, ImageHandle out,
                                    const gpu::SkyLightPush& push) {
    addImagePass(graph, "sky.upsample", upsample_, SKY_UPSAMPLE_SHARE, filtered, true, SKY_UPSAMPLE_OUT, out,
                 irradiance_, push);
}

}  // namespace penumbra
