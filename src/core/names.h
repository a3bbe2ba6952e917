// The contract between techniques: the names under which they publish what others read, each with
// its type. A technique reads another's output only through these (or through names its own folder
// declares for its own passes), never through the other's class.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/blackboard.h"
#include "core/light_space.h"
#include "shared/types.h"
#include "vk/resources.h"

namespace penumbra {

class FrameGraph;

// One layer of "shadow.map": the light it belongs to and its projection this frame (views row
// 1 + its index).
struct ShadowLayerView {
    uint32_t light = 0;
    uint32_t index = 0;  // cascade (directional), cube face, hemisphere
    LightProjection projection;
};
// One shadowed light and its run of layers.
struct ShadowedLightView {
    uint32_t light = 0;
    uint32_t firstLayer = 0, layerCount = 0;
    uint32_t kind = SHADOW_KIND_SINGLE;
};
// The shadow maps' host side: their layout from the build on, projections from the shadow
// technique's update() on.
struct ShadowLayers {
    uint32_t resolution = 0;
    std::vector<ShadowLayerView> layers;
    std::vector<ShadowedLightView> shadowed;
    // The light's shadow fields of the lights buffer (which layers, filter, bias).
    std::function<void(uint32_t light, gpu::GpuLight&)> fillGpuLight;
    // Layers whose visibility IDs another technique resolves this frame ("shadow.ids", layer
    // order): set after the shadow update, read when the shadow passes are declared.
    std::vector<uint32_t> idRequests;
};

// Casters another module rasterizes into "shadow.map" after the opaque ones (hair): whether it
// draws into a light's map (known at build), and its passes (with the frame's layers and lights).
struct ShadowCasters {
    std::function<bool(uint32_t light)> drawsInto;
    std::function<void(FrameGraph&, const ShadowLayers&, const std::vector<Light>&)> addTo;
};

// Lights whose translucent casters a deep shadow map takes instead of the ordinary shadow map.
struct DeepShadowLights {
    std::vector<bool> covered;  // per scene light
    bool covers(uint32_t light) const { return light < covered.size() && covered[light]; }
};

// The occupancy volume (a shared service, src/voxel): its builds so far, for consumers that redo
// their work when the voxels change.
struct OccupancyState {
    uint64_t generation = 0;
};

// The temporal-GI module's word to the GI techniques this frame: whether the frame adds to a
// history (then a gather may take fewer samples, varied from frame to frame by `frameSeed`) or
// starts one (the first frame, a cut, a light that changed too much: the full estimate).
struct GiAccumulation {
    bool accumulating = false;
    uint32_t frameSeed = 0;  // nonzero, different each frame, while accumulating
};

// How much a GI technique's light changed since the last frame, where the technique can measure it
// (temporal gradients): published with the image "gi.change", whose texel covers `pixels` x `pixels`
// pixels and holds (r) the change of a sample's luminance, (g) the larger of its two luminances, (b)
// change^2 / larger and (a) 1 where a sample was measured. The temporal-GI module weighs its history
// by it: a relative change of c in a frame, beyond what the samples' spread explains, weighs the new
// frame at least c / lagTolerance, the technique's own reading of its measure (a sampled estimate's
// gradients also hold the sampling's change; an exact one's hold the light's alone).
// Its texels are written by shaders/shared/gi_change.glsl, in kFormat.
struct GiChange {
    static constexpr VkFormat kFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    uint32_t pixels = 0;
    float lagTolerance = 1.0f;
};

// The sky, published by the lighting module's update for every technique that lights with it or
// bounces its light; its radiance is the GPU buffer names::kSkySh. `generation` changes whenever the
// sky does, so cached sky visibility restarts.
struct SkyLight {
    bool enabled = false;
    uint64_t generation = 0;
};

namespace names {
// Per-frame buffers the renderer writes.
inline constexpr BufferName kFrame{"frame"};
inline constexpr BufferName kViews{"views"};  // row 0 the camera, 1 + k shadow layer k
inline constexpr BufferName kLights{"lights"};
inline constexpr BufferName kInstances{"instances"};
inline constexpr BufferName kDrawnTriangles{"drawn-triangles"};
inline constexpr BufferName kProbe{"probe"};

// The camera's G-buffer.
inline constexpr ImageName kGbufferAlbedo{"gbuffer.albedo"};
inline constexpr ImageName kGbufferNormal{"gbuffer.normal"};
inline constexpr ImageName kGbufferDepth{"gbuffer.depth"};
inline constexpr ImageName kGbufferIds{"gbuffer.ids"};

// Shadow maps and masks.
inline constexpr ImageName kShadowMap{"shadow.map"};
inline constexpr ImageName kShadowMask{"shadow.mask"};
inline constexpr ImageName kShadowIds{"shadow.ids"};
inline constexpr HostName<ShadowLayers> kShadowLayers{"shadow.layers"};
inline constexpr HostName<ShadowCasters> kShadowCasters{"shadow.casters"};
inline constexpr HostName<DeepShadowLights> kDeepShadowLights{"dsm.lights"};

// Indirect irradiance per pixel: any number of techniques contribute an image under this name
// (FrameGraph::contribute) and the lighting pass sums them; kIrradiance is the sum it reads.
inline constexpr ImageName kIrradianceContribution{"gi.contribution"};
inline constexpr ImageName kIrradiance{"gi.irradiance"};
inline constexpr HostName<GiAccumulation> kGiAccumulation{"gi.accumulation"};
inline constexpr ImageName kGiChangeImage{"gi.change"};
inline constexpr HostName<GiChange> kGiChange{"gi.change"};

// The reflective shadow map that GI techniques inject or gather from ("rsm.depth", "rsm.normal",
// "rsm.flux", "rsm.vpls", "rsm.layers") and its layer count this frame.
inline constexpr ImageName kRsmDepth{"rsm.depth"};
inline constexpr HostName<uint32_t> kRsmLayerCount{"rsm.layer-count"};

// The sky's radiance (names.h SkyLight) and the visible sky's irradiance per pixel, which the
// lighting pass adds to the direct light when a technique writes it.
inline constexpr HostName<SkyLight> kSkyLight{"sky.light"};
// The sky's radiance as order-2 spherical harmonics (world space, +Y up, the user's scale applied):
// vec4 coefficients[9] of Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21, Y22 (core/sky.h's basis), RGB
// in .xyz; published by the lighting module's update, before any technique's passes.
inline constexpr BufferName kSkySh{"sky.sh"};
// The same radiance as an equirectangular RGBA16F image (shaders/sky/radiance.glsl reads it).
inline constexpr ImageName kSkyRadiance{"sky.radiance"};
inline constexpr ImageName kSkyIrradiance{"sky.irradiance"};

// Shared services.
inline constexpr BufferName kOccupancy{"occupancy"};
inline constexpr HostName<OccupancyState> kOccupancyState{"occupancy.state"};

// Lighting output: radiance (or the AOV) and the tone-mapped image.
inline constexpr ImageName kHdr{"hdr"};
inline constexpr ImageName kLdr{"ldr"};
// The images behind them, from the build on (read-back, a viewer's present blit).
inline constexpr HostName<vk::Image> kHdrImage{"hdr.image"};
inline constexpr HostName<vk::Image> kLdrImage{"ldr.image"};
// The tone mapper's scale of a count AOV, set by the technique the AOV shows (dsm-lists).
inline constexpr HostName<float> kCountAovScale{"aov.count-scale"};
}  // namespace names

}  // namespace penumbra
