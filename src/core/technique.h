// The interface every technique of a frame implements (camera G-buffer, shadow maps, deep shadow
// maps, RSM, LPV, lighting): a per-frame host update, then its passes, declared on the frame graph.
// Techniques read each other's outputs by name from the graph (FrameGraph::image/buffer) and publish
// their own; none includes another's header.
#pragma once
#include <vector>

#include "core/frame_graph.h"
#include "renderer/render_settings.h"
#include "scene/scene.h"
#include "shared/types.h"

namespace penumbra {

struct FrameContext {
    FrameGraph& graph;
    uint32_t slot;                   // frame-in-flight slot: selects host-written ring copies
    const Camera& camera;
    const std::vector<Light>& lights;
    const RenderSettings& settings;
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
    // Declares this frame's passes.
    virtual void addPasses(const FrameContext& frame) = 0;
    // Takes per-frame values of new settings (renderer/settings_change.h): no allocation.
    virtual void applyPerFrame(const RenderSettings&) {}
};

}  // namespace penumbra
