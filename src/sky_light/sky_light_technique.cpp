#include "sky_light/sky_light_technique.h"

#include <cmath>

#include "core/gpu_scene.h"
#include "core/light_space.h"
#include "vk/format_bytes.h"

namespace penumbra {
namespace {

constexpr VkFormat kClearRaysFormat = VK_FORMAT_R32G32_UINT;  // the mask, the receiver's depth
constexpr VkFormat kShareFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kIrradianceFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr uint64_t kClearRaysBytes = 2 * sizeof(uint32_t), kShareBytes = 4 * sizeof(uint16_t),
                   kIrradianceBytes = 4 * sizeof(float);
constexpr uint32_t kTracePhases = 4;  // a 2x2 block's texels, one a frame
constexpr uint32_t kSkyBinding = SKY_WEIGH_SKY_RADIANCE;
constexpr VkFormat kMapFormat = VK_FORMAT_R32_SFLOAT;  // the compute rasterizer writes it whole
// The maps' depth bias: no slope term. A receiver looks itself up --sky-map-offset (1.5) texels off
// its surface, which keeps its own surface (at most half a texel from it in the texel it falls in)
// behind it; a slope bias would also push an occluder a centimetre from the receiver (a ceiling over
// the top of a wall) behind it, and let the sky in along every seam.
constexpr RasterBias kMapBias{4.0f, 0.0f};

// What a pass reads of the sky at binding 5: nothing, its radiance image (the weigh and the map
// look-up) or its SH (the upsample).
enum class SkyInput { None, Radiance, Sh };

// Each pass reads the frame and the G-buffer's normal and depth (bindings 0 to 2) and one input,
// writes one image, and may read the sky.
std::vector<vk::Binding> passBindings(uint32_t input, uint32_t out, VkDescriptorType inputType,
                                      SkyInput sky = SkyInput::None) {
    constexpr VkDescriptorType tex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    std::vector<vk::Binding> bindings{{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}, {1, tex}, {2, tex}, {input, inputType},
                                      {out, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
    if (sky != SkyInput::None)
        bindings.push_back({kSkyBinding, sky == SkyInput::Sh ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : tex});
    return bindings;
}

}  // namespace

static_assert(SKY_TRACE_FRAME == 0 && SKY_WEIGH_FRAME == 0 && SKY_FILTER_FRAME == 0 && SKY_UPSAMPLE_FRAME == 0);
static_assert(SKY_TRACE_GBUFFER_NORMAL == 1 && SKY_WEIGH_GBUFFER_NORMAL == 1 && SKY_FILTER_GBUFFER_NORMAL == 1 &&
              SKY_UPSAMPLE_GBUFFER_NORMAL == 1);
static_assert(SKY_UPSAMPLE_SKY_SH == kSkyBinding && SKY_MAPS_SKY_RADIANCE == kSkyBinding);
static_assert(SKY_MAPS_FRAME == 0 && SKY_MAPS_GBUFFER_NORMAL == 1 && SKY_MAPS_GBUFFER_DEPTH == 2);
static_assert(SKY_TRACE_GBUFFER_DEPTH == 2 && SKY_WEIGH_GBUFFER_DEPTH == 2 && SKY_FILTER_GBUFFER_DEPTH == 2 &&
              SKY_UPSAMPLE_GBUFFER_DEPTH == 2);

SkyLightTechnique::SkyLightTechnique(const TechniqueBuild& b, const SkyLightSettings& s) : settings_(s) {
    vk::Context& ctx = b.alloc.context();
    const size_t push = sizeof(gpu::SkyLightPush);
    constexpr VkDescriptorType tex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    std::vector<vk::Binding> look = passBindings(SKY_MAPS_DEPTH, SKY_MAPS_OUT, tex, SkyInput::Radiance);
    look.push_back({SKY_MAPS_DIRECTIONS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    look_ = vk::ComputeKernel(ctx, "sky_light/maps.comp", look, push);
    trace_ = vk::ComputeKernel(ctx, "sky_light/trace.comp",
                               passBindings(SKY_TRACE_OCCUPANCY, SKY_TRACE_OUT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER), push);
    weigh_ = vk::ComputeKernel(ctx, "sky_light/weigh.comp",
                               passBindings(SKY_WEIGH_CLEAR_RAYS, SKY_WEIGH_OUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, SkyInput::Radiance),
                               push);
    filter_ = vk::ComputeKernel(ctx, "sky_light/filter.comp", passBindings(SKY_FILTER_SHARE, SKY_FILTER_OUT, tex), push);
    upsample_ = vk::ComputeKernel(ctx, "sky_light/upsample.comp",
                                  passBindings(SKY_UPSAMPLE_SHARE, SKY_UPSAMPLE_OUT, tex, SkyInput::Sh), push);
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
    if (s.visibility == SkyVisibility::Maps) makeMaps(b);
}

std::vector<glm::vec3> SkyLightTechnique::mapDirections(uint32_t count) {
    std::vector<glm::vec3> out(count);
    const double golden = 3.14159265358979 * (3.0 - std::sqrt(5.0));  // the golden angle
    for (uint32_t k = 0; k < count; ++k) {
        // Uniform in cos(theta) over [0, 1]: equal solid angles on the hemisphere.
        const double cosTheta = 1.0 - (k + 0.5) / count, sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
        const double phi = golden * k;
        out[k] = glm::vec3(float(sinTheta * std::cos(phi)), float(cosTheta), float(sinTheta * std::sin(phi)));
    }
    return out;
}

// The maps, their views (the whole scene, its animation included, from each direction) and the
// rasterizer that draws them.
void SkyLightTechnique::makeMaps(const TechniqueBuild& b) {
    const uint32_t n = settings_.mapCount, res = settings_.mapResolution;
    maps_ = vk::Image(b.alloc, {kMapFormat, res, res, n, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                "sky-maps", 1, true});
    mapRaster_ = makeDepthRaster(b.alloc, b.scene.meshes(), VkExtent2D{res, res}, n);
    mapViews_ = vk::Buffer(b.alloc, sizeof(glm::mat4) * n, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "sky-map-views");
    mapDirections_ = vk::Buffer(b.alloc, sizeof(gpu::SkyMapDirection) * n, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true,
                                "sky-map-directions");
    const std::vector<glm::vec3> dirs = mapDirections(n);
    for (uint32_t k = 0; k < n; ++k) {
        const LightProjection p = directionalProjection(-dirs[k], b.scene.scene().bounds, res);
        mapViews_.as<glm::mat4>()[k] = p.viewProj;
        mapDirections_.as<gpu::SkyMapDirection>()[k] = {p.viewProj, dirs[k], 0.0f};
        mapTexel_ = p.texelSize;
    }
    mapsDrawn_ = false;
}

uint64_t SkyLightTechnique::mapBytes(uint64_t resolution, uint32_t count) {
    return resolution * resolution * count * vk::texelBytes(kMapFormat);
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
    p.mapCount = settings_.mapCount;
    p.mapResolution = settings_.mapResolution;
    p.mapOffset = settings_.mapOffset * mapTexel_;
    return p;
}

void SkyLightTechnique::addPasses(const FrameContext& f) {
    const SkyLight* sky = f.board.get(names::kSkyLight);
    if (!sky || !sky->enabled) return;
    const ImageHandle out = f.graph.import(irradiance_);
    f.graph.publish(names::kSkyIrradiance, out);
    if (settings_.visibility == SkyVisibility::Maps) {
        // Looked up again for a new view, a new sky or new maps.
        const bool draw = !mapsDrawn_;
        if (!draw && cached_ && f.uniforms.viewProj == traced_.viewProj && sky->generation == weighedSky_) return;
        const ImageHandle share = f.graph.import(share_), filtered = f.graph.import(filtered_);
        const gpu::SkyLightPush push = constants();
        addMaps(f, share, push, draw);
        addImagePass(f.graph, "sky.filter", filter_, SKY_FILTER_SHARE, share, true, SKY_FILTER_OUT, filtered, filtered_,
                     push);
        addUpsample(f.graph, filtered, out, push);
        traced_.viewProj = f.uniforms.viewProj;
        weighedSky_ = sky->generation;
        cached_ = mapsDrawn_ = true;
        return;
    }
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

void SkyLightTechnique::addMaps(const FrameContext& f, ImageHandle share, const gpu::SkyLightPush& push, bool draw) {
    FrameGraph& graph = f.graph;
    const ImageHandle maps = graph.import(maps_);
    if (draw) {
        mapRaster_->setViews({RasterViews{0, 0, settings_.mapCount, false, RasterViews::kNoIds}}, f.slot);
        mapRaster_->addTo(graph, "sky.maps", maps, graph.import(mapViews_), kMapBias);
    }
    graph.pass("sky.look")
        .pipeline(look_.pipeline)
        .uniform(SKY_MAPS_FRAME, graph.buffer(names::kFrame))
        .sampled(SKY_MAPS_GBUFFER_NORMAL, graph.image(names::kGbufferNormal), point_.handle())
        .sampled(SKY_MAPS_GBUFFER_DEPTH, graph.image(names::kGbufferDepth), point_.handle())
        .sampled(SKY_MAPS_DEPTH, maps, point_.handle())
        .storageBuffer(SKY_MAPS_DIRECTIONS, graph.import(mapDirections_))
        .sampled(SKY_MAPS_SKY_RADIANCE, graph.image(names::kSkyRadiance), point_.handle())
        .storageImage(SKY_MAPS_OUT, share)
        .record([this, push](PassContext& c) {
            look_.pipeline.push(c.cmd, push);
            vkCmdDispatch(c.cmd, vk::divUp(share_.width(), 8), vk::divUp(share_.height(), 8), 1);
        });
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
    if (&kernel == &weigh_) pass.sampled(kSkyBinding, graph.image(names::kSkyRadiance), point_.handle());
    if (&kernel == &upsample_) pass.uniform(kSkyBinding, graph.buffer(names::kSkySh));
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
