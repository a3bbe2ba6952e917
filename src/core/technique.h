// The interface every technique of a frame implements (camera G-buffer, shadow maps, deep shadow
// maps, RSM, LPV, lighting, and any registered from outside): a per-frame host update, then its
// passes, declared on the frame graph in three stages. Techniques read each other's outputs by
// typed name (core/names.h: GPU resources from the frame graph, host values from the blackboard)
// and publish their own; none includes another's header. Each keeps its own settings struct: what
// all share is CoreSettings.
#pragma once
#include <string>
#include <vector>

#include "core/blackboard.h"
#include "core/core_settings.h"
#include "core/frame_graph.h"
#include "scene/scene.h"
#include "shared/types.h"

namespace penumbra {

class GpuScene;

// What a technique is built from: the device, the long-lived scene, the frame's lights and the
// blackboard, where techniques built before it published what it may need at build time.
// Why a technique's frame-to-frame caches are dropped (Technique::invalidateCaches).
enum class CacheDrop {
    Moved,  // casters moved (instance transforms changed)
    All,    // cold frames asked for: the next frame runs every pass
};

struct TechniqueBuild {
    vk::Allocator& alloc;
    vk::CommandContext& cmd;
    GpuScene& scene;
    VkDescriptorSetLayout drawLayout;  // set 0 of draws over the scene (SceneGpu::drawSetBindings)
    const std::vector<Light>& lights;
    const CoreSettings& core;
    Blackboard& board;
    std::vector<std::string>& warnings;  // things the user should know, collected once
};

struct FrameContext {
    FrameGraph& graph;
    Blackboard& board;
    uint32_t slot;                   // frame-in-flight slot: selects host-written ring copies
    const Camera& camera;
    const std::vector<Light>& lights;
    const CoreSettings& core;
    float aspect, zfar;
    float sceneFar;  // distance to the scene bounds' farthest corner: the depth AOV's PNG scale
    const gpu::FrameUniforms& uniforms;  // valid in addPasses (written after every update)
};

class Technique {
public:
    virtual ~Technique() = default;
    virtual const char* name() const = 0;
    // Host-side per-frame work: tables into this slot's ring copies, projections (before the frame's
    // views buffer is written).
    virtual void update(const FrameContext&) {}
    // The frame's passes, in three stages that each run over every technique in order: the scene
    // passes up to the lighting, passes that rewrite "hdr" after it (translucency), and the output
    // (debug views, tone map).
    virtual void addPasses(const FrameContext& frame) = 0;
    virtual void addCompositePasses(const FrameContext&) {}
    virtual void addOutputPasses(const FrameContext&) {}
    // Takes per-frame values of new core settings: no allocation. (Its own settings come through
    // the registry's apply.)
    virtual void applyPerFrame(const CoreSettings&) {}
    // Whether it contributes indirect irradiance (names::kIrradianceContribution) to the frames.
    virtual bool contributesIrradiance() const { return false; }
    // Casters moved (Moved) or the caller asked for cold frames (All): drop what frames keep for the
    // next. A technique that can tell what moved may keep the rest on Moved.
    virtual void invalidateCaches(CacheDrop) {}
};

}  // namespace penumbra
