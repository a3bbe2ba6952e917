#include "rsm/rsm_gather.h"

#include <cmath>
#include <random>

#include <fmt/format.h>

#include "rsm/bindings.h"
#include "vk/format_bytes.h"

namespace penumbra {
namespace {

constexpr VkFormat kIrradianceFormat = VK_FORMAT_R32G32B32A32_SFLOAT;  // exact sums stay exact

// The unbiased pattern is a mixture: half the samples on the r_max disc, half on a disc that reaches
// every texel of the map from any receiver (the light's whole footprint, radius sqrt 2). Near VPLs
// keep many samples, and far ones (the far walls of a closed room) are no longer left out.
// --rsm-weights paper keeps the paper's single disc. The gather places and weighs each sample
// (rsm/gather.glsl, patternSample), xi1 shifted per receiver with --rsm-radii shifted.
constexpr float kWholeMapRadius = 1.41421356f;

// Invocations per receiver (rsm/gather.glsl main). The low-resolution grid (130k receivers at 1080p)
// and the fallback list (a few percent of the pixels) are too few threads, one per receiver, to hide
// the samples' memory latency on a large GPU: 4 lanes per receiver hide it, 8 add nothing
// (docs/techniques/rsm.md). The full-resolution gather has receivers enough.
// The gradient gathers as the low-resolution gather did, so that a still light gives the same sum bit
// for bit.
uint32_t lanesPerReceiver(uint32_t mode) {
    return mode == RSM_GATHER_LIST || mode == RSM_GATHER_LOWRES || mode == RSM_GATHER_GRADIENT ? 4u : 1u;
}

}  // namespace

// Two vec4 per sample, in two runs of N: first its offset (uv, for r_max), weight (texels) and 1
// beyond r_max with fixed radii, read as they are by the gather; then (sin, cos) of its angle, xi1 and
// its disc's radius, from which the gather places and weighs it with xi1 shifted per receiver
// (--rsm-radii shifted).
std::vector<glm::vec4> rsmSamplePattern(const RsmSettings& s) {
    std::mt19937 rng(s.seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    const double texels = double(s.resolution) * s.resolution, inner = s.radius;
    const double outer = std::max(inner, double(kWholeMapRadius));
    std::vector<glm::vec4> out(2 * size_t(s.samples));
    for (size_t i = 0; i < s.samples; ++i) {
        const float xi1 = std::max(uniform(rng), 1e-6f), angle = 2.0f * float(M_PI) * uniform(rng);
        const bool paper = s.weights == RsmWeights::Paper;
        const double disc = paper || i % 2 == 0 ? inner : outer, r = xi1 * disc;
        double weight;
        if (paper) {  // the paper's single disc, its xi1^2 weights (E[xi1^2] = 1/3)
            weight = M_PI * inner * inner * texels / s.samples * 3.0 * xi1 * xi1;
        } else {  // the mixture: 1 / (N density), density 1 / (2 pi r R) on each polar disc
            const double density = 0.5 / (2.0 * M_PI * r * outer) + (r < inner ? 0.5 / (2.0 * M_PI * r * inner) : 0.0);
            weight = texels / (s.samples * density);
        }
        out[i] = {float(r * std::sin(angle)), float(r * std::cos(angle)), float(weight), r > inner ? 1.0f : 0.0f};
        out[s.samples + i] = {std::sin(angle), std::cos(angle), xi1, float(disc)};
    }
    return out;
}

RsmGather::RsmGather(vk::Allocator& alloc, vk::CommandContext& cmd, uint32_t width, uint32_t height,
                     const RsmSettings& settings)
    : alloc_(alloc), cmd_(cmd), settings_(settings), width_(width), height_(height) {
    vk::Context& ctx = alloc.context();
    const VkDescriptorType ubo = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, tex = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           ssbo = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, img = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    // The far disc with fixed radii has a lean pipeline of its own; the default (flux draws, shifted
    // radii) another, taken in the frames whose weights are unbiased (drawsByFlux).
    const bool voxels = settings.visibility == RsmVisibility::Voxels, shifted = shiftedRadii(settings);
    const char* gather = voxels                                         ? "rsm/gather_voxels.comp"
                         : shifted || settings.far == RsmFar::Flux ? "rsm/gather_shifted.comp"
                                                                        : "rsm/gather.comp";
    const std::vector<vk::Binding> bindings{
        {RSM_GATHER_FRAME, ubo},          {RSM_GATHER_GBUFFER_NORMAL, tex}, {RSM_GATHER_GBUFFER_DEPTH, tex},
        {RSM_GATHER_RSM_DEPTH, tex},      {RSM_GATHER_RSM_NORMAL, tex},     {RSM_GATHER_RSM_FLUX, tex},
        {RSM_GATHER_LAYERS, ssbo},        {RSM_GATHER_SAMPLES, ssbo},       {RSM_GATHER_IRRADIANCE, img},
        {RSM_GATHER_PIXEL_LIST, ssbo},    {RSM_GATHER_OCCUPANCY, ssbo},     {RSM_GATHER_VPLS, tex},
        {RSM_GATHER_FLUX_DRAWS, ssbo},    {RSM_GATHER_GRADIENT_SAMPLES, ssbo}};
    gather_ = vk::ComputeKernel(ctx, gather, bindings, sizeof(gpu::RsmPush));
    if (settings.far == RsmFar::Flux && shifted && !voxels)
        gatherFlux_ = vk::ComputeKernel(ctx, "rsm/gather_flux.comp", bindings, sizeof(gpu::RsmPush));
    interpolate_ = vk::ComputeKernel(
        ctx, "rsm/interpolate.comp",
        {{RSM_INTERPOLATE_FRAME, ubo}, {RSM_INTERPOLATE_GBUFFER_NORMAL, tex}, {RSM_INTERPOLATE_GBUFFER_DEPTH, tex},
         {RSM_INTERPOLATE_LOW_IRRADIANCE, tex}, {RSM_INTERPOLATE_IRRADIANCE, img}, {RSM_INTERPOLATE_PIXEL_LIST, ssbo},
         {RSM_INTERPOLATE_LAYERS, ssbo}},
        sizeof(gpu::RsmPush));
    args_ = vk::ComputeKernel(ctx, "core/indirect_args.comp", {ssbo, ssbo}, sizeof(uint32_t));
    pointSampler_ = vk::Sampler(ctx, {VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false, false});

    const uint32_t f = std::max(1u, settings.lowResFactor);
    lowWidth_ = vk::divUp(width, f);
    lowHeight_ = vk::divUp(height, f);
    const VkImageUsageFlags use = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    irradiance_ = vk::Image(alloc, {kIrradianceFormat, width, height, 1, use, "rsm-irradiance"});
    if (settings.mode == RsmMode::Interpolated) {
        low_ = vk::Image(alloc, {kIrradianceFormat, lowWidth_, lowHeight_, 1, use, "rsm-irradiance-low"});
        pixelList_ = vk::Buffer(alloc, pixelListBytes(width, height),
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                    VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                false, "rsm-fallback-pixels");
        dispatchArgs_ = vk::Buffer(alloc, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                                   false, "rsm-fallback-args");
        blocksWidth_ = vk::divUp(lowWidth_, 2u);
        blocksHeight_ = vk::divUp(lowHeight_, 2u);
        for (vk::Buffer& b : gradientSamples_)
            b = vk::Buffer(alloc, sizeof(gpu::GpuGradientSample) * blocksWidth_ * blocksHeight_,
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false, "rsm-gradient-samples");
        change_ = vk::Image(alloc, {GiChange::kFormat, blocksWidth_, blocksHeight_, 1,
                                    use | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "rsm-change"});
        changeTexel_.pixels = 2 * f;
    } else {
        pixelList_ = vk::Buffer(alloc, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false, "rsm-unused-list");
    }
    // Zeros, bound in place of an optional buffer not published this frame: an empty occupancy grid
    // (no voxels), or the flux draws under --rsm-far disc (never read there).
    emptyBuffer_ = vk::Buffer(alloc, sizeof(gpu::GpuOccupancyGrid),
                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false,
                              "rsm-empty");
    cmd.submitAndWait([&](VkCommandBuffer c) {
        vkCmdFillBuffer(c, emptyBuffer_.handle(), 0, VK_WHOLE_SIZE, 0);
        vk::memoryBarrier(c, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    });
    // Sized for the largest sample count, so that --rsm-samples is a per-frame value.
    samples_ = vk::BufferRing(alloc, 2 * sizeof(glm::vec4) * kMaxRsmSamples, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                              "rsm-samples");
    setSettings(settings);
}

void RsmGather::setSettings(const RsmSettings& s) {
    if (s.samples > kMaxRsmSamples) throw vk::VulkanError(fmt::format("{{rsm.samples}} {}: at most {}", s.samples,
                                                                     kMaxRsmSamples));
    settings_ = s;
    changeTexel_.lagTolerance = s.lagTolerance;
    pattern_ = rsmSamplePattern(s);
    RsmSettings perFrame = s;
    perFrame.samples = std::min(s.frameSamples, s.samples);
    framePattern_ = rsmSamplePattern(perFrame);
}

uint64_t RsmGather::gradientBytes(uint32_t width, uint32_t height, uint32_t lowResFactor) {
    const uint64_t cells = 2 * std::max(1u, lowResFactor);
    const uint64_t blocks = (width + cells - 1) / cells * ((height + cells - 1) / cells);
    return blocks * (2 * sizeof(gpu::GpuGradientSample) + vk::texelBytes(GiChange::kFormat));
}

// Push constants shared by the gather and interpolation passes; sizes are the low-resolution grid's
// for RSM_GATHER_LOWRES (which the interpolation reads), the blocks' for RSM_GATHER_GRADIENT, the
// full image's otherwise.
gpu::RsmPush RsmGather::constants(uint32_t mode, uint32_t layers) const {
    const bool low = mode == RSM_GATHER_LOWRES, gradient = mode == RSM_GATHER_GRADIENT;
    gpu::RsmPush pc{};
    pc.mode = mode;
    pc.sampleCount = sampleCount();
    pc.frameSeed = frameSeed_;
    pc.layerCount = layers;
    pc.lowResFactor = std::max(1u, settings_.lowResFactor);
    pc.width = gradient ? blocksWidth_ : low ? lowWidth_ : width_;
    pc.height = gradient ? blocksHeight_ : low ? lowHeight_ : height_;
    if (gradient) pc.sampleCount = kept_.samples, pc.frameSeed = kept_.seed, pc.gradientPhase = 2;
    if (low && accumulating_) pc.gradientPhase = 1 + uint32_t(framesKept_ % 4);
    pc.rsmResolution = settings_.resolution;
    pc.bilinearVpls = settings_.bilinearVpls ? 1u : 0u;
    pc.normalThreshold = settings_.normalThreshold;
    pc.distanceThreshold = settings_.distanceThreshold;
    pc.radius = settings_.radius;
    pc.visibility = visibilityMode();
    pc.visibilityRays = settings_.visibilityRays;
    pc.paperWeights = settings_.weights == RsmWeights::Paper ? 1u : 0u;
    pc.lanesPerReceiver = lanes(mode);
    pc.farByFlux = drawsByFlux() ? 1u : 0u;
    pc.shiftedRadii = shiftedRadii(settings_) ? 1u : 0u;
    pc.visibilityPoints = settings_.visibilityPoints;
    return pc;
}

// Samples per receiver this frame: a share while the history accumulates, all of them when it starts.
uint32_t RsmGather::sampleCount() const {
    return accumulating_ ? std::min(settings_.frameSamples, settings_.samples) : settings_.samples;
}

// Radii shifted per receiver: asked for, or implied by voxel visibility (its pipeline always shifts).
bool RsmGather::shiftedRadii(const RsmSettings& s) {
    return s.radii == RsmRadii::Shifted || s.visibility == RsmVisibility::Voxels;
}

// The voxel pipeline keeps one invocation per receiver: its visible share is a ratio per receiver.
uint32_t RsmGather::lanes(uint32_t mode) const {
    return settings_.visibility == RsmVisibility::Voxels ? 1u : lanesPerReceiver(mode);
}

uint32_t RsmGather::visibilityMode() const {
    switch (settings_.visibility) {
        case RsmVisibility::None: return RSM_VISIBILITY_NONE;
        case RsmVisibility::Depth: return RSM_VISIBILITY_DEPTH;
        case RsmVisibility::Voxels: return RSM_VISIBILITY_VOXELS;
        case RsmVisibility::Views: return RSM_VISIBILITY_VIEWS;
    }
    return RSM_VISIBILITY_NONE;
}

// The far half by flux: drawn this frame, and the unbiased mixture (the paper's disc has no far half).
bool RsmGather::drawsByFlux() const { return fluxDraws_ && settings_.weights == RsmWeights::Unbiased; }

void RsmGather::addGather(FrameGraph& graph, const char* name, uint32_t mode, ImageHandle out, uint32_t layers) {
    const VkSampler point = pointSampler_.handle();
    const vk::ComputeKernel& kernel = drawsByFlux() && gatherFlux_.pipeline.handle() ? gatherFlux_ : gather_;
    PassBuilder pass = graph.pass(name);
    pass.pipeline(kernel.pipeline)
        .uniform(RSM_GATHER_FRAME, graph.buffer("frame"))
        .sampled(RSM_GATHER_GBUFFER_NORMAL, graph.image("gbuffer.normal"), point)
        .sampled(RSM_GATHER_GBUFFER_DEPTH, graph.image("gbuffer.depth"), point)
        .sampled(RSM_GATHER_RSM_DEPTH, graph.image("rsm.depth"), point)
        .sampled(RSM_GATHER_RSM_NORMAL, graph.image("rsm.normal"), point)
        .sampled(RSM_GATHER_RSM_FLUX, graph.image("rsm.flux"), point)
        .storageBuffer(RSM_GATHER_LAYERS, graph.buffer("rsm.layers"))
        .storageBuffer(RSM_GATHER_SAMPLES, graph.import(samples_.current()))
        .storageImage(RSM_GATHER_IRRADIANCE, out)
        .storageBuffer(RSM_GATHER_PIXEL_LIST, graph.import(pixelList_))
        .storageBuffer(RSM_GATHER_OCCUPANCY,
                       graph.hasBuffer("occupancy") ? graph.buffer("occupancy") : graph.import(emptyBuffer_))
        .sampled(RSM_GATHER_VPLS, graph.image("rsm.vpls"), point)
        .storageBuffer(RSM_GATHER_FLUX_DRAWS, fluxDraws_ ? graph.buffer("rsm.flux-draws") : graph.import(emptyBuffer_));
    if (mode == RSM_GATHER_LOWRES && accumulating_)  // keeps this frame's gradient samples
        pass.storageBuffer(RSM_GATHER_GRADIENT_SAMPLES, graph.import(gradientSamples_[keep_]), Use::StorageWrite);
    else if (mode == RSM_GATHER_GRADIENT)  // gathers last frame's again
        pass.storageBuffer(RSM_GATHER_GRADIENT_SAMPLES, graph.import(gradientSamples_[1 - keep_]));
    else
        pass.storageBuffer(RSM_GATHER_GRADIENT_SAMPLES, graph.import(emptyBuffer_));
    const BufferHandle args = mode == RSM_GATHER_LIST ? graph.import(dispatchArgs_) : BufferHandle{};
    if (args) pass.use(args, Use::IndirectArgs);
    const gpu::RsmPush pc = constants(mode, layers);
    pass.record([&kernel, pc, args](PassContext& c) {
        kernel.pipeline.push(c.cmd, pc);
        if (args) vkCmdDispatchIndirect(c.cmd, c.buffer(args).handle(), 0);
        else vkCmdDispatch(c.cmd, vk::divUp(pc.width, 8), vk::divUp(pc.height, 8 / pc.lanesPerReceiver), 1);
    });
}

void RsmGather::addTo(FrameGraph& graph, uint32_t layers, uint32_t slot, const GiAccumulation* accumulation) {
    fluxDraws_ = graph.hasBuffer("rsm.flux-draws");
    accumulating_ = accumulation && accumulation->accumulating;
    frameSeed_ = accumulating_ ? accumulation->frameSeed : 0u;
    const std::vector<glm::vec4>& pattern = accumulating_ ? framePattern_ : pattern_;
    samples_.select(slot);
    samples_.write(pattern.data(), pattern.size() * sizeof(glm::vec4));
    const ImageHandle irradiance = graph.import(irradiance_);
    graph.publish("gi.irradiance", irradiance);
    if (settings_.mode == RsmMode::Full || settings_.mode == RsmMode::AllTexels) {
        const uint32_t mode = settings_.mode == RsmMode::Full ? RSM_GATHER_FULL : RSM_GATHER_ALL_TEXELS;
        addGather(graph, "rsm.gather", mode, irradiance, layers);
        return;
    }
    const ImageHandle low = graph.import(low_);
    const BufferHandle list = graph.import(pixelList_), args = graph.import(dispatchArgs_);
    const uint32_t samples = sampleCount();
    if (accumulating_ && kept_.valid && kept_.samples == samples) addGradient(graph, layers);
    addGather(graph, "rsm.gather-lowres", RSM_GATHER_LOWRES, low, layers);
    kept_ = {accumulating_, frameSeed_, samples};
    if (accumulating_) keep_ = 1 - keep_, ++framesKept_;

    graph.pass("rsm.clear-list", PassKind::Transfer).use(list, Use::TransferDst).record([list](PassContext& c) {
        vkCmdFillBuffer(c.cmd, c.buffer(list).handle(), 0, 16, 0);
    });

    const VkSampler point = pointSampler_.handle();
    const gpu::RsmPush pc = constants(RSM_GATHER_LOWRES, layers);  // sizes = the low-res grid
    graph.pass("rsm.interpolate")
        .pipeline(interpolate_.pipeline)
        .uniform(RSM_INTERPOLATE_FRAME, graph.buffer("frame"))
        .sampled(RSM_INTERPOLATE_GBUFFER_NORMAL, graph.image("gbuffer.normal"), point)
        .sampled(RSM_INTERPOLATE_GBUFFER_DEPTH, graph.image("gbuffer.depth"), point)
        .sampled(RSM_INTERPOLATE_LOW_IRRADIANCE, low, point)
        .storageImage(RSM_INTERPOLATE_IRRADIANCE, irradiance)
        .storageBuffer(RSM_INTERPOLATE_PIXEL_LIST, list, Use::StorageWrite)
        .storageBuffer(RSM_INTERPOLATE_LAYERS, graph.buffer("rsm.layers"))
        .record([this, pc](PassContext& c) {
            interpolate_.pipeline.push(c.cmd, pc);
            vkCmdDispatch(c.cmd, vk::divUp(width_, 8), vk::divUp(height_, 8), 1);
        });

    graph.pass("rsm.fallback-args")
        .pipeline(args_.pipeline)
        .storageBuffer(0, list, Use::StorageRead)
        .storageBuffer(1, args, Use::StorageWrite)
        .record([this](PassContext& c) {
            args_.pipeline.push(c.cmd, 64 / lanes(RSM_GATHER_LIST));  // receivers per gather workgroup
            vkCmdDispatch(c.cmd, 1, 1, 1);
        });
    addGather(graph, "rsm.gather-fallback", RSM_GATHER_LIST, irradiance, layers);
}

// Temporal gradients: last frame's kept receivers gathered again with their pattern (its seed) and this
// frame's RSM, into the cleared change image (Schied et al. 2018, "Gradient Estimation for Real-Time
// Adaptive Temporal Filtering"). The same pattern on the same point gives the same sum while the light
// stands still, so the difference is the light's change and not the pattern's noise.
void RsmGather::addGradient(FrameGraph& graph, uint32_t layers) {
    const ImageHandle change = graph.import(change_);
    graph.pass("rsm.clear-change", PassKind::Transfer).use(change, Use::TransferDst).record([change](PassContext& c) {
        const VkClearColorValue zero{};
        const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(c.cmd, c.image(change).handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &all);
    });
    addGather(graph, "rsm.gradient", RSM_GATHER_GRADIENT, change, layers);
    graph.publish(names::kGiChangeImage, change);
}

double RsmGather::fallbackFraction() {
    if (settings_.mode != RsmMode::Interpolated) return 0.0;
    std::vector<uint8_t> header = cmd_.readBuffer(pixelList_, 4);
    uint32_t count = 0;
    std::memcpy(&count, header.data(), 4);
    return double(count) / (double(width_) * height_);
}

}  // namespace penumbra
