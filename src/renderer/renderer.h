// The frame pipeline: the techniques the registry (renderer/technique_registry.h) builds for the
// settings, in its frame order (G-buffer -> shadow maps -> deep shadow maps -> RSM (gather or LPV)
// -> deferred lighting -> translucency -> tone map for the built-in ones), each behind the one
// Technique interface declaring its passes on a FrameGraph, over a long-lived GpuScene. Frames in flight (2 by default): per-slot command buffers, fences, timestamp pools and
// host-written buffers; the loop never waits for the device to idle. Settings changes rebuild only
// what they invalidate (renderer/settings_change.h).
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/blackboard.h"
#include "core/frame_graph.h"
#include "core/gpu_scene.h"
#include "core/names.h"
#include "core/technique.h"
#include "renderer/render_settings.h"
#include "renderer/settings_change.h"
#include "renderer/technique_registry.h"

namespace penumbra {

// What one frame shows besides the settings: the camera, the lights (moved, added or removed
// freely: a changed light count or shadow layout re-creates the shadow resources, nothing else) and
// the world transform of every Scene::instances entry (empty: the rest pose). Moving things touches
// only these per-frame buffers: geometry is never uploaded again.
struct FrameInputs {
    Camera camera;
    std::vector<Light> lights;
    std::vector<glm::mat4> instances;
    std::optional<glm::uvec2> probePixel;  // every AOV at this pixel, read back with the frame (probe())
    // The previous frame's camera and instance transforms, for the velocity AOV; without it the
    // renderer takes the frame it rendered last (the first frame: this one, so nothing moves).
    struct Previous {
        Camera camera;
        std::vector<glm::mat4> instances;
    };
    std::optional<Previous> previous;
};

// Recorded into a frame's command buffer after its last pass (a viewer's present blit and UI), with
// the semaphores the frame's submission waits on and signals.
struct FrameHooks {
    std::function<void(VkCommandBuffer, vk::Image& ldr)> record;
    VkSemaphore wait = VK_NULL_HANDLE;
    VkPipelineStageFlags2 waitStage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkSemaphore signal = VK_NULL_HANDLE;
};

// GPU timings of one completed frame: per pass, and the whole frame between two timestamps.
struct FrameTimings {
    uint64_t frame = 0;                  // index of the frame they belong to
    std::vector<vk::ScopeTiming> passes;
    double gpuMs = 0.0;                  // timestamp before the first pass to after the last
    double cpuMs = 0.0;                  // recording + submission on the host
};

class Renderer {
public:
    static constexpr uint32_t kDefaultFramesInFlight = 2;
    // The frame pipeline for `settings` over a long-lived scene (uploaded once, shared).
    Renderer(vk::Context& ctx, GpuScene& scene, const RenderSettings& settings,
             uint32_t framesInFlight = kDefaultFramesInFlight);
    // One-shot form (tests, single images): uploads its own copy of `scene`.
    Renderer(vk::Context& ctx, const Scene& scene, const RenderSettings& settings);
    ~Renderer();

    // Takes new settings; returns the largest class of what changed. Per-frame values apply to the
    // next frame; structure and size changes wait for the frames in flight, then rebuild what they own.
    // An Auto choice is resolved for the scene (settings() holds what it stands for).
    SettingsChange apply(const RenderSettings& settings);

    // Records and submits one frame, waiting only for the frame slot it reuses (frames in flight).
    void submit(const FrameInputs& inputs, const FrameHooks& hooks = {});
    // Waits for every frame in flight (their fences) and collects their timings.
    void finish();
    // One frame with the scene's own lights, waited for (render, tests).
    void render(const Camera& camera);
    void render(const FrameInputs& inputs) { submit(inputs); finish(); }

    // A timestamp scope per pass from the next frame on (off by default: the frame's scope only).
    // A timestamp waits for the work before it, so with scopes the passes run one after another, in
    // the order added, as the scopes' times add up to the frame's; without them the frame graph runs
    // independent passes together (RenderSettings::overlapPasses).
    void setPassScopes(bool on) { passScopes_ = on; }
    // Per-pass GPU times of the newest completed frame (empty without pass scopes).
    const std::vector<vk::ScopeTiming>& timings() const { return lastTimings_.passes; }
    const FrameTimings& frameTimings() const { return lastTimings_; }
    // Every completed frame's timings since the last call (bench), oldest first.
    std::vector<FrameTimings> takeCompletedTimings();
    uint64_t framesSubmitted() const { return frameIndex_; }
    // Every AOV at FrameInputs::probePixel of the newest completed frame that asked for one.
    const std::optional<gpu::PixelProbe>& probe() const { return lastProbe_; }

    std::vector<float> readHdr();     // RGBA32F, row-major, top row first (after finish())
    std::vector<uint8_t> readLdr();   // RGBA8 (sRGB-encoded for radiance and colour AOVs)
    std::string describePasses() const { return graph_.describe(); }
    const std::vector<PassDesc>& passes() const { return graph_.passes(); }
    // Things the user should know (e.g. lights rendered without shadows), collected once.
    const std::vector<std::string>& warnings() const { return warnings_; }
    vk::Allocator& allocator() { return alloc_; }
    const RenderSettings& settings() const { return settings_; }
    const Scene& scene() const { return scene_.scene(); }
    GpuScene& gpuScene() { return scene_; }
    // The AOV of the next frames (a per-frame value).
    void setAov(Aov aov) { settings_.aov = core_.aov = aov; }
    // The built technique of type T (null when the settings did not build one): internals for
    // tests and statistics. The caller includes T's header; the renderer knows only Technique.
    template <class T>
    T* find() const {
        for (const Built& b : techniques_)
            if (T* t = dynamic_cast<T*>(b.technique.get())) return t;
        return nullptr;
    }
    // Host-side values the techniques published (core/names.h), e.g. names::kShadowLayers.
    Blackboard& blackboard() { return board_; }
    // Drops what frames keep for the next (cached shadow layers): the next frame runs every pass.
    // Frames whose instance transforms differ from the last frame's call it themselves; call it when
    // casters move otherwise (edited geometry) or to time cold frames.
    void invalidateCaches(CacheDrop why = CacheDrop::All) {
        for (const Built& b : techniques_) b.technique->invalidateCaches(why);
    }
    vk::CommandContext& commands() { return cmd_; }
    const gpu::FrameUniforms& frameUniforms() const { return frameConstants_; }
    vk::Image& ldr() { return board_.require(names::kLdrImage); }

private:
    struct FrameSlot;
    void init();
    RenderSettings resolved(const RenderSettings& s) const;  // every Auto choice made for the scene
    void build(uint32_t parts);
    bool layoutChanged(const std::vector<Light>& lights) const;
    FrameSlot& acquireSlot();
    void writeFrameData(const FrameInputs& in);
    const std::vector<glm::mat4>& frameInstances(const FrameInputs& in) const;
    void recordFrame(FrameSlot& slot, const FrameInputs& in, const FrameHooks& hooks);
    void collect(FrameSlot& slot);
    uint32_t shadowLayerCount() const;
    struct Built {
        const TechniqueEntry* entry;
        std::unique_ptr<Technique> technique;
    };

    std::unique_ptr<GpuScene> ownedScene_;  // the one-shot form's
    vk::Context& ctx_;
    GpuScene& scene_;
    RenderSettings settings_;
    vk::Allocator alloc_;
    vk::CommandContext cmd_;
    uint32_t framesInFlight_;
    std::vector<std::unique_ptr<FrameSlot>> slots_;
    uint64_t frameIndex_ = 0;
    std::vector<Light> lights_;  // the lights the shadow layout was built for
    vk::DescriptorLayout drawLayout_;
    vk::BufferRing frame_, views_, lightBuffer_, instances_, probe_;
    // The camera and instance transforms last rendered: the velocity's previous frame, and what cached
    // shadow layers were drawn with.
    std::optional<FrameInputs::Previous> lastFrame_;
    Blackboard board_;  // declared before the techniques: they drop their entries when they go
    std::vector<Built> techniques_;  // frame order
    CoreSettings core_;
    FrameGraph graph_;
    FrameTimings lastTimings_;
    bool passScopes_ = false;  // setPassScopes()
    std::optional<gpu::PixelProbe> lastProbe_;
    std::vector<FrameTimings> completed_;
    std::vector<std::string> warnings_;
    float zfar_ = 1.0f;
    gpu::FrameUniforms frameConstants_{};
};

}  // namespace penumbra
