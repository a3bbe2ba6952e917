#include "renderer/renderer.h"

#include <algorithm>
#include <chrono>
#include <cstring>

#include <fmt/format.h>

#include "core/raster_mode.h"


namespace penumbra {
namespace {

// The light without its shadow fields (ShadowMapPass::fillGpuLight adds them).
gpu::GpuLight toGpu(const Light& l) {
    gpu::GpuLight g{};
    g.position = l.position;
    g.type = static_cast<uint32_t>(l.type);
    g.direction = glm::normalize(l.direction);
    g.range = l.range;
    g.radiance = l.color * l.intensity;
    g.shadowIndex = NO_SHADOW;
    g.cosInner = std::cos(l.innerConeAngle);
    g.cosOuter = std::cos(l.outerConeAngle);
    g.shadowViewProj = glm::mat4(1.0f);
    return g;
}

// Far plane that encloses the whole scene from the eye.
// Distance from the eye to the farthest corner of the scene's bounds (at least 1).
float boundsFar(const Camera& c, const Bounds& b) {
    float far = 1.0f;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner{(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
        far = std::max(far, glm::length(corner - c.eye));
    }
    return far;
}

float sceneFar(const Camera& c, const Bounds& b) { return c.zfar > 0.0f ? c.zfar : boundsFar(c, b) * 1.05f; }

// What of a light sizes or structures the shadow resources (its position, direction, colour and
// intensity are per-frame values).
bool sameLayout(const Light& a, const Light& b) {
    return a.type == b.type && a.castsShadow == b.castsShadow && a.shadowFilter == b.shadowFilter;
}

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

// One frame in flight: its command buffer, fence and timestamp pool.
struct Renderer::FrameSlot {
    vk::Context& ctx;
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    vk::GpuTimer timer;
    uint32_t index = 0;  // its copy in every BufferRing
    bool pending = false;
    bool probed = false;  // the frame wrote the pixel probe
    FrameTimings timings;

    explicit FrameSlot(vk::Context& c) : ctx(c), timer(c, 512) {
        VkCommandPoolCreateInfo ci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        ci.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
        ci.queueFamilyIndex = ctx.queueFamily();
        VK_CHECK(vkCreateCommandPool(ctx.device(), &ci, nullptr, &pool));
        VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        ai.commandPool = pool;
        ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        ai.commandBufferCount = 1;
        VK_CHECK(vkAllocateCommandBuffers(ctx.device(), &ai, &cmd));
        VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VK_CHECK(vkCreateFence(ctx.device(), &fi, nullptr, &fence));
    }
    ~FrameSlot() {
        if (pending) vkWaitForFences(ctx.device(), 1, &fence, VK_TRUE, UINT64_MAX);
        vkDestroyFence(ctx.device(), fence, nullptr);
        vkDestroyCommandPool(ctx.device(), pool, nullptr);
    }
};

Renderer::Renderer(vk::Context& ctx, GpuScene& scene, const RenderSettings& settings, uint32_t framesInFlight)
    : ctx_(ctx), scene_(scene), settings_(settings), alloc_(ctx), cmd_(alloc_),
      framesInFlight_(std::clamp(framesInFlight, 1u, vk::kMaxFramesInFlight)), graph_(ctx) {
    init();
}

Renderer::Renderer(vk::Context& ctx, const Scene& scene, const RenderSettings& settings)
    : ownedScene_(std::make_unique<GpuScene>(ctx, scene)), ctx_(ctx), scene_(*ownedScene_), settings_(settings),
      alloc_(ctx), cmd_(alloc_), framesInFlight_(1), graph_(ctx) {
    init();
}

void Renderer::init() {
    settings_ = resolved(settings_);
    if (settings_.width == 0 || settings_.height == 0 || settings_.width > 16384 || settings_.height > 16384)
        throw vk::VulkanError(fmt::format("image size {}x{} is out of range (1..16384)", settings_.width,
                                          settings_.height));
    for (uint32_t i = 0; i < framesInFlight_; ++i) {
        slots_.push_back(std::make_unique<FrameSlot>(ctx_));
        slots_.back()->index = i;
    }
    drawLayout_ = vk::DescriptorLayout(ctx_, SceneGpu::drawSetBindings());
    frame_ = vk::BufferRing(alloc_, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, "frame");
    const size_t instances = scene_.meshes().restTransforms().size();
    instances_ = vk::BufferRing(alloc_, sizeof(gpu::GpuInstance) * std::max<size_t>(instances, 1),
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "instances");
    probe_ = vk::BufferRing(alloc_, sizeof(gpu::PixelProbe), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "probe");
    lights_ = scene_.scene().lights;
    build(kPartShadow | kPartCamera | kPartGi | kPartDsm);
}

Renderer::~Renderer() {
    // The frames in flight finish before their resources go (FrameSlot waits for its fence).
    slots_.clear();
}

// Re-creates the techniques whose registry entry names a part in `parts`, and builds or drops those
// the settings now enable or disable (the caller made sure no frame in flight uses them). Shadow
// maps, deep shadow maps and GI depend on one another's layout: any of the first two rebuilds all
// three, and the camera's size rebuilds GI.
void Renderer::build(uint32_t parts) {
    if (parts & (kPartShadow | kPartDsm)) parts |= kPartShadow | kPartDsm | kPartGi;
    if (parts & kPartCamera) parts |= kPartGi;
    warnings_.clear();
    core_ = settings_.core(computeRasterFor(settings_.shadow.raster, ctx_.properties()));
    const TechniqueRegistry& registry = TechniqueRegistry::instance();
    std::vector<std::unique_ptr<Technique>> kept(registry.entries().size());
    for (Built& b : techniques_) {
        const size_t i = size_t(b.entry - registry.entries().data());
        if ((b.entry->adjustParts & parts) && !(b.entry->parts & parts)) b.entry->adjust(*b.technique, settings_, lights_);
        if (!(b.entry->parts & parts) && b.entry->enabled(settings_)) kept[i] = std::move(b.technique);
    }
    // Destroyed in reverse frame order (consumers before producers), then built anew in build order.
    while (!techniques_.empty()) techniques_.pop_back();
    const TechniqueBuild context{alloc_, cmd_, scene_, drawLayout_.handle(), lights_, core_, board_, warnings_};
    for (const TechniqueEntry* e : registry.buildOrder()) {
        const size_t i = size_t(e - registry.entries().data());
        if (!kept[i] && e->enabled(settings_)) kept[i] = e->create(context, settings_);
    }
    for (size_t i = 0; i < kept.size(); ++i)
        if (kept[i]) techniques_.push_back({&registry.entries()[i], std::move(kept[i])});
    if (parts & (kPartShadow | kPartDsm)) {
        views_ = vk::BufferRing(alloc_, sizeof(glm::mat4) * (1 + shadowLayerCount()), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                "views");
        lightBuffer_ = vk::BufferRing(alloc_, sizeof(gpu::GpuLight) * std::max<size_t>(lights_.size(), 1),
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "lights");
    }
    graph_.forgetStates();
}

uint32_t Renderer::shadowLayerCount() const {
    const ShadowLayers* layers = board_.get(names::kShadowLayers);
    return layers ? uint32_t(layers->layers.size()) : 0u;
}

RenderSettings Renderer::resolved(const RenderSettings& s) const { return resolveForScene(s, scene_.scene()); }

SettingsChange Renderer::apply(const RenderSettings& requested) {
    const RenderSettings settings = resolved(requested);
    const SettingsDiff diff = diffSettings(settings_, settings);
    if (diff.change == SettingsChange::None) return diff.change;
    if (diff.change != SettingsChange::PerFrame) finish();  // what is rebuilt may be in use by the frames in flight
    settings_ = settings;
    if (diff.change != SettingsChange::PerFrame && diff.parts != kPartNone) build(diff.parts);
    core_ = settings_.core(core_.computeRaster);
    for (const Built& b : techniques_) {
        b.technique->applyPerFrame(core_);
        if (b.entry->apply) b.entry->apply(*b.technique, settings_);
    }
    return diff.change;
}

bool Renderer::layoutChanged(const std::vector<Light>& lights) const {
    if (lights.size() != lights_.size()) return true;
    for (size_t i = 0; i < lights.size(); ++i)
        if (!sameLayout(lights[i], lights_[i])) return true;
    return false;
}

Renderer::FrameSlot& Renderer::acquireSlot() {
    FrameSlot& slot = *slots_[frameIndex_ % slots_.size()];
    if (slot.pending) collect(slot);
    return slot;
}

// Waits for the slot's last frame and keeps its timings.
void Renderer::collect(FrameSlot& slot) {
    VK_CHECK(vkWaitForFences(ctx_.device(), 1, &slot.fence, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(ctx_.device(), 1, &slot.fence));
    slot.pending = false;
    std::vector<vk::ScopeTiming> scopes = slot.timer.results();
    if (!scopes.empty()) {  // scope 0 spans the whole frame
        slot.timings.gpuMs = scopes.front().ms;
        slot.timings.passes.assign(scopes.begin() + 1, scopes.end());
    }
    if (slot.timings.frame >= lastTimings_.frame) lastTimings_ = slot.timings;
    if (slot.probed) lastProbe_ = *probe_.at(slot.index).as<gpu::PixelProbe>();
    completed_.push_back(slot.timings);
    if (completed_.size() > 4096) completed_.erase(completed_.begin(), completed_.begin() + 2048);
}

void Renderer::finish() {
    // Oldest first, so that completed_ stays in frame order.
    std::vector<FrameSlot*> pending;
    for (auto& s : slots_)
        if (s->pending) pending.push_back(s.get());
    std::sort(pending.begin(), pending.end(),
              [](const FrameSlot* a, const FrameSlot* b) { return a->timings.frame < b->timings.frame; });
    for (FrameSlot* s : pending) collect(*s);
}

std::vector<FrameTimings> Renderer::takeCompletedTimings() {
    std::vector<FrameTimings> out;
    out.swap(completed_);
    return out;
}

void Renderer::writeFrameData(const FrameInputs& in) {
    const Camera& camera = in.camera;
    const float aspect = float(settings_.width) / float(settings_.height);
    gpu::FrameUniforms f{};
    f.viewProj = cameraViewProj(camera, aspect, zfar_);
    f.invViewProj = glm::inverse(f.viewProj);
    const std::optional<FrameInputs::Previous>& previous = in.previous ? in.previous : lastFrame_;
    f.previousViewProj = previous ? cameraViewProj(previous->camera, aspect, zfar_) : f.viewProj;
    f.reprojection = glm::mat4(glm::dmat4(f.previousViewProj) * glm::inverse(glm::dmat4(f.viewProj)));
    f.eye = camera.eye;
    f.farPlane = zfar_;
    f.width = settings_.width;
    f.height = settings_.height;
    f.lightCount = uint32_t(in.lights.size());
    f.aov = uint32_t(settings_.aov);
    const glm::uvec2 probe = in.probePixel.value_or(glm::uvec2(PROBE_OFF));
    const bool ids = settings_.cameraPath == CameraPath::Visibility;
    bool indirect = false;  // a technique contributes indirect irradiance
    for (const Built& b : techniques_) indirect |= b.technique->contributesIrradiance();
    f.giValid = indirect ? 1u : 0u;
    f.visibilityIds = ids ? 1u : 0u;
    f.probeX = probe.x;
    f.probeY = probe.y;
    f.pixelSpread = 2.0f * std::tan(0.5f * camera.fovy) / float(settings_.height);
    frame_.write(&f, sizeof(f));
    frameConstants_ = f;

    const ShadowLayers* shadow = board_.get(names::kShadowLayers);
    std::vector<glm::mat4> views{f.viewProj};
    if (shadow)
        for (const ShadowLayerView& l : shadow->layers) views.push_back(l.projection.viewProj);
    views_.write(views.data(), views.size() * sizeof(glm::mat4));

    std::vector<gpu::GpuLight> lights;
    for (uint32_t i = 0; i < in.lights.size(); ++i) {
        lights.push_back(toGpu(in.lights[i]));
        if (shadow && shadow->fillGpuLight) shadow->fillGpuLight(i, lights.back());
    }
    if (!lights.empty()) lightBuffer_.write(lights.data(), lights.size() * sizeof(gpu::GpuLight));
    const std::vector<glm::mat4>& transforms = frameInstances(in);
    const std::vector<gpu::GpuInstance> rows =
        scene_.meshes().instanceRows(transforms, previous ? previous->instances : std::vector<glm::mat4>{});
    if (!rows.empty()) instances_.write(rows.data(), rows.size() * sizeof(gpu::GpuInstance));
    lastFrame_ = FrameInputs::Previous{camera, transforms};
}

const std::vector<glm::mat4>& Renderer::frameInstances(const FrameInputs& in) const {
    const std::vector<glm::mat4>& rest = scene_.meshes().restTransforms();
    return in.instances.size() == rest.size() ? in.instances : rest;
}

void Renderer::recordFrame(FrameSlot& slot, const FrameInputs& in, const FrameHooks& hooks) {
    const uint32_t index = uint32_t(frameIndex_ % slots_.size());
    for (vk::BufferRing* r : {&frame_, &views_, &lightBuffer_, &instances_, &probe_}) r->select(index);
    const std::vector<glm::mat4>& transforms = frameInstances(in);
    scene_.meshes().setFrameInstances(transforms);
    // Casters moved since the last frame: cached shadow layers show them where they were.
    if (!lastFrame_ || transforms != lastFrame_->instances) invalidateCaches(CacheDrop::Moved);
    zfar_ = sceneFar(in.camera, scene_.scene().bounds);
    graph_.clear();
    graph_.setOverlap(settings_.overlapPasses && !passScopes_);
    graph_.setPassTimings(passScopes_);
    const float aspect = float(settings_.width) / float(settings_.height);
    const float depthFar = std::min(zfar_, boundsFar(in.camera, scene_.scene().bounds));
    FrameContext context{graph_, board_, index, in.camera, in.lights, core_, aspect, zfar_, depthFar, frameConstants_};
    for (const Built& b : techniques_) b.technique->update(context);
    writeFrameData(in);
    graph_.publish(names::kFrame, graph_.import(frame_.current()));
    graph_.publish(names::kViews, graph_.import(views_.current()));
    graph_.publish(names::kLights, graph_.import(lightBuffer_.current()));
    graph_.publish(names::kInstances, graph_.import(instances_.current()));
    graph_.publish(names::kDrawnTriangles, graph_.import(scene_.meshes().drawnTriangles()));
    graph_.publish(names::kProbe, graph_.import(probe_.current()));
    for (const Built& b : techniques_) b.technique->addPasses(context);
    for (const Built& b : techniques_) b.technique->addCompositePasses(context);
    for (const Built& b : techniques_) b.technique->addOutputPasses(context);

    VK_CHECK(vkResetCommandPool(ctx_.device(), slot.pool, VK_COMMAND_POOL_RESET_RELEASE_RESOURCES_BIT));
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(slot.cmd, &bi));
    slot.timer.reset();
    const uint32_t whole = slot.timer.begin(slot.cmd, "frame");
    graph_.execute(slot.cmd, &slot.timer);
    slot.timer.end(slot.cmd, whole);
    slot.probed = in.probePixel && in.probePixel->x < settings_.width && in.probePixel->y < settings_.height;
    if (slot.probed)  // the probe's shader write, made visible to the host read after the fence
        vk::memoryBarrier(slot.cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    if (hooks.record) hooks.record(slot.cmd, ldr());
    VK_CHECK(vkEndCommandBuffer(slot.cmd));
}

void Renderer::submit(const FrameInputs& in, const FrameHooks& hooks) {
    if (layoutChanged(in.lights)) {
        finish();
        lights_ = in.lights;
        build(kPartShadow | kPartDsm | kPartGi);
    }
    FrameSlot& slot = acquireSlot();
    const auto t0 = std::chrono::steady_clock::now();  // CPU time: recording and submission only
    recordFrame(slot, in, hooks);

    VkCommandBufferSubmitInfo cb{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cb.commandBuffer = slot.cmd;
    VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    wait.semaphore = hooks.wait;
    wait.stageMask = hooks.waitStage;
    VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signal.semaphore = hooks.signal;
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    si.commandBufferInfoCount = 1;
    si.pCommandBufferInfos = &cb;
    si.waitSemaphoreInfoCount = hooks.wait ? 1 : 0;
    si.pWaitSemaphoreInfos = &wait;
    si.signalSemaphoreInfoCount = hooks.signal ? 1 : 0;
    si.pSignalSemaphoreInfos = &signal;
    VK_CHECK(vkQueueSubmit2(ctx_.queue(), 1, &si, slot.fence));
    slot.pending = true;
    slot.timings = {};
    slot.timings.frame = frameIndex_++;
    slot.timings.cpuMs = msSince(t0);
}

void Renderer::render(const Camera& camera) { render(FrameInputs{camera, scene_.scene().lights}); }

std::vector<float> Renderer::readHdr() {
    finish();
    std::vector<uint8_t> bytes = cmd_.readImage(board_.require(names::kHdrImage), 16);
    std::vector<float> out(bytes.size() / 4);
    std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
}

std::vector<uint8_t> Renderer::readLdr() {
    finish();
    return cmd_.readImage(ldr(), 4);
}

}  // namespace penumbra
