// The settings below the techniques: image size, what the frame shows, how the camera draws. Every
// technique gets these (Technique, FrameContext); each keeps its own settings struct besides, and
// the assembly (renderer/render_settings.h) aggregates them all.
#pragma once
#include <cstdint>

#include "shared/types.h"

namespace penumbra {

enum class Aov {
    Direct = AOV_DIRECT,
    Albedo = AOV_ALBEDO,
    Normal = AOV_NORMAL,
    Depth = AOV_DEPTH,
    Shadow = AOV_SHADOW,
    Final = AOV_FINAL,
    Indirect = AOV_INDIRECT,
    LpvSlice = AOV_LPV_SLICE,
    GvSlice = AOV_GV_SLICE,
    Cascade = AOV_CASCADE,
    Transmittance = AOV_TRANSMITTANCE,
    DsmLists = AOV_DSM_LISTS,
    RsmDepth = AOV_RSM_DEPTH,
    RsmNormal = AOV_RSM_NORMAL,
    RsmFlux = AOV_RSM_FLUX,
    ShadowMap = AOV_SHADOW_MAP,
    Velocity = AOV_VELOCITY,
    Sky = AOV_SKY,
};

// The camera's G-buffer (lighting/gbuffer_pass.h): visibility buffer + compute resolve, or classic raster.
enum class CameraPath { Visibility, Gbuffer };

struct CoreSettings {
    uint32_t width = 1280;
    uint32_t height = 720;
    Aov aov = Aov::Final;
    uint32_t aovLayer = 0;
    float exposure = 1.0f;
    CameraPath cameraPath = CameraPath::Visibility;
    // Hair and BLEND surfaces composited in depth order (src/dsm/translucency.h); off: drawn opaque.
    bool translucency = true;
    // The compute rasterizer draws the camera's and the lights' views (resolved for the device).
    bool computeRaster = false;
    // Exposure like a camera's: the geometry's log-average luminance maps to middle grey, adapted
    // over frames (src/lighting/auto_exposure.h); `exposure` is used when off. Either way the
    // compensation (EV) multiplies it by 2^EV.
    bool autoExposure = false;
    float exposureCompensation = 0.0f;
};

}  // namespace penumbra
